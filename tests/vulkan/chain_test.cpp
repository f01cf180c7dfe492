// The Vulkan harness (aogen/vulkan/*.hpp) on the device it picks (lavapipe here and in CI),
// with the Khronos validation layer enabled and no message allowed. No test asserts on time.
#include "harness.hpp"

#include <aogen/vulkan/timing.hpp>

#include <algorithm>
#include <memory>

#include <catch2/catch.hpp>

#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_chain_test {

using namespace aogen;
using namespace aogen_test;

TEST_CASE("vulkan: the context picks a device and enables validation where installed")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    INFO(ctx->device_name());
    CHECK(!ctx->device_name().empty());
    if (vulkan::layer_available(vulkan::validation_layer)) CHECK(ctx->validation_enabled());
    else WARN("VK_LAYER_KHRONOS_validation not installed: running without it");
    CHECK_THROWS_AS(vulkan::context(vulkan::device_options{false, "no such device name"}), aogen::error);
}

void facing_plane_test(technique t)
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    variant v;
    v.tech = t;
    v.half_resolution = false;
    check_facing_plane(*ctx, v);
}

TEST_CASE("vulkan: ssao, a plane facing the camera is unoccluded, background is exactly 1") { facing_plane_test(technique::ssao); }

TEST_CASE("vulkan: gtao, a plane facing the camera is unoccluded, background is exactly 1")
{
    facing_plane_test(technique::gtao);
}

TEST_CASE("vulkan: half resolution of 101x61 is 51x31, every pixel written, finite, in [0, 1]")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 101, H = 61;
    const mat4 proj = perspective(0.9f, float(W) / H, 0.1f, 100.0f);
    vulkan::gbuffer g = facing_plane(W, H, proj);
    // Some relief, so the AO is not all ones: a ramp of depths across the plane.
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W * 2 / 3; ++x) {
            const vec4 clip = proj * vec4{0, 0, -5.0f + 0.05f * float((x + y) % 9), 1};
            g.depth[static_cast<size_t>(y) * W + x] = clip.z / clip.w;
        }
    for (technique t : {technique::ssao, technique::gtao}) {
        variant v;
        v.tech = t;
        v.half_resolution = true;
        v.workgroup_x = 16;
        v.workgroup_y = 4;
        // Without the upsample the chain returns the 51x31 target; with it, the 101x61 screen.
        for (upsample_mode up : {upsample_mode::nearest, upsample_mode::depth_aware}) {
            v.upsample = up;
            INFO(to_name(v));
            const int w = up == upsample_mode::nearest ? 51 : 101, h = up == upsample_mode::nearest ? 31 : 61;
            CHECK(codegen::make_plan(v).output_size(W, H) == std::pair<int, int>{w, h});
            vulkan::chain c = chain_under_test(*ctx, v);
            const vulkan::chain_result zero = c.run(g, settings_for(proj), {0.0f});
            const vulkan::chain_result one = c.run(g, settings_for(proj), {1.0f});
            REQUIRE(zero.width == w);
            REQUIRE(zero.height == h);
            REQUIRE(zero.ao.size() == size_t(w) * size_t(h));
            CHECK(zero.ao == one.ao); // the clear value never shows through
            for (float a : zero.ao) {
                REQUIRE(std::isfinite(a));
                REQUIRE(a >= 0.0f);
                REQUIRE(a <= 1.0f);
            }
            require_clean(*ctx);
        }
    }
}

TEST_CASE("vulkan: a chain bound once runs again and again with the same result, and times back to back")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 48, H = 30;
    const float tan_half_fov_y = 0.6f;
    const mat4 proj = perspective(tan_half_fov_y, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease(W, H, tan_half_fov_y, proj);
    const vulkan::gpu_gbuffer g(*ctx, host);
    variant ssao; // bilateral: ao, blur_x, blur_y, upsample
    variant gtao;
    gtao.tech = technique::gtao;
    gtao.blur = blur_mode::box;
    const vulkan::chain a = chain_under_test(*ctx, ssao), b = chain_under_test(*ctx, gtao);
    const std::unique_ptr<vulkan::bound_chain> ba = a.bind(g, settings_for(proj)), bb = b.bind(g, settings_for(proj));
    const vulkan::chain_result first = ba->run_once(0.0f);
    // The one-call convenience gives what the bound chain gives.
    CHECK(a.run(host, settings_for(proj)).ao == first.ao);
    // The crease is occluded somewhere (about 0.96 at this size; everything else is open,
    // 1): the comparisons below compare real images.
    CHECK(*std::min_element(first.ao.begin(), first.ao.end()) < 0.98f);

    vulkan::timing_options o;
    o.rounds = 3;
    o.iterations = 4;
    o.warmup_ms = 20;
    const vulkan::timing_result t = vulkan::time_chains(*ctx, {ba.get(), bb.get()}, o);
    if (ctx->timestamp_valid_bits() > 0) {
        REQUIRE(t.chains.size() == 2);
        CHECK(t.warmup_submissions >= 1);
        CHECK(t.warmup_ms >= 20);
        for (size_t c = 0; c < 2; ++c) {
            const vulkan::chain_times& ct = t.chains[c];
            CHECK(ct.passes.size() == (c == 0 ? 4u : 3u)); // each ends with the upsample
            CHECK(ct.total_ms.size() == 12u); // rounds × iterations
            CHECK(ct.round_ms.size() == 3u);
            for (double ms : ct.total_ms) {
                REQUIRE(std::isfinite(ms));
                REQUIRE(ms >= 0.0);
            }
            CHECK(ct.total.p10 <= ct.total.median);
            CHECK(ct.total.median <= ct.total.p90);
        }
    }
    CHECK(t.iterations == 4);
    // A budget smaller than one iteration of both chains leaves one per round (never zero);
    // a generous one leaves the iterations asked for.
    vulkan::timing_options tight = o;
    tight.warmup_ms = 0;
    tight.budget_ms = 1e-6;
    if (ctx->timestamp_valid_bits() > 0) {
        const vulkan::timing_result one = vulkan::time_chains(*ctx, {ba.get(), bb.get()}, tight);
        CHECK(one.iterations == 1);
        CHECK(one.chains[0].total_ms.size() == 3u);
        tight.budget_ms = 1e9;
        CHECK(vulkan::time_chains(*ctx, {ba.get()}, tight).iterations == 4);
    }
    // Dispatched 3 × 4 + warm-up times since, interleaved with another chain: same AO.
    CHECK(ba->run_once(1.0f).ao == first.ao);
    CHECK(bb->run_once(0.0f).ao == b.run(host, settings_for(proj)).ao);

    o.rounds = 0;
    CHECK_THROWS_AS(vulkan::time_chains(*ctx, {ba.get()}, o), aogen::error);
    CHECK_THROWS_AS(vulkan::time_chains(*ctx, {}, {}), aogen::error);
    require_clean(*ctx);
}

TEST_CASE("vulkan: spread_of is the median and nearest-rank p10 and p90")
{
    const vulkan::spread s = vulkan::spread_of({5, 1, 4, 2, 3, 10, 6, 7, 9, 8});
    CHECK(s.median == 5.5);
    CHECK(s.p10 == 1);
    CHECK(s.p90 == 9);
    CHECK(vulkan::spread_of({2, 1, 3}).median == 2);
    CHECK(std::isnan(vulkan::spread_of({}).median));
}

} // namespace unity_chain_test
