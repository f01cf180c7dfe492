// codegen: the shape of the generated sources -- determinism, the variant's #defines,
// the bindings and constants, the uniform block, the template files with their #line
// directives -- and the embedded templates against the source tree's templates/.
// (Whether the sources compile is tests/compiler/test_codegen_glslang.cpp's business.)

#include "support.hpp"

#include <aogen/codegen.hpp>
#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

#include <algorithm>
#include <map>
#include <set>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_codegen {

using namespace aogen;
using aogen::codegen::resource_kind;
using aogen::codegen::shader_source;
using aogen::codegen::shader_stage;
using aogen_test::error_of;
using Catch::Matchers::Contains;

namespace {

// A broad set: every choice axis with both stages.
std::vector<variant> broad_set()
{
    variant_matrix m;
    m.techniques = {technique::ssao, technique::gtao, technique::vbao};
    m.samples = {1, 16};
    m.slices = {1, 3};
    m.blur = {blur_mode::bilateral, blur_mode::box, blur_mode::denoise, blur_mode::none};
    m.blur_depth = {bilateral_depth::linear, bilateral_depth::seed_raw};
    m.normals = {normal_source::gbuffer_world, normal_source::reconstructed};
    m.point_cloud_fallback = {false, true};
    m.depth = {depth_convention::standard, depth_convention::reversed_infinite};
    m.projection = {projection_kind::perspective, projection_kind::orthographic};
    m.half_resolution = {false, true};
    m.stage = {pipeline_stage::compute, pipeline_stage::fragment};
    std::vector<variant> vs = expand(m);
    // The depth MIP chain and the deinterleaved dispatch (compute only, not matrix axes): each
    // technique once, and a half-resolution chain with every pass after the prefilter.
    for (const char* name : {"gtao-3x3-full-noblur-gbufworld-std-persp-cs-mip5", "vbao-2x3-half-bilateral-recon-rev-persp-cs-mip3",
                             "ssao-s16-half-denoise-gbufworld-revinf-ortho-cs-mip2",
                             // the deinterleaved dispatch (compute only): each technique, one with a chain
                             "gtao-3x3-full-noblur-gbufworld-std-persp-cs-deint", "ssao-s16-half-bilateral-recon-rev-ortho-cs-deint",
                             "vbao-2x3-half-denoise-gbufworld-std-persp-cs-mip3-deint-wg16x8",
                             // SAO (not a matrix axis here, to keep the set's size): both stages, every
                             // normal source, depth convention and projection, one with a chain
                             "sao-s16-half-bilateral-gbufworld-std-persp-cs", "sao-s1-full-noblur-recon-revinf-ortho-fs",
                             "sao-s8-half-denoise-gbufview-rev-persp-cs-mip3-deint", "sao-s32-full-box-gbufworld-std-ortho-fs",
                             // multi-bounce in every kind of last pass: AO, blurs, upsample; both stages
                             "gtao-2x3-full-noblur-gbufworld-std-persp-cs-mb", "ssao-s16-half-bilateral-gbufworld-std-persp-fs-mb",
                             "vbao-2x3-half-denoise-recon-std-persp-cs-nearest-mb", "sao-s16-full-box-gbufworld-std-persp-fs-mb",
                             // the history pass: each technique, by the camera and by motion vectors, last or before the upsample
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist", "ssao-s16-full-bilateral-recon-revinf-ortho-cs-histmv",
                             "sao-s8-half-box-gbufview-rev-persp-cs-nearest-mb-hist", "vbao-2x3-half-noblur-gbufworld-std-persp-cs-mip3-deint-histmv",
                             // the 3x3 denoise (compute only; its AO pass writes the edges): with the upsample, with a MIP
                             // chain, as the last pass of a multi-bounce chain
                             "gtao-3x3-half-denoise3-recon-revinf-ortho-cs", "ssao-s16-full-denoise3-gbufworld-std-persp-cs-mip2",
                             "sao-s16-full-denoise3-gbufworld-std-persp-cs-mb"})
        vs.push_back(variant_from_name(name));
    return vs;
}

std::vector<std::string> lines_of(const std::string& text)
{
    std::vector<std::string> out(1);
    for (char c : text) {
        if (c == '\n') out.emplace_back();
        else out.back() += c;
    }
    return out;
}

// The part of a source before its first #line directive: version, defines, comments.
std::string preamble(const std::string& glsl) { return glsl.substr(0, glsl.find("#line ")); }

bool contains_line(const std::string& text, const std::string& line)
{
    for (const std::string& l : lines_of(text))
        if (l == line) return true;
    return false;
}

} // namespace

TEST_CASE("codegen: same variant, same bytes, a pass's source depends on its defines only", "[codegen]")
{
    std::map<std::string, std::string> by_defines; // a pass's defines -> its source
    std::set<std::string> sources;
    const std::vector<variant> vs = broad_set();
    for (const variant& v : vs) {
        const std::vector<shader_source> a = codegen::generate(codegen::make_plan(v));
        const std::vector<shader_source> b = codegen::generate(codegen::make_plan(variant_from_name(to_name(v))));
        REQUIRE(a.size() == b.size());
        for (size_t i = 0; i < a.size(); ++i) {
            CHECK(a[i].glsl == b[i].glsl);
            CHECK(a[i].name == b[i].name);
            CHECK(a[i].files == b[i].files);
        }
        for (const shader_source& s : a) {
            if (s.stage == shader_stage::vertex) continue;
            // The defines, and the format the chain's images have (a -denoise3 variant's are
            // four channels wide in every pass, as a -bn variant's, whose define says so).
            std::string key = "format=" + codegen::output_format_of(v, {}) + ";";
            for (const define& d : defines(v, s.pass)) key += d.name + "=" + d.value + ";";
            auto [it, inserted] = by_defines.emplace(key, s.glsl);
            if (!inserted) CHECK(it->second == s.glsl);
            sources.insert(s.glsl);
        }
    }
    // Different defines, different sources.
    CHECK(sources.size() == by_defines.size());
}

TEST_CASE("codegen: passes, stages, names and order", "[codegen]")
{
    for (const variant& v : broad_set()) {
        const std::vector<shader_source> s = codegen::generate(codegen::make_plan(v));
        const std::vector<pass_kind> p = passes(v);
        const size_t per_pass = v.stage == pipeline_stage::compute ? 1 : 2;
        REQUIRE(s.size() == p.size() * per_pass);
        for (size_t i = 0; i < s.size(); ++i) {
            INFO(s[i].name);
            CHECK(s[i].pass == p[i / per_pass]);
            const shader_stage expected = v.stage == pipeline_stage::compute ? shader_stage::compute
                                          : i % 2 == 0                       ? shader_stage::vertex
                                                                             : shader_stage::fragment;
            CHECK(s[i].stage == expected);
            CHECK(s[i].name == to_name(v) + "." + names::name_of(pass_kind_names, s[i].pass, "pass") + "." +
                                   codegen::file_extension(expected));
            CHECK(s[i].glsl.rfind("#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : require\n", 0) == 0);
        }
    }
    variant v;
    CHECK(codegen::generate(codegen::make_plan(v)).size() == 4); // ao, blur_x, blur_y, upsample
    v.blur = blur_mode::box;
    v.stage = pipeline_stage::fragment;
    CHECK(codegen::generate(codegen::make_plan(v)).size() == 6); // (vertex, fragment) for ao, blur_box, upsample
    v.upsample = upsample_mode::nearest;
    CHECK(codegen::generate(codegen::make_plan(v)).size() == 4);
}

TEST_CASE("codegen: every #define of the pass is in its source, before the templates", "[codegen]")
{
    for (const variant& v : broad_set())
        for (const shader_source& s : codegen::generate(codegen::make_plan(v))) {
            INFO(s.name);
            const std::string head = preamble(s.glsl);
            if (s.stage == shader_stage::vertex) {
                CHECK(head.find("#define") == std::string::npos);
                continue;
            }
            for (const define& d : defines(v, s.pass))
                CHECK(contains_line(head, "#define " + d.name + (d.value.empty() ? "" : " " + d.value)));
            for (const codegen::resource& r : s.resources) {
                std::string upper = r.name;
                for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
                CHECK(contains_line(head, "#define AO_BINDING_" + upper + " " + std::to_string(r.binding)));
            }
            for (const define& d : codegen::constants(v, s.pass)) CHECK(contains_line(head, "#define " + d.name + " " + d.value));
            // Exactly one value of each choice.
            for (const char* group : {"AO_STAGE_", "AO_DEPTH_", "AO_PROJECTION_", "AO_PASS_"}) {
                size_t n = 0;
                for (const define& d : defines(v, s.pass)) n += d.name.rfind(group, 0) == 0;
                CHECK(n == 1);
            }
            CHECK((head.find("#define AO_HALF_RESOLUTION\n") != std::string::npos) == v.half_resolution);
            CHECK((head.find("#define AO_POINT_CLOUD_FALLBACK\n") != std::string::npos) ==
                  (s.pass == pass_kind::ao && v.point_cloud_fallback));
        }
}

TEST_CASE("codegen: the constants come from params.hpp as GLSL float literals", "[codegen]")
{
    variant v;
    auto value = [](const std::vector<define>& ds, const std::string& name) {
        for (const define& d : ds)
            if (d.name == name) return d.value;
        return std::string("<missing>");
    };
    const std::vector<define> blur = codegen::constants(v, pass_kind::blur_x);
    CHECK(value(blur, "AO_BLUR_WEIGHT_0") == "0.196");
    CHECK(value(blur, "AO_BLUR_WEIGHT_1") == "0.175");
    CHECK(value(blur, "AO_BLUR_WEIGHT_2") == "0.122");
    CHECK(value(blur, "AO_BLUR_WEIGHT_3") == "0.067");
    CHECK(value(codegen::constants(v, pass_kind::ao), "AO_SSAO_VOTE_BAND") == "0.05"); // smooth decisions' bands
    v.decisions = ssao_decisions::step;
    CHECK(codegen::constants(v, pass_kind::ao).empty()); // the seeds' steps need none
    v.point_cloud_fallback = true;
    const std::vector<define> pc = codegen::constants(v, pass_kind::ao);
    CHECK(value(pc, "AO_PC_BACKGROUND_DEPTH") == "0.9999");
    CHECK(value(pc, "AO_PC_SAME_DEPTH") == "5e-06");
    CHECK(value(pc, "AO_PC_CAVITY_THRESHOLD") == "2e-04");
    CHECK(value(pc, "AO_PC_RING_PIXELS") == "3");
    v.blur = blur_mode::box;
    CHECK(value(codegen::constants(v, pass_kind::blur_box), "AO_BLUR_BOX_SIZE") == "4");
}

TEST_CASE("codegen: the uniform block is declare()'s std140 block at set 0, binding 0", "[codegen]")
{
    layout::declaration_options o;
    o.instance = "u";
    auto decl = [&](const layout::block_desc& b) {
        return layout::declare(layout::compute(b, layout::rules::std140), layout::language::glsl, o);
    };
    variant v;
    v.samples = 32;
    std::vector<shader_source> s = codegen::generate(codegen::make_plan(v));
    CHECK(s[0].glsl.find("#line 1 \"aogen:SsaoUniforms\"\n" + decl(uniforms::ssao_block(32))) != std::string::npos);
    CHECK(s[1].glsl.find("#line 1 \"aogen:BlurUniforms\"\n" + decl(uniforms::blur_block())) != std::string::npos);
    v.tech = technique::gtao;
    s = codegen::generate(codegen::make_plan(v));
    CHECK(s[0].glsl.find(decl(uniforms::gtao_block())) != std::string::npos);
    v.tech = technique::vbao;
    s = codegen::generate(codegen::make_plan(v));
    CHECK(s[0].glsl.find("#line 1 \"aogen:VbaoUniforms\"\n" + decl(uniforms::vbao_block())) != std::string::npos);
    CHECK(s[0].glsl.find("#line 1 \"vbao.glsl\"") != std::string::npos);
    CHECK(s[0].glsl.find("#line 1 \"gtao.glsl\"") == std::string::npos);
    v.tech = technique::sao;
    v.samples = 12;
    s = codegen::generate(codegen::make_plan(v));
    CHECK(s[0].glsl.find("#line 1 \"aogen:SaoUniforms\"\n" + decl(uniforms::sao_block(12))) != std::string::npos);
    CHECK(s[0].glsl.find("#line 1 \"sao.glsl\"") != std::string::npos);
    CHECK(s[0].glsl.find("#line 1 \"ssao.glsl\"") == std::string::npos);
    CHECK(s[0].glsl.find("#define AO_SAO_SAMPLES 12") != std::string::npos);
    v = variant{};
    v.point_cloud_fallback = true; // seed 004's variant still reads SsaoUniforms
    CHECK(codegen::uniform_block(v, pass_kind::ao).root.name == "SsaoUniforms");
    // No template declares a uniform block of its own.
    for (const codegen::template_text& t : codegen::embedded_templates()) {
        INFO(t.path);
        CHECK(t.text.find("uniform Ssao") == std::string::npos);
        CHECK(t.text.find("uniform Gtao") == std::string::npos);
        CHECK(t.text.find("uniform Vbao") == std::string::npos);
        CHECK(t.text.find("uniform Blur") == std::string::npos);
        CHECK(t.text.find("layout(std140") == std::string::npos);
    }
}

TEST_CASE("codegen: template files in order, each after #line 1 \"<file>\"", "[codegen]")
{
    for (const variant& v : broad_set())
        for (const shader_source& s : codegen::generate(codegen::make_plan(v))) {
            INFO(s.name);
            REQUIRE_FALSE(s.files.empty());
            size_t at = 0;
            for (const std::string& f : s.files) {
                const std::string directive = "#line 1 \"" + f + "\"\n";
                const size_t found = s.glsl.find(directive, at);
                REQUIRE(found != std::string::npos);
                const std::string text = codegen::embedded_template(f);
                CHECK(s.glsl.compare(found + directive.size(), text.size(), text) == 0);
                at = found + directive.size();
            }
            CHECK(s.files == codegen::template_files(v, s.pass, s.stage));
            const bool pc = std::find(s.files.begin(), s.files.end(), "ssao_point_cloud.glsl") != s.files.end();
            CHECK(pc == (s.pass == pass_kind::ao && s.stage != shader_stage::vertex && v.point_cloud_fallback));
        }
    variant v;
    CHECK(codegen::template_files(v, pass_kind::ao, shader_stage::compute) ==
          std::vector<std::string>{"common/core.glsl", "common/depth.glsl", "common/normals.glsl", "common/noise.glsl",
                                   "ssao.glsl", "entry_compute.glsl"});
    v.stage = pipeline_stage::fragment;
    CHECK(codegen::template_files(v, pass_kind::blur_y, shader_stage::fragment) ==
          std::vector<std::string>{"common/core.glsl", "common/depth.glsl", "blur_bilateral.glsl", "entry_fragment.glsl"});
    CHECK(codegen::template_files(v, pass_kind::ao, shader_stage::vertex) ==
          std::vector<std::string>{"common/fullscreen_vertex.glsl"});
}

TEST_CASE("codegen: resources per pass and stage", "[codegen]")
{
    using k = resource_kind;
    auto bindings = [](const std::vector<codegen::resource>& rs) {
        std::vector<std::tuple<uint32_t, k, std::string>> out;
        for (const auto& r : rs) {
            CHECK(r.set == 0);
            out.emplace_back(r.binding, r.kind, r.name);
        }
        return out;
    };
    variant v;
    using row = std::tuple<uint32_t, k, std::string>;
    CHECK(bindings(codegen::resources(v, pass_kind::ao, shader_stage::compute)) ==
          std::vector<row>{{0, k::uniform_buffer, "uniforms"}, {1, k::combined_image_sampler, "depth"},
                           {2, k::combined_image_sampler, "normals"}, {3, k::combined_image_sampler, "noise"},
                           {4, k::storage_image, "output"}});
    CHECK(bindings(codegen::resources(v, pass_kind::blur_x, shader_stage::compute)) ==
          std::vector<row>{{0, k::uniform_buffer, "uniforms"}, {1, k::combined_image_sampler, "depth"},
                           {2, k::combined_image_sampler, "ao_input"}, {3, k::storage_image, "output"}});
    CHECK(codegen::resources(v, pass_kind::ao, shader_stage::compute).front().block == "SsaoUniforms");
    CHECK(codegen::resources(v, pass_kind::blur_y, shader_stage::compute).front().block == "BlurUniforms");
    v.normals = normal_source::reconstructed;
    v.stage = pipeline_stage::fragment;
    CHECK(bindings(codegen::resources(v, pass_kind::ao, shader_stage::fragment)) ==
          std::vector<row>{{0, k::uniform_buffer, "uniforms"}, {1, k::combined_image_sampler, "depth"},
                           {3, k::combined_image_sampler, "noise"}});
    CHECK(codegen::resources(v, pass_kind::ao, shader_stage::vertex).empty());
}

TEST_CASE("codegen: the webgpu binding model separates textures and samplers, at bindings.hpp's numbers", "[codegen]")
{
    using k = codegen::resource_kind;
    using row = std::tuple<uint32_t, k, std::string>;
    const auto bindings = [](const std::vector<codegen::resource>& rs) {
        std::vector<row> out;
        for (const codegen::resource& r : rs) out.emplace_back(r.binding, r.kind, r.name);
        return out;
    };
    codegen::options o;
    o.model = binding_model::webgpu;
    o.output_format = "rgba8";
    variant v;
    CHECK(bindings(codegen::resources(v, pass_kind::ao, shader_stage::compute, o)) ==
          std::vector<row>{{0, k::uniform_buffer, "uniforms"}, {1, k::sampled_image, "depth"}, {2, k::sampler, "depth_sampler"},
                           {3, k::sampled_image, "normals"}, {4, k::sampled_image, "noise"}, {5, k::storage_image, "output"}});
    CHECK(bindings(codegen::resources(v, pass_kind::upsample, shader_stage::compute, o)) ==
          std::vector<row>{{0, k::uniform_buffer, "uniforms"}, {1, k::sampled_image, "depth"}, {2, k::sampler, "depth_sampler"},
                           {3, k::sampled_image, "ao_input"}, {4, k::sampler, "ao_input_sampler"}, {5, k::storage_image, "output"}});
    // The GLSL declares exactly these, and the templates' names stay usable.
    const std::string glsl = codegen::generate(codegen::make_plan(v, o)).front().glsl;
    CHECK(glsl.find("layout(set = 0, binding = 1) uniform texture2D u_depth_texture;") != std::string::npos);
    CHECK(glsl.find("layout(set = 0, binding = 2) uniform sampler u_depth_sampler;\n#define u_depth sampler2D(u_depth_texture, u_depth_sampler)") !=
          std::string::npos);
    CHECK(glsl.find("layout(set = 0, binding = 4) uniform texture2D u_noise;") != std::string::npos);
    CHECK(glsl.find("layout(set = 0, binding = 5, AO_OUTPUT_FORMAT) uniform writeonly image2D u_output;") != std::string::npos);
    CHECK(glsl.find("#define AO_OUTPUT_FORMAT rgba8") != std::string::npos);
    CHECK(glsl.find("#extension GL_EXT_samplerless_texture_functions : require") != std::string::npos);
    CHECK(glsl.find("sampler2D u_") == std::string::npos);
    // Core WebGPU has no r8unorm storage texture.
    o.output_format = "r8";
    CHECK_THROWS_WITH(codegen::resources(v, pass_kind::ao, shader_stage::compute, o),
                      Catch::Contains("r8 is not a storage texture format of core WebGPU") && Catch::Contains("valid: rgba8, r32f, rgba16f"));
}

TEST_CASE("codegen: docs/bindings.md's binding table is bindings.hpp's", "[codegen]")
{
    std::ifstream in(AOGEN_SOURCE_DIR "/docs/bindings.md");
    REQUIRE(in);
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(doc.find(binding_table_markdown()) != std::string::npos);
}

TEST_CASE("codegen: the fullscreen vertex shader is one text for every pass and variant", "[codegen]")
{
    std::set<std::string> texts;
    for (const variant& v : broad_set())
        for (const shader_source& s : codegen::generate(codegen::make_plan(v)))
            if (s.stage == shader_stage::vertex) {
                texts.insert(s.glsl);
                CHECK(s.resources.empty());
            }
    CHECK(texts.size() == 1);
}

TEST_CASE("codegen: embedded templates equal the source tree's", "[codegen]")
{
    REQUIRE(codegen::have_embedded_templates());
    const std::vector<codegen::template_text> embedded = codegen::embedded_templates();
    REQUIRE(embedded.size() >= 12);
    CHECK(std::is_sorted(embedded.begin(), embedded.end(),
                         [](const auto& a, const auto& b) { return a.path < b.path; }));
    const codegen::template_reader source = codegen::directory_reader(AOGEN_TEMPLATE_DIR);
    for (const codegen::template_text& t : embedded) {
        INFO(t.path);
        CHECK(source(t.path) == t.text);
        CHECK(t.text.find('\r') == std::string::npos);
        CHECK(std::all_of(t.text.begin(), t.text.end(),
                          [](char c) { return c == '\n' || c == '\t' || (c >= ' ' && c <= '~'); }));
        CHECK(t.text.find(")aogen_glsl\"") == std::string::npos);
        CHECK((!t.text.empty() && t.text.back() == '\n'));
    }
    // Every file any variant uses is embedded.
    std::set<std::string> used;
    for (const variant& v : broad_set())
        for (const shader_source& s : codegen::generate(codegen::make_plan(v))) used.insert(s.files.begin(), s.files.end());
    std::set<std::string> have;
    for (const auto& t : embedded) have.insert(t.path);
    CHECK(used == have);
}

TEST_CASE("codegen: a directory reader normalises CRLF and names a missing file", "[codegen]")
{
    const std::string dir = AOGEN_TEMPLATE_DIR;
    codegen::options missing;
    missing.templates = codegen::directory_reader(dir + "/no-such-dir");
    CHECK_THAT(error_of([&] { codegen::generate(codegen::make_plan(variant{}, missing)); }),
               Contains("template 'common/core.glsl': cannot read " + dir + "/no-such-dir/common/core.glsl"));
    CHECK_THAT(error_of([] { codegen::embedded_template("nope.glsl"); }),
               Contains("template 'nope.glsl': is not among the embedded templates (valid: blur_bilateral.glsl, "));
    // A reader of CRLF text gives the same source as one of LF text.
    const codegen::template_reader lf = codegen::template_reader(codegen::embedded_template);
    const codegen::template_reader crlf = [](const std::string& path) {
        std::string out;
        for (char c : codegen::embedded_template(path)) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
        return out;
    };
    // (generate() itself does not normalise a custom reader; directory_reader does.)
    codegen::options with_lf, with_crlf;
    with_lf.templates = lf, with_crlf.templates = crlf;
    CHECK(codegen::generate(codegen::make_plan(variant{}, with_lf))[0].glsl != codegen::generate(codegen::make_plan(variant{}, with_crlf))[0].glsl);
}

TEST_CASE("codegen: invalid input is an aogen::error", "[codegen]")
{
    variant v;
    v.samples = 0;
    CHECK_THAT(error_of([&] { codegen::generate(codegen::make_plan(v)); }), Contains("ssao samples: 0 is out of range (valid: 1..256)"));
    v = variant{};
    v.tech = technique::gtao;
    v.point_cloud_fallback = true;
    CHECK_THAT(error_of([&] { codegen::generate(codegen::make_plan(v)); }), Contains("point-cloud fallback"));
    v = variant{};
    CHECK_THAT(error_of([&] { codegen::resources(v, pass_kind::blur_box, shader_stage::compute); }),
               Contains("pass: blur_box is not a pass of ssao-s16-half-bilateral-gbufworld-std-persp-cs (valid: ao, blur_x, blur_y, upsample)"));
    CHECK_THAT(error_of([&] { codegen::template_files(v, pass_kind::ao, shader_stage::fragment); }),
               Contains("shader stage: fragment is not a stage of a compute variant (valid: compute)"));
    v.stage = pipeline_stage::fragment;
    CHECK_THAT(error_of([&] { codegen::resources(v, pass_kind::ao, shader_stage::compute); }), Contains("valid: vertex, fragment"));
    CHECK_THAT(error_of([&] { codegen::resources(v, pass_kind::ao, static_cast<shader_stage>(7)); }),
               Contains("shader stage: 7 is not a valid value"));
}

TEST_CASE("codegen: options::output_format becomes AO_OUTPUT_FORMAT in compute shaders only", "[codegen]")
{
    const std::string dir = AOGEN_TEMPLATE_DIR;
    for (const variant& v : broad_set()) {
        const std::vector<shader_source> defaults = codegen::generate(codegen::make_plan(v));
        // The default options are the old signatures' output, byte for byte.
        const std::vector<shader_source> explicit_default = codegen::generate(codegen::make_plan(v, codegen::options{}));
        REQUIRE(defaults.size() == explicit_default.size());
        for (size_t i = 0; i < defaults.size(); ++i) CHECK(defaults[i].glsl == explicit_default[i].glsl);
        const std::string default_format = codegen::output_format_of(v, {}); // r8, or rgba8 where a variant widens it
        for (const char* asked : {"r8", "rgba8", "r32f", "rgba16f"}) {
            codegen::options o;
            o.output_format = asked;
            if (v.blur == blur_mode::denoise3 && o.output_format == "r32f") { // one channel, and its AO pass writes three
                CHECK_THROWS_WITH(codegen::make_plan(v, o), Contains("valid with -denoise3"));
                continue;
            }
            const std::string format = codegen::output_format_of(v, o);
            const std::vector<shader_source> s = codegen::generate(codegen::make_plan(v, o));
            REQUIRE(s.size() == defaults.size());
            for (size_t i = 0; i < s.size(); ++i) {
                INFO(s[i].name << " " << format);
                const std::string line = "#define AO_OUTPUT_FORMAT " + std::string(format) + "\n";
                if (s[i].stage != shader_stage::compute) {
                    CHECK(preamble(s[i].glsl).find("AO_OUTPUT_FORMAT") == std::string::npos);
                    CHECK(s[i].glsl == defaults[i].glsl);
                    continue;
                }
                if (s[i].pass == pass_kind::prefilter) { // it writes raw depth whatever the AO images are
                    CHECK(contains_line(preamble(s[i].glsl), "#define AO_OUTPUT_FORMAT r32f"));
                    CHECK(s[i].glsl == defaults[i].glsl);
                    continue;
                }
                // One line differs from the default's, in the preamble, and the output
                // resource carries the format.
                CHECK(contains_line(preamble(s[i].glsl), line.substr(0, line.size() - 1)));
                std::string as_default = s[i].glsl;
                as_default.replace(as_default.find(line), line.size(), "#define AO_OUTPUT_FORMAT " + default_format + "\n");
                CHECK(as_default == defaults[i].glsl);
                for (const codegen::resource& r : s[i].resources) {
                    if (r.role == resource_role::output) {
                        CHECK(r.kind == resource_kind::storage_image);
                        CHECK(r.format == format);
                    } else if (r.role == resource_role::history_output) { // the history keeps its own format
                        CHECK(r.format == codegen::history_format);
                    } else if (r.role != resource_role::raw) {
                        CHECK(r.format.empty());
                    }
                }
                for (const codegen::resource& r : codegen::resources(v, s[i].pass, s[i].stage, o))
                    if (r.role == resource_role::output) CHECK(r.format == format);
            }
            // A template reader and a plan moved to these options carry them too.
            codegen::options from_dir = o;
            from_dir.templates = codegen::directory_reader(dir);
            const std::vector<shader_source> read = codegen::generate(codegen::make_plan(v, from_dir));
            const std::vector<shader_source> moved = codegen::generate(codegen::make_plan(v).with_options(o));
            REQUIRE(read.size() == s.size());
            REQUIRE(moved.size() == s.size());
            for (size_t i = 0; i < s.size(); ++i) {
                CHECK(read[i].glsl == s[i].glsl);
                CHECK(moved[i].glsl == s[i].glsl);
            }
        }
    }
    // Codegen declares the output image with the define (bindings.hpp's binding), and the
    // entry point declares nothing of its own.
    CHECK(codegen::generate(codegen::make_plan(variant{})).front().glsl.find("layout(set = 0, binding = 4, AO_OUTPUT_FORMAT) uniform writeonly image2D u_output;") !=
          std::string::npos);
    const std::string entry = codegen::embedded_template("entry_compute.glsl");
    CHECK(entry.find("uniform writeonly image2D") == std::string::npos);
    CHECK(entry.find(", r8)") == std::string::npos);
}

TEST_CASE("codegen: an output format not in the list is an aogen::error naming the valid ones", "[codegen]")
{
    const std::string valid = "(valid: r8, rgba8, r32f, rgba16f)";
    for (const char* format : {"r16f", "R8", "", "rgba8 ", "r8) uniform image2D x; //"}) {
        INFO("'" << format << "'");
        codegen::options o;
        o.output_format = format;
        variant compute;
        variant fragment;
        fragment.stage = pipeline_stage::fragment;
        const std::string expected = "output format: '" + std::string(format) + "' is not a storage image format aogen writes " + valid;
        CHECK(error_of([&] { codegen::generate(codegen::make_plan(compute, o)); }) == expected);
        CHECK(error_of([&] { codegen::generate(codegen::make_plan(fragment, o)); }) == expected); // validated even where unused
        CHECK(error_of([&] { codegen::make_plan(compute).with_options(o); }) == expected);
        CHECK(error_of([&] { codegen::resources(compute, pass_kind::ao, shader_stage::compute, o); }) == expected);
        CHECK(error_of([&] { codegen::validate(o); }) == expected);
    }
    CHECK_NOTHROW(codegen::validate(codegen::options{}));
}

TEST_CASE("codegen: a plan validates its variant once, and generating from it never again", "[codegen][plan]")
{
    // Before the plan, validate(v) ran in every codegen function: 33 times per generate() of
    // a 4-pass compute variant and 49 times for a fragment one (issue 21).
    for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "gtao-2x3-half-denoise-recon-rev-persp-fs"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        const unsigned long before = aogen::detail::validations();
        const std::vector<shader_source> direct = codegen::generate(codegen::make_plan(v));
        CHECK(aogen::detail::validations() - before == 1);

        const codegen::plan p = codegen::make_plan(v);
        const unsigned long planned = aogen::detail::validations();
        const std::vector<shader_source> from_plan = codegen::generate(p);
        CHECK(aogen::detail::validations() == planned);

        REQUIRE(from_plan.size() == direct.size());
        for (size_t i = 0; i < direct.size(); ++i) {
            CHECK(from_plan[i].name == direct[i].name);
            CHECK(from_plan[i].glsl == direct[i].glsl);
        }
    }
}

TEST_CASE("codegen: a plan holds what the public part functions return", "[codegen][plan]")
{
    for (const variant& v : broad_set()) {
        const codegen::plan p = codegen::make_plan(v);
        INFO(p.name());
        CHECK(p.name() == to_name(v));
        CHECK(p.variant() == v);
        CHECK(p.passes() == passes(v));
        size_t i = 0;
        for (pass_kind pass : passes(v))
            for (shader_stage stage : codegen::stages(v)) {
                REQUIRE(i < p.shaders().size());
                const codegen::shader_plan& s = p.shaders()[i++];
                CHECK(s.pass == pass);
                CHECK(s.stage == stage);
                CHECK(s.files == codegen::template_files(v, pass, stage));
                CHECK(s.resources.size() == codegen::resources(v, pass, stage).size());
                if (stage == shader_stage::vertex) continue;
                std::string planned, direct;
                for (const define& d : s.defines) planned += d.name + "=" + d.value + ";";
                for (const define& d : defines(v, pass)) direct += d.name + "=" + d.value + ";";
                CHECK(planned == direct);
                CHECK(s.constants.size() == codegen::constants(v, pass).size());
                CHECK(s.block.root.name == codegen::uniform_block(v, pass).root.name);
                const layout::struct_layout l = layout::compute(s.block, layout::rules::std140);
                CHECK(s.layout.name == l.name);
                CHECK(s.layout.size == l.size);
                CHECK(s.layout.members.size() == l.members.size());
                CHECK(s.pixels_per_invocation == pixels_per_invocation(pass, v.stage));
                CHECK(s.workgroup == (stage == shader_stage::compute ? workgroup_of(v, pass) : std::pair<int, int>{0, 0}));
            }
        CHECK(i == p.shaders().size());
    }
    variant bad;
    bad.samples = 0;
    CHECK_THAT(error_of([&] { codegen::make_plan(bad); }), Contains("ssao samples"));
}

TEST_CASE("codegen: a plan lays each uniform block out once, and generating, other options and a frame loop's inputs lay out nothing again",
          "[codegen][plan]")
{
    // Before the plan carried its layouts, every frame's inputs laid each pass's block out
    // again (every uniforms::pack_* called layout::compute), and generate() once more per shader.
    chain_settings s;
    s.camera = {mat4{}, perspective(1, 1, 1, 3)};
    codegen::options rgba8;
    rgba8.output_format = "rgba8";
    for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "gtao-2x3-half-denoise-recon-rev-persp-fs",
                             "sao-s12-full-box-gbufview-std-persp-cs-mip4", "vbao-2x2-full-noblur-gbufworld-std-persp-cs"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        const unsigned long before = layout::detail::computations(), plans = codegen::detail::plans_made();
        const codegen::plan p = codegen::make_plan(v);
        CHECK(codegen::detail::plans_made() - plans == 1);
        CHECK(layout::detail::computations() - before == passes(v).size()); // one std140 layout per pass
        const unsigned long planned = layout::detail::computations();
        const std::vector<shader_source> sources = codegen::generate(p);
        const codegen::plan moved = p.with_options(rgba8);
        CHECK(codegen::generate(moved).size() == sources.size());
        std::vector<std::vector<uint8_t>> first;
        for (uint32_t frame = 0; frame < 8; ++frame) {
            s.frame = frame;
            const chain_inputs in = p.inputs(s, 160, 90);
            REQUIRE(in.uniforms.size() == passes(v).size());
            if (frame == 0) first = in.uniforms;
        }
        CHECK(layout::detail::computations() == planned);
        CHECK(codegen::detail::plans_made() - plans == 1); // with_options plans nothing again
        // The bytes are the public packers' (which lay their block out themselves: the counter counts).
        const auto [tw, th] = p.target_size(160, 90);
        const vec2 size{float(tw), float(th)};
        s.frame = 0;
        for (size_t i = 0; i < p.passes().size(); ++i) {
            if (p.passes()[i] == pass_kind::ao) continue;
            const unsigned long packing = layout::detail::computations();
            CHECK(uniforms::pack_blur(s.blur, s.camera.proj, size, layout::rules::std140, {{1, 0}, s.finalize, 0}) == first[i]);
            CHECK(layout::detail::computations() - packing == 1);
        }
    }
}

} // namespace unity_test_codegen
