// Raw float diagnostics (codegen::options::diagnostics, aogen/vulkan/diagnostics.hpp) on the
// device the harness picks, validation layer on and no message allowed: each pass's value
// before ao_finalize is stored and counted, while the shipped output stays what it was.
// The faults are planted in the one input a renderer packs itself, the uniform block: a
// GTAO strength of NaN (pow(v, NaN) is NaN) or of -1 (pow(v, -1) > 1 where v < 1).
#include "harness.hpp"

#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_diagnostics_test {

using namespace aogen;
using namespace aogen_test;

namespace {

struct crease_setup {
    static constexpr int W = 64, H = 40;
    static constexpr float tan_half_fov_y = 0.6f;
    mat4 proj = perspective(tan_half_fov_y, float(W) / H, 0.1f, 100.0f);
    vulkan::gbuffer host = crease(W, H, tan_half_fov_y, proj);
};

// `block` with the float member `name` of the std140 GtaoUniforms set to `value`.
std::vector<uint8_t> with_gtao_member(std::vector<uint8_t> block, const char* name, float value)
{
    const layout::struct_layout l = layout::compute(uniforms::gtao_block(), layout::rules::std140);
    for (const layout::member_layout& m : l.members)
        if (m.name == name) {
            std::memcpy(block.data() + m.offset, &value, sizeof value);
            return block;
        }
    FAIL("GtaoUniforms has no member " << name);
    return block;
}

// Target pixels of `v` that read geometry (not background) on the G-buffer `g`.
size_t geometry_pixels(const variant& v, const vulkan::gbuffer& g)
{
    const auto [TW, TH] = target_size(v, g.width, g.height);
    size_t n = 0;
    for (int y = 0; y < TH; ++y)
        for (int x = 0; x < TW; ++x) n += g.depth[full_pixel_of(v, g.width, g.height, x, y)] < 1.0f;
    return n;
}

// Runs the gtao variant `v` (diagnostic build) on the crease with its AO pass's strength replaced.
vulkan::chain_result run_with_strength(vulkan::context& ctx, const variant& v, const crease_setup& c, float strength)
{
    const vulkan::chain diagnostic = chain_under_test(ctx, v, true);
    const vulkan::gpu_gbuffer g(ctx, c.host);
    vulkan::chain_inputs in = diagnostic.plan().inputs(settings_for(c.proj), c.W, c.H);
    in.uniforms[0] = with_gtao_member(in.uniforms[0], "strength", strength);
    return vulkan::bound_chain(ctx, diagnostic.passes(), g, in).run_once();
}

} // namespace

TEST_CASE("vulkan: a diagnostic chain gives the shipped AO and clean raw counts on valid input")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const crease_setup c;
    for (pipeline_stage stage : {pipeline_stage::compute, pipeline_stage::fragment}) {
        for (technique t : {technique::ssao, technique::gtao}) {
            variant v;
            v.tech = t;
            v.stage = stage;
            INFO(to_name(v));
            if (stage == pipeline_stage::fragment && !ctx->fragment_stores()) {
                CHECK_THROWS_AS(vulkan::chain(*ctx, plan_under_test(v, true)), aogen::error);
                continue;
            }
            const vulkan::chain_result shipped = chain_under_test(*ctx, v).run(c.host, settings_for(c.proj));
            const vulkan::chain_result diagnostic = chain_under_test(*ctx, v, true).run(c.host, settings_for(c.proj));
            CHECK(shipped.raw.empty());
            CHECK(diagnostic.ao == shipped.ao);
            REQUIRE(diagnostic.raw.size() == passes(v).size());
            for (const vulkan::raw_counts& r : diagnostic.raw) {
                CHECK(r.nan == 0);
                CHECK(r.inf == 0);
                CHECK(r.out_of_range() == 0);
                CHECK(r.max_excess == 0.0f);
            }
        }
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: a NaN strength shows in the AO pass's raw count, never in the output")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const crease_setup c;
    variant v;
    v.tech = technique::gtao;
    v.blur = blur_mode::none;
    v.half_resolution = false;
    const vulkan::chain_result r = run_with_strength(*ctx, v, c, std::numeric_limits<float>::quiet_NaN());
    REQUIRE(r.raw.size() == 1);
    // Every geometry pixel's visibility is raised to NaN (an occluded one's visibility 0
    // returns 0 before pow, so not quite every one); background returns 1 before the pow.
    const size_t geometry = geometry_pixels(v, c.host);
    INFO("geometry pixels " << geometry);
    CHECK(r.raw[0].nan > geometry / 2);
    CHECK(r.raw[0].nan <= geometry);
    CHECK(r.raw[0].inf == 0);
    CHECK(r.raw[0].max_excess == 0.0f); // NaN is not out of range: it is counted as NaN only
    for (float a : r.ao) {
        REQUIRE(std::isfinite(a));
        REQUIRE(a >= 0.0f);
        REQUIRE(a <= 1.0f);
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: a negative strength shows as raw values above 1 in the AO pass only")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const crease_setup c;
    variant v;
    v.tech = technique::gtao;
    v.blur = blur_mode::box;
    const vulkan::chain_result r = run_with_strength(*ctx, v, c, -1.0f);
    REQUIRE(r.raw.size() == 3); // ao, blur_box, upsample
    CHECK(r.raw[0].above_one > 0);   // occluded pixels: visibility < 1, so 1 / visibility > 1
    // The crease's corner is well occluded: 1 / visibility lies far above 1 there.
    CHECK(r.raw[0].max_excess > 0.1f);
    CHECK(std::isfinite(r.raw[0].max_excess));
    CHECK(r.raw[0].non_finite() == 0);
    CHECK(r.raw[0].below_zero == 0);
    // The box blur reads the guarded output: its own values stay in range, and the upsample's.
    CHECK(r.raw[1].out_of_range() == 0);
    CHECK(r.raw[2].out_of_range() == 0);
    CHECK(r.raw[1].non_finite() == 0);
    for (float a : r.ao) REQUIRE((a >= 0.0f && a <= 1.0f));
    require_clean(*ctx);
}

} // namespace unity_diagnostics_test
