// The history pass (-hist, -histmv: templates/history.glsl), run frame after frame on one
// binding as a renderer runs it, against oracles of its own:
//   - its twin: the same variant without the pass. At a reset, on the first frame (a cleared
//     history holds no frame), after a turn of 180 degrees (every point was behind the
//     previous camera) and where a planted NaN or infinity is the only history, the chain's
//     output is the twin's, bit for bit;
//   - the plain mean: with a still camera and no clamp, the history after n frames holds
//     the mean of the n frames the twin's blur wrote (w = 1 / (n + 1) while 1 / (n + 1) >
//     blend), to 16-bit rounding;
//   - a planted history under a moving camera: a camera that moves one AO target texel to the
//     side reads the history one texel over, and motion vectors in every convention
//     history_params::motion names read it from the same texel; each clamp holds a planted
//     history where its closed form says.
// Bad input is refused by name: a history of another size, a -histmv chain without motion
// vectors.
#include "harness.hpp"

#include <aogen/half.hpp>

#include <cmath>
#include <limits>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_history_test {

using namespace aogen;
using namespace aogen_test;

namespace {

// `v` without its history pass.
variant twin_of(variant v)
{
    v.history = history_mode::off;
    return v;
}

// The index of `kind` in the passes of `c`, or the last pass's.
size_t pass_index(const vulkan::chain& c, pass_kind kind)
{
    const std::vector<pass_kind>& ps = c.plan().passes();
    for (size_t i = 0; i < ps.size(); ++i)
        if (ps[i] == kind) return i;
    return ps.size() - 1;
}

// The pass a history pass reads: the one before it.
size_t input_of_history(const vulkan::chain& c) { return pass_index(c, pass_kind::history) - 1; }

// A camera translated by `t` in world space (the view moves by -t).
uniforms::camera moved_camera(const mat4& proj, vec3 t)
{
    mat4 view;
    view.columns[3] = {-t.x, -t.y, -t.z, 1.0f};
    return {view, proj};
}

// A plane facing the camera at view depth `z` over the whole image (AO 1: an open plane).
vulkan::gbuffer full_facing_plane(int w, int h, const mat4& proj, float z)
{
    vulkan::gbuffer g = cleared(w, h);
    for (size_t i = 0; i < g.depth.size(); ++i) {
        g.depth[i] = depth_of(proj, {0, 0, -z});
        set_normal(g, i, {0, 0, 1});
    }
    return g;
}

// A history of w × h texels holding AO `ao(x, y)` for a surface at view distance `z`, `frames` frames.
template <class F>
std::vector<float> planted_history(int w, int h, float z, float frames, F ao)
{
    std::vector<float> rgba;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) rgba.insert(rgba.end(), {ao(x, y), std::log2(z), frames, 0.0f});
    return rgba;
}

} // namespace

TEST_CASE("vulkan: history: at a reset, on the first frame and after a turn of 180 degrees, a history chain writes its twin's output bit for bit")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    vulkan::gbuffer host = crease(W, H, 0.6f, proj); // floor, wall, their crease, background
    host.motion.assign(static_cast<size_t>(W) * H * 2, 0.0f);
    const vulkan::gpu_gbuffer g(*ctx, host);
    for (const char* name : {"gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist", "ssao-s16-half-bilateral-gbufworld-std-persp-cs-histmv",
                             "gtao-2x3-full-noblur-gbufworld-std-persp-cs-hist", "sao-s16-half-box-gbufworld-std-persp-cs-nearest-hist",
                             "vbao-2x2-half-denoise-recon-std-persp-cs-deint-histmv", "gtao-2x2-half-denoise-gbufworld-std-persp-fs-hist",
                             "ssao-s16-full-bilateral-gbufworld-std-persp-fs-histmv"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        const vulkan::chain with = chain_under_test(*ctx, v), twin = chain_under_test(*ctx, twin_of(v));
        vulkan::chain_settings s = settings_for(proj);
        vulkan::bound_chain b(*ctx, with.passes(), g, with.plan().inputs(s, W, H));
        // Frame 0: the history is cleared, it holds no frame.
        CHECK(first_difference(b.run_once().ao, twin.run(host, s).ao) == "");
        // Frames 1..3 of a still camera: the history is used (the output moves off the twin's).
        size_t moved = 0;
        for (uint32_t f = 1; f <= 3; ++f) {
            s.frame = f;
            b.set_uniforms(with.plan().inputs(s, W, H));
            const std::vector<float> out = b.run_once().ao, alone = twin.run(host, s).ao;
            for (size_t i = 0; i < out.size(); ++i) moved += out[i] != alone[i];
        }
        CHECK(moved > 0);
        // A reset: this frame alone.
        s.frame = 4, s.reset_history = true;
        b.set_uniforms(with.plan().inputs(s, W, H));
        CHECK(first_difference(b.run_once().ao, twin.run(host, s).ao) == "");
        // A turn of 180 degrees about the view's y axis: every point was behind the camera.
        s.frame = 5, s.reset_history = false;
        mat4 turned;
        turned.columns[0] = {-1, 0, 0, 0}, turned.columns[2] = {0, 0, -1, 0};
        s.previous_camera = uniforms::camera{turned, proj};
        b.set_uniforms(with.plan().inputs(s, W, H));
        CHECK(first_difference(b.run_once().ao, twin.run(host, s).ao) == "");
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: a fragment history chain (two colour attachments) writes the compute chain's frames and history, frame after frame")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease_in_motion(W, H, proj, -0.02f * proj[0][0] / 5.0f, 0.0f); // about the camera's move at the crease
    for (const char* name : {"gtao-2x2-half-denoise-gbufworld-std-persp-fs-histmv", "gtao-1x4-half-noblur-gbufworld-std-persp-fs-hist",
                             "ssao-s16-full-bilateral-gbufworld-std-persp-fs-hist"}) {
        INFO(name);
        const variant fragment = variant_from_name(name);
        const vulkan::chain f = chain_under_test(*ctx, fragment), c = chain_under_test(*ctx, as_compute(fragment));
        const std::vector<chain_inputs> frames = sideways_frames(f.plan(), settings_for(proj), W, H, 6);
        std::vector<float> f_history, c_history;
        const std::vector<vulkan::chain_result> got = spirv_frames(*ctx, f, host, frames, &f_history);
        const std::vector<vulkan::chain_result> expected = spirv_frames(*ctx, c, host, frames, &c_history);
        for (size_t k = 0; k < frames.size(); ++k) {
            INFO("frame " << k);
            CHECK(first_difference(got[k].ao, expected[k].ao) == "");
        }
        CHECK(first_difference(f_history, c_history) == "");
        const auto [held, surface] = held_of(c_history, float(frames.size()));
        CHECK(held * 2 > surface); // the history was used: most surface texels hold every frame
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: with a still camera and no clamp, the history of n frames is their plain mean, and the output that mean in 8 bits")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease(W, H, 0.6f, proj);
    const vulkan::gpu_gbuffer g(*ctx, host);
    for (const char* name : {"gtao-2x2-half-denoise-gbufworld-std-persp-cs-nearest-hist", "ssao-s16-full-noblur-gbufworld-std-persp-cs-hist"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        const vulkan::chain with = chain_under_test(*ctx, v), twin = chain_under_test(*ctx, twin_of(v));
        vulkan::chain_settings s = settings_for(proj);
        s.history.clamp = history_clamp::none;
        s.history.blend = 0.1f; // 1 / (n + 1) > 0.1 for the 8 frames: they weigh evenly
        vulkan::bound_chain b(*ctx, with.passes(), g, with.plan().inputs(s, W, H));
        std::vector<double> sum;
        for (uint32_t f = 0; f < 8; ++f) {
            INFO("frame " << f);
            s.frame = f;
            b.set_uniforms(with.plan().inputs(s, W, H));
            const std::vector<float> out = b.run_once().ao;
            const std::vector<float> history = b.read_history();
            vulkan::bound_chain t(*ctx, twin.passes(), g, twin.plan().inputs(s, W, H));
            t.run_once();
            const std::vector<float> frame = t.read_output(input_of_history(with));
            sum.resize(frame.size(), 0.0);
            REQUIRE(out.size() == frame.size());
            double worst_history = 0, worst_output = 0;
            size_t surface = 0;
            for (size_t i = 0; i < frame.size(); ++i) {
                sum[i] += frame[i];
                if (history[4 * i + 2] == 0.0f) { // background: AO exactly 1, no frame held
                    CHECK(out[i] == 1.0f);
                    continue;
                }
                ++surface;
                const double mean = sum[i] / (f + 1);
                CHECK(history[4 * i + 2] == float(f + 1));
                worst_history = std::max(worst_history, std::fabs(history[4 * i] - mean));
                worst_output = std::max(worst_output, std::fabs(out[i] - mean));
            }
            INFO(surface << " surface texels; history off the mean by at most " << worst_history << ", the output by " << worst_output * 255 << "/255");
            CHECK(surface * 2 > frame.size());
            CHECK(worst_history <= 2e-3);                  // 16-bit rounding, frame after frame
            CHECK(worst_output <= 0.5 / 255 + 2e-3 + 1e-6); // and the 8-bit output's
        }
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: a camera that moves one target texel reads the history one texel over, and motion vectors in every convention read the same")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 64, H = 40, TW = W / 2, TH = H / 2;
    constexpr float Z = 5.0f;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    vulkan::gbuffer host = full_facing_plane(W, H, proj, Z);
    // The current camera stands right of and above the previous one by one half-resolution
    // texel's worth at depth Z: a point's previous uv is (2 / W, -2 / H) from its current
    // one, so target texel (x, y) reads the history at (x + 1, y - 1).
    const float tx = (4.0f / W) * Z / proj[0][0], ty = (4.0f / H) * Z / proj[1][1];
    auto planted = [](int x, int y) { return float((x * 7 + y * 3) % 10) / 20.0f; }; // 0 .. 0.45
    const float frames = 3.0f; // this frame then weighs max(blend, 1 / 4) = 1 / 4
    // That move's motion vector in each convention, written out by hand.
    struct convention {
        motion_convention c;
        float x, y;
    };
    const float u = 2.0f / W, v = 2.0f / H;
    const std::vector<convention> conventions{
        {{motion_units::uv, motion_direction::current_to_previous, motion_y::down}, u, -v},
        {{motion_units::uv, motion_direction::previous_to_current, motion_y::up}, -u, -v},
        {{motion_units::ndc, motion_direction::previous_to_current, motion_y::up}, -2 * u, -2 * v}, // UE5's, three.js's: the default
        {{motion_units::ndc, motion_direction::current_to_previous, motion_y::up}, 2 * u, 2 * v},
        {{motion_units::pixels, motion_direction::current_to_previous, motion_y::down}, 2.0f, -2.0f},
        {{motion_units::pixels, motion_direction::previous_to_current, motion_y::down}, -2.0f, 2.0f}};
    for (int k = -1; k < int(conventions.size()); ++k) {
        const bool by_camera = k < 0;
        const std::string how = by_camera ? std::string("by the camera")
                                          : "motion vectors in " + std::string(names::name_of(motion_units_names, conventions[k].c.units, "")) + ", " +
                                                names::name_of(motion_direction_names, conventions[k].c.direction, "") + ", y " +
                                                names::name_of(motion_y_names, conventions[k].c.y, "");
        INFO(how);
        const variant var = variant_from_name(by_camera ? "gtao-2x2-half-noblur-gbufworld-std-persp-cs-nearest-hist"
                                                         : "gtao-2x2-half-noblur-gbufworld-std-persp-cs-nearest-histmv");
        host.motion.assign(static_cast<size_t>(W) * H * 2, 0.0f);
        if (!by_camera)
            for (size_t i = 0; i < host.motion.size(); i += 2) host.motion[i] = conventions[k].x, host.motion[i + 1] = conventions[k].y;
        const vulkan::gpu_gbuffer g(*ctx, host);
        vulkan::chain_settings s = settings_for(proj);
        s.camera = moved_camera(proj, {tx, ty, 0});
        s.previous_camera = moved_camera(proj, {0, 0, 0});
        s.history.clamp = history_clamp::none;
        if (!by_camera) s.history.motion = conventions[k].c;
        const vulkan::chain c = chain_under_test(*ctx, var);
        vulkan::bound_chain b(*ctx, c.passes(), g, c.plan().inputs(s, W, H));
        b.load_history(TW, TH, planted_history(TW, TH, Z, frames, planted));
        b.run_once();
        const std::vector<float> history = b.read_history();
        double worst = 0;
        for (int y = 0; y < TH; ++y)
            for (int x = 0; x < TW; ++x) {
                const size_t i = pixel(TW, x, y);
                if (x + 1 == TW || y == 0) { // the point was off the previous screen: this frame alone
                    CHECK(history[4 * i] == 1.0f);
                    CHECK(history[4 * i + 2] == 1.0f);
                    continue;
                }
                const double expected = 0.75 * planted(x + 1, y - 1) + 0.25 * 1.0; // an open plane: this frame is 1
                worst = std::max(worst, std::fabs(history[4 * i] - expected));
                CHECK(history[4 * i + 2] == frames + 1);
            }
        INFO("history off the texel one over by at most " << worst);
        CHECK(worst <= 1e-3);
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: half a texel over, a quadratic history is read exactly (Catmull-Rom), where a bilinear read is off by a quarter of its curvature, and beside another surface by the taps that count")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 64, H = 40, TW = W / 2, TH = H / 2;
    constexpr float Z = 5.0f;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gpu_gbuffer g(*ctx, full_facing_plane(W, H, proj, Z));
    // The camera half a target texel to the right: texel x reads the history at x + 0.5.
    const float tx = (2.0f / W) * Z / proj[0][0];
    // h(x) = ((x - 16) / 16)^2, as the 16-bit history holds it.
    auto h = [](int x) { return half_to_float(float_to_half(float((x - 16) * (x - 16)) / 256.0f)); };
    vulkan::chain_settings s = settings_for(proj);
    s.camera = moved_camera(proj, {tx, 0, 0});
    s.previous_camera = moved_camera(proj, {0, 0, 0});
    s.history.clamp = history_clamp::none;
    const vulkan::chain c = chain_under_test(*ctx, variant_from_name("gtao-2x2-half-noblur-gbufworld-std-persp-cs-nearest-hist"));
    vulkan::bound_chain b(*ctx, c.passes(), g, c.plan().inputs(s, W, H));
    b.load_history(TW, TH, planted_history(TW, TH, Z, 3.0f, [&](int x, int) { return h(x); }));
    b.run_once();
    const std::vector<float> history = b.read_history();
    double worst = 0;
    for (int y = 1; y + 2 < TH; ++y)
        for (int x = 1; x + 2 < TW; ++x) { // the 4 x 4 texels about x + 0.5 all on the screen
            // Catmull-Rom at the midpoint: (-h(x-1) + 9 h(x) + 9 h(x+1) - h(x+2)) / 16, exactly h(x + 0.5) for a quadratic.
            const double read = (-h(x - 1) + 9.0 * h(x) + 9.0 * h(x + 1) - h(x + 2)) / 16.0;
            const double expected = 0.75 * read + 0.25;
            worst = std::max(worst, std::fabs(history[4 * pixel(TW, x, y)] - expected));
        }
    INFO("off the Catmull-Rom read by at most " << worst << " (a bilinear read: 0.75 / 1024 = 7.3e-4 off)");
    CHECK(worst <= 3e-4); // 16-bit rounding of values up to 1

    // Column 26 another surface's (twice as far): the taps that count are renormalised.
    // x = 24 reads 23..26 with weights -1, 9, 9, -1 (/16); 26 drops, their sum is 17/16, and
    // the read is (-h(23) + 9 h(24) + 9 h(25)) / 17, Catmull-Rom alone (2 S - 1 >= 1). x = 25
    // reads 24..27, and 26 takes 9/16 of it: S = 7/16, the bilinear read alone, of 25 (26
    // counts 0): h(25), fully trusted (the bilinear weights' sum 0.5).
    std::vector<float> planted = planted_history(TW, TH, Z, 3.0f, [&](int x, int) { return h(x); });
    for (int y = 0; y < TH; ++y) planted[4 * pixel(TW, 26, y) + 1] = std::log2(2.0f * Z);
    vulkan::bound_chain split(*ctx, c.passes(), g, c.plan().inputs(s, W, H));
    split.load_history(TW, TH, planted);
    split.run_once();
    const std::vector<float> read = split.read_history();
    for (int y = 1; y + 2 < TH; ++y) {
        INFO("row " << y);
        CHECK(std::fabs(read[4 * pixel(TW, 24, y)] - (0.75 * (-h(23) + 9.0 * h(24) + 9.0 * h(25)) / 17.0 + 0.25)) <= 3e-4);
        CHECK(std::fabs(read[4 * pixel(TW, 25, y)] - (0.75 * h(25) + 0.25)) <= 3e-4);
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: a history texel of another surface (its depth past the tolerance) is not read, one within half of it is, and one between in part")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 64, H = 40, TW = W / 2, TH = H / 2;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gpu_gbuffer g(*ctx, full_facing_plane(W, H, proj, 5.0f)); // this frame: AO 1 at depth 5
    const vulkan::chain c = chain_under_test(*ctx, variant_from_name("gtao-2x2-half-noblur-gbufworld-std-persp-cs-nearest-hist"));
    vulkan::chain_settings s = settings_for(proj);
    s.history.clamp = history_clamp::none;
    s.history.depth_tolerance = 0.05f;
    // The count of a texel that saw depth `seen`: 1 within half the tolerance (in log2), 0 past it.
    const double tolerance = std::log2(1.05);
    for (const float seen : {5.0f * 0.99f, 5.0f * 1.015f, 5.0f * 1.04f, 5.0f * 1.06f, 5.0f * 0.9f, 5.0f * 2.0f}) {
        const double off = std::fabs(double(half_to_float(float_to_half(std::log2(seen)))) - std::log2(5.0)); // the history holds 16 bits
        const double count = std::clamp(2.0 - 2.0 * off / tolerance, 0.0, 1.0), confidence = std::min(2.0 * count, 1.0);
        // This frame 1, the history 0 of 3 frames: mix(1, 0.75 * 0 + 0.25 * 1, confidence).
        const double expected = 1.0 - confidence * 0.75;
        INFO("the history saw depth " << seen << ": its count " << count << ", confidence " << confidence);
        vulkan::bound_chain b(*ctx, c.passes(), g, c.plan().inputs(s, W, H));
        b.load_history(TW, TH, planted_history(TW, TH, seen, 3.0f, [](int, int) { return 0.0f; }));
        b.run_once();
        const std::vector<float> history = b.read_history();
        for (size_t i = 0; i < history.size(); i += 4) {
            INFO("texel " << i / 4);
            REQUIRE(std::fabs(history[i] - expected) <= 1e-3); // 16-bit rounding
            REQUIRE(std::fabs(history[i + 2] - (1.0 + 3.0 * confidence)) <= 4e-3);
        }
        if (off <= tolerance / 2) CHECK(expected == 0.25);
        if (off >= tolerance) CHECK(expected == 1.0);
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: each clamp holds a planted history where its closed form puts it")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 64, H = 40, TW = W / 2, TH = H / 2;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gpu_gbuffer g(*ctx, full_facing_plane(W, H, proj, 5.0f)); // this frame: 1 everywhere
    const variant v = variant_from_name("gtao-2x2-half-noblur-gbufworld-std-persp-cs-nearest-hist");
    const vulkan::chain c = chain_under_test(*ctx, v);
    struct expectation {
        history_clamp clamp;
        float held; // where a history of 0 is held before the blend
    };
    for (const expectation& e : {expectation{history_clamp::none, 0.0f}, expectation{history_clamp::range, 0.9f},
                                 expectation{history_clamp::min_max, 0.95f}, expectation{history_clamp::variance, 1.0f}}) {
        INFO(names::name_of(history_clamp_names, e.clamp, ""));
        vulkan::chain_settings s = settings_for(proj);
        s.history.clamp = e.clamp;
        s.history.range = 0.1f;
        s.history.min_max_widening = 0.05f; // [1, 1] widened to [0.95, 1.05]
        vulkan::bound_chain b(*ctx, c.passes(), g, c.plan().inputs(s, W, H));
        b.load_history(TW, TH, planted_history(TW, TH, 5.0f, 3.0f, [](int, int) { return 0.0f; }));
        b.run_once();
        const std::vector<float> history = b.read_history();
        for (size_t i = 0; i < history.size(); i += 4) {
            INFO("texel " << i / 4);
            REQUIRE(std::fabs(history[i] - (0.75f * e.held + 0.25f)) <= 1e-3f);
        }
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: a NaN or an infinity planted in the history is dropped the frame it is read and never written back")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease(W, H, 0.6f, proj);
    const vulkan::gpu_gbuffer g(*ctx, host);
    const variant v = variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-nearest-hist");
    const vulkan::chain with = chain_under_test(*ctx, v), twin = chain_under_test(*ctx, twin_of(v));
    const vulkan::chain_settings s = settings_for(proj);
    vulkan::bound_chain b(*ctx, with.passes(), g, with.plan().inputs(s, W, H));
    b.run_once(); // a history of one frame
    std::vector<float> planted = b.read_history();
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<size_t> spoiled;
    for (size_t i = 0; i * 4 < planted.size(); i += 7) {
        const float bad[] = {nan, inf, -inf, 1e30f};
        planted[4 * i + (i / 7) % 3] = bad[(i / 21) % 4]; // in the AO, the depth or the frame count
        spoiled.push_back(i);
    }
    b.load_history((W + 1) / 2, (H + 1) / 2, planted);
    const std::vector<float> out = b.run_once().ao, alone = twin.run(host, s).ao;
    const std::vector<float> history = b.read_history();
    for (float x : out) REQUIRE(std::isfinite(x));
    for (float x : history) REQUIRE(std::isfinite(x));
    // In 16 bits 1e30 is an infinity too; a still camera reads each texel's own history only,
    // so a spoiled texel leaves this frame alone.
    for (size_t i : spoiled) {
        INFO("texel " << i);
        CHECK(out[i] == alone[i]);
    }
    CHECK(spoiled.size() > 50);
    require_clean(*ctx);
}

TEST_CASE("vulkan: history: a history of another size, and a -histmv chain without motion vectors, are refused by name")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = full_facing_plane(W, H, proj, 5.0f);
    const vulkan::gpu_gbuffer g(*ctx, host);
    const vulkan::chain c = chain_under_test(*ctx, variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist"));
    vulkan::bound_chain b(*ctx, c.passes(), g, c.plan().inputs(settings_for(proj), W, H));
    CHECK_THROWS_WITH(b.load_history(W, H, std::vector<float>(size_t(W) * H * 4, 0.0f)),
                      Catch::Contains("history: 64x40") && Catch::Contains("valid: 32x20"));
    const vulkan::chain mv = chain_under_test(*ctx, variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-histmv"));
    CHECK_THROWS_WITH(vulkan::bound_chain(*ctx, mv.passes(), g, mv.plan().inputs(settings_for(proj), W, H)),
                      Catch::Contains("motion vectors") && Catch::Contains("valid:"));
    const vulkan::chain plain = chain_under_test(*ctx, variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs"));
    vulkan::bound_chain none(*ctx, plain.passes(), g, plain.plan().inputs(settings_for(proj), W, H));
    CHECK_THROWS_WITH(none.read_history(), Catch::Contains("has no history pass"));
    require_clean(*ctx);
}

} // namespace unity_history_test
