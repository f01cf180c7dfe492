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
//           counted (NaN, Inf, out of [0, 1], per pass). Then frames 1..frames-1 of the
//           shipped chain (temporal.hpp's frame index turning the noise and moving the slice
//           techniques' inner steps), and the plain
//           mean of all the frames compared with the reference: the AO a static camera
//           shows after an accumulation of that many frames;
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
//   The records it fills are records.hpp's; the summaries summary.hpp's: the calibrated
//   column, per-variant means and medians, Pareto marks, and the feature saving (each SSAO
//   variant without the point-cloud fallback against its twin with it, "everything on", on
//   the mesh-only scenes — SPIR-V instructions, and the time ratio round by round).
//   Errors depend only on the inputs: the same settings give the same numbers; only the
//   times (and the clocks) vary from run to run.
//
// USAGE
//     aogen_report::report_settings s;
//     s.scenes = {...};  s.variants = aogen::default_matrix();
//     s.scene_done = [](const aogen_report::report_data& so_far) { ... };
//     aogen_report::report_data r = aogen_report::run_report(s);
#pragma once

#include "clocks.hpp"
#include "fetch_floor.hpp"
#include "records.hpp"
#include "motion.hpp"
#include "scene_bench.hpp"
#include "settings.hpp"
#include "summary.hpp"

#include <aogen/loops.hpp>
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

// The timing protocol on a CPU device (Mesa's lavapipe), unless one is asked for: one round
// of one iteration of every chain (interleaved with its floors, as on a GPU), no warm-up.
// The GPU protocol's warm-up exists because a GPU idles at a fraction of its working clock
// (timing.hpp: 4.6× slow on an H200) and its 20 back-to-back iterations because one
// iteration there is microseconds; a CPU device has no idle clock to bring up, its
// timestamps are the CPU's own time running each chain, and one iteration of every chain
// takes seconds: one interleaved sample per chain and scene, the report's figure its median
// over the scenes. The GPU protocol cost lavapipe 300 of the default report's 881 s
// (issue 49; BENCHMARKS.md).
inline constexpr aogen::vulkan::timing_options cpu_timing{1, 1, 0.0, 0.0};

struct report_settings {
    std::vector<aogen::scenes::scene> scenes;
    std::vector<aogen::variant> variants;
    int width = 0, height = 0;       // every scene's resolution; 0: each scene's own
    int grid = 32;                   // reference rays per pixel: grid × grid (aogen_report's --rays: why 32)
    // Frames averaged for the "after N frames" error (a static camera, a plain mean standing
    // in for TAA's history): frame 0 is the single-frame output.
    static constexpr aogen::int_range frames_range{1, 1024};
    int frames = 8;
    // Per scene on a GPU: 3 rounds of up to 20 iterations of every chain, as many as fit ~1 s
    // of GPU work, after a warm-up of at least 500 ms, until settled. On a CPU device
    // (lavapipe) cpu_timing above, unless timing_given.
    aogen::vulkan::timing_options timing{3, 20, 500.0, 1000.0};
    bool timing_given = false;       // `timing` was asked for (--rounds, ...): kept on a CPU device too
    bool fetch_floor = true;         // time each variant's fetch floor beside it
    bool feature_saving = true;      // run the point-cloud twins of SSAO variants
    size_t bound_bytes = size_t(2) << 30; // output images bound at once for timing, at most
    // The report in motion (motion.hpp): these variants along every scene that has a path;
    // none: not run.
    std::vector<aogen::variant> motion_variants = default_motion_variants();
    std::vector<aogen::scenes::scene> motion_scenes; // scenes with a camera path (arguments.hpp's load_motion_scenes)
    motion_options motion;
    aogen::history_params history;   // the history pass's settings, still and in motion (--history)
    aogen::vulkan::device_options device;
    std::function<void(const std::string&)> progress = [](const std::string&) {};
    std::function<void(const report_data&)> scene_done = [](const report_data&) {};
};

namespace detail {

inline clock_record clocks_of(std::vector<double> mhz)
{
    clock_record c;
    c.samples = mhz.size();
    if (mhz.empty()) return c;
    std::sort(mhz.begin(), mhz.end());
    c.min = mhz.front(), c.max = mhz.back(), c.median = aogen::vulkan::spread_of(mhz).median;
    return c;
}

// Every shader a run needs of one variant, planned once and generated once: as shipped
// (timed), in diagnostic form (scored: the same plan with options::diagnostics) and its two
// floors (none for twins and without floors).
struct generated_variant {
    aogen::codegen::plan shipped, diagnostic;
    std::vector<aogen::codegen::shader_source> shipped_sources, diagnostic_sources;
    std::vector<floor_shaders> floors; // the fetch floor, then the bandwidth floor; or none
};

inline generated_variant generate_variant(const aogen::variant& v, bool floor)
{
    aogen::codegen::options d;
    d.diagnostics = true;
    const aogen::codegen::plan shipped = aogen::codegen::make_plan(v);
    generated_variant g{shipped, shipped.with_options(d), {}, {}, {}};
    g.shipped_sources = aogen::codegen::generate(g.shipped);
    g.diagnostic_sources = aogen::codegen::generate(g.diagnostic);
    if (floor) {
        const aogen::codegen::plan base = floor_base(shipped);
        g.floors = {floor_of(shipped, base, floor_kind::fetch), floor_of(shipped, base, floor_kind::bandwidth)};
    }
    return g;
}

// Every source of `g`, for one compile_all.
inline void append_sources(const generated_variant& g, std::vector<aogen::codegen::shader_source>& out)
{
    for (const auto* list : {&g.shipped_sources, &g.diagnostic_sources}) out.insert(out.end(), list->begin(), list->end());
    for (const floor_shaders& f : g.floors) out.insert(out.end(), f.sources.begin(), f.sources.end());
}

// The static instructions per tap of `v`'s AO pass (`spirv`): its tap loop's instructions
// (aogen/loops.hpp's THE COUNT) over the taps one iteration reads; 0 where no loop is left.
inline double tap_instructions(const aogen::variant& v, const std::vector<uint32_t>& spirv, const std::string& name)
{
    const std::optional<aogen::compile::loop> tap = aogen::compile::tap_loop_of(spirv, name);
    return tap ? double(tap->instructions) / aogen::technique_of(v.tech).taps_per_iteration : 0.0;
}

// The compiled size of each of the variant's shaders, in chain order, and its AO pass's per tap.
inline void count_instructions(variant_record& r, const generated_variant& g, aogen::vulkan::spirv_cache& cache)
{
    for (const aogen::codegen::shader_source& s : g.shipped_sources) {
        const uint32_t n = aogen::compile::count_instructions(cache.get(s), s.name);
        r.instructions.push_back(n);
        if (s.pass == aogen::pass_kind::ao && s.stage != aogen::shader_stage::vertex) {
            r.ao_instructions = n;
            r.ao_tap_instructions = tap_instructions(g.shipped.variant(), cache.get(s), s.name);
        }
        if (s.stage != aogen::shader_stage::vertex) r.passes.push_back(aogen::names::name_of(aogen::pass_kind_names, s.pass, "pass"));
    }
}

// One variant's pipelines for the whole run: as shipped (timed), in diagnostic form
// (scored; none where the device cannot store from fragment shaders) and its two floors.
struct compiled_variant {
    std::unique_ptr<aogen::vulkan::chain> shipped, diagnostic;
    std::unique_ptr<aogen::vulkan::pass_pipelines> floor, bandwidth; // null for twins and without floors
};

inline compiled_variant compile_variant(aogen::vulkan::context& ctx, const generated_variant& g, aogen::vulkan::spirv_cache& cache)
{
    compiled_variant c;
    c.shipped = std::make_unique<aogen::vulkan::chain>(ctx, g.shipped, &cache); // SPIR-V from the cache: compiled already
    if (g.shipped.variant().stage == aogen::pipeline_stage::compute || ctx.fragment_stores())
        c.diagnostic = std::make_unique<aogen::vulkan::chain>(ctx, g.diagnostic, &cache);
    const auto floor = [&](const char* what, const floor_shaders& f) {
        return std::make_unique<aogen::vulkan::pass_pipelines>(ctx, f.plan, f.sources, &cache, std::string(what) + g.shipped.name());
    };
    if (!g.floors.empty()) c.floor = floor("the fetch floor of ", g.floors[0]), c.bandwidth = floor("the bandwidth floor of ", g.floors[1]);
    return c;
}

// What a record needs of its scene to run, or why it cannot.
inline std::string why_not(const variant_record& r, const scene_record& s, bool twin)
{
    if (twin && !s.mesh_only()) return "not a mesh-only scene";
    return cannot_run(r.v, s.scene);
}

// Scores `c` on one scene: runs its diagnostic build once (the shipped one where there is
// none), reads the AO back, counts raw values; then runs the shipped chain at frames
// 1..frames-1 and scores the mean of all `frames` frames against the truth -- or, for a chain
// with a history pass, which accumulates the frames itself, its own output after frames
// 0..frames-1 on one binding. The single-frame metrics follow in finish_scoring().
inline run_record score(const compiled_variant& c, scene_bench& bench, int frames, const aogen::history_params& history)
{
    run_record r;
    const aogen::vulkan::chain& chain = c.diagnostic ? *c.diagnostic : *c.shipped;
    aogen::vulkan::chain_settings settings = default_settings(chain.plan().variant(), bench.scene());
    settings.history = history;
    const bench_run out = bench.run(chain, settings);
    r.raw = out.out.raw;
    r.ao = ao_readback::of(out.out, out.scale);
    if (!out.full_bent_normal.empty()) {
        r.bent = compare_bent_normals(out.full_bent_normal, bench.truth().bent_normal, bench.truth().valid);
        r.bent_normal_rgb = normal_bytes(out.full_bent_normal);
    }
    if (aogen::has_history_pass(chain.plan().variant())) {
        r.accumulated = compare(bench.last_frame(*c.shipped, settings, uint32_t(frames)), bench.truth().ao, bench.truth().valid);
        return r;
    }
    std::vector<double> sum(out.full.begin(), out.full.end());
    if (frames > 1) bench.add_frames(*c.shipped, settings, 1, uint32_t(frames - 1), sum); // bound once, frame after frame
    std::vector<float> mean(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) mean[i] = float(sum[i] / frames);
    r.accumulated = compare(mean, bench.truth().ao, bench.truth().valid);
    return r;
}

// The metrics of a scored run (on a worker thread: compare and summarise are the slow part).
inline void finish_scoring(run_record& r, const scene_record& s)
{
    const std::vector<float> ao = r.ao.full(s.truth.width, s.truth.height);
    r.plain = compare(ao, s.truth.ao, s.truth.valid);
    r.summary = summarise(ao, s.truth.ao, s.truth.valid);
}

// One chain to time: which record and scene it belongs to, and whether it is the variant
// itself or one of its floors.
enum class timed_as { variant, fetch_floor, bandwidth_floor };
struct timed_chain {
    run_record* run = nullptr;
    timed_as what = timed_as::variant;
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
        if (chains[i].what == timed_as::fetch_floor) {
            r.floor_ms = t.chains[i].total;
            continue;
        }
        if (chains[i].what == timed_as::bandwidth_floor) {
            r.bandwidth_ms = t.chains[i].total;
            continue;
        }
        r.ms = t.chains[i].total;
        r.pass_ms = t.chains[i].passes;
        r.round_ms = t.chains[i].round_ms;
    }
}

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Every scene can be scored, checked before anything is compiled or traced: its radius
// makes valid settings and its camera sees some of its geometry (an error over no pixel is
// not a score).
inline void require_scoreable(const report_settings& settings)
{
    aogen::require_in("--frames", settings.frames, report_settings::frames_range);
    if (settings.scenes.empty()) aogen::fail("report", "no scenes", "valid: at least one scene");
    if (settings.variants.empty()) aogen::fail("report", "no variants", "valid: at least one variant");
    for (aogen::scenes::scene s : settings.scenes) {
        require_radius_works(s);
        if (settings.width > 0) s.camera.width = settings.width, s.camera.height = settings.height;
        aogen::scenes::require_scoreable(s, *aogen::scenes::make_tracer(s));
    }
}

// The records: the variants, then the point-cloud twins of the SSAO ones without it;
// returns, per twin, the index of its selected variant.
inline std::vector<int> add_records(const report_settings& settings, report_data& out)
{
    std::vector<int> twin_of;
    for (const aogen::variant& v : settings.variants) out.variants.push_back({v, aogen::to_name(v)});
    if (!settings.feature_saving) return twin_of;
    for (size_t i = 0; i < out.variants.size(); ++i) {
        const aogen::variant& v = out.variants[i].v;
        if (v.tech != aogen::technique::ssao || v.point_cloud_fallback) continue;
        aogen::variant all = v;
        all.point_cloud_fallback = true;
        out.twins.push_back({all, aogen::to_name(all)});
        twin_of.push_back(int(i));
    }
    return twin_of;
}

// Every record's pipelines for the whole run, in record order.
struct compiled_records {
    std::vector<compiled_variant> variants, twins;
};

// Generates every record's shaders once, compiles them all at once on every core, counts
// their instructions into the records and builds their pipelines.
inline compiled_records compile_records(aogen::vulkan::context& ctx, report_data& out, bool fetch_floor)
{
    std::vector<generated_variant> generated, generated_twins;
    for (const variant_record& r : out.variants) generated.push_back(generate_variant(r.v, fetch_floor));
    for (const variant_record& r : out.twins) generated_twins.push_back(generate_variant(r.v, false));
    aogen::vulkan::spirv_cache cache;
    std::vector<aogen::codegen::shader_source> sources;
    for (const auto* list : {&generated, &generated_twins})
        for (const generated_variant& g : *list) append_sources(g, sources);
    cache.compile_all(sources);
    compiled_records c;
    for (size_t i = 0; i < out.variants.size(); ++i) {
        count_instructions(out.variants[i], generated[i], cache);
        c.variants.push_back(compile_variant(ctx, generated[i], cache));
    }
    for (size_t i = 0; i < out.twins.size(); ++i) {
        count_instructions(out.twins[i], generated_twins[i], cache);
        c.twins.push_back(compile_variant(ctx, generated_twins[i], cache));
    }
    return c;
}

// Scoring: every record that can run on the bench's scene, once, in its diagnostic build;
// each record gets a run for the scene (a skipped one saying why). Returns the runs scored.
inline size_t score_scene(scene_bench& bench, report_data& out, const compiled_records& c, int frames, const aogen::history_params& history)
{
    const scene_record& scene = out.scenes.back();
    std::vector<run_record*> scored;
    const auto score_record = [&](variant_record& r, const compiled_variant& compiled, bool twin) {
        const std::string skipped = why_not(r, scene, twin);
        // A twin is there for its time and single-frame error (the feature saving): one frame.
        r.runs.push_back(skipped.empty() ? score(compiled, bench, twin ? 1 : frames, history) : run_record{skipped});
        if (skipped.empty()) scored.push_back(&r.runs.back());
    };
    for (size_t i = 0; i < out.variants.size(); ++i) score_record(out.variants[i], c.variants[i], false);
    for (size_t i = 0; i < out.twins.size(); ++i) score_record(out.twins[i], c.twins[i], true);
    aogen::parallel_for(scored.size(), [&](size_t k) { finish_scoring(*scored[k], scene); });
    return scored.size();
}

// Timing: the shipped chains, their floors and twins, bound in groups whose outputs fit
// `settings.bound_bytes`, each group interleaved; the scene's runs get their times, the
// scene its clocks (also appended to `all_clocks`).
inline void time_scene(aogen::vulkan::context& ctx, const report_settings& settings, scene_bench& bench, report_data& out,
                       const compiled_records& c, const std::vector<int>& twin_of, clock_monitor& clocks, std::vector<double>& all_clocks)
{
    scene_record& scene = out.scenes.back();
    std::vector<double> scene_clocks;
    std::vector<timed_chain> group;
    size_t group_bytes = 0;
    const auto flush = [&] {
        if (group.empty()) return;
        time_group(ctx, group, out.timing, scene, clocks, scene_clocks);
        group.clear(), group_bytes = 0;
    };
    // A floor binds the bytes of its variant's plan (the same blocks: floor_of).
    const auto add = [&](run_record& run, timed_as what, const aogen::vulkan::pass_pipelines& passes, const aogen::codegen::plan& p) {
        const aogen::variant& v = p.variant();
        const aogen::vulkan::gpu_gbuffer& g = bench.gpu(v);
        auto bound = std::make_unique<aogen::vulkan::bound_chain>(ctx, passes, g, p.inputs(default_settings(v, scene.scene), g.width(), g.height()));
        group_bytes += output_bytes(*bound);
        group.push_back({&run, what, std::move(bound)});
    };
    for (size_t i = 0; i < out.variants.size(); ++i) {
        run_record& run = out.variants[i].runs.back();
        if (!run.ran()) continue;
        if (group_bytes > settings.bound_bytes) flush();
        const aogen::codegen::plan& p = c.variants[i].shipped->plan();
        add(run, timed_as::variant, c.variants[i].shipped->passes(), p);
        if (c.variants[i].floor) add(run, timed_as::fetch_floor, *c.variants[i].floor, p);
        if (c.variants[i].bandwidth) add(run, timed_as::bandwidth_floor, *c.variants[i].bandwidth, p);
        for (size_t t = 0; t < out.twins.size(); ++t) // the twin right after its variant
            if (twin_of[t] == int(i) && out.twins[t].runs.back().ran()) add(out.twins[t].runs.back(), timed_as::variant, c.twins[t].shipped->passes(), c.twins[t].shipped->plan());
    }
    flush();
    scene.clocks = clocks_of(scene_clocks);
    all_clocks.insert(all_clocks.end(), scene_clocks.begin(), scene_clocks.end());
    out.clocks = clocks_of(all_clocks);
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

namespace detail {

// The report in motion: every motion variant along every scene with a path, at the report's
// resolution; a variant a scene's renderer cannot run is left out of that scene.
inline void run_motion(aogen::vulkan::context& ctx, const report_settings& settings, report_data& out, const compiled_records& compiled)
{
    out.motion_settings = settings.motion;
    motion_options o = settings.motion;
    o.timed = true; // each chain's time beside its error: the plot's panel in motion
    // Each variant's shipped chain: the still part's where it ran there, else compiled here.
    std::vector<std::unique_ptr<aogen::vulkan::chain>> own;
    std::vector<const aogen::vulkan::chain*> chains;
    for (const aogen::variant& v : settings.motion_variants) {
        const aogen::vulkan::chain* found = nullptr;
        for (size_t i = 0; i < out.variants.size() && !found; ++i)
            if (out.variants[i].v == v) found = compiled.variants[i].shipped.get();
        for (size_t i = 0; i < out.twins.size() && !found; ++i)
            if (out.twins[i].v == v) found = compiled.twins[i].shipped.get();
        if (!found) own.push_back(std::make_unique<aogen::vulkan::chain>(ctx, aogen::codegen::make_plan(v))), found = own.back().get();
        chains.push_back(found);
    }
    for (const aogen::scenes::scene& asked : settings.motion_scenes) {
        if (aogen::scenes::frame_count(asked) < 2) continue;
        settings.progress("in motion: " + asked.name + ", " + std::to_string(std::min(settings.motion.frames, aogen::scenes::frame_count(asked))) +
                          " frames (" + std::to_string(settings.motion.grid * settings.motion.grid) + " rays per pixel from frame " +
                          std::to_string(settings.motion.first_scored) + "), " + std::to_string(chains.size()) + " variants");
        motion_scene m(ctx, sized(asked, settings), o, settings.history);
        for (const aogen::vulkan::chain* c : chains)
            if (cannot_run(c->plan().variant(), m.scene()).empty()) out.motion.push_back(m.score(*c, out.timing));
    }
}

} // namespace detail

inline report_data run_report(const report_settings& settings)
{
    using clock = std::chrono::steady_clock;
    detail::require_scoreable(settings);
    report_data out;
    out.grid = settings.grid, out.frames = settings.frames, out.fetch_floor = settings.fetch_floor, out.history = settings.history;
    // Then: a missing device fails before any compiling or tracing.
    aogen::vulkan::context ctx(settings.device);
    out.device = ctx.device_name();
    out.cpu_device = ctx.cpu();
    out.timing = ctx.cpu() && !settings.timing_given ? cpu_timing : settings.timing;
    clock_monitor clocks(ctx.cpu() ? "" : ctx.device_name());
    out.max_sm_mhz = clocks.max_mhz();
    const std::vector<int> twin_of = detail::add_records(settings, out);

    const auto compile_start = clock::now();
    settings.progress("compiling " + std::to_string(out.variants.size() + out.twins.size()) + " variants (as shipped, for diagnostics" +
                      (settings.fetch_floor ? ", fetch floors" : "") + ")");
    const detail::compiled_records compiled = detail::compile_records(ctx, out, settings.fetch_floor);
    out.phases.compile = detail::seconds_since(compile_start);

    std::vector<double> all_clocks;
    for (size_t si = 0; si < settings.scenes.size(); ++si) {
        const aogen::scenes::scene& asked = settings.scenes[si];
        const std::string tag = "[scene " + std::to_string(si + 1) + "/" + std::to_string(settings.scenes.size()) + "] " + asked.name;
        settings.progress(tag + ": G-buffer and reference (" + std::to_string(settings.grid * settings.grid) + " rays per pixel)");
        const auto trace_start = clock::now();
        scene_bench bench(ctx, sized(asked, settings), settings.grid);
        out.scenes.push_back(record_of(bench));
        if (const size_t left_out = out.scenes.back().truth.untrusted)
            settings.progress(tag + ": " + std::to_string(left_out) + " pixels left out of the score: their geometry lies too far from the camera, and spans too much, " +
                              "for a reference at ao_radius " + aogen::format_number(asked.ao_radius) + " (rays that short are placed reliably within " +
                              aogen::format_number(aogen::truth::reliable_extent(asked.ao_radius)) + " of a tracer's origin)");
        out.phases.trace += detail::seconds_since(trace_start);

        const auto score_start = clock::now();
        settings.progress(tag + ": scoring " + std::to_string(out.variants.size() + out.twins.size()) + " variants" +
                          (settings.frames > 1 ? " (" + std::to_string(settings.frames) + " frames each)" : ""));
        out.phases.runs += detail::score_scene(bench, out, compiled, settings.frames, settings.history);
        out.phases.score += detail::seconds_since(score_start);

        const auto time_start = clock::now();
        settings.progress(tag + ": timing (" + std::to_string(out.timing.rounds) + (out.timing.rounds == 1 ? " round" : " rounds") + " of up to " +
                          std::to_string(out.timing.iterations) + (out.timing.iterations == 1 ? " iteration" : " iterations") + " per chain, " +
                          aogen::format_number(out.timing.warmup_ms) + " ms warm-up" + (out.cpu_device ? ", a CPU device" : "") + ")");
        detail::time_scene(ctx, settings, bench, out, compiled, twin_of, clocks, all_clocks);
        out.phases.time += detail::seconds_since(time_start);

        const auto summarise_start = clock::now();
        detail::summarise_all(out, twin_of);
        out.phases.summarise += detail::seconds_since(summarise_start);
        const auto write_start = clock::now();
        settings.scene_done(out);
        out.phases.write += detail::seconds_since(write_start);
    }
    if (!settings.motion_variants.empty()) {
        const auto motion_start = clock::now();
        detail::run_motion(ctx, settings, out, compiled);
        out.phases.motion = detail::seconds_since(motion_start);
    }
    return out;
}

} // namespace aogen_report
