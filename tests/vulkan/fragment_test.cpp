// The Vulkan harness with fragment variants (a fullscreen triangle per pass into an R8
// colour attachment) and with the depth buffer as a D32_SFLOAT depth image, on lavapipe
// with the validation layer enabled and no message allowed. No test asserts on time.
#include "harness.hpp"

#include <aogen/ao_difference.hpp>

#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_fragment_test {

using namespace aogen;
using namespace aogen_test;

namespace {

// The fragment variants of the default matrix: the seeds' own configurations.
std::vector<variant> fragment_seeds()
{
    std::vector<variant> out;
    for (const variant& v : default_matrix())
        if (v.stage == pipeline_stage::fragment) out.push_back(v);
    return out;
}

// The crease scene the comparisons run on, with its projection.
struct crease_scene {
    static constexpr int W = 96, H = 64;
    static constexpr float tan_half_fov_y = 0.6f;
    mat4 proj = perspective(tan_half_fov_y, float(W) / H, 0.1f, 100.0f);
    vulkan::gbuffer g = crease(W, H, tan_half_fov_y, proj);
};

// The largest per-pixel difference between two results of the same size.
float max_difference(const vulkan::chain_result& a, const vulkan::chain_result& b)
{
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    REQUIRE(a.ao.size() == b.ao.size());
    return difference_of(a.ao, b.ao).largest;
}

} // namespace

TEST_CASE("vulkan: the default matrix has fragment seed variants")
{
    CHECK(fragment_seeds().size() == 4);
}

TEST_CASE("vulkan: fragment seed variants, a plane facing the camera is unoccluded, background is exactly 1")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    for (const variant& v : fragment_seeds()) check_facing_plane(*ctx, v);
}

TEST_CASE("vulkan: the crease G-buffer has floor, wall and background pixels, depth in 0 to 1")
{
    const crease_scene s;
    int floor = 0, wall = 0, background = 0;
    for (size_t i = 0; i < s.g.depth.size(); ++i) {
        if (s.g.depth[i] >= 1.0f) ++background;
        else if (s.g.normals[i * 4 + 1] == 1.0f) ++floor;
        else if (s.g.normals[i * 4 + 2] == 1.0f) ++wall;
        REQUIRE(s.g.depth[i] >= 0.0f);
        REQUIRE(s.g.depth[i] <= 1.0f);
    }
    CHECK(floor > 500);
    CHECK(wall > 500);
    CHECK(background > 100);
}

TEST_CASE("vulkan: fragment and compute variants of the same axes give the same AO on a crease")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const crease_scene s;
    // The seeds' four, and fragment variants with what they lack: VBAO (its fragment passes
    // count sector bits without bitCount, for ESSL 3.00: vbao.glsl), the denoise and the
    // depth-aware upsample.
    std::vector<variant> compared = fragment_seeds();
    for (const char* name : {"vbao-3x3-half-bilateral-gbufworld-std-persp-fs", "vbao-2x2-full-noblur-recon-std-persp-fs",
                             "gtao-2x3-half-denoise-gbufworld-std-persp-fs"})
        compared.push_back(variant_from_name(name));
    for (const variant& v : compared) {
        INFO(to_name(v));
        const vulkan::chain fragment = chain_under_test(*ctx, v), compute = chain_under_test(*ctx, as_compute(v));
        const vulkan::chain_result f = fragment.run(s.g, settings_for(s.proj));
        const vulkan::chain_result c = compute.run(s.g, settings_for(s.proj));
        CHECK(max_difference(f, c) <= 1.0f / 255.0f);
        // Not all ones: the crease is occluded, so the comparison compares something. (Only
        // the crease: at this size it reads 0.90 to 0.97, and the open floor is 1 -- it read
        // darker before depth.glsl's ao_depth_at, from a depth-lookup error.)
        float lowest = 1.0f;
        for (float a : f.ao) lowest = std::min(lowest, a);
        CHECK(lowest < 0.98f);
        require_clean(*ctx);
    }
}

TEST_CASE("vulkan: fragment variants write every pixel, two clear values give the same AO")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const crease_scene s;
    for (const variant& v : fragment_seeds()) {
        INFO(to_name(v));
        vulkan::chain c = chain_under_test(*ctx, v);
        const vulkan::chain_result zero = c.run(s.g, settings_for(s.proj), {0.0f});
        const vulkan::chain_result one = c.run(s.g, settings_for(s.proj), {1.0f});
        CHECK(zero.ao == one.ao); // the clear value never shows through
        require_clean(*ctx);
    }
}

TEST_CASE("vulkan: depth as D32_SFLOAT gives bit-identical AO to R32_SFLOAT")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const crease_scene s;
    std::vector<variant> vs = {variant{}, fragment_seeds().front()};
    vs.push_back(vs.front());
    vs.back().tech = technique::gtao;
    for (const variant& v : vs) {
        INFO(to_name(v));
        vulkan::chain c = chain_under_test(*ctx, v);
        vulkan::run_options o;
        const vulkan::chain_result r32 = c.run(s.g, settings_for(s.proj), o);
        o.depth = vulkan::depth_format::d32_sfloat;
        const vulkan::chain_result d32 = c.run(s.g, settings_for(s.proj), o);
        CHECK(r32.ao == d32.ao);
        require_clean(*ctx);
    }
}

TEST_CASE("vulkan: D32_SFLOAT refuses depth outside 0 to 1, R32_SFLOAT takes it")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    crease_scene s;
    s.g.depth[5] = std::nanf("");
    vulkan::chain c = chain_under_test(*ctx, variant{});
    vulkan::run_options o;
    o.depth = vulkan::depth_format::d32_sfloat;
    CHECK_THROWS_AS(c.run(s.g, settings_for(s.proj), o), aogen::error);
    s.g.depth[5] = 1.5f;
    CHECK_THROWS_AS(c.run(s.g, settings_for(s.proj), o), aogen::error);
    CHECK_NOTHROW(c.run(s.g, settings_for(s.proj)));
    require_clean(*ctx);
}

} // namespace unity_fragment_test
