// The Vulkan harness (aogen/vulkan/*.hpp) on the device it picks (lavapipe here and in CI),
// with the Khronos validation layer enabled and no message allowed. No test asserts on time.
#include "harness.hpp"

#include <aogen/vulkan/timing.hpp>

#include <catch2/catch.hpp>

#include <cmath>

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
        INFO(to_name(v));
        vulkan::chain c(*ctx, v);
        const vulkan::chain_result zero = c.run(g, settings_for(proj), {0.0f});
        const vulkan::chain_result one = c.run(g, settings_for(proj), {1.0f});
        REQUIRE(zero.width == 51);
        REQUIRE(zero.height == 31);
        REQUIRE(zero.ao.size() == 51u * 31u);
        CHECK(zero.ao == one.ao); // the clear value never shows through
        for (float a : zero.ao) {
            REQUIRE(std::isfinite(a));
            REQUIRE(a >= 0.0f);
            REQUIRE(a <= 1.0f);
        }
        require_clean(*ctx);
    }
}

TEST_CASE("vulkan: median_pass_ms gives one time per pass")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 32, H = 20;
    const mat4 proj = perspective(0.9f, float(W) / H, 0.1f, 100.0f);
    variant v; // bilateral: ao, blur_x, blur_y
    vulkan::chain c(*ctx, v);
    const std::vector<double> ms = vulkan::median_pass_ms(c, facing_plane(W, H, proj), settings_for(proj), 3, 1);
    if (ctx->timestamp_valid_bits() > 0) CHECK(ms.size() == passes(v).size());
    CHECK_THROWS_AS(vulkan::median_pass_ms(c, facing_plane(W, H, proj), settings_for(proj), 0, 1), aogen::error);
    require_clean(*ctx);
}
