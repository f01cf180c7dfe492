// codegen::options::output_format against the compilers: every format compiles for
// Vulkan with glslang, passes spirv-val and declares the output image in that format
// (read back from the SPIR-V with SPIRV-Cross); rgba8 variants -- the ones for OpenGL ES --
// go through compile::compile's essl target, and glslang accepts the result as ESSL 310.

#include "glsl_compile.hpp"
#include "spirv_layout_compare.hpp"

#include <aogen/codegen.hpp>
#include <aogen/compile.hpp>

#include <catch2/catch.hpp>

#include <string>
#include <string_view>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_codegen_output_format {

using aogen::codegen::shader_source;
using aogen::shader_stage;
namespace codegen = aogen::codegen;
namespace cc = aogen::compile;

namespace {

using aogen_test::language_of;

// The one storage image a module declares, read back with SPIRV-Cross: its binding and format.
struct storage_image {
    uint32_t binding = 0;
    spv::ImageFormat format = spv::ImageFormatUnknown;
};
storage_image reflect_storage_image(const std::vector<uint32_t>& words)
{
    spirv_cross::Compiler c(words);
    const spirv_cross::ShaderResources r = c.get_shader_resources();
    REQUIRE(r.storage_images.size() == 1);
    const spirv_cross::Resource& image = r.storage_images.front();
    return {c.get_decoration(image.id, spv::DecorationBinding), c.get_type(image.base_type_id).image.format};
}

spv::ImageFormat spirv_format(const std::string& name)
{
    if (name == "r8") return spv::ImageFormatR8;
    if (name == "rgba8") return spv::ImageFormatRgba8;
    if (name == "r32f") return spv::ImageFormatR32f;
    if (name == "rgba16f") return spv::ImageFormatRgba16f;
    FAIL("no SPIR-V format for " << name);
    return spv::ImageFormatUnknown;
}

// Compute variants with every kind of compute pass: SSAO (with and without the
// point-cloud fallback), GTAO, bilateral and box blurs, full and half resolution.
std::vector<aogen::variant> compute_variants()
{
    using namespace aogen;
    std::vector<variant> vs(6);
    vs[1].tech = technique::gtao;
    vs[2].blur = blur_mode::box;
    vs[2].half_resolution = false;
    vs[3].point_cloud_fallback = true;
    vs[3].normals = normal_source::reconstructed;
    vs[4].tech = technique::gtao;
    vs[4].blur = blur_mode::box;
    vs[4].depth = depth_convention::reversed_infinite;
    vs[5].tech = technique::gtao;
    vs[5].blur = blur_mode::denoise; // its shared-memory tile, and the upsample pass after it
    for (const variant& v : vs) REQUIRE(v.stage == pipeline_stage::compute);
    return vs;
}

// glslang on a text that carries its own `#version` (OpenGL / OpenGL ES rules, no SPIR-V
// client): "" when it parses and links without a message, otherwise the log; `version`
// and `profile` are what glslang read.
std::string glslang_log(const std::string& text, shader_stage stage, int& version, EProfile& profile)
{
    aogen_test::init_glslang();
    glslang::TShader shader(language_of(stage));
    const char* s = text.c_str();
    shader.setStrings(&s, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, language_of(stage), glslang::EShClientNone, 0);
    if (!shader.parse(GetDefaultResources(), 100, false, EShMsgDefault))
        return std::string("parse: ") + shader.getInfoLog() + shader.getInfoDebugLog();
    version = shader.getIntermediate()->getVersion();
    profile = shader.getIntermediate()->getProfile();
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(EShMsgDefault)) return std::string("link: ") + program.getInfoLog() + program.getInfoDebugLog();
    return shader.getInfoLog();
}

} // namespace

TEST_CASE("codegen+glslang: every output format compiles, and the SPIR-V's storage image has it", "[codegen][glslang]")
{
    for (const codegen::storage_format& f : codegen::output_formats) {
        const std::string_view format = f.qualifier;
        codegen::options o;
        o.output_format = std::string(format);
        size_t shaders = 0;
        for (const aogen::variant& v : compute_variants())
            for (const shader_source& s : codegen::generate(codegen::make_plan(v, o))) {
                ++shaders;
                INFO(s.name << " " << format);
                const aogen_test::spirv_result r = aogen_test::compile_glsl(s.glsl, language_of(s.stage));
                REQUIRE(r.ok);
                CHECK(r.log.empty());
                CHECK(aogen_test::validate_spirv(r.words, false) == "");
                REQUIRE(s.resources.back().kind == codegen::resource_kind::storage_image);
                CHECK(s.resources.back().format == o.output_format);
                const storage_image image = reflect_storage_image(r.words);
                CHECK(image.binding == s.resources.back().binding);
                CHECK(image.format == spirv_format(o.output_format));
            }
        CHECK(shaders == 20); // 4 + 4 + 2 + 4 + 3 + 3 passes (half resolution ends with the upsample)
    }
}

TEST_CASE("codegen+compile: rgba8 compute variants compile to ESSL 310, which glslang accepts as ESSL 310",
          "[codegen][glslang][essl]")
{
    codegen::options rgba8;
    rgba8.output_format = "rgba8";
    size_t shaders = 0;
    for (const aogen::variant& v : compute_variants())
        for (const shader_source& s : codegen::generate(codegen::make_plan(v, rgba8))) {
            INFO(s.name);
            ++shaders;
            const cc::compiled out = cc::compile(s.glsl, s.stage, s.name, {cc::target::essl});
            CHECK(reflect_storage_image(out.spirv).format == spv::ImageFormatRgba8);
            const std::string& essl = out.text.at(cc::target::essl);
            INFO(essl);
            CHECK(essl.rfind("#version 310 es\n", 0) == 0);
            CHECK(essl.find("rgba8) uniform writeonly highp image2D u_output;") != std::string::npos);
            int version = 0;
            EProfile profile = ENoProfile;
            CHECK(glslang_log(essl, s.stage, version, profile) == "");
            CHECK(version == 310);
            CHECK(profile == EEsProfile);
        }
    CHECK(shaders == 20);

    // The default, r8, is refused for essl, naming the image; r32f and rgba16f are ES formats too.
    const aogen::variant v;
    const std::vector<shader_source> r8 = codegen::generate(codegen::make_plan(v));
    std::string refused;
    try {
        cc::compile(r8.front().glsl, r8.front().stage, r8.front().name, {cc::target::essl});
    } catch (const aogen::error& e) {
        refused = e.what();
    }
    CHECK(refused.find("essl: storage image u_output: format r8 does not exist in OpenGL ES") != std::string::npos);
    for (const char* format : {"r32f", "rgba16f"}) {
        codegen::options o;
        o.output_format = format;
        for (const shader_source& s : codegen::generate(codegen::make_plan(v, o))) {
            INFO(s.name << " " << format);
            const cc::compiled out = cc::compile(s.glsl, s.stage, s.name, {cc::target::essl});
            CHECK(reflect_storage_image(out.spirv).format == spirv_format(format));
            int version = 0;
            EProfile profile = ENoProfile;
            CHECK(glslang_log(out.text.at(cc::target::essl), s.stage, version, profile) == "");
            CHECK(version == 310);
            CHECK(profile == EEsProfile);
        }
    }
}

} // namespace unity_test_codegen_output_format
