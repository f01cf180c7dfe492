// The floors (report/floor/, aogen_report/fetch_floor.hpp): for every variant of the default
// matrix, each of its two floors is a list of compute shaders that glslang compiles and
// spirv-val accepts, one per pass of the variant, declaring exactly the variant's compute
// resources (so it binds like the variant), each smaller than the pass it stands in for (the
// shading is gone), and the bandwidth floor's smaller than the fetch floor's (it reads each
// input once, not at every sample).
#include <aogen_report/fetch_floor.hpp>

#include <aogen/compile.hpp>
#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include <map>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_fetch_floor_test {

namespace {

bool same_resources(const std::vector<aogen::codegen::resource>& a, const std::vector<aogen::codegen::resource>& b)
{
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].binding != b[i].binding || a[i].kind != b[i].kind || a[i].name != b[i].name || a[i].format != b[i].format) return false;
    return true;
}

uint32_t instructions(const aogen::codegen::shader_source& s, std::map<std::string, uint32_t>& cache)
{
    auto it = cache.find(s.glsl);
    if (it != cache.end()) return it->second;
    const aogen::compile::compiled c = aogen::compile::compile(s.glsl, s.stage, s.name, {aogen::compile::target::spv});
    return cache[s.glsl] = c.refl.spirv_instructions;
}

// Does the shader write a 2 x 2 quad per invocation (entry_compute.glsl's AO_PASS_WRITES_QUADS)?
bool writes_quads(const aogen::codegen::shader_source& s)
{
    return s.glsl.find("#define AO_PASS_WRITES_QUADS") != std::string::npos;
}

} // namespace

TEST_CASE("report: every default-matrix variant's floors compile, bind like the variant, write its pixels per invocation and are smaller, the bandwidth floor the smallest")
{
    using aogen_report::floor_kind;
    std::map<std::string, uint32_t> compiled;
    for (const aogen::variant& v : aogen::default_matrix()) {
        INFO(aogen::to_name(v));
        const aogen::codegen::plan p = aogen::codegen::make_plan(v);
        const std::vector<aogen::codegen::shader_source> fetch = aogen_report::floor_of(p, floor_kind::fetch).sources;
        const std::vector<aogen::codegen::shader_source> bandwidth = aogen_report::floor_of(p, floor_kind::bandwidth).sources;
        const std::vector<aogen::codegen::shader_source> twin = aogen::codegen::generate(aogen::codegen::make_plan(aogen_report::floor_variant(v)));
        REQUIRE(fetch.size() == twin.size());
        REQUIRE(bandwidth.size() == twin.size());
        REQUIRE(twin.size() == aogen::passes(v).size());
        for (size_t i = 0; i < twin.size(); ++i) {
            for (const aogen::codegen::shader_source* floor : {&fetch[i], &bandwidth[i]}) {
                INFO(floor->name);
                CHECK(floor->stage == aogen::shader_stage::compute);
                CHECK(floor->pass == twin[i].pass);
                CHECK(same_resources(floor->resources, twin[i].resources));
                // Dispatched by the pass's pixels_per_invocation, a floor writes what its pass
                // writes per invocation: a 2 x 2 quad where the pass does, else one pixel.
                CHECK(writes_quads(*floor) == writes_quads(twin[i]));
                CHECK(instructions(*floor, compiled) < instructions(twin[i], compiled));
            }
            INFO(bandwidth[i].name);
            CHECK(instructions(bandwidth[i], compiled) < instructions(fetch[i], compiled));
        }
    }
}

TEST_CASE("report: a floor replaces exactly the shading templates")
{
    using aogen_report::floor_kind;
    for (floor_kind kind : {floor_kind::fetch, floor_kind::bandwidth}) {
        for (const char* shading : {"gtao.glsl", "ssao.glsl", "vbao.glsl", "common/normals.glsl", "blur_denoise.glsl", "upsample.glsl"})
            CHECK(!aogen_report::floor_replacement(kind, shading).empty());
        CHECK(aogen_report::floor_replacement(kind, "common/depth.glsl").empty());
        CHECK(aogen_report::floor_replacement(kind, "entry_compute.glsl").empty());
    }
    // The bandwidth floor reads the same inputs for every technique and every blur.
    CHECK(aogen_report::floor_replacement(floor_kind::bandwidth, "ssao.glsl") == aogen_report::floor_replacement(floor_kind::bandwidth, "gtao.glsl"));
    CHECK(aogen_report::floor_replacement(floor_kind::bandwidth, "blur_box.glsl") == aogen_report::floor_replacement(floor_kind::bandwidth, "blur_denoise.glsl"));
    // The variant's own depth and entry code stay in the floor.
    aogen::variant v;
    v.tech = aogen::technique::gtao;
    const std::vector<aogen::codegen::shader_source> floor = aogen_report::floor_of(aogen::codegen::make_plan(v)).sources;
    CHECK(floor[0].glsl.find(aogen::codegen::embedded_template("common/depth.glsl")) != std::string::npos);
    CHECK(floor[0].glsl.find(aogen::codegen::embedded_template("gtao.glsl")) == std::string::npos);
    // A fragment variant's floor is the compute kernel of the same axes.
    v.stage = aogen::pipeline_stage::fragment;
    CHECK(aogen_report::floor_of(aogen::codegen::make_plan(v)).sources[0].stage == aogen::shader_stage::compute);
}

} // namespace unity_fetch_floor_test
