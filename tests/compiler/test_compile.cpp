// compile.hpp: GLSL -> SPIR-V -> every target, with reflection.
//
// Every text compile() emits is compiled again by an independent front end, so that a
// target "passes" only when a compiler accepts it, not when it merely exists:
//   glsl   glslang, desktop GLSL 450 with OpenGL semantics (no Vulkan client), parsed and
//          linked; and again for OpenGL SPIR-V (GL_ARB_gl_spirv), checked by spirv-val
//          (not with push constants: SPIRV-Cross writes them as a plain uniform struct,
//          which GL_ARB_gl_spirv would want a location on)
//   essl   glslang, ESSL 310 / 300 (its `#version ... es`), parsed and linked: ES rules,
//          including "no default precision for float" in fragment shaders
//   hlsl   glslang's HLSL front end (EShSourceHlsl) with the reflected entry point, to
//          SPIR-V for Vulkan, checked by spirv-val; the cbuffer's packoffsets, compiled
//          with HLSL packing, land at the std140 offsets of the original block
//   spv    spirv-val (Vulkan 1.0)
//   msl    no Metal compiler here: non-empty, `#include <metal_stdlib>`, the entry point
//          with the stage's qualifier (kernel / vertex / fragment)
// Reflection is checked against known values and against aogen::layout::compute.

#include "support.hpp"

#include <aogen/compile.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_compile {

namespace cc = aogen::compile;
using aogen_test::error_of;
using Catch::Contains;

namespace {

// A compute pass with the three kinds of binding an AO pass has: a std140 uniform block
// (members chosen so that std140 and std430 disagree), a sampler2D and a writeonly r8
// output image. Not every member is read: spirv-opt must keep the block whole anyway.
const char* const compute_source = R"(#version 450
layout(local_size_x = 8, local_size_y = 4) in;
struct Light { vec3 color; float intensity; };
layout(std140, set = 0, binding = 0) uniform SsaoTest {
    mat4 projection;
    vec4 kernel[8];
    vec3 light_dir;
    float radius;
    vec2 texel;
    int count;
    float weights[4];
    Light light;
    mat3 normal_matrix;
    float bias;
} u;
layout(set = 0, binding = 1) uniform sampler2D depth_tex;
layout(set = 0, binding = 2, FORMAT) uniform writeonly image2D ao_out;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    vec2 uv = (vec2(p) + 0.5) * u.texel;
    float depth = textureLod(depth_tex, uv, 0.0).r;
    vec4 view = u.projection * vec4(uv, depth, 1.0);
    float occlusion = 0.0;
    for (int i = 0; i < u.count; ++i) {
        vec3 s = (u.normal_matrix * u.kernel[i].xyz) * u.radius;
        occlusion += step(view.z + s.z + u.bias, depth) * u.weights[i & 3];
    }
    imageStore(ao_out, p, vec4(1.0 - occlusion * u.light.intensity));
}
)";

std::string compute_with_format(const std::string& format)
{
    std::string s = compute_source;
    s.replace(s.find("FORMAT"), 6, format);
    return s;
}

// A fragment pass reading through a separate texture and sampler (Vulkan GLSL), writing a float.
const char* const fragment_source = R"(#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out float ao;
layout(set = 0, binding = 0) uniform texture2D depth_tex;
layout(set = 0, binding = 1) uniform sampler point_sampler;
layout(std140, set = 1, binding = 0) uniform BlurTest { vec2 direction; float sharpness; } b;
void main() {
    float center = texture(sampler2D(depth_tex, point_sampler), uv).r;
    float side = texture(sampler2D(depth_tex, point_sampler), uv + b.direction).r;
    ao = exp(-abs(center - side) * b.sharpness);
}
)";

// A full-screen triangle.
const char* const vertex_source = R"(#version 450
layout(location = 0) out vec2 uv;
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// Storage buffers (readonly with a runtime array, writeonly), push constants, a binding
// the shader never uses (spirv-opt must keep it) and an array of separate images.
const char* const storage_source = R"(#version 450
layout(local_size_x = 64) in;
layout(push_constant) uniform Push { uint count; float scale; } pc;
layout(std430, set = 0, binding = 0) readonly buffer Input { vec4 header; float values[]; } src;
layout(std430, set = 0, binding = 1) writeonly buffer Output { float results[]; } dst;
layout(set = 0, binding = 2) uniform sampler2D unused_tex;
layout(set = 1, binding = 3) uniform texture2D textures[4];
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < pc.count) dst.results[i] = src.values[i] * pc.scale + src.header.x;
}
)";

// ---------------------------------------------------------------------------------
// The independent front ends
// ---------------------------------------------------------------------------------

EShLanguage glslang_stage(cc::shader_stage s)
{
    switch (s) {
    case cc::shader_stage::compute: return EShLangCompute;
    case cc::shader_stage::vertex: return EShLangVertex;
    case cc::shader_stage::fragment: return EShLangFragment;
    }
    return EShLangCompute;
}

std::string spirv_val(const std::vector<uint32_t>& words, spv_target_env env)
{
    spvtools::SpirvTools tools(env);
    std::string log;
    tools.SetMessageConsumer([&log](spv_message_level_t, const char*, const spv_position_t& p, const char* m) {
        log += "word " + std::to_string(p.index) + ": " + m + "\n";
    });
    if (tools.Validate(words.data(), words.size(), spvtools::ValidatorOptions())) return {};
    return log.empty() ? std::string("invalid") : log;
}

struct front_end_result {
    std::string log;             // empty when accepted
    std::vector<uint32_t> spirv; // when a SPIR-V client was asked for
};

enum class client { none, opengl, vulkan };

// glslang on one text. `source` GLSL takes version and profile from its #version line.
front_end_result run_glslang(const std::string& text, cc::shader_stage stage, glslang::EShSource source, client cl,
                             const std::string& entry)
{
    cc::detail::initialize_glslang();
    front_end_result r;
    const EShLanguage lang = glslang_stage(stage);
    glslang::TShader shader(lang);
    const char* s = text.c_str();
    shader.setStrings(&s, 1);
    int messages = EShMsgDefault;
    if (source == glslang::EShSourceHlsl) {
        shader.setEntryPoint(entry.c_str());
        messages |= EShMsgReadHlsl | EShMsgHlslOffsets;
    }
    switch (cl) {
    case client::none: shader.setEnvInput(source, lang, glslang::EShClientNone, 0); break;
    case client::opengl:
        shader.setEnvInput(source, lang, glslang::EShClientOpenGL, 100);
        shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
        shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
        messages |= EShMsgSpvRules;
        break;
    case client::vulkan:
        shader.setEnvInput(source, lang, glslang::EShClientVulkan, 100);
        shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
        shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
        messages |= EShMsgSpvRules | EShMsgVulkanRules;
        break;
    }
    if (!shader.parse(GetDefaultResources(), 100, false, static_cast<EShMessages>(messages))) {
        r.log = std::string("parse: ") + shader.getInfoLog() + shader.getInfoDebugLog();
        return r;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(static_cast<EShMessages>(messages))) {
        r.log = std::string("link: ") + program.getInfoLog() + program.getInfoDebugLog();
        return r;
    }
    if (cl == client::none) return r;
    std::vector<unsigned int> words;
    glslang::SpvOptions options;
    options.disableOptimizer = true;
    glslang::GlslangToSpv(*program.getIntermediate(lang), words, &options);
    r.spirv.assign(words.begin(), words.end());
    if (r.spirv.empty()) r.log = "no SPIR-V";
    else r.log = spirv_val(r.spirv, cl == client::vulkan ? SPV_ENV_VULKAN_1_0 : SPV_ENV_OPENGL_4_5);
    return r;
}

const char* msl_qualifier(cc::shader_stage s)
{
    switch (s) {
    case cc::shader_stage::compute: return "kernel ";
    case cc::shader_stage::vertex: return "vertex ";
    case cc::shader_stage::fragment: return "fragment ";
    }
    return "?";
}

// Checks every text of `out` with its front end; returns the HLSL modules glslang made.
std::map<cc::target, std::vector<uint32_t>> revalidate(const cc::compiled& out, cc::shader_stage stage)
{
    std::map<cc::target, std::vector<uint32_t>> hlsl_modules;
    INFO("SPIR-V");
    CHECK(spirv_val(out.spirv, SPV_ENV_VULKAN_1_0).empty());
    CHECK(out.refl.entry_points.at(cc::target::spv) == "main");
    for (const auto& [t, text] : out.text) {
        const std::string entry = out.refl.entry_points.at(t);
        INFO("target " << cc::to_name(t) << ", entry point " << entry << "\n" << text);
        REQUIRE(!text.empty());
        switch (t) {
        case cc::target::spv: FAIL("spv has no text"); break;
        case cc::target::glsl: {
            CHECK(text.rfind("#version 450\n", 0) == 0);
            CHECK(entry == "main");
            CHECK(text.find("void main()") != std::string::npos);
            const front_end_result gl = run_glslang(text, stage, glslang::EShSourceGlsl, client::none, entry);
            CHECK(gl.log == "");
            // OpenGL SPIR-V wants a location on plain uniforms, which SPIRV-Cross's push
            // constants (`uniform Push pc;`) lack: that check only without push constants.
            if (std::none_of(out.refl.blocks.begin(), out.refl.blocks.end(),
                             [](const cc::buffer_block& b) { return b.kind == cc::block_kind::push_constant; })) {
                const front_end_result gl_spirv = run_glslang(text, stage, glslang::EShSourceGlsl, client::opengl, entry);
                CHECK(gl_spirv.log == "");
            }
            break;
        }
        case cc::target::essl: {
            const char* version = stage == cc::shader_stage::compute ? "#version 310 es\n" : "#version 300 es\n";
            CHECK(text.rfind(version, 0) == 0);
            CHECK(entry == "main");
            CHECK(text.find("void main()") != std::string::npos);
            CHECK(text.find("precision highp float;") != std::string::npos);
            CHECK(text.find("precision highp int;") != std::string::npos);
            CHECK(text.find("mediump") == std::string::npos);
            CHECK(text.find("lowp") == std::string::npos);
            const front_end_result es = run_glslang(text, stage, glslang::EShSourceGlsl, client::none, entry);
            CHECK(es.log == "");
            break;
        }
        case cc::target::hlsl:
        case cc::target::hlsl60: {
            CHECK(entry == "main");
            CHECK(text.find(" main(") != std::string::npos);
            const front_end_result hlsl = run_glslang(text, stage, glslang::EShSourceHlsl, client::vulkan, entry);
            CHECK(hlsl.log == "");
            hlsl_modules[t] = hlsl.spirv;
            break;
        }
        case cc::target::msl_macos:
        case cc::target::msl_ios: {
            CHECK(entry == "main0");
            CHECK(text.rfind("#include <metal_stdlib>\n", 0) == 0);
            CHECK(text.find(std::string(msl_qualifier(stage))) != std::string::npos);
            CHECK(text.find(" " + entry + "(") != std::string::npos);
            break;
        }
        }
    }
    return hlsl_modules;
}

// The cbuffer members' Offset decorations in a module glslang made from HLSL.
std::vector<uint32_t> cbuffer_offsets(const std::vector<uint32_t>& spirv, const std::string& block)
{
    spirv_cross::Compiler c(spirv);
    for (const spirv_cross::Resource& res : c.get_shader_resources().uniform_buffers) {
        if (res.name != block) continue;
        const spirv_cross::SPIRType& type = c.get_type(res.base_type_id);
        std::vector<uint32_t> offsets;
        for (uint32_t i = 0; i < type.member_types.size(); ++i) offsets.push_back(c.type_struct_member_offset(type, i));
        return offsets;
    }
    return {};
}

aogen::layout::block_desc ssao_test_block()
{
    return {{"SsaoTest",
             {{"projection", "mat4"},
              {"kernel", "vec4", 8},
              {"light_dir", "vec3"},
              {"radius", "float"},
              {"texel", "vec2"},
              {"count", "int"},
              {"weights", "float", 4},
              {"light", "Light"},
              {"normal_matrix", "mat3"},
              {"bias", "float"}}},
            {{"Light", {{"color", "vec3"}, {"intensity", "float"}}}}};
}

const std::vector<cc::target> all_but_essl{cc::target::spv,    cc::target::glsl,      cc::target::hlsl,
                                           cc::target::hlsl60, cc::target::msl_macos, cc::target::msl_ios};

} // namespace

// ---------------------------------------------------------------------------------

TEST_CASE("compile: target and stage names", "[compile]")
{
    CHECK(cc::target_list() == "spv, glsl, essl, hlsl, hlsl60, msl, msl_ios, wgsl");
    CHECK(cc::spirv_cross_targets.size() + 1 == cc::all_targets.size()); // all but wgsl (naga's)
    for (cc::target t : cc::all_targets) CHECK(cc::target_from_name(cc::to_name(t)) == t);
    CHECK(cc::target_from_name("msl-ios") == cc::target::msl_ios);
    CHECK(cc::target_from_name("hlsl") == cc::target::hlsl);
    CHECK(error_of([] { cc::target_from_name("dxil", "--target"); }) ==
          "--target: 'dxil' is not a known name (valid: spv, glsl, essl, hlsl, hlsl60, msl, msl_ios, wgsl)");
    CHECK(cc::shader_stage_from_name("fragment") == cc::shader_stage::fragment);
}

TEST_CASE("compile: compute shader to every target but essl (r8 output), re-validated", "[compile]")
{
    const cc::compiled out = cc::compile(compute_with_format("r8"), cc::shader_stage::compute, "test compute", all_but_essl);
    REQUIRE(out.text.size() == 5);
    const auto hlsl = revalidate(out, cc::shader_stage::compute);

    const cc::reflection& r = out.refl;
    CHECK(r.stage == cc::shader_stage::compute);
    CHECK(r.workgroup_size == std::array<uint32_t, 3>{{8, 4, 1}});
    CHECK(r.entry_points.size() == 6);
    CHECK(r.entry_points.at(cc::target::hlsl60) == "main");
    CHECK(r.entry_points.at(cc::target::msl_ios) == "main0");

    REQUIRE(r.bindings.size() == 3);
    CHECK(r.bindings[0].set == 0);
    CHECK(r.bindings[0].binding == 0);
    CHECK(r.bindings[0].kind == cc::descriptor_kind::uniform_buffer);
    CHECK(r.bindings[0].name == "SsaoTest");
    CHECK(r.bindings[0].instance == "u");
    CHECK(r.bindings[0].type == "uniform");
    CHECK(r.bindings[0].msl_buffer == 0);
    CHECK(r.bindings[1].binding == 1);
    CHECK(r.bindings[1].kind == cc::descriptor_kind::combined_image_sampler);
    CHECK(r.bindings[1].name == "depth_tex");
    CHECK(r.bindings[1].type == "sampler2D");
    CHECK(r.bindings[1].image_format == "");
    CHECK(r.bindings[1].msl_texture == 0);
    CHECK(r.bindings[1].msl_sampler == 0);
    CHECK(r.bindings[2].binding == 2);
    CHECK(r.bindings[2].kind == cc::descriptor_kind::storage_image);
    CHECK(r.bindings[2].name == "ao_out");
    CHECK(r.bindings[2].type == "image2D");
    CHECK(r.bindings[2].image_format == "r8");
    CHECK_FALSE(r.bindings[2].readable);
    CHECK(r.bindings[2].writable);
    CHECK(r.bindings[2].msl_texture == 1);
    CHECK(r.bindings[2].msl_buffer == cc::no_index);
    for (const cc::descriptor_binding& b : r.bindings) CHECK(b.count == 1);

    // The texts bind what the reflection says.
    const std::string& glsl = out.text.at(cc::target::glsl);
    CHECK(glsl.find("layout(binding = 0, std140) uniform SsaoTest") != std::string::npos);
    CHECK(glsl.find("layout(binding = 1) uniform sampler2D depth_tex;") != std::string::npos);
    CHECK(glsl.find("layout(binding = 2, r8) uniform writeonly image2D ao_out;") != std::string::npos);
    CHECK(glsl.find("layout(local_size_x = 8, local_size_y = 4, local_size_z = 1) in;") != std::string::npos);
    CHECK(out.text.at(cc::target::hlsl).find("cbuffer SsaoTest : register(b0)") != std::string::npos);
    CHECK(out.text.at(cc::target::hlsl60).find("cbuffer SsaoTest : register(b0, space0)") != std::string::npos);
    CHECK(out.text.at(cc::target::hlsl).find("[numthreads(8, 4, 1)]") != std::string::npos);
    CHECK(out.text.at(cc::target::hlsl).find("RWTexture2D<unorm float> ao_out : register(u2)") != std::string::npos);
    CHECK(out.text.at(cc::target::msl_macos).find("kernel void main0(constant SsaoTest& u [[buffer(0)]]") != std::string::npos);
    CHECK(out.text.at(cc::target::msl_macos).find("texture2d<float, access::write> ao_out [[texture(1)]]") != std::string::npos);

    // Size figures: the header plus whole instructions; the optimizer made it smaller.
    CHECK(r.spirv_words == out.spirv.size());
    CHECK(r.spirv_instructions == cc::count_instructions(out.spirv));
    CHECK(r.spirv_instructions > 20);
    CHECK(r.unoptimized_words > r.spirv_words);
    CHECK(r.unoptimized_instructions > r.spirv_instructions);

    // The block, as SPIR-V declares it, against known std140 offsets and the layout engine.
    const cc::buffer_block* block = cc::find_block(r, "SsaoTest");
    REQUIRE(block != nullptr);
    CHECK(block->kind == cc::block_kind::uniform);
    CHECK(block->instance == "u");
    REQUIRE(block->members.size() == 10);
    const auto& m = block->members;
    CHECK(m[0].name == "projection");
    CHECK(m[0].type == "mat4");
    CHECK(m[0].offset == 0);
    CHECK(m[0].matrix_stride == 16);
    CHECK(m[0].size == 64);
    CHECK(m[1].type == "vec4");
    CHECK(m[1].array == std::vector<uint32_t>{8});
    CHECK(m[1].offset == 64);
    CHECK(m[1].array_stride == 16);
    CHECK(m[2].offset == 192);
    CHECK(m[3].offset == 204); // radius in light_dir's fourth lane
    CHECK(m[4].offset == 208);
    CHECK(m[5].offset == 216);
    CHECK(m[6].offset == 224);
    CHECK(m[6].array_stride == 16); // std140 rounds a float array's stride up to 16
    CHECK(m[6].size == 64);
    CHECK(m[7].type == "Light");
    CHECK(m[7].offset == 288);
    REQUIRE(m[7].members.size() == 2);
    CHECK(m[7].members[1].name == "intensity");
    CHECK(m[7].members[1].offset == 12);
    CHECK(m[8].type == "mat3");
    CHECK(m[8].offset == 304);
    CHECK(m[8].matrix_stride == 16);
    CHECK(m[9].offset == 352);
    CHECK(block->size == 356);

    const aogen::layout::struct_layout std140 = aogen::layout::compute(ssao_test_block(), aogen::layout::rules::std140);
    CHECK(cc::layout_mismatches(*block, std140).empty());
    CHECK_NOTHROW(cc::check_layout(*block, std140));

    // The same block under std430 is a different layout: every disagreement is named.
    const aogen::layout::struct_layout std430 = aogen::layout::compute(ssao_test_block(), aogen::layout::rules::std430);
    const std::vector<std::string> mismatches = cc::layout_mismatches(*block, std430);
    CHECK(std::find(mismatches.begin(), mismatches.end(), "SsaoTest.weights: array stride SPIR-V 16, layout 4") != mismatches.end());
    CHECK(std::find(mismatches.begin(), mismatches.end(), "SsaoTest.light: offset SPIR-V 288, layout 240") != mismatches.end());
    const std::string e = error_of([&] { cc::check_layout(*block, std430); });
    CHECK(e.rfind("block SsaoTest (std430): the SPIR-V does not match the layout: ", 0) == 0);
    CHECK(e.find("SsaoTest.weights: array stride SPIR-V 16, layout 4") != std::string::npos);

    // HLSL read back through glslang with HLSL packing: the packoffsets SPIRV-Cross wrote
    // put every cbuffer member at the std140 offset of the original block.
    std::vector<uint32_t> std140_offsets;
    for (const cc::block_member& member : m) std140_offsets.push_back(member.offset);
    for (const auto& [t, module] : hlsl) {
        INFO(cc::to_name(t));
        CHECK(cbuffer_offsets(module, "SsaoTest") == std140_offsets);
    }
}

TEST_CASE("compile: compute shader with an ES image format to every target", "[compile]")
{
    for (const char* format : {"r32f", "rgba8"}) {
        INFO(format);
        const cc::compiled out = cc::compile(compute_with_format(format), cc::shader_stage::compute, "test compute", cc::spirv_cross_targets);
        CHECK(out.text.size() == 6);
        revalidate(out, cc::shader_stage::compute);
        CHECK(out.refl.bindings.at(2).image_format == format);
        const std::string& essl = out.text.at(cc::target::essl);
        CHECK(essl.find(std::string("layout(binding = 2, ") + format + ") uniform writeonly highp image2D ao_out;") != std::string::npos);
        CHECK(essl.find("uniform highp sampler2D depth_tex;") != std::string::npos);
        // The precision statements come after #version and before the first declaration.
        CHECK(essl.rfind("#version 310 es\nprecision highp float;\nprecision highp int;\n\nlayout(local_size_x = 8", 0) == 0);
    }
}

TEST_CASE("compile: essl refuses a desktop-only image format by name", "[compile]")
{
    const std::string e = error_of([] {
        cc::compile(compute_with_format("r8"), cc::shader_stage::compute, "ssao-s16 ao", {cc::target::essl});
    });
    CHECK(e.rfind("ssao-s16 ao: essl: storage image ao_out: format r8 does not exist in OpenGL ES (valid in ESSL 3.10: rgba32f, ", 0) == 0);
}

TEST_CASE("compile: a GLSL/ESSL text using what its version lacks is refused, naming the shader", "[compile]")
{
    // bitCount exists in GLSL 4.00 and ESSL 3.10, not in ESSL 3.00 (fragment shaders' ESSL).
    const char* const source = R"(#version 450
layout(location = 0) out float ao;
layout(std140, set = 0, binding = 0) uniform Mask { uint bits; } m;
void main() { ao = float(bitCount(m.bits)) / 32.0; }
)";
    const cc::compiled glsl = cc::compile(source, cc::shader_stage::fragment, "vbao ao", {cc::target::glsl});
    CHECK(glsl.text.at(cc::target::glsl).find("bitCount") != std::string::npos);
    const std::string e = error_of([&] { cc::compile(source, cc::shader_stage::fragment, "vbao ao", {cc::target::essl}); });
    CHECK(e.rfind("vbao ao: SPIRV-Cross's ESSL 300 fragment shader does not compile as ESSL 300 (valid: ", 0) == 0);
    CHECK_THAT(e, Contains("'bitCount' : no matching overloaded function found"));
}

TEST_CASE("compile: fragment shader with a separate texture and sampler, re-validated", "[compile]")
{
    const cc::compiled out = cc::compile(fragment_source, cc::shader_stage::fragment, "test fragment", cc::spirv_cross_targets);
    CHECK(out.text.size() == 6);
    const auto hlsl = revalidate(out, cc::shader_stage::fragment);
    const cc::reflection& r = out.refl;
    CHECK(r.workgroup_size == std::array<uint32_t, 3>{{0, 0, 0}});
    REQUIRE(r.bindings.size() == 3);
    CHECK(r.bindings[0].kind == cc::descriptor_kind::sampled_image);
    CHECK(r.bindings[0].type == "texture2D");
    CHECK(r.bindings[0].msl_texture == 0);
    CHECK(r.bindings[1].kind == cc::descriptor_kind::sampler);
    CHECK(r.bindings[1].type == "sampler");
    CHECK(r.bindings[1].msl_sampler == 0);
    CHECK(r.bindings[2].set == 1);
    CHECK(r.bindings[2].binding == 0);
    CHECK(r.bindings[2].kind == cc::descriptor_kind::uniform_buffer);
    CHECK(r.bindings[2].msl_buffer == 0);
    REQUIRE(r.inputs.size() == 1);
    CHECK(r.inputs[0].name == "uv");
    CHECK(r.inputs[0].type == "vec2");
    REQUIRE(r.outputs.size() == 1);
    CHECK(r.outputs[0].location == 0);
    CHECK(r.outputs[0].name == "ao");
    CHECK(r.outputs[0].type == "float");

    // OpenGL has no separate samplers: one combined sampler, at the image's binding.
    const std::string& glsl = out.text.at(cc::target::glsl);
    CHECK(glsl.find("layout(binding = 0) uniform sampler2D depth_tex_point_sampler;") != std::string::npos);
    CHECK(glsl.find("layout(binding = 0, std140) uniform BlurTest") != std::string::npos);
    // ESSL 300: default precision highp, from SPIRV-Cross itself for fragment shaders.
    const std::string& essl = out.text.at(cc::target::essl);
    CHECK(essl.find("precision highp float;\nprecision highp int;\n") != std::string::npos);
    // ESSL 300 has no layout(binding): blocks and samplers are bound by name.
    CHECK(essl.find("uniform highp sampler2D depth_tex_point_sampler;") != std::string::npos);
    CHECK(essl.find("layout(std140) uniform BlurTest") != std::string::npos);
    CHECK(essl.find("binding") == std::string::npos);
    // HLSL: registers from the bindings; SM 5.0 has no spaces, SM 6.0 has set 1's.
    CHECK(out.text.at(cc::target::hlsl).find("cbuffer BlurTest : register(b0)") != std::string::npos);
    CHECK(out.text.at(cc::target::hlsl60).find("cbuffer BlurTest : register(b0, space1)") != std::string::npos);
    CHECK(out.text.at(cc::target::hlsl).find("SamplerState point_sampler : register(s1);") != std::string::npos);
    CHECK(out.text.at(cc::target::msl_macos).find("fragment main0_out main0(") != std::string::npos);

    const cc::buffer_block* block = cc::find_block(r, "BlurTest");
    REQUIRE(block != nullptr);
    const aogen::layout::block_desc desc{{"BlurTest", {{"direction", "vec2"}, {"sharpness", "float"}}}, {}};
    CHECK_NOTHROW(cc::check_layout(*block, aogen::layout::compute(desc, aogen::layout::rules::std140)));
    for (const auto& [t, module] : hlsl) CHECK(cbuffer_offsets(module, "BlurTest") == std::vector<uint32_t>{0, 8});
}

TEST_CASE("compile: vertex shader, re-validated", "[compile]")
{
    const cc::compiled out = cc::compile(vertex_source, cc::shader_stage::vertex, "test vertex", cc::spirv_cross_targets);
    CHECK(out.text.size() == 6);
    revalidate(out, cc::shader_stage::vertex);
    const cc::reflection& r = out.refl;
    CHECK(r.bindings.empty());
    CHECK(r.blocks.empty());
    CHECK(r.inputs.empty());
    REQUIRE(r.outputs.size() == 1);
    CHECK(r.outputs[0].name == "uv");
    CHECK(out.text.at(cc::target::essl).rfind("#version 300 es\nprecision highp float;\nprecision highp int;\n\n", 0) == 0);
    CHECK(out.text.at(cc::target::glsl).find("gl_VertexID") != std::string::npos);
    CHECK(out.text.at(cc::target::glsl).find("SPIRV_Cross_BaseInstance") == std::string::npos);
    CHECK(out.text.at(cc::target::hlsl).find("SV_VertexID") != std::string::npos);
    CHECK(out.text.at(cc::target::msl_ios).find("vertex main0_out main0(") != std::string::npos);
}

TEST_CASE("compile: storage buffers, push constants and unused bindings", "[compile]")
{
    const cc::compiled out = cc::compile(storage_source, cc::shader_stage::compute, "test storage", cc::spirv_cross_targets);
    CHECK(out.text.size() == 6);
    revalidate(out, cc::shader_stage::compute);
    const cc::reflection& r = out.refl;
    CHECK(r.workgroup_size == std::array<uint32_t, 3>{{64, 1, 1}});
    REQUIRE(r.bindings.size() == 4);
    const cc::descriptor_binding& src = r.bindings[0];
    CHECK(src.kind == cc::descriptor_kind::storage_buffer);
    CHECK(src.name == "Input");
    CHECK(src.instance == "src");
    CHECK(src.readable);
    CHECK_FALSE(src.writable);
    const cc::descriptor_binding& dst = r.bindings[1];
    CHECK(dst.kind == cc::descriptor_kind::storage_buffer);
    CHECK_FALSE(dst.readable);
    CHECK(dst.writable);
    // Never read, still in the interface (preserve_bindings), and in HLSL; not in MSL.
    const cc::descriptor_binding& unused = r.bindings[2];
    CHECK(unused.name == "unused_tex");
    CHECK(unused.kind == cc::descriptor_kind::combined_image_sampler);
    CHECK(unused.msl_texture == cc::no_index);
    CHECK(out.text.at(cc::target::hlsl).find("unused_tex : register(t2)") != std::string::npos);
    CHECK(out.text.at(cc::target::glsl).find("layout(binding = 2) uniform sampler2D unused_tex;") != std::string::npos);
    CHECK(out.text.at(cc::target::msl_macos).find("unused_tex") == std::string::npos);
    const cc::descriptor_binding& textures = r.bindings[3];
    CHECK(textures.set == 1);
    CHECK(textures.binding == 3);
    CHECK(textures.kind == cc::descriptor_kind::sampled_image);
    CHECK(textures.count == 4);
    CHECK(out.text.at(cc::target::hlsl60).find("Texture2D<float4> textures[4] : register(t3, space1);") != std::string::npos);

    REQUIRE(r.blocks.size() == 3); // Input, Output, then the push constants
    const cc::buffer_block& input = r.blocks[0];
    CHECK(input.kind == cc::block_kind::storage);
    CHECK(input.size == 16); // the runtime array counts no elements
    REQUIRE(input.members.size() == 2);
    CHECK(input.members[1].array == std::vector<uint32_t>{0});
    CHECK(input.members[1].array_stride == 4);
    const aogen::layout::block_desc input_desc{{"Input", {{"header", "vec4"}, {"values", "float", 0u}}}, {}};
    CHECK_NOTHROW(cc::check_layout(input, aogen::layout::compute(input_desc, aogen::layout::rules::std430)));
    CHECK(r.blocks[1].name == "Output");
    const cc::buffer_block& push = r.blocks[2];
    CHECK(push.kind == cc::block_kind::push_constant);
    CHECK(push.name == "Push");
    CHECK(push.instance == "pc");
    CHECK(push.size == 8);
    CHECK(push.members.at(1).offset == 4);
    // SPIRV-Cross's MSL order: push constants, then the buffers as it meets them.
    CHECK(push.msl_buffer == 0);
    CHECK(r.blocks[1].msl_buffer == dst.msl_buffer);
    CHECK(input.msl_buffer == src.msl_buffer);
    CHECK(std::set<uint32_t>{push.msl_buffer, src.msl_buffer, dst.msl_buffer} == std::set<uint32_t>{0, 1, 2});
}

TEST_CASE("compile: hlsl (SM 5.0) refuses two sets' resources in one register", "[compile]")
{
    std::string source = storage_source;
    source.replace(source.find("binding = 3"), 11, "binding = 0");
    const std::string e = error_of([&] { cc::compile(source, cc::shader_stage::compute, "s", {cc::target::hlsl}); });
    CHECK(e == "s: hlsl: register t0 holds both src and textures; shader model 5.0 has no register spaces, so bindings of "
               "different sets collide (valid: bindings distinct across descriptor sets for each register kind, or the hlsl60 target)");
    // SM 6.0 has spaces: the same source is fine there.
    const cc::compiled out = cc::compile(source, cc::shader_stage::compute, "s", {cc::target::hlsl60});
    CHECK(out.text.at(cc::target::hlsl60).find("textures[4] : register(t0, space1)") != std::string::npos);
}

TEST_CASE("compile: 16-bit float arithmetic goes to spv, hlsl (min16float) and msl (half), and is refused for glsl and essl", "[compile]")
{
    const std::string source = R"(#version 450
#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, r32f) uniform writeonly image2D result;
layout(set = 0, binding = 1) uniform Block { float x; } u;
void main()
{
    float16_t h = float16_t(u.x) * float16_t(0.5);
    imageStore(result, ivec2(gl_GlobalInvocationID.xy), vec4(float(h)));
}
)";
    const cc::compiled out = cc::compile(source, cc::shader_stage::compute, "h", {cc::target::hlsl, cc::target::msl_macos});
    CHECK(out.text.at(cc::target::hlsl).find("min16float") != std::string::npos);
    CHECK(out.text.at(cc::target::msl_macos).find("half") != std::string::npos);
    for (cc::target t : {cc::target::glsl, cc::target::essl})
        CHECK_THAT(error_of([&] { cc::compile(source, cc::shader_stage::compute, "h", {t}); }),
                   Contains("h: does 16-bit float arithmetic (an fp16 variant), which has no portable") &&
                       Contains("valid: --targets spv,hlsl,hlsl60,msl,msl_ios for fp16 variants"));
}

TEST_CASE("compile: same input, same bytes", "[compile]")
{
    const std::string source = compute_with_format("r32f");
    const cc::compiled a = cc::compile(source, cc::shader_stage::compute, "a", cc::spirv_cross_targets);
    const cc::compiled b = cc::compile(source, cc::shader_stage::compute, "b",
                                       {cc::target::msl_ios, cc::target::essl, cc::target::hlsl60, cc::target::glsl,
                                        cc::target::msl_macos, cc::target::hlsl, cc::target::glsl});
    CHECK(a.spirv == b.spirv);
    CHECK(a.text == b.text);
    CHECK(a.refl.entry_points == b.refl.entry_points);
    for (size_t i = 0; i < a.refl.bindings.size(); ++i) CHECK(a.refl.bindings[i].msl_texture == b.refl.bindings[i].msl_texture);
    // Only what was asked for.
    const cc::compiled spv_only = cc::compile(source, cc::shader_stage::compute, "c", {cc::target::spv});
    CHECK(spv_only.text.empty());
    CHECK(spv_only.spirv == a.spirv);
    CHECK(spv_only.refl.entry_points.size() == 1);
}

TEST_CASE("compile: several threads at once, same bytes as one", "[compile]")
{
    const std::string sources[] = {compute_with_format("r32f"), fragment_source, vertex_source, storage_source};
    const cc::shader_stage stages[] = {cc::shader_stage::compute, cc::shader_stage::fragment, cc::shader_stage::vertex,
                                       cc::shader_stage::compute};
    std::vector<cc::compiled> alone;
    for (int i = 0; i < 4; ++i) alone.push_back(cc::compile(sources[i], stages[i], "alone", cc::spirv_cross_targets));
    std::vector<cc::compiled> together(8);
    std::vector<std::string> failures(8);
    std::vector<std::thread> threads;
    for (int i = 0; i < 8; ++i)
        threads.emplace_back([&, i] {
            try {
                together[i] = cc::compile(sources[i % 4], stages[i % 4], "thread", cc::spirv_cross_targets);
            } catch (const std::exception& e) {
                failures[i] = e.what();
            }
        });
    for (std::thread& t : threads) t.join();
    for (int i = 0; i < 8; ++i) {
        INFO("thread " << i);
        CHECK(failures[i] == "");
        CHECK(together[i].spirv == alone[i % 4].spirv);
        CHECK(together[i].text == alone[i % 4].text);
    }
}

TEST_CASE("compile: without the optimizer", "[compile]")
{
    cc::options o;
    o.optimize = false;
    const cc::compiled out = cc::compile(compute_with_format("r32f"), cc::shader_stage::compute, "raw", cc::spirv_cross_targets, o);
    revalidate(out, cc::shader_stage::compute);
    CHECK(out.refl.spirv_words == out.refl.unoptimized_words);
    CHECK(out.refl.spirv_instructions == out.refl.unoptimized_instructions);
}

TEST_CASE("compile: glslang errors name the file and line of #line directives", "[compile]")
{
    // Line 3 of ssao.glsl is the undeclared identifier; the extension is not requested.
    const std::string source = "#version 450\n"
                               "#line 1 \"ssao.glsl\"\n"
                               "layout(local_size_x = 8) in;\n"
                               "void main() {\n"
                               "    float x = undeclared_thing;\n"
                               "}\n";
    const std::string e = error_of([&] { cc::compile(source, cc::shader_stage::compute, "ssao-s16 ao", cc::spirv_cross_targets); });
    CHECK(e.rfind("ssao-s16 ao: glslang rejected the compute shader", 0) == 0);
    CHECK(e.find("ssao.glsl:3: 'undeclared_thing' : undeclared identifier") != std::string::npos);

    // With the extension requested by the source itself, the same.
    const std::string with_extension = "#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : require\n" +
                                       source.substr(source.find('\n') + 1);
    CHECK(error_of([&] { cc::glsl_to_spirv(with_extension, cc::shader_stage::compute, "x"); })
              .find("ssao.glsl:3: 'undeclared_thing'") != std::string::npos);

    // Without #line, the caller's name is the file name.
    const std::string no_line = "#version 450\nlayout(local_size_x = 8) in;\nvoid main() { int y = nope; }\n";
    CHECK(error_of([&] { cc::glsl_to_spirv(no_line, cc::shader_stage::compute, "blur_x"); })
              .find("blur_x:3: 'nope' : undeclared identifier") != std::string::npos);

    // The wrong stage is glslang's error too.
    CHECK(error_of([&] { cc::glsl_to_spirv(vertex_source, cc::shader_stage::compute, "v"); })
              .rfind("v: glslang rejected the compute shader", 0) == 0);
}

TEST_CASE("compile: spirv-val and malformed modules", "[compile]")
{
    std::vector<uint32_t> words = cc::glsl_to_spirv(vertex_source, cc::shader_stage::vertex, "v");
    CHECK_NOTHROW(cc::validate_spirv(words, "v"));
    // Point the entry point's execution model at an invalid value.
    std::vector<uint32_t> broken = words;
    for (size_t i = 5; i < broken.size(); i += broken[i] >> 16)
        if ((broken[i] & 0xffff) == 15 /* OpEntryPoint */) {
            broken[i + 1] = 77;
            break;
        }
    const std::string e = error_of([&] { cc::validate_spirv(broken, "v", "a broken module"); });
    CHECK(e.rfind("v: spirv-val rejected a broken module (valid: SPIR-V 1.0 for Vulkan 1.0); spirv-val says:\n  error: ", 0) == 0);

    // count_instructions: a header and two instructions; a zero word count is an error.
    const std::vector<uint32_t> tiny{0x07230203u, 0x00010000u, 0, 1, 0, 0x00020011u, 1, 0x0003000Eu, 0, 1};
    CHECK(cc::count_instructions(tiny) == 2);
    std::vector<uint32_t> zero = tiny;
    zero[7] = 0;
    CHECK(error_of([&] { cc::count_instructions(zero, "m"); }) == "m: instruction at word 7 has word count 0 (valid: 1..3)");
    CHECK(error_of([&] { cc::count_instructions({1, 2, 3}, "m"); }).rfind("m: is not a SPIR-V module", 0) == 0);
}

TEST_CASE("compile: SPIRV-Cross errors name the target", "[compile]")
{
    // A fragment shader with a storage image cannot be ESSL 300.
    const std::string source = "#version 450\n"
                               "layout(set = 0, binding = 0, rgba8) uniform writeonly image2D img;\n"
                               "layout(location = 0) out vec4 color;\n"
                               "void main() { imageStore(img, ivec2(gl_FragCoord.xy), vec4(1.0)); color = vec4(0.0); }\n";
    const std::string e = error_of([&] { cc::compile(source, cc::shader_stage::fragment, "f", {cc::target::essl}); });
    CHECK(e.rfind("f: SPIRV-Cross could not write essl", 0) == 0);
    CHECK(error_of([] { cc::cross_compile({}, cc::shader_stage::compute, cc::target::spv, "s"); }) ==
          "s: target spv has no text (valid: the SPIR-V words themselves)");
}

} // namespace unity_test_compile
