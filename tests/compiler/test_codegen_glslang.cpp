// The generated GLSL against glslang, spirv-val and SPIRV-Cross's reflection.
//
// Every shader of every pass of a broad set of variants (the SSAO and GTAO matrices, every
// choice axis crossed, the edge counts) must compile with glslang for Vulkan 1.0 / SPIR-V
// 1.0 without errors, pass spirv-val, and declare exactly the descriptors codegen says it
// does (set, binding and kind, read back from the SPIR-V). Identical sources -- the blur
// passes of many AO variants, the shared vertex shader -- are compiled once.
//
// Also: a variant without the point-cloud fallback carries none of its code; a
// reconstructed-normal variant declares no binding 2; an error in a template is reported
// with the template's file name and line.

#include "glsl_compile.hpp"
#include "spirv_layout_compare.hpp"

#include <aogen/codegen.hpp>
#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <tuple>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_codegen_glslang {

using namespace aogen;
using aogen::codegen::resource_kind;
using aogen::codegen::shader_source;
using aogen::codegen::shader_stage;

namespace {

struct compiled_shader {
    bool ok = false;
    std::string log;     // glslang's log (errors when !ok)
    std::string invalid; // spirv-val's messages; empty when valid
    std::vector<uint32_t> words;
};

using aogen_test::language_of;

// glslang + spirv-val, once per distinct (stage, source).
const compiled_shader& compile(const shader_source& s)
{
    static std::map<std::pair<shader_stage, std::string>, compiled_shader> cache;
    auto key = std::make_pair(s.stage, s.glsl);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    compiled_shader c;
    aogen_test::spirv_result r = aogen_test::compile_glsl(s.glsl, language_of(s.stage));
    c.ok = r.ok;
    c.log = r.log;
    c.words = std::move(r.words);
    if (c.ok) c.invalid = aogen_test::validate_spirv(c.words, false);
    return cache.emplace(std::move(key), std::move(c)).first->second;
}

using descriptor = std::tuple<uint32_t, uint32_t, resource_kind>; // set, binding, kind

// The descriptors a SPIR-V module declares (used or not), sorted.
std::vector<descriptor> reflected_descriptors(const std::vector<uint32_t>& words)
{
    spirv_cross::Compiler c(words);
    const spirv_cross::ShaderResources r = c.get_shader_resources();
    std::vector<descriptor> out;
    auto add = [&](const spirv_cross::SmallVector<spirv_cross::Resource>& list, resource_kind kind) {
        for (const spirv_cross::Resource& x : list)
            out.emplace_back(c.get_decoration(x.id, spv::DecorationDescriptorSet),
                             c.get_decoration(x.id, spv::DecorationBinding), kind);
    };
    add(r.uniform_buffers, resource_kind::uniform_buffer);
    add(r.sampled_images, resource_kind::combined_image_sampler);
    add(r.storage_images, resource_kind::storage_image);
    CHECK(r.separate_images.empty());
    CHECK(r.separate_samplers.empty());
    CHECK(r.storage_buffers.empty());
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<descriptor> expected_descriptors(const shader_source& s)
{
    std::vector<descriptor> out;
    for (const codegen::resource& r : s.resources) out.emplace_back(r.set, r.binding, r.kind);
    std::sort(out.begin(), out.end());
    return out;
}

// The source with line numbers, for failure messages.
std::string numbered(const std::string& glsl)
{
    std::string out;
    int line = 1;
    out += "   1  ";
    for (char c : glsl) {
        out += c;
        if (c == '\n') {
            std::string n = std::to_string(++line);
            out += std::string(4 - std::min<size_t>(4, n.size()), ' ') + n + "  ";
        }
    }
    return out;
}

struct totals {
    size_t variants = 0;
    size_t shaders = 0;
};

// Every shader of every pass of `v`: compiles, validates, declares what codegen says.
void check_variant(const variant& v, totals& t)
{
    ++t.variants;
    for (const shader_source& s : codegen::generate(codegen::make_plan(v))) {
        ++t.shaders;
        const compiled_shader& c = compile(s);
        INFO(s.name);
        if (!c.ok) FAIL_CHECK("glslang:\n" << c.log << "\n" << numbered(s.glsl));
        if (!c.ok) continue;
        CHECK(c.log.empty()); // no warnings either
        CHECK(c.invalid == "");
        CHECK(reflected_descriptors(c.words) == expected_descriptors(s));
    }
}

void check_all(const std::vector<variant>& variants, size_t expected_count)
{
    totals t;
    for (const variant& v : variants) check_variant(v, t);
    CHECK(t.variants == expected_count);
    INFO(t.variants << " variants, " << t.shaders << " shaders");
    CHECK(t.shaders >= t.variants);
}

size_t instruction_count(const std::vector<uint32_t>& words)
{
    size_t n = 0;
    for (size_t i = 5; i < words.size(); i += std::max<uint32_t>(1, words[i] >> 16)) ++n;
    return n;
}

// The OpName strings of a module (glslang names every function and variable).
std::vector<std::string> debug_names(const std::vector<uint32_t>& words)
{
    std::vector<std::string> out;
    for (size_t i = 5; i < words.size();) {
        const uint32_t count = std::max<uint32_t>(1, words[i] >> 16), opcode = words[i] & 0xffffu;
        if (opcode == 5 /* OpName */ && count > 2) {
            std::string name;
            for (size_t w = i + 2; w < i + count && w < words.size(); ++w)
                for (int b = 0; b < 4; ++b) {
                    const char c = static_cast<char>((words[w] >> (8 * b)) & 0xffu);
                    if (c == 0) goto done;
                    name += c;
                }
        done:
            out.push_back(name);
        }
        i += count;
    }
    return out;
}

// The source after glslang's preprocessor: what the compiler parses.
std::string preprocessed(const shader_source& s)
{
    aogen_test::init_glslang();
    glslang::TShader shader(language_of(s.stage));
    const char* text = s.glsl.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, language_of(s.stage), glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    std::string out;
    glslang::TShader::ForbidIncluder includer;
    const bool ok = shader.preprocess(GetDefaultResources(), 450, ENoProfile, false, false,
                                      static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules), &out, includer);
    INFO(shader.getInfoLog());
    CHECK(ok);
    return out;
}

const shader_source& ao_shader(const std::vector<shader_source>& sources)
{
    for (const shader_source& s : sources)
        if (s.pass == pass_kind::ao && s.stage != shader_stage::vertex) return s;
    FAIL("no AO shader");
    return sources.front();
}

bool has_binding(const std::vector<uint32_t>& words, uint32_t binding)
{
    for (const descriptor& d : reflected_descriptors(words))
        if (std::get<1>(d) == binding) return true;
    return false;
}

namespace fs = std::filesystem;

// A scratch copy of the embedded templates in a fresh directory.
fs::path write_templates(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("aogen_codegen_test_" + name);
    fs::remove_all(dir);
    for (const codegen::template_text& t : codegen::embedded_templates()) {
        const fs::path file = dir / t.path;
        fs::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << t.text;
    }
    return dir;
}

size_t line_count(const std::string& text)
{
    return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

} // namespace

// Codegen options that read the templates from `dir` (codegen::options::templates).
inline codegen::options reading(const fs::path& dir)
{
    codegen::options o;
    o.templates = codegen::directory_reader(dir.string());
    return o;
}

TEST_CASE("codegen+glslang: SSAO samples 8/16/32/64 x blur x full/half", "[codegen][glslang]")
{
    variant_matrix m;
    m.samples = {8, 16, 32, 64};
    m.blur = {blur_mode::bilateral, blur_mode::box, blur_mode::none};
    m.half_resolution = {false, true};
    check_all(expand(m), 24);
}

TEST_CASE("codegen+glslang: GTAO slices 1/2/3/4/8 x steps 2/3/4 x blur", "[codegen][glslang]")
{
    variant_matrix m;
    m.techniques = {technique::gtao};
    m.slices = {1, 2, 3, 4, 8};
    m.steps = {2, 3, 4};
    m.blur = {blur_mode::bilateral, blur_mode::box, blur_mode::none};
    check_all(expand(m), 45);
}

TEST_CASE("codegen+glslang: SSAO, every choice axis crossed", "[codegen][glslang]")
{
    // normals x depth x projection x stage x fallback x range check x output x blur depth:
    // 3 * 3 * 2 * 2 * 2 * 2 * 2 * 2 variants, at half and full resolution for the stages.
    variant_matrix m;
    m.normals = {normal_source::gbuffer_world, normal_source::gbuffer_view, normal_source::reconstructed};
    m.depth = {depth_convention::standard, depth_convention::reversed, depth_convention::reversed_infinite};
    m.projection = {projection_kind::perspective, projection_kind::orthographic};
    m.stage = {pipeline_stage::compute, pipeline_stage::fragment};
    m.point_cloud_fallback = {false, true};
    m.range_check = {ssao_range_check::taos, ssao_range_check::seed004};
    m.output = {ssao_output::strength, ssao_output::power_intensity};
    m.blur_depth = {bilateral_depth::linear, bilateral_depth::seed_raw};
    check_all(expand(m), 576);
}

TEST_CASE("codegen+glslang: GTAO, every choice axis crossed", "[codegen][glslang]")
{
    variant_matrix m;
    m.techniques = {technique::gtao};
    m.normals = {normal_source::gbuffer_world, normal_source::gbuffer_view, normal_source::reconstructed};
    m.depth = {depth_convention::standard, depth_convention::reversed, depth_convention::reversed_infinite};
    m.projection = {projection_kind::perspective, projection_kind::orthographic};
    m.stage = {pipeline_stage::compute, pipeline_stage::fragment};
    m.half_resolution = {false, true};
    m.blur = {blur_mode::bilateral, blur_mode::box};
    m.blur_depth = {bilateral_depth::linear, bilateral_depth::seed_raw};
    // bilateral: 2 blur depths; box: one (its blur depth collapses)
    check_all(expand(m), 3 * 3 * 2 * 2 * 2 * 3);
}

TEST_CASE("codegen+glslang: VBAO, every choice axis crossed, fp16 too, and its edge counts", "[codegen][glslang]")
{
    variant_matrix m;
    m.techniques = {technique::vbao};
    m.normals = {normal_source::gbuffer_world, normal_source::gbuffer_view, normal_source::reconstructed};
    m.depth = {depth_convention::standard, depth_convention::reversed, depth_convention::reversed_infinite};
    m.projection = {projection_kind::perspective, projection_kind::orthographic};
    m.stage = {pipeline_stage::compute, pipeline_stage::fragment};
    m.half_resolution = {false, true};
    m.fp16 = {false, true};
    m.blur = {blur_mode::bilateral, blur_mode::none};
    check_all(expand(m), 3 * 3 * 2 * 2 * 2 * 2 * 2);
    std::vector<variant> edges;
    for (auto [slices, steps] : {std::pair{1, 1}, {1, 16}, {16, 1}, {16, 16}, {9, 3}}) {
        variant v;
        v.tech = technique::vbao;
        v.slices = slices;
        v.steps = steps;
        v.blur = blur_mode::none;
        edges.push_back(v);
    }
    check_all(edges, 5);
}

TEST_CASE("codegen+glslang: edge counts and workgroup sizes", "[codegen][glslang]")
{
    std::vector<variant> vs;
    for (int samples : {1, 2, 255, 256})
        for (bool half : {false, true}) {
            variant v;
            v.samples = samples;
            v.half_resolution = half;
            v.blur = blur_mode::none;
            vs.push_back(v);
        }
    for (auto [slices, steps] : {std::pair{1, 1}, {1, 16}, {16, 1}, {16, 16}}) {
        variant v;
        v.tech = technique::gtao;
        v.slices = slices;
        v.steps = steps;
        v.blur = blur_mode::none;
        vs.push_back(v);
    }
    for (auto [x, y] : {std::pair{1, 1}, {32, 32}, {32, 1}, {1, 32}, {16, 16}}) {
        variant v;
        v.workgroup_x = x;
        v.workgroup_y = y;
        vs.push_back(v);
    }
    {
        variant v; // seed 004 as a compute variant at 256 samples
        v.samples = 256;
        v.point_cloud_fallback = true;
        v.normals = normal_source::reconstructed;
        v.range_check = ssao_range_check::seed004;
        v.blur = blur_mode::none;
        vs.push_back(v);
    }
    check_all(vs, vs.size());
}

TEST_CASE("codegen+glslang: the default matrix and the seeds' variants", "[codegen][glslang]")
{
    const std::vector<variant> vs = default_matrix();
    check_all(vs, vs.size());
}

TEST_CASE("codegen+glslang: without the point-cloud fallback none of its code is compiled in", "[codegen][glslang]")
{
    for (pipeline_stage stage : {pipeline_stage::compute, pipeline_stage::fragment}) {
        variant with;
        with.stage = stage;
        with.point_cloud_fallback = true;
        with.normals = normal_source::reconstructed;
        variant without = with;
        without.point_cloud_fallback = false;
        const std::vector<shader_source> sa = codegen::generate(codegen::make_plan(with)), sb = codegen::generate(codegen::make_plan(without));
        const shader_source& a = ao_shader(sa);
        const shader_source& b = ao_shader(sb);
        INFO(a.name << " vs " << b.name);
        // The source: no file, constant or definition of the fallback ...
        for (const char* text : {"#line 1 \"ssao_point_cloud.glsl\"", "#define AO_POINT_CLOUD_FALLBACK",
                                 "#define AO_PC_", "float ao_point_cloud_billboard(", "bool ao_pc_is_background("}) {
            CHECK(a.glsl.find(text) != std::string::npos);
            CHECK(b.glsl.find(text) == std::string::npos);
        }
        // ... what the compiler sees after preprocessing names none of it ...
        const std::string pa = preprocessed(a), pb = preprocessed(b);
        for (const char* text : {"ao_point_cloud_billboard", "ao_pc_", "AO_PC_NEIGHBOURS"}) {
            CHECK(pa.find(text) != std::string::npos);
            CHECK(pb.find(text) == std::string::npos);
        }
        const compiled_shader& ca = compile(a);
        const compiled_shader& cb = compile(b);
        REQUIRE(ca.ok);
        REQUIRE(cb.ok);
        // ... and the SPIR-V has no function of it and fewer instructions.
        auto pc_names = [](const std::vector<uint32_t>& words) {
            size_t n = 0;
            for (const std::string& name : debug_names(words)) n += name.rfind("ao_pc_", 0) == 0 || name.rfind("ao_point_cloud", 0) == 0;
            return n;
        };
        CHECK(pc_names(ca.words) >= 3);
        CHECK(pc_names(cb.words) == 0);
        CHECK(instruction_count(cb.words) < instruction_count(ca.words));
        CHECK(cb.words.size() < ca.words.size());
    }
}

TEST_CASE("codegen+glslang: reconstructed normals declare no binding 2, G-buffer normals do", "[codegen][glslang]")
{
    for (technique tech : {technique::ssao, technique::gtao, technique::vbao})
        for (pipeline_stage stage : {pipeline_stage::compute, pipeline_stage::fragment})
            for (normal_source normals :
                 {normal_source::gbuffer_world, normal_source::gbuffer_view, normal_source::reconstructed}) {
                variant v;
                v.tech = tech;
                v.stage = stage;
                v.normals = normals;
                const std::vector<shader_source> sources = codegen::generate(codegen::make_plan(v));
                const shader_source& s = ao_shader(sources);
                INFO(s.name);
                const compiled_shader& c = compile(s);
                REQUIRE(c.ok);
                const bool reconstructed = normals == normal_source::reconstructed;
                CHECK(has_binding(c.words, 2) == !reconstructed);
                CHECK((s.glsl.find("#define AO_BINDING_NORMALS 2\n") != std::string::npos) == !reconstructed);
                CHECK(has_binding(c.words, 3)); // the noise tile keeps its binding
            }
}

TEST_CASE("codegen+glslang: an error in a template names the template file and line", "[codegen][glslang]")
{
    REQUIRE(codegen::have_embedded_templates());
    struct broken_case {
        const char* file;
        variant v;
    };
    variant gtao;
    gtao.tech = technique::gtao;
    variant vbao;
    vbao.tech = technique::vbao;
    variant box;
    box.blur = blur_mode::box;
    box.stage = pipeline_stage::fragment;
    for (const broken_case& b : {broken_case{"ssao.glsl", variant{}}, broken_case{"common/depth.glsl", variant{}},
                                 broken_case{"gtao.glsl", gtao}, broken_case{"vbao.glsl", vbao}, broken_case{"blur_box.glsl", box},
                                 broken_case{"entry_fragment.glsl", box}}) {
        const fs::path dir = write_templates("broken");
        const std::string original = codegen::embedded_template(b.file);
        // A broken statement on a line of its own at the end of the file.
        const size_t broken_line = line_count(original) + 1;
        std::ofstream(dir / b.file, std::ios::binary) << original << "float broken = no_such_identifier;\n";
        bool reported = false;
        for (const shader_source& s : codegen::generate(codegen::make_plan(b.v, reading(dir)))) {
            if (std::find(s.files.begin(), s.files.end(), b.file) == s.files.end()) continue;
            const compiled_shader& c = compile(s);
            INFO(s.name << "\n" << c.log);
            CHECK_FALSE(c.ok);
            const std::string where = std::string(b.file) + ":" + std::to_string(broken_line) + ":";
            CHECK(c.log.find(where) != std::string::npos);
            CHECK(c.log.find("no_such_identifier") != std::string::npos);
            reported = true;
        }
        CHECK(reported);
        fs::remove_all(dir);
    }
}

TEST_CASE("codegen+glslang: a template directory with the same files gives the same sources", "[codegen][glslang]")
{
    const fs::path dir = write_templates("copy");
    for (const variant& v : default_matrix()) {
        const std::vector<shader_source> a = codegen::generate(codegen::make_plan(v));
        const std::vector<shader_source> b = codegen::generate(codegen::make_plan(v, reading(dir)));
        REQUIRE(a.size() == b.size());
        for (size_t i = 0; i < a.size(); ++i) CHECK(a[i].glsl == b[i].glsl);
    }
    fs::remove_all(dir);
}

} // namespace unity_test_codegen_glslang
