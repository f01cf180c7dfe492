// tests/accuracy/truth_scenes.hpp — what the accuracy tests share: the built-in scenes at
// 160 × 90 with their ray-traced reference, and a variant's AO on them as the report runs it.
//
//     const truth_scene& t = truth_of("crease");              // traced once per test program
//     std::vector<float> ao = ao_of(ctx, v, t);               // frame 0, default settings
//     std::vector<float> mean = mean_of_frames(ctx, v, t, 8); // frames 0..7, their plain mean
#pragma once

#include "vulkan/harness.hpp"

#include <aogen_report/reference.hpp>
#include <aogen_report/settings.hpp>
#include <aogen_scenes/gbuffer.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace aogen_test {

constexpr int width = 160, height = 90; // half resolution: 80 × 45
constexpr int reference_grid = 24;      // 576 rays a pixel: a standard error of about 0.02 a pixel, 1e-4 on a mean

// A built-in scene at width × height with its G-buffer tracer and reference image.
struct truth_scene {
    scenes::scene scene;
    std::unique_ptr<truth::scene> tracer;
    aogen_report::reference truth;
};

inline const truth_scene& truth_of(const std::string& name)
{
    static std::map<std::string, truth_scene> cache;
    auto found = cache.find(name);
    if (found != cache.end()) return found->second;
    truth_scene t;
    t.scene = scenes::builtin_scene(name);
    t.scene.camera.width = width, t.scene.camera.height = height;
    t.tracer = scenes::make_tracer(t.scene);
    scenes::gbuffer_options world;
    world.use_scene_normals = false;
    world.normals = scenes::normal_space::world;
    t.truth = aogen_report::trace_reference(*t.tracer, scenes::render_gbuffer(t.scene, *t.tracer, world), t.scene.ao_radius, reference_grid);
    return cache.emplace(name, std::move(t)).first->second;
}

// The G-buffer the report's renderer stores for `v` on `t`.
inline vulkan::gbuffer gbuffer_for(const variant& v, const truth_scene& t)
{
    scenes::gbuffer_options go;
    go.use_scene_normals = false;
    go.face_camera = false;
    go.normals = v.normals == normal_source::gbuffer_view ? scenes::normal_space::view : scenes::normal_space::world;
    return scenes::to_gbuffer<vulkan::gbuffer>(scenes::render_gbuffer(aogen_report::for_variant(t.scene, v), *t.tracer, go));
}

// `c`'s output on `g` with settings `s`, at full resolution (every variant here ends there:
// the upsample, or full resolution).
inline std::vector<float> full_output(const vulkan::chain& c, const vulkan::gbuffer& g, const vulkan::chain_settings& s)
{
    const vulkan::chain_result r = c.run(g, s);
    REQUIRE(r.width == width);
    REQUIRE(r.height == height);
    return r.ao;
}

// `v`'s AO on `t` as the report runs it (its G-buffer, frame 0), with the report's default
// settings of `settings_of` (v itself unless given: the smooth decisions' tuned values for a
// -step variant, say).
inline std::vector<float> ao_of(vulkan::context& ctx, const variant& v, const truth_scene& t, const variant* settings_of = nullptr)
{
    return full_output(chain_under_test(ctx, v), gbuffer_for(v, t), aogen_report::default_settings(settings_of ? *settings_of : v, t.scene));
}

// The plain mean of `v`'s frames 0..frames-1 on `t` (default settings), the noise turned
// frame by frame by `sequence` (aogen/temporal.hpp).
inline std::vector<float> mean_of_frames(vulkan::context& ctx, const variant& v, const truth_scene& t, int frames,
                                         temporal::sequence sequence = temporal::sequence::van_der_corput)
{
    const vulkan::chain c = chain_under_test(ctx, v);
    const vulkan::gbuffer g = gbuffer_for(v, t);
    vulkan::chain_settings s = aogen_report::default_settings(v, t.scene);
    s.frame_sequence = sequence;
    std::vector<double> sum(size_t(width) * height, 0.0);
    for (int f = 0; f < frames; ++f) {
        s.frame = uint32_t(f);
        const std::vector<float> ao = full_output(c, g, s);
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += ao[i];
    }
    std::vector<float> mean(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) mean[i] = float(sum[i] / frames);
    return mean;
}

} // namespace aogen_test
