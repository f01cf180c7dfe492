// aogen_report/motion.hpp — AO as engines show it: variants run frame after frame along a
// scene's camera path (and its moving objects), each frame scored against its own truth.
//
// WHAT
//   The still report scores frame 0 and the plain mean of N frames of a still camera. Here a
//   scene with a path (aogen_scenes/scene.hpp's camera.path: room, stairs, engine,
//   rolling_sphere) is run as a renderer runs it: frame f's G-buffer (render_frame, with its
//   motion vectors), frame f's camera and the previous one, the history pass's state carried
//   from frame to frame on one binding (vulkan::bound_chain::set_gbuffer, set_uniforms). Per
//   variant and scene, over the scored frames (from `first_scored` on, once a history has
//   had time to fill; each traced with its own reference):
//     error      the mean over the scored frames of each frame's RMSE against its own truth
//     ghosting   the RMSE over the pixels whose surface point came into view within the last
//                `ghost_window` frames (disoccluded: age < ghost_window) -- where a history
//                is wrong or young
//     flicker    the RMS of the frame-to-frame change of (AO − truth) at one surface point:
//                pixel p of frame f against frame f − 1's (AO − truth) where p's point stood
//                (bilinear over that frame's pixels of the same object), over the points in
//                view in both -- what a still error does not show
//   A point's age (motion_metrics.hpp's next_ages) is the truth's, not a shader's guess: frame f's hit
//   point, moved back by its object's motion, is in view at frame f − 1 when it projects
//   onto that frame's screen and nothing of frame f − 1's scene lies between it and that
//   frame's eye (a ray cast in frame f − 1's tracer).
//
// USAGE
//     aogen_report::motion_scene m(ctx, scene, {16, 8, 4, 16}, history);   // frames, first scored, window, grid
//     aogen_report::motion_record r = m.score(chain);              // r.error, r.ghosting, r.flicker
//
// WHY
//   A still camera's mean is the N8AO case, which no moving engine sees: in motion a history
//   is reprojected, rejected and clamped, and what it costs -- ghosts on uncovered pixels,
//   shimmer -- only shows frame against frame. Frames before `first_scored` are run but not
//   traced: a history starts empty, and its first frames say how fast it fills, not where it
//   settles.
#pragma once

#include "images.hpp"
#include "motion_metrics.hpp"
#include "settings.hpp"

#include <aogen/vulkan/chain.hpp>
#include <aogen/vulkan/timing.hpp>
#include <aogen_scenes/gbuffer.hpp>
#include <aogen_scenes/scene.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aogen_report {

// The variants the default report runs in motion: the default variant and two cheap GTAO
// chains of 8 taps a pixel, each without and with the history pass (by motion vectors; the
// 2×2 also by the camera alone, which cannot follow rolling_sphere's sphere), and the dear
// single frame the cheap ones are to match (gtao-4x4-half-noblur). The 1×4 without a blur is
// the chain built for the pass: frames average a slice's directions but not its steps (a
// horizon is the largest of its steps' angles, and a mean of maxima of 2 is not a maximum of
// more), so of two 8-tap chains the one with 4 steps converges lower; and without a spatial
// filter the history is the denoiser (docs/design.md § The history pass).
inline std::vector<aogen::variant> default_motion_variants()
{
    std::vector<aogen::variant> v;
    for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "ssao-s16-half-bilateral-gbufworld-std-persp-cs-histmv",
                             "gtao-1x4-half-noblur-gbufworld-std-persp-cs", "gtao-1x4-half-noblur-gbufworld-std-persp-cs-histmv",
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs", "gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist",
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs-histmv", "gtao-4x4-half-noblur-gbufworld-std-persp-cs"})
        v.push_back(aogen::variant_from_name(name));
    return v;
}

// ---------------------------------------------------------------------------------
// A scene's path on the bench
// ---------------------------------------------------------------------------------

// One frame of a path, made once for every variant run along it.
struct motion_frame {
    aogen::scenes::scene scene;                       // the scene at this frame
    std::unique_ptr<aogen::truth::scene> tracer;
    aogen::scenes::gbuffer world;                     // ray-cast with world normals: the reference's, the ages'
    std::vector<previous_place> from;                 // previous_pixels (empty at frame 0)
    std::vector<int> ages;                            // after this frame
    std::unique_ptr<reference> truth;                 // scored frames only
};

class motion_scene {
public:
    // Every frame's G-buffer and ages; the references of the scored frames (the tracing).
    motion_scene(aogen::vulkan::context& ctx, const aogen::scenes::scene& s, const motion_options& o, const aogen::history_params& history = {})
        : ctx_(ctx), scene_(s), options_(o), history_(history)
    {
        const int frames = std::min(o.frames, aogen::scenes::frame_count(s));
        if (frames < 2 || o.first_scored < 1 || o.first_scored >= frames)
            aogen::fail(s.source + ": motion", std::to_string(frames) + " frames, scored from " + std::to_string(o.first_scored),
                        "valid: a path of at least 2 frames, scored from 1 .. frames − 1");
        for (int f = 0; f < frames; ++f) {
            motion_frame m;
            m.scene = aogen::scenes::at_frame(s, f);
            m.tracer = aogen::scenes::make_tracer(m.scene);
            aogen::scenes::gbuffer_options world;
            world.use_scene_normals = false;
            world.normals = aogen::scenes::normal_space::world;
            m.world = aogen::scenes::render_gbuffer(m.scene, *m.tracer, world);
            if (f > 0) m.from = previous_pixels(m.scene, m.world, frames_.back().scene, *frames_.back().tracer);
            m.ages = f > 0 ? next_ages(frames_.back().ages, m.from) : std::vector<int>(m.world.depth.size(), 0);
            if (f >= o.first_scored) m.truth = std::make_unique<reference>(trace_reference(m.scene, *m.tracer, m.world, o.grid));
            frames_.push_back(std::move(m));
        }
    }

    const aogen::scenes::scene& scene() const { return scene_; }
    int frames() const { return int(frames_.size()); }
    const motion_frame& frame(int f) const { return frames_.at(size_t(f)); }

    // Chain `c` along the path, one binding frame after frame (its history kept), scored;
    // its history pass with the scene's settings (the constructor's), or `history`.
    // With motion_options::timed, and `timing`, the chain is then timed on the path's last
    // frame, its history kept (the report's protocol; motion_record::ms).
    motion_record score(const aogen::vulkan::chain& c, const aogen::vulkan::timing_options& timing = {}) { return score(c, history_, timing); }
    motion_record score(const aogen::vulkan::chain& c, const aogen::history_params& history, const aogen::vulkan::timing_options& timing = {})
    {
        const aogen::codegen::plan& p = c.plan();
        const aogen::variant& v = p.variant();
        std::unique_ptr<aogen::vulkan::bound_chain> bound;
        std::vector<scored_frame> scored;
        for (int f = 0; f < frames(); ++f) {
            const motion_frame& m = frames_[size_t(f)];
            const aogen::vulkan::gpu_gbuffer& g = gpu(f, v);
            aogen::vulkan::chain_settings s = default_settings(v, m.scene);
            s.frame = uint32_t(f);
            s.history = history;
            s.reset_history = f == 0;
            if (f > 0) s.previous_camera = default_settings(v, frames_[size_t(f) - 1].scene).camera;
            const aogen::chain_inputs in = p.inputs(s, g.width(), g.height());
            if (!bound) bound = std::make_unique<aogen::vulkan::bound_chain>(ctx_, c.passes(), g, in, c.counter());
            else bound->set_gbuffer(g), bound->set_uniforms(in);
            const aogen::vulkan::chain_result out = bound->run_once();
            if (!m.truth) continue;
            scored.push_back({upsample(out.ao, out.width, out.height, aogen::output_scale(v), g.width(), g.height()), m.truth.get(), m.from, m.ages,
                              m.world.geometry, g.width()});
        }
        motion_record r = motion_metrics(scored, options_.ghost_window);
        r.variant = p.name(), r.scene = scene_.name;
        if (options_.timed) {
            const aogen::vulkan::timing_result t = aogen::vulkan::time_chains(ctx_, {bound.get()}, timing);
            if (!t.chains.empty()) r.ms = t.chains[0].total.median;
        }
        return r;
    }

private:
    // Frame f's G-buffer as the renderer stores it for `v` (its depth convention and normal
    // space, with motion vectors), uploaded once per frame and kind.
    const aogen::vulkan::gpu_gbuffer& gpu(int f, const aogen::variant& v)
    {
        const aogen::scenes::normal_space space =
            v.normals == aogen::normal_source::gbuffer_view ? aogen::scenes::normal_space::view : aogen::scenes::normal_space::world;
        const int key = (f * 4 + int(v.depth)) * 4 + int(space);
        for (const auto& [k, g] : uploaded_)
            if (k == key) return *g;
        aogen::scenes::gbuffer_options o;
        o.use_scene_normals = false;
        o.normals = space;
        o.face_camera = false; // as the scene's renderer stores them
        o.motion = true;       // from the frame before, through the frame's own tracer (built once, in the constructor)
        const std::optional<aogen::scenes::scene> before = f > 0 ? std::optional(for_variant(frames_[size_t(f) - 1].scene, v)) : std::nullopt;
        o.previous = before ? &*before : nullptr;
        const motion_frame& m = frames_[size_t(f)];
        const aogen::scenes::gbuffer rendered = aogen::scenes::render_gbuffer(for_variant(m.scene, v), *m.tracer, o);
        uploaded_.emplace_back(key, std::make_unique<aogen::vulkan::gpu_gbuffer>(ctx_, renderer_gbuffer(rendered)));
        return *uploaded_.back().second;
    }

    aogen::vulkan::context& ctx_;
    aogen::scenes::scene scene_;
    motion_options options_;
    aogen::history_params history_;
    std::vector<motion_frame> frames_;
    std::vector<std::pair<int, std::unique_ptr<aogen::vulkan::gpu_gbuffer>>> uploaded_;
};

} // namespace aogen_report
