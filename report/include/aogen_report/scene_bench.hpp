// aogen_report/scene_bench.hpp — one scene on the bench: its tracer, its reference, its
// G-buffers, and a run of any chain on it. The harness under the report, the stability
// suite and the tuner.
//
// WHAT
//   scene_bench(ctx, scene, grid) makes the scene's tracer (camera-relative) and traces its
//   reference once (grid² rays per pixel on the world-normal G-buffer, reference.hpp). Then:
//     gbuffer(v), gpu(v)   the G-buffer as the scene's renderer stores it for variant v (its
//                          depth convention and normal space), ray-cast on first use and
//                          uploaded once: every variant of one convention and space shares it
//                          (gbuffer_cache, for a harness that needs no reference);
//     run(c, s, inputs)    runs chain c (its variant: c.plan().variant()) once with settings s, reads the
//                          AO back and upsamples it to the screen, nearest, by the chain's
//                          output_scale(). With bench_inputs::faults, a copy of the G-buffer
//                          with the faults planted is uploaded for that run only; with
//                          bench_inputs::noise_rotation, every noise texel holds that rotation.
//   The sizes all come from the chain's variant (target_size, output_scale), never from
//   comparing widths.
//
// USAGE
//     aogen_report::scene_bench bench(ctx, scene, 32);
//     aogen::vulkan::chain c(ctx, aogen::codegen::make_plan(v, diagnostics));   // codegen::options::diagnostics
//     aogen_report::bench_run r = bench.run(c, aogen_report::default_settings(v, scene));
//     compare(r.full, bench.truth().ao, bench.truth().valid).rmse;
#pragma once

#include "images.hpp"
#include "reference.hpp"
#include "settings.hpp"

#include <aogen/chain_inputs.hpp>
#include <aogen/vulkan/chain.hpp>
#include <aogen_scenes/gbuffer.hpp>
#include <aogen_scenes/scene.hpp>

#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace aogen_report {

// A fault planted in a G-buffer before a run: a NaN depth or a zero normal at one pixel.
struct gbuffer_fault {
    enum class kind { nan_depth, zero_normal } what = kind::nan_depth;
    double u = 0.5, v = 0.5; // where, as fractions of the image (pixel floor(u·W), floor(v·H))
};

// The full-resolution pixel a fault lands on in a W × H image.
inline size_t fault_pixel(const gbuffer_fault& f, int w, int h)
{
    const int x = std::min(w - 1, int(f.u * w)), y = std::min(h - 1, int(f.v * h));
    return size_t(y) * w + x;
}

// What a run changes in its inputs beyond the settings.
struct bench_inputs {
    std::vector<gbuffer_fault> faults;
    std::optional<aogen::vec2> noise_rotation; // every pixel's noise rotation, when set
};

// One run read back.
struct bench_run {
    aogen::vulkan::chain_result out; // the chain's output, at output_size()
    std::vector<float> full;         // out.ao upsampled to the screen (nearest)
    std::vector<float> full_bent_normal; // a -bn chain's bent normals in world space, 3 per screen pixel (nearest); else empty
    int scale = 1;                   // screen pixels per output pixel along each axis
};

// A scene's G-buffers as its renderer stores them for each variant: ray-cast on first use,
// one per depth convention and normal space (with settings.hpp's renderer_gbuffer albedo),
// and uploaded once each, for every chain to share.
class gbuffer_cache {
public:
    gbuffer_cache(aogen::vulkan::context& ctx, const aogen::scenes::scene& s, const aogen::truth::scene& t) : ctx_(ctx), scene_(s), tracer_(t) {}
    gbuffer_cache(const gbuffer_cache&) = delete;
    gbuffer_cache& operator=(const gbuffer_cache&) = delete;

    const aogen::vulkan::gbuffer& host(const aogen::variant& v) { return entry(v).host; }
    const aogen::vulkan::gpu_gbuffer& gpu(const aogen::variant& v)
    {
        entry_type& e = entry(v);
        if (!e.gpu) e.gpu = std::make_unique<aogen::vulkan::gpu_gbuffer>(ctx_, e.host);
        return *e.gpu;
    }

private:
    struct entry_type {
        aogen::vulkan::gbuffer host;
        std::unique_ptr<aogen::vulkan::gpu_gbuffer> gpu;
    };
    entry_type& entry(const aogen::variant& v)
    {
        const aogen::scenes::normal_space space =
            v.normals == aogen::normal_source::gbuffer_view ? aogen::scenes::normal_space::view : aogen::scenes::normal_space::world;
        const int key = int(v.depth) * 4 + int(space);
        auto it = cache_.find(key);
        if (it != cache_.end()) return it->second;
        aogen::scenes::gbuffer_options o;
        o.use_scene_normals = false;
        o.normals = space;
        o.face_camera = false; // as the scene's renderer stores them (the reference's face the camera)
        o.motion = true;       // a still frame's motion vectors, all 0: what a -histmv variant reads
        const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(for_variant(scene_, v), tracer_, o);
        return cache_.emplace(key, entry_type{renderer_gbuffer(g), nullptr}).first->second;
    }

    aogen::vulkan::context& ctx_;
    const aogen::scenes::scene& scene_;
    const aogen::truth::scene& tracer_;
    std::map<int, entry_type> cache_;
};

class scene_bench {
public:
    scene_bench(aogen::vulkan::context& ctx, aogen::scenes::scene s, int grid)
        : ctx_(ctx), scene_(std::move(s)), tracer_(aogen::scenes::make_tracer(scene_)), gbuffers_(ctx, scene_, *tracer_)
    {
        aogen::scenes::gbuffer_options world;
        world.use_scene_normals = false;
        world.normals = aogen::scenes::normal_space::world;
        truth_ = trace_reference(scene_, *tracer_, aogen::scenes::render_gbuffer(scene_, *tracer_, world), grid);
    }
    scene_bench(const scene_bench&) = delete;
    scene_bench& operator=(const scene_bench&) = delete;

    const aogen::scenes::scene& scene() const { return scene_; }
    const aogen::truth::scene& tracer() const { return *tracer_; }
    const reference& truth() const { return truth_; }
    int width() const { return truth_.width; }
    int height() const { return truth_.height; }

    // The G-buffer the renderer stores for `v`, on the host and uploaded.
    const aogen::vulkan::gbuffer& gbuffer(const aogen::variant& v) { return gbuffers_.host(v); }
    const aogen::vulkan::gpu_gbuffer& gpu(const aogen::variant& v) { return gbuffers_.gpu(v); }
    // Chain `c` bound to this scene's G-buffer with settings `s`, for a caller's own frame loop.
    std::unique_ptr<aogen::vulkan::bound_chain> bind(const aogen::vulkan::chain& c, const aogen::vulkan::chain_settings& s)
    {
        return std::make_unique<aogen::vulkan::bound_chain>(ctx_, c.passes(), gpu(c.plan().variant()), c.plan().inputs(s, width(), height()),
                                                            c.counter());
    }

    // Chain `c` once on this scene with settings `s` (see WHAT).
    bench_run run(const aogen::vulkan::chain& c, const aogen::vulkan::chain_settings& s, const bench_inputs& inputs = {})
    {
        const aogen::variant& v = c.plan().variant();
        aogen::chain_inputs in = c.plan().inputs(s, width(), height());
        if (inputs.noise_rotation) {
            const float texel[4] = {inputs.noise_rotation->x, inputs.noise_rotation->y, 0.0f, 1.0f};
            for (size_t i = 0; i + sizeof texel <= in.noise.size(); i += sizeof texel) std::memcpy(in.noise.data() + i, texel, sizeof texel);
        }
        bench_run r;
        if (inputs.faults.empty()) {
            r.out = aogen::vulkan::bound_chain(ctx_, c.passes(), gpu(v), in, c.counter()).run_once();
        } else {
            const aogen::vulkan::gpu_gbuffer faulted(ctx_, with_faults(gbuffer(v), inputs.faults));
            r.out = aogen::vulkan::bound_chain(ctx_, c.passes(), faulted, in, c.counter()).run_once();
        }
        r.scale = aogen::output_scale(v);
        r.full = upsample(r.out.ao, r.out.width, r.out.height, r.scale, width(), height());
        if (!r.out.bent_normal.empty())
            r.full_bent_normal = upsample(view_to_world(r.out.bent_normal, for_variant(scene_, v).camera.world_to_view()), r.out.width,
                                          r.out.height, r.scale, width(), height(), 3);
        return r;
    }

    // Frames `first` .. `first + count - 1` of chain `c` with settings `s` (their frame
    // index: temporal.hpp), each upsampled to the screen as run() does and added into `sum`
    // (a screen's worth). The chain is bound once; each frame after the first writes only its
    // uniform bytes anew (bound_chain::set_uniforms), as a frame loop does.
    void add_frames(const aogen::vulkan::chain& c, aogen::vulkan::chain_settings s, uint32_t first, uint32_t count, std::vector<double>& sum)
    {
        const aogen::codegen::plan& p = c.plan();
        const aogen::variant& v = p.variant();
        s.frame = first;
        aogen::vulkan::bound_chain bound(ctx_, c.passes(), gpu(v), p.inputs(s, width(), height()), c.counter());
        for (uint32_t f = first; f < first + count; ++f) {
            if (f != first) s.frame = f, bound.set_uniforms(p.inputs(s, width(), height()));
            const aogen::vulkan::chain_result out = bound.run_once();
            const std::vector<float> full = upsample(out.ao, out.width, out.height, aogen::output_scale(v), width(), height());
            if (full.size() != sum.size()) aogen::fail("scene bench frames", "a sum of " + std::to_string(sum.size()) + " pixels", "valid: the screen's");
            for (size_t i = 0; i < sum.size(); ++i) sum[i] += full[i];
        }
    }

    // Frames 0 .. count − 1 of chain `c` with settings `s` on one binding, as a frame loop
    // runs them -- a history pass keeps its history from frame to frame --, and the last
    // frame's output upsampled to the screen (what a renderer shows after `count` frames).
    std::vector<float> last_frame(const aogen::vulkan::chain& c, aogen::vulkan::chain_settings s, uint32_t count)
    {
        const aogen::codegen::plan& p = c.plan();
        const aogen::variant& v = p.variant();
        s.frame = 0;
        aogen::vulkan::bound_chain bound(ctx_, c.passes(), gpu(v), p.inputs(s, width(), height()), c.counter());
        aogen::vulkan::chain_result out;
        for (uint32_t f = 0; f < count; ++f) {
            if (f > 0) s.frame = f, bound.set_uniforms(p.inputs(s, width(), height()));
            out = bound.run_once();
        }
        return upsample(out.ao, out.width, out.height, aogen::output_scale(v), width(), height());
    }

    // View-space directions (3 floats each) turned into world space by the inverse of
    // world_to_view's rotation (its transpose); zero stays zero.
    static std::vector<float> view_to_world(std::vector<float> n, const aogen::mat4& world_to_view)
    {
        for (size_t i = 0; i + 2 < n.size(); i += 3) {
            const float view[3] = {n[i], n[i + 1], n[i + 2]};
            for (int j = 0; j < 3; ++j) n[i + j] = world_to_view[j][0] * view[0] + world_to_view[j][1] * view[1] + world_to_view[j][2] * view[2];
        }
        return n;
    }

    // `g` with `faults` planted: a NaN depth, or a zero normal (RGB 0).
    static aogen::vulkan::gbuffer with_faults(aogen::vulkan::gbuffer g, const std::vector<gbuffer_fault>& faults)
    {
        for (const gbuffer_fault& f : faults) {
            const size_t i = fault_pixel(f, g.width, g.height);
            if (f.what == gbuffer_fault::kind::nan_depth) g.depth[i] = std::nanf("");
            else
                for (int k = 0; k < 3; ++k) g.normals[4 * i + k] = 0.0f;
        }
        return g;
    }

private:
    aogen::vulkan::context& ctx_;
    aogen::scenes::scene scene_;
    std::unique_ptr<aogen::truth::scene> tracer_;
    gbuffer_cache gbuffers_; // refers to scene_ and *tracer_: declared after them
    reference truth_;
};

} // namespace aogen_report
