// The Vulkan harness (aogen/vulkan/*.hpp) on the device it picks (lavapipe here and in CI),
// with the Khronos validation layer enabled and no message allowed. No test asserts on time.
#include <aogen/vulkan/chain.hpp>
#include <aogen/vulkan/device.hpp>
#include <aogen/vulkan/timing.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

namespace {

using namespace aogen;

// One context for the whole run (lavapipe's start-up is not free); null without a device.
vulkan::context* shared_context()
{
    static std::unique_ptr<vulkan::context> ctx = []() -> std::unique_ptr<vulkan::context> {
        try {
            return std::make_unique<vulkan::context>(vulkan::device_options{true, ""});
        } catch (const std::exception& e) {
            WARN("no Vulkan device, Vulkan harness tests skipped: " << e.what());
            return nullptr;
        }
    }();
    return ctx.get();
}

// A plane facing the camera at view depth 5 over the left 2/3 of the image; the rest is
// cleared depth (1.0, background). World space = view space.
vulkan::gbuffer facing_plane(int w, int h, const mat4& proj)
{
    vulkan::gbuffer g{w, h, std::vector<float>(static_cast<size_t>(w) * h, 1.0f), std::vector<float>(static_cast<size_t>(w) * h * 4, 0.0f)};
    const vec4 clip = proj * vec4{0, 0, -5, 1};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w * 2 / 3; ++x) {
            g.depth[static_cast<size_t>(y) * w + x] = clip.z / clip.w;
            g.normals[(static_cast<size_t>(y) * w + x) * 4 + 2] = 1.0f;
        }
    return g;
}

vulkan::chain_settings settings_for(const mat4& proj)
{
    vulkan::chain_settings s;
    s.camera = {mat4{}, proj};
    return s;
}

void require_clean(vulkan::context& ctx)
{
    const std::vector<std::string> m = ctx.messages();
    for (const std::string& s : m) UNSCOPED_INFO(s);
    CHECK(m.empty());
}

} // namespace

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

void check_facing_plane(technique t)
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.9f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = facing_plane(W, H, proj);
    {
        variant v;
        v.tech = t;
        v.half_resolution = false;
        INFO(to_name(v));
        vulkan::chain c(*ctx, v);
        const vulkan::chain_result r = c.run(g, settings_for(proj));
        REQUIRE(r.width == W);
        REQUIRE(r.height == H);
        REQUIRE(r.ao.size() == static_cast<size_t>(W) * H);
        CHECK(r.passes.size() == passes(v).size());
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const float a = r.ao[static_cast<size_t>(y) * W + x];
                REQUIRE(std::isfinite(a));
                if (x < W * 2 / 3) REQUIRE(std::fabs(a - 1.0f) <= 1.0f / 255.0f);
                else REQUIRE(a == 1.0f);
            }
        require_clean(*ctx);
    }
}

TEST_CASE("vulkan: ssao, a plane facing the camera is unoccluded, background is exactly 1") { check_facing_plane(technique::ssao); }

TEST_CASE("vulkan: gtao, a plane facing the camera is unoccluded, background is exactly 1")
{
    check_facing_plane(technique::gtao);
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
