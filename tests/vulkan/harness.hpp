// tests/vulkan/harness.hpp — what the Vulkan harness tests share: one validated context,
// analytic G-buffers and the zero-validation-messages check.
//
//     vulkan::context* ctx = shared_context();   // null (tests return) when skipped
//     vulkan::gbuffer g = facing_plane(w, h, proj);
//     vulkan::gbuffer c = crease(w, h, tan_half_fov_y, proj);   // floor + wall, some background
//     vulkan::chain_result r = chain_under_test(*ctx, v).run(g, settings_for(proj));   // AOGEN_MUTANT planted
//     require_clean(*ctx);                        // no validation message so far
//     check_facing_plane(*ctx, v);                // AO 1 on the plane, exactly 1 on background
#pragma once

#include <aogen/vulkan/chain.hpp>
#include <aogen/vulkan/device.hpp>

#include "mutants/mutants.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace aogen_test {

using namespace aogen;

// The variants whose emitted texts the gl: and HLSL round-trip tests run against their SPIR-V.
// Ten compute variants: SSAO, GTAO, VBAO; every blur; half and full resolution, with and
// without the upsample; view-space and reconstructed normals; the point-cloud fallback. Two
// of them are where a depth interpolated with GLSL's mix() came out one ulp apart on GL and
// on Vulkan and flipped an SSAO vote (8/255) and a VBAO sector (4/255): common/core.glsl's
// ao_lerp. Then fragment variants: the seeds' four (the default matrix's fragment variants)
// and three with the upsample, the denoise and VBAO, drawn as fullscreen triangles. Last, SAO
// in each stage. Two carry multi-bounce (-mb), in an AO pass and in a fragment blur; two bent
// normals (-bn), through the denoise and upsample and through the bilateral blur, whose
// rgba8 texels' .gba the tests compare too; three read the albedo G-buffer (-mbg) in the
// upsample, in a half-resolution compute AO pass and in a fragment box blur.
inline const char* const emitted_target_variants[] = {
    "ssao-s16-half-bilateral-gbufworld-std-persp-cs",
    "ssao-s8-full-box-recon-std-persp-cs",
    "gtao-2x3-half-bilateral-gbufworld-std-persp-cs",
    "gtao-4x4-full-denoise-gbufview-std-persp-cs",
    "gtao-2x2-half-denoise-gbufworld-std-persp-cs",
    "gtao-1x2-half-noblur-gbufworld-std-persp-cs-nearest-mb",
    "vbao-3x3-half-bilateral-gbufworld-std-persp-cs",
    "ssao-s64-full-noblur-recon-std-persp-cs-pc-rc004",
    "ssao-s32-full-noblur-gbufworld-std-persp-cs",
    "vbao-1x2-half-bilateral-gbufworld-std-persp-cs",
    "ssao-s16-half-bilateral-gbufworld-std-persp-fs-rawdepth-nearest",
    "gtao-2x3-half-bilateral-gbufworld-std-persp-fs-rawdepth-nearest",
    "ssao-s32-half-bilateral-gbufview-std-persp-fs-powint-nearest",
    "ssao-s64-full-noblur-recon-std-persp-fs-pc-rc004",
    "ssao-s16-half-bilateral-gbufworld-std-persp-fs",
    "gtao-2x3-half-denoise-gbufworld-std-persp-fs",
    "vbao-2x2-full-box-recon-std-persp-fs-mb",
    "sao-s16-half-denoise-gbufworld-std-persp-cs",
    "sao-s8-full-noblur-recon-std-persp-fs",
    "gtao-2x2-half-denoise-gbufworld-std-persp-cs-bn",
    "gtao-3x2-full-bilateral-recon-std-persp-cs-bn-mb",
    "ssao-s16-half-bilateral-gbufworld-std-persp-cs-mbg",
    "vbao-2x2-half-noblur-gbufworld-std-persp-cs-nearest-mbg",
    "gtao-2x3-half-box-gbufworld-std-persp-fs-nearest-mbg"};

// One validated context for the whole run (lavapipe's start-up is not free). Without a
// device, or without the validation layer, each test fails, or, with
// AOGEN_TESTS_OPTIONAL_DEPS=1 (support.hpp), gets null (no device) and returns, or runs
// unvalidated (no layer).
inline vulkan::context* shared_context()
{
    static std::string failure;
    static std::unique_ptr<vulkan::context> ctx = []() -> std::unique_ptr<vulkan::context> {
        try {
            return std::make_unique<vulkan::context>(vulkan::device_options{true, ""});
        } catch (const std::exception& e) {
            failure = e.what();
            return nullptr;
        }
    }();
    if (!ctx) aogen_test::skip_missing_dependency("no Vulkan device: " + failure);
    // Without the layer every require_clean() would pass on nothing: a missing layer is a
    // missing dependency like a missing device.
    else if (!ctx->validation_enabled())
        aogen_test::skip_missing_dependency(std::string("no Vulkan validation layer (") + vulkan::validation_layer +
                                            ", Debian's vulkan-validationlayers): require_clean would prove nothing");
    return ctx.get();
}

// `v`'s plan with its templates read through template_under_test (mutants/mutants.hpp):
// the embedded ones, or with AOGEN_MUTANT's fault planted; `diagnostics`: each pass also
// stores its raw value (codegen::options::diagnostics).
inline codegen::plan plan_under_test(const variant& v, bool diagnostics = false)
{
    codegen::options o = under_test();
    o.diagnostics = diagnostics;
    return codegen::make_plan(v, o);
}

// `v`'s chain from plan_under_test(v, diagnostics).
inline vulkan::chain chain_under_test(vulkan::context& ctx, const variant& v, bool diagnostics = false)
{
    return vulkan::chain(ctx, plan_under_test(v, diagnostics));
}

inline size_t pixel(int w, int x, int y) { return static_cast<size_t>(y) * w + x; }

// Channel c of the test albedo at pixel (x, y): tenths from 0 to 1 that differ between
// neighbouring pixels and between channels, so that a -mbg pass reading its albedo at
// another pixel, or one channel for the luminance, writes other values.
inline float test_albedo(int x, int y, int c)
{
    return float((7 * x + 13 * y + 5 * c) % 11) / 10.0f;
}

// `g` with the test albedo (test_albedo) in its albedo G-buffer.
inline vulkan::gbuffer with_test_albedo(vulkan::gbuffer g)
{
    g.albedo.assign(static_cast<size_t>(g.width) * g.height * 4, 1.0f);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            for (int c = 0; c < 3; ++c) g.albedo[(static_cast<size_t>(y) * g.width + x) * 4 + c] = test_albedo(x, y, c);
    return g;
}

// A G-buffer of w × h cleared to background: standard depth 1, zero normals, the test albedo.
inline vulkan::gbuffer cleared(int w, int h)
{
    return with_test_albedo({w, h, std::vector<float>(static_cast<size_t>(w) * h, 1.0f), std::vector<float>(static_cast<size_t>(w) * h * 4, 0.0f)});
}

// The depth-buffer value of view-space point p: clip z / clip w.
inline float depth_of(const mat4& proj, vec3 p)
{
    const vec4 clip = proj * vec4{p.x, p.y, p.z, 1};
    return clip.z / clip.w;
}

inline void set_normal(vulkan::gbuffer& g, size_t i, vec3 n)
{
    g.normals[i * 4 + 0] = n.x, g.normals[i * 4 + 1] = n.y, g.normals[i * 4 + 2] = n.z;
}

// The plane through view-space (0, 0, -4) with its normal tilted `tilt_degrees` from the view
// axis (about x and y), seen by a camera at the origin looking down -z (tan_half_fov_y, w × h);
// background where it lies behind the camera or farther than 12 (where depth is coarse).
// Normals are the plane's, in view space = world space.
inline vulkan::gbuffer tilted_plane(int w, int h, float tan_half_fov_y, const mat4& proj, float tilt_degrees)
{
    const float a = tilt_degrees * 3.14159265f / 180.0f;
    const vec3 n{std::sin(a) * 0.6f, std::sin(a) * 0.8f, std::cos(a)};
    const float aspect = float(w) / float(h);
    vulkan::gbuffer g = cleared(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const vec3 d{(2.0f * (x + 0.5f) / w - 1.0f) * aspect * tan_half_fov_y, (1.0f - 2.0f * (y + 0.5f) / h) * tan_half_fov_y, -1.0f};
            const float t = dot(vec3{0, 0, -4}, n) / dot(d, n);
            if (!(t > 0.0f && t < 12.0f)) continue;
            g.depth[pixel(w, x, y)] = depth_of(proj, d * t);
            set_normal(g, pixel(w, x, y), n);
        }
    return g;
}

// A plane facing the camera at view depth 5 over the left 2/3 of the image; the rest is
// cleared depth (1.0, background). World space = view space.
inline vulkan::gbuffer facing_plane(int w, int h, const mat4& proj)
{
    vulkan::gbuffer g = cleared(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w * 2 / 3; ++x) {
            g.depth[pixel(w, x, y)] = depth_of(proj, {0, 0, -5});
            set_normal(g, pixel(w, x, y), {0, 0, 1});
        }
    return g;
}

// A crease: the floor y = -0.6 meeting the wall z = -3, the wall only for |x| < 1.5, so the
// image has a concave corner (occluded), open floor and wall (not), and background beside
// the wall. The camera sits at the origin looking down -z with `tan_half_fov_y`; each
// pixel centre's ray is intersected analytically. World space = view space.
inline vulkan::gbuffer crease(int w, int h, float tan_half_fov_y, const mat4& proj)
{
    vulkan::gbuffer g = cleared(w, h);
    const float aspect = float(w) / float(h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // The view ray through the pixel centre (uv.y = 0 is the top row).
            const vec3 d{(2.0f * (x + 0.5f) / w - 1.0f) * aspect * tan_half_fov_y, (1.0f - 2.0f * (y + 0.5f) / h) * tan_half_fov_y, -1.0f};
            float t = 1e30f;
            vec3 n{};
            if (d.y < 0.0f) t = -0.6f / d.y, n = {0, 1, 0};                      // floor
            if (3.0f < t && std::fabs(3.0f * d.x) < 1.5f) t = 3.0f, n = {0, 0, 1}; // wall (d.z = -1)
            if (t > 100.0f) continue;                                            // past the far plane: background
            const size_t i = pixel(w, x, y);
            g.depth[i] = depth_of(proj, {t * d.x, t * d.y, t * d.z});
            set_normal(g, i, n);
        }
    return g;
}

inline vulkan::chain_settings settings_for(const mat4& proj)
{
    vulkan::chain_settings s;
    s.camera = {mat4{}, proj};
    return s;
}

// The full-resolution pixel target pixel (x, y) of `v` reads (common/depth.glsl's ao_full_pixel).
inline size_t full_pixel_of(const variant& v, int w, int h, int x, int y)
{
    const int k = v.half_resolution ? 2 : 1;
    return pixel(w, std::min(x * k, w - 1), std::min(y * k, h - 1));
}

// "" when a and b are equal, else where they first differ and how: "size 12 against 9", or
// "[7]: 0.25 against 0.5" -- what a failing CHECK of two long vectors should say.
inline std::string first_difference(const std::vector<float>& a, const std::vector<float>& b)
{
    if (a.size() != b.size()) return "size " + std::to_string(a.size()) + " against " + std::to_string(b.size());
    for (size_t i = 0; i < a.size(); ++i)
        if (!(a[i] == b[i])) return "[" + std::to_string(i) + "]: " + std::to_string(a[i]) + " against " + std::to_string(b[i]);
    return "";
}

// crease(w, h, 0.6, proj) with every pixel's motion vector (mx, my) (NDC, current - previous,
// y up): the G-buffer a history variant's runners are compared on.
inline vulkan::gbuffer crease_in_motion(int w, int h, const mat4& proj, float mx, float my)
{
    vulkan::gbuffer g = crease(w, h, 0.6f, proj);
    g.motion.resize(static_cast<size_t>(w) * h * 2);
    for (size_t i = 0; i < g.motion.size(); i += 2) g.motion[i] = mx, g.motion[i + 1] = my;
    return g;
}

// The same axes as `v`, run as a compute variant (what a fragment variant is compared with).
inline variant as_compute(variant v)
{
    v.stage = pipeline_stage::compute;
    return v;
}

// `count` frames of settings `still` with the camera moving sideways 0.02 a frame (each frame's
// previous camera the frame before's; frame 0's its own), each frame its own index: plan `p`'s
// inputs for a w × h G-buffer -- what a history variant's runners are compared on.
inline std::vector<chain_inputs> sideways_frames(const codegen::plan& p, const vulkan::chain_settings& still, int w, int h, uint32_t count)
{
    std::vector<chain_inputs> frames;
    for (uint32_t f = 0; f < count; ++f) {
        vulkan::chain_settings s = still;
        s.frame = f;
        s.camera.world_to_view.columns[3].x -= 0.02f * float(f);
        s.previous_camera = still.camera;
        s.previous_camera->world_to_view.columns[3].x -= 0.02f * float(f > 0 ? f - 1 : 0);
        frames.push_back(p.inputs(s, w, h));
    }
    return frames;
}

// Chain `c`'s frames of `frames` on one Vulkan binding to `g`, frame after frame (a history
// kept), each read back; and into `history`, when given, the history after the last.
inline std::vector<vulkan::chain_result> spirv_frames(vulkan::context& ctx, const vulkan::chain& c, const vulkan::gbuffer& g,
                                                      const std::vector<chain_inputs>& frames, std::vector<float>* history = nullptr)
{
    const vulkan::gpu_gbuffer uploaded(ctx, g);
    vulkan::bound_chain b(ctx, c.passes(), uploaded, frames.at(0));
    std::vector<vulkan::chain_result> out;
    for (size_t f = 0; f < frames.size(); ++f) {
        if (f > 0) b.set_uniforms(frames[f]);
        out.push_back(b.run_once());
    }
    if (history) *history = b.read_history();
    return out;
}

// How many surface texels of a history hold `frames` frames, and how many hold any.
inline std::pair<size_t, size_t> held_of(const std::vector<float>& history, float frames)
{
    size_t held = 0, surface = 0;
    for (size_t i = 2; i < history.size(); i += 4) held += history[i] == frames, surface += history[i] > 0.0f;
    return {held, surface};
}

inline void require_clean(vulkan::context& ctx)
{
    const std::vector<std::string> m = ctx.messages();
    for (const std::string& s : m) UNSCOPED_INFO(s);
    CHECK(m.empty());
}

// Runs `v` on facing_plane(): one result per target pixel, each finite; AO 1 within 1/255
// where the pixel reads the plane, exactly 1 where it reads background; no validation message.
inline void check_facing_plane(vulkan::context& ctx, const variant& v)
{
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.9f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = facing_plane(W, H, proj);
    INFO(to_name(v));
    vulkan::chain c = chain_under_test(ctx, v);
    const vulkan::chain_result r = c.run(g, settings_for(proj));
    const auto [TW, TH] = c.plan().output_size(W, H);
    const bool screen_sized = TW == W; // the depth-aware upsample's output, or a full-resolution target
    REQUIRE(r.width == TW);
    REQUIRE(r.height == TH);
    REQUIRE(r.ao.size() == static_cast<size_t>(TW) * TH);
    CHECK(r.passes.size() == passes(v).size());
    for (int y = 0; y < TH; ++y)
        for (int x = 0; x < TW; ++x) {
            INFO("pixel " << x << ", " << y);
            const float a = r.ao[pixel(TW, x, y)];
            REQUIRE(std::isfinite(a));
            if (g.depth[screen_sized ? pixel(W, x, y) : full_pixel_of(v, W, H, x, y)] < 1.0f) REQUIRE(std::fabs(a - 1.0f) <= 1.0f / 255.0f);
            else REQUIRE(a == 1.0f);
        }
    require_clean(ctx);
}

} // namespace aogen_test
