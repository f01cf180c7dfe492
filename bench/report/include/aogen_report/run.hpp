// aogen_report/run.hpp — the report's measurements: every variant on every scene against
// the ray-traced ground truth, with its GPU time.
//
// WHAT
//   run_report(settings) does, in order:
//     1. per scene: the G-buffer (Embree ray cast) and the reference AO image
//        (reference.hpp, grid² rays per pixel, with its Monte-Carlo noise);
//     2. per variant: one Vulkan chain (compiled once), run on each scene it can run on
//        (settings.hpp) with the variant's default parameters; the AO read back,
//        upsampled to full resolution, compared with the reference (metrics.hpp); the
//        median GPU time of `runs` timed runs after `warmup` (timestamp queries, per pass);
//     3. per variant: the calibrated column (calibrate.hpp): ao^p, p fitted on the other
//        scenes, scored on this one;
//     4. summaries: per variant the mean RMSE over its scenes and the median of its
//        per-scene times; Pareto-optimal variants (pareto.hpp) by time against default
//        and against calibrated RMSE;
//     5. the feature saving: for each SSAO variant without the point-cloud fallback, its
//        twin with the fallback ("everything on"), run right after it on the mesh-only
//        scenes — SPIR-V instructions and time of the scene-selected variant against the twin.
//   Errors depend only on the inputs: the same settings give the same numbers; only the
//   times vary from run to run.
//
// USAGE
//     aogen_report::report_settings s;
//     s.scenes = {...};  s.variants = aogen::default_matrix();
//     aogen_report::report_data r = aogen_report::run_report(s);
#pragma once

#include "calibrate.hpp"
#include "images.hpp"
#include "metrics.hpp"
#include "pareto.hpp"
#include "reference.hpp"
#include "settings.hpp"

#include <aogen/selection.hpp>
#include <aogen/vulkan/timing.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aogen_report {

struct report_settings {
    std::vector<aogen::scenes::scene> scenes;
    std::vector<aogen::variant> variants;
    int width = 0, height = 0;       // every scene's resolution; 0: each scene's own
    int grid = 64;                   // reference rays per pixel: grid × grid
    int runs = 7, warmup = 1;        // timed runs per variant and scene
    bool feature_saving = true;      // run the point-cloud twins of SSAO variants
    aogen::vulkan::device_options device;
    std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct scene_record {
    aogen::scenes::scene scene;      // as run (resolution applied)
    reference truth;
    size_t valid_pixels = 0;
    double truth_mean = 0;           // mean reference AO over valid pixels
    bool mesh_only() const { return !scene.renderer.point_cloud; }
};

// One variant on one scene.
struct run_record {
    std::string skipped;             // why it did not run; "" when it ran
    error_metrics plain, calibrated; // default parameters; ao^power
    double power = 1;                // fitted on the other scenes
    std::vector<double> pass_ms;     // median GPU time per pass
    double ms = std::numeric_limits<double>::quiet_NaN(); // their sum
    std::vector<float> ao;           // full resolution, as read back (upsampled)
    bool ran() const { return skipped.empty(); }
};

struct variant_record {
    aogen::variant v;
    std::string name;
    std::vector<std::string> passes;
    std::vector<uint32_t> instructions; // SPIR-V instructions per shader (after spirv-opt)
    uint32_t ao_instructions = 0;       // of the AO pass's shader (fragment: its fragment shader)
    std::vector<run_record> runs;       // one per scene, in settings order
    // Summaries over the scenes it ran on.
    double rmse = std::numeric_limits<double>::quiet_NaN(), rmse_calibrated = std::numeric_limits<double>::quiet_NaN();
    double ms = std::numeric_limits<double>::quiet_NaN();
    size_t non_finite = 0;
    bool pareto = false, pareto_calibrated = false;
};

// The scene-selected variant beside the same variant with every feature compiled in.
struct feature_saving {
    std::string selected, everything_on;
    uint32_t selected_instructions = 0, everything_on_instructions = 0; // AO pass
    double selected_ms = 0, everything_on_ms = 0;                       // median over the mesh-only scenes
    double selected_rmse = 0, everything_on_rmse = 0;                   // mean over the mesh-only scenes
    std::vector<std::string> left_out;                                  // what selection left out, and why
};

struct report_data {
    std::string device;
    int grid = 0, runs = 0, warmup = 0;
    std::vector<scene_record> scenes;
    std::vector<variant_record> variants;
    std::vector<feature_saving> savings;
};

namespace detail {

inline double median(std::vector<double> v)
{
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The compiled size of each of the variant's shaders, in chain order.
inline void count_instructions(variant_record& r)
{
    for (const aogen::codegen::shader_source& s : aogen::codegen::generate(r.v)) {
        const aogen::compile::compiled c = aogen::compile::compile(s.glsl, s.stage, s.name, {aogen::compile::target::spv});
        r.instructions.push_back(c.refl.spirv_instructions);
        if (s.pass == aogen::pass_kind::ao && s.stage != aogen::shader_stage::vertex) r.ao_instructions = c.refl.spirv_instructions;
        if (s.stage != aogen::shader_stage::vertex) r.passes.push_back(aogen::names::name_of(aogen::pass_kind_names, s.pass, "pass"));
    }
}

// A scene's G-buffers as the harness takes them, one per depth convention and normal
// space a variant asks for, ray-cast on first use.
class gbuffer_cache {
public:
    gbuffer_cache(const aogen::scenes::scene& s, const aogen::truth::scene& t) : scene_(s), tracer_(t) {}

    const aogen::vulkan::gbuffer& get(const aogen::variant& v)
    {
        const aogen::scenes::normal_space space =
            v.normals == aogen::normal_source::gbuffer_view ? aogen::scenes::normal_space::view : aogen::scenes::normal_space::world;
        const int key = int(v.depth) * 4 + int(space);
        auto it = cache_.find(key);
        if (it != cache_.end()) return it->second;
        aogen::scenes::gbuffer_options o;
        o.use_scene_normals = false;
        o.normals = space;
        const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(for_variant(scene_, v), tracer_, o);
        return cache_.emplace(key, aogen::scenes::to_gbuffer<aogen::vulkan::gbuffer>(g)).first->second;
    }

private:
    const aogen::scenes::scene& scene_;
    const aogen::truth::scene& tracer_;
    std::map<int, aogen::vulkan::gbuffer> cache_;
};

// Runs `c` on one scene: AO at full resolution, metrics with default parameters, times.
inline run_record run_on_scene(aogen::vulkan::chain& c, gbuffer_cache& gbuffers, const scene_record& s, const report_settings& settings)
{
    run_record r;
    r.skipped = cannot_run(c.var(), s.scene);
    if (!r.ran()) return r;
    const aogen::vulkan::gbuffer& g = gbuffers.get(c.var());
    const aogen::vulkan::chain_settings cs = default_settings(c.var(), s.scene);
    const aogen::vulkan::chain_result out = c.run(g, cs);
    const int factor = out.width == g.width ? 1 : 2;
    r.ao = upsample(out.ao, out.width, out.height, factor, g.width, g.height);
    r.plain = compare(r.ao, s.truth.ao, s.truth.valid);
    r.pass_ms = aogen::vulkan::median_pass_ms(c, g, cs, settings.runs, settings.warmup);
    if (!r.pass_ms.empty()) {
        r.ms = 0;
        for (double ms : r.pass_ms) r.ms += ms;
    }
    return r;
}

// The calibrated column of one variant: leave-one-out powers over the scenes it ran on.
inline void calibrate(variant_record& v, const std::vector<scene_record>& scenes)
{
    std::vector<calibration_scene> summaries;
    std::vector<size_t> index;
    for (size_t s = 0; s < scenes.size(); ++s)
        if (v.runs[s].ran()) {
            summaries.push_back(summarise(v.runs[s].ao, scenes[s].truth.ao, scenes[s].truth.valid));
            index.push_back(s);
        }
    const std::vector<double> powers = leave_one_out_powers(summaries);
    for (size_t k = 0; k < index.size(); ++k) {
        run_record& r = v.runs[index[k]];
        r.power = powers[k];
        r.calibrated = compare(apply_power(r.ao, r.power), scenes[index[k]].truth.ao, scenes[index[k]].truth.valid);
    }
}

inline void summarise(variant_record& v)
{
    double plain = 0, calibrated = 0;
    int count = 0;
    std::vector<double> times;
    for (const run_record& r : v.runs) {
        if (!r.ran()) continue;
        plain += r.plain.rmse, calibrated += r.calibrated.rmse, ++count;
        v.non_finite += r.plain.non_finite;
        if (std::isfinite(r.ms)) times.push_back(r.ms);
    }
    if (count > 0) v.rmse = plain / count, v.rmse_calibrated = calibrated / count;
    v.ms = median(times);
}

inline void mark_pareto(std::vector<variant_record>& variants)
{
    std::vector<double> ms, plain, calibrated;
    for (const variant_record& v : variants) ms.push_back(v.ms), plain.push_back(v.rmse), calibrated.push_back(v.rmse_calibrated);
    const std::vector<bool> p = pareto_optimal(ms, plain), pc = pareto_optimal(ms, calibrated);
    for (size_t i = 0; i < variants.size(); ++i) variants[i].pareto = p[i], variants[i].pareto_calibrated = pc[i];
}

// The feature saving of `selected` against `twin`, the same variant with every feature
// compiled in, over the scenes both ran on; none when they share no scene.
inline std::optional<feature_saving> compare_twin(const variant_record& selected, const variant_record& twin, const std::vector<scene_record>& scenes)
{
    feature_saving f;
    f.selected = selected.name, f.everything_on = twin.name;
    f.selected_instructions = selected.ao_instructions, f.everything_on_instructions = twin.ao_instructions;
    std::vector<double> ms_selected, ms_all;
    int count = 0;
    for (size_t s = 0; s < scenes.size(); ++s) {
        if (!twin.runs[s].ran() || !selected.runs[s].ran()) continue;
        ms_selected.push_back(selected.runs[s].ms), ms_all.push_back(twin.runs[s].ms);
        f.selected_rmse += selected.runs[s].plain.rmse, f.everything_on_rmse += twin.runs[s].plain.rmse, ++count;
    }
    if (count == 0) return std::nullopt;
    f.selected_ms = median(ms_selected), f.everything_on_ms = median(ms_all);
    f.selected_rmse /= count, f.everything_on_rmse /= count;
    aogen::scene_needs mesh_scene;
    mesh_scene.normals = selected.v.normals;
    for (const aogen::left_out_feature& l : aogen::features(selected.v, &mesh_scene).left_out) f.left_out.push_back(l.feature + ": " + l.why);
    return f;
}

} // namespace detail

// Scene `s` at the report's resolution, with its G-buffer and reference traced.
inline scene_record prepare_scene(aogen::scenes::scene s, const aogen::truth::scene& tracer, const report_settings& settings)
{
    if (settings.width > 0) s.camera.width = settings.width, s.camera.height = settings.height;
    scene_record r;
    r.scene = s;
    aogen::scenes::gbuffer_options world;
    world.use_scene_normals = false;
    world.normals = aogen::scenes::normal_space::world;
    const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(s, tracer, world);
    r.truth = trace_reference(tracer, g, s.ao_radius, settings.grid);
    double sum = 0;
    for (size_t i = 0; i < r.truth.ao.size(); ++i)
        if (r.truth.valid[i]) sum += r.truth.ao[i], ++r.valid_pixels;
    r.truth_mean = r.valid_pixels ? sum / double(r.valid_pixels) : 0;
    return r;
}

inline report_data run_report(const report_settings& settings)
{
    if (settings.scenes.empty()) aogen::fail("report", "no scenes", "valid: at least one scene");
    if (settings.variants.empty()) aogen::fail("report", "no variants", "valid: at least one variant");
    report_data out;
    out.grid = settings.grid, out.runs = settings.runs, out.warmup = settings.warmup;
    // First: a missing device fails before any tracing.
    auto ctx = std::make_unique<aogen::vulkan::context>(settings.device);
    out.device = ctx->device_name();
    bool graphics_ran = false;

    std::vector<std::unique_ptr<aogen::truth::scene>> tracers;
    for (size_t i = 0; i < settings.scenes.size(); ++i) {
        const aogen::scenes::scene& s = settings.scenes[i];
        settings.progress("[scene " + std::to_string(i + 1) + "/" + std::to_string(settings.scenes.size()) + "] " + s.name +
                          ": G-buffer and reference (" + std::to_string(settings.grid * settings.grid) + " rays per pixel)");
        tracers.push_back(std::make_unique<aogen::truth::scene>());
        s.build(*tracers.back());
        out.scenes.push_back(prepare_scene(s, *tracers.back(), settings));
    }
    std::vector<detail::gbuffer_cache> gbuffers;
    for (size_t i = 0; i < out.scenes.size(); ++i) gbuffers.emplace_back(out.scenes[i].scene, *tracers[i]);

    const auto run_variant = [&](const aogen::variant& v, bool mesh_only_scenes) {
        variant_record r;
        r.v = v;
        r.name = aogen::to_name(v);
        detail::count_instructions(r);
        // On lavapipe, compute timestamps taken after a graphics pipeline ran on the same
        // device come out ~100x too small, so a compute variant after a fragment one gets a
        // fresh device there. Only there: NVIDIA's driver refuses new instances after a few
        // dozen, and the first variants on a fresh device timed up to 3x fast on an H200.
        const bool fragment = v.stage == aogen::pipeline_stage::fragment;
        if (ctx->cpu() && graphics_ran && !fragment)
            ctx.reset(), ctx = std::make_unique<aogen::vulkan::context>(settings.device), graphics_ran = false;
        graphics_ran = graphics_ran || fragment;
        aogen::vulkan::chain c(*ctx, v);
        for (size_t s = 0; s < out.scenes.size(); ++s) {
            if (mesh_only_scenes && !out.scenes[s].mesh_only()) {
                r.runs.push_back({"not a mesh-only scene"});
                continue;
            }
            r.runs.push_back(detail::run_on_scene(c, gbuffers[s], out.scenes[s], settings));
        }
        detail::calibrate(r, out.scenes);
        detail::summarise(r);
        return r;
    };
    for (size_t i = 0; i < settings.variants.size(); ++i) {
        settings.progress("[variant " + std::to_string(i + 1) + "/" + std::to_string(settings.variants.size()) + "] " +
                          aogen::to_name(settings.variants[i]));
        out.variants.push_back(run_variant(settings.variants[i], false));
        // The twin right after its variant: both timed in the same state of the device.
        const variant_record& selected = out.variants.back();
        if (!settings.feature_saving || selected.v.tech != aogen::technique::ssao || selected.v.point_cloud_fallback) continue;
        aogen::variant all = selected.v;
        all.point_cloud_fallback = true;
        settings.progress("[feature saving] " + selected.name + " against " + aogen::to_name(all));
        const std::optional<feature_saving> f = detail::compare_twin(selected, run_variant(all, true), out.scenes);
        if (f) out.savings.push_back(*f);
    }
    detail::mark_pareto(out.variants);
    return out;
}

} // namespace aogen_report
