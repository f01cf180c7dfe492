// aogen_report/run.hpp — the report's measurements: every variant on every scene against
// the ray-traced ground truth, with its GPU time beside its fetch floor's.
//
// WHAT
//   run_report(settings) does, in order:
//     1. compile: every distinct shader of every variant — as shipped, in diagnostic form
//        (codegen::options::diagnostics) and its fetch floor (fetch_floor.hpp) — once, on
//        all cores (vulkan::spirv_cache), then one set of pipelines per variant for the
//        whole run, on one Vulkan device;
//     2. per scene, on its scene_bench (scene_bench.hpp, the harness the suite and the
//        tuner share):
//        a. the G-buffer (Embree ray cast) and the reference AO image (reference.hpp,
//           grid² rays per pixel, with its Monte-Carlo noise); the G-buffer uploaded once
//           per depth convention and normal space a variant asks for;
//        b. scoring: each variant that can run on the scene (settings.hpp) runs once in
//           its diagnostic form with its default parameters: the AO read back (the
//           diagnostic output is the shipped one), upsampled to full resolution and
//           compared with the reference (metrics.hpp); its raw values before the guard
//           counted (NaN, Inf, out of [0, 1], per pass);
//        c. timing: the shipped chains, their fetch floors and the point-cloud twins
//           bound at once and timed together (vulkan::time_chains): a warm-up of
//           continuous GPU work, then rounds in which every chain runs back to back,
//           interleaved — variant, floor, twin, next variant, ... — so every time in the
//           report was taken in the same state of the GPU's clock as every other;
//           nvidia-smi's SM clock sampled meanwhile (clocks.hpp); chains are bound in
//           groups whose outputs fit settings.bound_bytes;
//        d. the summaries of everything so far (below), handed to settings.scene_done —
//           the program writes results.json and report.md there, so an interrupted run
//           keeps every scene it finished;
//   Summaries: the calibrated column (calibrate.hpp: ao^p, p fitted on the other scenes);
//   per variant the mean RMSE over its scenes, the median of its per-scene median times,
//   p10 and p90, its floor and time / floor; Pareto-optimal variants by time against
//   default and calibrated RMSE; the feature saving: each SSAO variant without the
//   point-cloud fallback against its twin with it ("everything on") on the mesh-only
//   scenes — SPIR-V instructions, and the time ratio round by round.
//   Errors depend only on the inputs: the same settings give the same numbers; only the
//   times (and the clocks) vary from run to run.
//
// USAGE
//     aogen_report::report_settings s;
//     s.scenes = {...};  s.variants = aogen::default_matrix();
//     s.scene_done = [](const aogen_report::report_data& so_far) { ... };
//     aogen_report::report_data r = aogen_report::run_report(s);
#pragma once

#include "calibrate.hpp"
#include "clocks.hpp"
#include "fetch_floor.hpp"
#include "images.hpp"
#include "metrics.hpp"
#include "pareto.hpp"
#include "reference.hpp"
#include "scene_bench.hpp"
#include "settings.hpp"

#include <aogen/parallel.hpp>
#include <aogen/selection.hpp>
#include <aogen/vulkan/chain.hpp>
#include <aogen/vulkan/timing.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace aogen_report {

struct report_data;

struct report_settings {
    std::vector<aogen::scenes::scene> scenes;
    std::vector<aogen::variant> variants;
    int width = 0, height = 0;       // every scene's resolution; 0: each scene's own
    int grid = 64;                   // reference rays per pixel: grid × grid
    // Per scene: 3 rounds of up to 20 iterations of every chain, as many as fit ~1 s of GPU
    // work (a GPU runs 20, lavapipe 1), after a warm-up of at least 500 ms, until settled.
    aogen::vulkan::timing_options timing{3, 20, 500.0, 1000.0};
    bool fetch_floor = true;         // time each variant's fetch floor beside it
    bool feature_saving = true;      // run the point-cloud twins of SSAO variants
    size_t bound_bytes = size_t(2) << 30; // output images bound at once for timing, at most
    aogen::vulkan::device_options device;
    std::function<void(const std::string&)> progress = [](const std::string&) {};
    std::function<void(const report_data&)> scene_done = [](const report_data&) {};
};

// A distribution of SM clock readings (MHz) while timing.
struct clock_record {
    double min = std::numeric_limits<double>::quiet_NaN(), median = min, max = min;
    size_t samples = 0;
};

struct scene_record {
    aogen::scenes::scene scene;      // as run (resolution applied)
    reference truth;
    size_t valid_pixels = 0;
    double truth_mean = 0;           // mean reference AO over valid pixels
    clock_record clocks;             // SM clock while this scene was timed (nvidia-smi)
    double timed_gpu_ms = 0, timed_wall_ms = 0; // the timing rounds: timestamp span, host wall clock
    int iterations = 0;              // per round, as run (the budget's choice)
    bool settled = true;             // every warm-up ended with two agreeing submissions
    bool mesh_only() const { return !scene.renderer.point_cloud; }
};

// A variant's AO as read back: the R8 target's 8-bit values at the target's resolution
// (a quarter of the screen at half resolution), kept for calibration and the strips at a
// quarter of the memory of floats; full() is the full-resolution image they are scored at.
struct ao_readback {
    int width = 0, height = 0, factor = 1; // target size; full resolution = ×factor (clamped)
    std::vector<uint8_t> unorm;

    static ao_readback of(const aogen::vulkan::chain_result& r, int factor)
    {
        ao_readback a{r.width, r.height, factor, std::vector<uint8_t>(r.ao.size())};
        for (size_t i = 0; i < r.ao.size(); ++i) a.unorm[i] = uint8_t(std::lround(r.ao[i] * 255.0f)); // exact: r.ao[i] = k / 255
        return a;
    }
    // Nearest upsampling to the screen's W × H (images.hpp), as floats k / 255.
    std::vector<float> full(int W, int H) const
    {
        std::vector<float> ao(unorm.size());
        for (size_t i = 0; i < unorm.size(); ++i) ao[i] = unorm[i] / 255.0f;
        return upsample(ao, width, height, factor, W, H);
    }
};

// One variant on one scene.
struct run_record {
    std::string skipped;                          // why it did not run; "" when it ran
    error_metrics plain, calibrated;              // default parameters; ao^power
    double power = 1;                             // fitted on the other scenes
    calibration_scene summary;                    // of the default-parameter AO
    std::vector<aogen::vulkan::raw_counts> raw;   // per pass, before the guard; empty: not measured
    std::vector<aogen::vulkan::spread> pass_ms;   // per pass
    aogen::vulkan::spread ms;                     // the whole chain, per iteration
    aogen::vulkan::spread floor_ms;               // its fetch floor, timed in the same rounds
    std::vector<double> round_ms;                 // the chain's median of each timing round
    ao_readback ao;                               // as read back (default parameters)
    bool ran() const { return skipped.empty(); }
};

struct variant_record {
    aogen::variant v;
    std::string name;
    std::vector<std::string> passes;
    std::vector<uint32_t> instructions; // SPIR-V instructions per shader (after spirv-opt)
    uint32_t ao_instructions = 0;       // of the AO pass's shader (fragment: its fragment shader)
    std::vector<run_record> runs;       // one per scene so far, in settings order
    // Summaries over the scenes it ran on.
    double rmse = std::numeric_limits<double>::quiet_NaN(), rmse_calibrated = rmse;
    double ms = rmse, ms_p10 = rmse, ms_p90 = rmse; // medians over scenes of each scene's median, p10, p90
    double floor_ms = rmse, floor_ratio = rmse;     // median over scenes of the floor, and of time / floor
    aogen::vulkan::raw_counts raw;                  // summed over scenes and passes
    bool raw_measured = false;                      // a diagnostic build ran (fragment passes need fragment stores)
    bool pareto = false, pareto_calibrated = false;
};

// The scene-selected variant beside the same variant with every feature compiled in.
struct feature_saving {
    std::string selected, everything_on;
    uint32_t selected_instructions = 0, everything_on_instructions = 0; // AO pass
    double selected_ms = 0, everything_on_ms = 0;                       // median over the mesh-only scenes
    aogen::vulkan::spread ratio;                                        // selected / everything on, per scene and round
    double selected_rmse = 0, everything_on_rmse = 0;                   // mean over the mesh-only scenes
    std::vector<std::string> left_out;                                  // what selection left out, and why
};

// Wall-clock seconds of the report's phases.
struct phase_times {
    double compile = 0, trace = 0, score = 0, time = 0;
    size_t runs = 0; // variant × scene runs scored (twins included)
};

struct report_data {
    std::string device;
    int grid = 0;
    aogen::vulkan::timing_options timing;
    bool fetch_floor = true;
    double max_sm_mhz = 0;                 // nvidia-smi's clocks.max.sm; 0 when unknown
    clock_record clocks;                   // every SM clock reading while timing
    std::vector<scene_record> scenes;      // the scenes done so far
    std::vector<variant_record> variants;
    std::vector<variant_record> twins;     // the point-cloud twins of the feature saving
    std::vector<feature_saving> savings;
    phase_times phases;
};

namespace detail {

inline double median(std::vector<double> v)
{
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    return aogen::vulkan::spread_of(std::move(v)).median;
}

inline clock_record clocks_of(std::vector<double> mhz)
{
    clock_record c;
    c.samples = mhz.size();
    if (mhz.empty()) return c;
    std::sort(mhz.begin(), mhz.end());
    c.min = mhz.front(), c.max = mhz.back(), c.median = aogen::vulkan::spread_of(mhz).median;
    return c;
}

// Every shader a run needs of one variant, planned and generated once: as shipped (timed),
// in diagnostic form (scored) and its fetch floor (empty for twins and without floors).
struct generated_variant {
    aogen::codegen::plan shipped, diagnostic;
    std::vector<aogen::codegen::shader_source> shipped_sources, diagnostic_sources, floor_sources;
};

inline generated_variant generate_variant(const aogen::variant& v, bool floor)
{
    aogen::codegen::options d;
    d.diagnostics = true;
    generated_variant g{aogen::codegen::make_plan(v), aogen::codegen::make_plan(v, d), {}, {}, {}};
    g.shipped_sources = aogen::codegen::generate(g.shipped);
    g.diagnostic_sources = aogen::codegen::generate(g.diagnostic);
    if (floor) g.floor_sources = floor_sources(v);
    return g;
}

// Every source of `g`, for one compile_all.
inline void append_sources(const generated_variant& g, std::vector<aogen::codegen::shader_source>& out)
{
    for (const auto* list : {&g.shipped_sources, &g.diagnostic_sources, &g.floor_sources}) out.insert(out.end(), list->begin(), list->end());
}

// The compiled size of each of the variant's shaders, in chain order.
inline void count_instructions(variant_record& r, const generated_variant& g, aogen::vulkan::spirv_cache& cache)
{
    for (const aogen::codegen::shader_source& s : g.shipped_sources) {
        const uint32_t n = aogen::compile::count_instructions(cache.get(s), s.name);
        r.instructions.push_back(n);
        if (s.pass == aogen::pass_kind::ao && s.stage != aogen::shader_stage::vertex) r.ao_instructions = n;
        if (s.stage != aogen::shader_stage::vertex) r.passes.push_back(aogen::names::name_of(aogen::pass_kind_names, s.pass, "pass"));
    }
}

// One variant's pipelines for the whole run: as shipped (timed), in diagnostic form
// (scored; none where the device cannot store from fragment shaders) and its fetch floor.
struct compiled_variant {
    std::unique_ptr<aogen::vulkan::chain> shipped, diagnostic;
    std::unique_ptr<aogen::vulkan::pass_pipelines> floor; // null for twins and without floors
};

inline compiled_variant compile_variant(aogen::vulkan::context& ctx, const generated_variant& g, aogen::vulkan::spirv_cache& cache)
{
    compiled_variant c;
    c.shipped = std::make_unique<aogen::vulkan::chain>(ctx, g.shipped, g.shipped_sources, &cache);
    if (g.shipped.axes().stage == aogen::pipeline_stage::compute || ctx.fragment_stores())
        c.diagnostic = std::make_unique<aogen::vulkan::chain>(ctx, g.diagnostic, g.diagnostic_sources, &cache);
    if (!g.floor_sources.empty()) {
        const aogen::variant f = floor_variant(g.shipped.axes());
        c.floor = std::make_unique<aogen::vulkan::pass_pipelines>(ctx, "the fetch floor of " + g.shipped.name(), f.stage, f.workgroup_x,
                                                                  f.workgroup_y, g.floor_sources, &cache);
    }
    return c;
}

// What a record needs of its scene to run, or why it cannot.
inline std::string why_not(const variant_record& r, const scene_record& s, bool twin)
{
    if (twin && !s.mesh_only()) return "not a mesh-only scene";
    return cannot_run(r.v, s.scene);
}

// Scores `c` on one scene: runs its diagnostic build once (the shipped one where there is
// none), reads the AO back, counts raw values; metrics follow in finish_scoring().
inline run_record score(const compiled_variant& c, scene_bench& bench)
{
    run_record r;
    const aogen::vulkan::chain& chain = c.diagnostic ? *c.diagnostic : *c.shipped;
    const bench_run out = bench.run(chain, default_settings(chain.var(), bench.scene()));
    r.raw = out.out.raw;
    r.ao = ao_readback::of(out.out, out.scale);
    return r;
}

// The metrics of a scored run (on a worker thread: compare and summarise are the slow part).
inline void finish_scoring(run_record& r, const scene_record& s)
{
    const std::vector<float> ao = r.ao.full(s.truth.width, s.truth.height);
    r.plain = compare(ao, s.truth.ao, s.truth.valid);
    r.summary = summarise(ao, s.truth.ao, s.truth.valid);
}

// One chain to time: which record and scene it belongs to, and whether it is the floor.
struct timed_chain {
    run_record* run = nullptr;
    bool floor = false;
    std::unique_ptr<aogen::vulkan::bound_chain> bound;
};

inline size_t output_bytes(const aogen::vulkan::bound_chain& b) { return b.passes().size() * size_t(b.width()) * b.height(); }

// Times `chains` together (interleaved) and stores each one's times in its run record;
// the rounds' timestamp span and wall clock are added to the scene's, and the SM clocks
// read during the rounds (not the warm-up) to `mhz`.
inline void time_group(aogen::vulkan::context& ctx, std::vector<timed_chain>& chains, const aogen::vulkan::timing_options& o, scene_record& scene,
                       clock_monitor& clocks, std::vector<double>& mhz)
{
    std::vector<const aogen::vulkan::bound_chain*> bound;
    for (const timed_chain& c : chains) bound.push_back(c.bound.get());
    clocks.start();
    const aogen::vulkan::timing_result t = aogen::vulkan::time_chains(ctx, bound, o);
    clocks.stop();
    for (double m : clocks.between(t.rounds_begin, t.rounds_end)) mhz.push_back(m);
    scene.settled = scene.settled && t.settled;
    if (t.chains.empty()) return; // no timestamps
    scene.timed_gpu_ms += t.rounds_gpu_ms, scene.timed_wall_ms += t.rounds_wall_ms;
    scene.iterations = scene.iterations == 0 ? t.iterations : std::min(scene.iterations, t.iterations);
    for (size_t i = 0; i < chains.size(); ++i) {
        run_record& r = *chains[i].run;
        if (chains[i].floor) {
            r.floor_ms = t.chains[i].total;
            continue;
        }
        r.ms = t.chains[i].total;
        r.pass_ms = t.chains[i].passes;
        r.round_ms = t.chains[i].round_ms;
    }
}

// The calibrated column of one variant: leave-one-out powers over the scenes it ran on.
inline void calibrate(variant_record& v, const std::vector<scene_record>& scenes)
{
    std::vector<calibration_scene> summaries;
    std::vector<size_t> index;
    for (size_t s = 0; s < v.runs.size(); ++s)
        if (v.runs[s].ran()) summaries.push_back(v.runs[s].summary), index.push_back(s);
    const std::vector<double> powers = leave_one_out_powers(summaries);
    for (size_t k = 0; k < index.size(); ++k) {
        run_record& r = v.runs[index[k]];
        r.power = powers[k];
        const reference& truth = scenes[index[k]].truth;
        r.calibrated = compare(apply_power(r.ao.full(truth.width, truth.height), r.power), truth.ao, truth.valid);
    }
}

inline void summarise(variant_record& v)
{
    double plain = 0, calibrated = 0;
    int count = 0;
    std::vector<double> ms, p10, p90, floors, ratios;
    v.raw = {};
    v.raw_measured = false;
    for (const run_record& r : v.runs) {
        if (!r.ran()) continue;
        plain += r.plain.rmse, calibrated += r.calibrated.rmse, ++count;
        for (const aogen::vulkan::raw_counts& c : r.raw) v.raw += c;
        v.raw_measured = v.raw_measured || !r.raw.empty();
        ms.push_back(r.ms.median), p10.push_back(r.ms.p10), p90.push_back(r.ms.p90);
        floors.push_back(r.floor_ms.median), ratios.push_back(r.ms.median / r.floor_ms.median);
    }
    if (count > 0) v.rmse = plain / count, v.rmse_calibrated = calibrated / count;
    v.ms = median(ms), v.ms_p10 = median(p10), v.ms_p90 = median(p90);
    v.floor_ms = median(floors), v.floor_ratio = median(ratios);
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
inline std::optional<feature_saving> compare_twin(const variant_record& selected, const variant_record& twin, size_t scene_count)
{
    feature_saving f;
    f.selected = selected.name, f.everything_on = twin.name;
    f.selected_instructions = selected.ao_instructions, f.everything_on_instructions = twin.ao_instructions;
    std::vector<double> ms_selected, ms_all, ratios;
    int count = 0;
    for (size_t s = 0; s < scene_count; ++s) {
        const run_record &a = selected.runs[s], &b = twin.runs[s];
        if (!a.ran() || !b.ran()) continue;
        ms_selected.push_back(a.ms.median), ms_all.push_back(b.ms.median);
        // Round by round: both were timed in the same rounds, interleaved.
        for (size_t k = 0; k < std::min(a.round_ms.size(), b.round_ms.size()); ++k) ratios.push_back(a.round_ms[k] / b.round_ms[k]);
        f.selected_rmse += a.plain.rmse, f.everything_on_rmse += b.plain.rmse, ++count;
    }
    if (count == 0) return std::nullopt;
    f.selected_ms = median(ms_selected), f.everything_on_ms = median(ms_all);
    f.ratio = aogen::vulkan::spread_of(ratios);
    f.selected_rmse /= count, f.everything_on_rmse /= count;
    aogen::scene_needs mesh_scene;
    mesh_scene.normals = selected.v.normals;
    for (const aogen::left_out_feature& l : aogen::features(selected.v, &mesh_scene).left_out) f.left_out.push_back(l.feature + ": " + l.why);
    return f;
}

// The summaries of everything measured so far (calibration, medians, Pareto, savings).
inline void summarise_all(report_data& out, const std::vector<int>& twin_of)
{
    aogen::parallel_for(out.variants.size() + out.twins.size(), [&](size_t i) {
        variant_record& v = i < out.variants.size() ? out.variants[i] : out.twins[i - out.variants.size()];
        calibrate(v, out.scenes);
        summarise(v);
    });
    mark_pareto(out.variants);
    out.savings.clear();
    for (size_t t = 0; t < out.twins.size(); ++t) {
        const std::optional<feature_saving> f = compare_twin(out.variants[size_t(twin_of[t])], out.twins[t], out.scenes.size());
        if (f) out.savings.push_back(*f);
    }
}

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace detail

// Scene `s` at the report's resolution.
inline aogen::scenes::scene sized(aogen::scenes::scene s, const report_settings& settings)
{
    if (settings.width > 0) s.camera.width = settings.width, s.camera.height = settings.height;
    return s;
}

// What the report keeps of a scene on the bench: the scene as run and its reference.
inline scene_record record_of(const scene_bench& bench)
{
    scene_record r;
    r.scene = bench.scene();
    r.truth = bench.truth();
    double sum = 0;
    for (size_t i = 0; i < r.truth.ao.size(); ++i)
        if (r.truth.valid[i]) sum += r.truth.ao[i], ++r.valid_pixels;
    r.truth_mean = r.valid_pixels ? sum / double(r.valid_pixels) : 0;
    return r;
}

inline report_data run_report(const report_settings& settings)
{
    using clock = std::chrono::steady_clock;
    if (settings.scenes.empty()) aogen::fail("report", "no scenes", "valid: at least one scene");
    if (settings.variants.empty()) aogen::fail("report", "no variants", "valid: at least one variant");
    report_data out;
    out.grid = settings.grid, out.timing = settings.timing, out.fetch_floor = settings.fetch_floor;
    // Every scene can be scored, checked before anything is compiled or traced: its radius
    // makes valid settings and its camera sees some of its geometry (an error over no
    // pixel is not a score).
    for (aogen::scenes::scene s : settings.scenes) {
        require_radius_works(s);
        if (settings.width > 0) s.camera.width = settings.width, s.camera.height = settings.height;
        aogen::scenes::require_scoreable(s, *aogen::scenes::make_tracer(s));
    }
    // Then: a missing device fails before any compiling or tracing.
    aogen::vulkan::context ctx(settings.device);
    out.device = ctx.device_name();
    clock_monitor clocks(ctx.cpu() ? "" : ctx.device_name());
    out.max_sm_mhz = clocks.max_mhz();

    // The records: the variants, then the point-cloud twins of the SSAO ones without it.
    std::vector<int> twin_of; // per twin, the index of its selected variant
    for (const aogen::variant& v : settings.variants) out.variants.push_back({v, aogen::to_name(v)});
    if (settings.feature_saving)
        for (size_t i = 0; i < out.variants.size(); ++i) {
            const aogen::variant& v = out.variants[i].v;
            if (v.tech != aogen::technique::ssao || v.point_cloud_fallback) continue;
            aogen::variant all = v;
            all.point_cloud_fallback = true;
            out.twins.push_back({all, aogen::to_name(all)});
            twin_of.push_back(int(i));
        }

    const auto compile_start = clock::now();
    settings.progress("compiling " + std::to_string(out.variants.size() + out.twins.size()) + " variants (as shipped, for diagnostics" +
                      (settings.fetch_floor ? ", fetch floors" : "") + ")");
    std::vector<detail::generated_variant> generated, generated_twins;
    for (const variant_record& r : out.variants) generated.push_back(detail::generate_variant(r.v, settings.fetch_floor));
    for (const variant_record& r : out.twins) generated_twins.push_back(detail::generate_variant(r.v, false));
    aogen::vulkan::spirv_cache cache;
    std::vector<aogen::codegen::shader_source> sources;
    for (const auto* list : {&generated, &generated_twins})
        for (const detail::generated_variant& g : *list) detail::append_sources(g, sources);
    cache.compile_all(sources);
    std::vector<detail::compiled_variant> compiled, compiled_twins;
    for (size_t i = 0; i < out.variants.size(); ++i) {
        detail::count_instructions(out.variants[i], generated[i], cache);
        compiled.push_back(detail::compile_variant(ctx, generated[i], cache));
    }
    for (size_t i = 0; i < out.twins.size(); ++i) {
        detail::count_instructions(out.twins[i], generated_twins[i], cache);
        compiled_twins.push_back(detail::compile_variant(ctx, generated_twins[i], cache));
    }
    out.phases.compile = detail::seconds_since(compile_start);

    std::vector<double> all_clocks;
    for (size_t si = 0; si < settings.scenes.size(); ++si) {
        const std::string tag = "[scene " + std::to_string(si + 1) + "/" + std::to_string(settings.scenes.size()) + "] " + settings.scenes[si].name;
        settings.progress(tag + ": G-buffer and reference (" + std::to_string(settings.grid * settings.grid) + " rays per pixel)");
        const auto trace_start = clock::now();
        scene_bench bench(ctx, sized(settings.scenes[si], settings), settings.grid);
        out.scenes.push_back(record_of(bench));
        if (const size_t left_out = out.scenes.back().truth.untrusted)
            settings.progress(tag + ": " + std::to_string(left_out) + " pixels left out of the score: their geometry lies too far from the camera, and spans too much, " +
                              "for a reference at ao_radius " + aogen::format_number(settings.scenes[si].ao_radius) + " (rays that short are placed reliably within " +
                              aogen::format_number(aogen::truth::reliable_extent(settings.scenes[si].ao_radius)) + " of a tracer's origin)");
        const scene_record& scene = out.scenes.back();
        out.phases.trace += detail::seconds_since(trace_start);

        // Scoring: every record that can run, once, in its diagnostic build.
        const auto score_start = clock::now();
        settings.progress(tag + ": scoring " + std::to_string(out.variants.size() + out.twins.size()) + " variants");
        std::vector<std::pair<variant_record*, const detail::compiled_variant*>> records;
        for (size_t i = 0; i < out.variants.size(); ++i) records.push_back({&out.variants[i], &compiled[i]});
        for (size_t i = 0; i < out.twins.size(); ++i) records.push_back({&out.twins[i], &compiled_twins[i]});
        std::vector<run_record*> scored;
        for (size_t k = 0; k < records.size(); ++k) {
            variant_record& r = *records[k].first;
            const std::string skipped = detail::why_not(r, scene, k >= out.variants.size());
            r.runs.push_back(skipped.empty() ? detail::score(*records[k].second, bench) : run_record{skipped});
            if (skipped.empty()) scored.push_back(&r.runs.back()), ++out.phases.runs;
        }
        aogen::parallel_for(scored.size(), [&](size_t k) { detail::finish_scoring(*scored[k], scene); });
        out.phases.score += detail::seconds_since(score_start);

        // Timing: shipped chains, floors and twins bound in groups, each group interleaved.
        const auto time_start = clock::now();
        settings.progress(tag + ": timing (" + std::to_string(settings.timing.rounds) + " rounds of up to " + std::to_string(settings.timing.iterations) +
                          " iterations per chain, " + aogen::format_number(settings.timing.warmup_ms) + " ms warm-up)");
        std::vector<double> scene_clocks;
        std::vector<detail::timed_chain> group;
        size_t group_bytes = 0;
        const auto flush = [&] {
            if (group.empty()) return;
            detail::time_group(ctx, group, settings.timing, out.scenes.back(), clocks, scene_clocks);
            group.clear(), group_bytes = 0;
        };
        const auto add = [&](run_record& run, bool floor, const aogen::vulkan::pass_pipelines& passes, const aogen::variant& v) {
            const aogen::vulkan::gpu_gbuffer& g = bench.gpu(v);
            const auto [tw, th] = aogen::vulkan::target_size(v, bench.width(), bench.height());
            auto bound = std::make_unique<aogen::vulkan::bound_chain>(
                ctx, passes, g, aogen::vulkan::inputs_for(v, default_settings(v, scene.scene), tw, th), tw, th);
            group_bytes += detail::output_bytes(*bound);
            group.push_back({&run, floor, std::move(bound)});
        };
        for (size_t i = 0; i < out.variants.size(); ++i) {
            run_record& run = out.variants[i].runs.back();
            if (!run.ran()) continue;
            if (group_bytes > settings.bound_bytes) flush();
            add(run, false, compiled[i].shipped->passes(), out.variants[i].v);
            if (compiled[i].floor) add(run, true, *compiled[i].floor, out.variants[i].v);
            for (size_t t = 0; t < out.twins.size(); ++t) // the twin right after its variant
                if (twin_of[t] == int(i) && out.twins[t].runs.back().ran()) add(out.twins[t].runs.back(), false, compiled_twins[t].shipped->passes(), out.twins[t].v);
        }
        flush();
        out.scenes.back().clocks = detail::clocks_of(scene_clocks);
        all_clocks.insert(all_clocks.end(), scene_clocks.begin(), scene_clocks.end());
        out.clocks = detail::clocks_of(all_clocks);
        out.phases.time += detail::seconds_since(time_start);

        detail::summarise_all(out, twin_of);
        settings.scene_done(out);
    }
    return out;
}

} // namespace aogen_report
