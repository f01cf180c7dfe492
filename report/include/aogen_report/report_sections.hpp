// aogen_report/report_sections.hpp — the parts of the report that report.md and
// report.html both show, written once as the report's Markdown (text_table.hpp,
// html_text.hpp show it as HTML).
//
//     for (const std::string& fact : aogen_report::measurement_facts(d, meta)) ...
//     std::string how = aogen_report::how_to_read(data.frames);
//     aogen_report::text_table scenes = aogen_report::scenes_table(d, strip_files);
//
//   partial_notice      what a report written after each scene says first
//   measurement_facts   how it was measured: device, scenes, reference, timing, clocks, and
//                       whether the GPU's timestamps kept time — one line each
//   how_to_read         what each column means
//   scenes_table        size, radius, valid pixels, the reference's own noise, clocks
//   feature_saving_*    what leaving the point-cloud fallback out saves on mesh-only scenes
//   not_run_lines       the runs that did not happen, grouped by why
#pragma once

#include "number_text.hpp"
#include "results_json.hpp"
#include "text_table.hpp"

#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace aogen_report {

struct strip_file {
    std::string path;                  // relative to report.md
    std::vector<std::string> variants; // one per row
};

namespace detail {

// How much smaller `a` is than `b`, in percent ("−5 %" when it is larger).
inline std::string saved(double a, double b)
{
    return (std::isfinite(a) && std::isfinite(b) && b > 0) ? fixed(100.0 * (1.0 - a / b), 0) + " %" : "–";
}

// Variant indices, fastest first (unmeasured last, then by name), so tables are stable.
inline std::vector<size_t> by_time(const std::vector<variant_record>& v)
{
    std::vector<size_t> order(v.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const bool fa = std::isfinite(v[a].ms), fb = std::isfinite(v[b].ms);
        if (fa != fb) return fa;
        if (fa && v[a].ms != v[b].ms) return v[a].ms < v[b].ms;
        return v[a].name < v[b].name;
    });
    return order;
}

// "p10–p90" of a time.
inline std::string range(double lo, double hi) { return fixed(lo, 3) + "–" + fixed(hi, 3); }

// Raw counts as "NaN/Inf" and "out of [0, 1]" cells; "–" where no diagnostic build ran.
inline std::string raw_non_finite(const aogen::vulkan::raw_counts& r, bool measured)
{
    return measured ? std::to_string(r.nan) + "/" + std::to_string(r.inf) : "–";
}
inline std::string raw_range(const aogen::vulkan::raw_counts& r, bool measured)
{
    if (!measured) return "–";
    if (r.out_of_range() == 0) return "0";
    char excess[32];
    std::snprintf(excess, sizeof excess, "%.2g", double(r.max_excess));
    return std::to_string(r.out_of_range()) + " (by ≤ " + excess + ")";
}

inline std::string clocks_text(const clock_record& c)
{
    if (c.samples == 0) return "not read (no nvidia-smi for this device)";
    return fixed(c.median, 0) + " MHz median, " + fixed(c.min, 0) + "–" + fixed(c.max, 0) + " over " + std::to_string(c.samples) + " readings";
}

} // namespace detail

// What a report written while scenes are still to come says first.
inline std::string partial_notice(const report_data& d)
{
    return "**Partial report**: written after scene " + std::to_string(d.scenes.size()) + "; the run goes on (or was interrupted).";
}

// How it was measured, one Markdown line per fact.
inline std::vector<std::string> measurement_facts(const report_data& d, const report_meta& meta)
{
    using detail::fixed;
    std::vector<std::string> facts;
    const scene_record& first = d.scenes.front();
    facts.push_back("Device: **" + d.device + "**" + (d.max_sm_mhz > 0 ? " (maximum SM clock " + fixed(d.max_sm_mhz, 0) + " MHz)" : ""));
    facts.push_back(std::to_string(d.scenes.size()) + " scenes at " + std::to_string(first.scene.camera.width) + "×" +
                    std::to_string(first.scene.camera.height) + ", " + std::to_string(d.variants.size()) + " variants");
    facts.push_back("Reference: Embree, " + std::to_string(d.grid * d.grid) + " stratified cosine-distributed rays per pixel");
    if (d.frames > 1)
        facts.push_back("Temporal accumulation: " + std::to_string(d.frames) + " frames per variant and scene (frame index 0.." +
                        std::to_string(d.frames - 1) + ", aogen::temporal's van der Corput turns of the noise and, GTAO's and VBAO's, Sobol moves of the "
                        "inner steps), their plain mean scored");
    int fewest = d.timing.iterations, most = 0;
    for (const scene_record& s : d.scenes) fewest = std::min(fewest, s.iterations), most = std::max(most, s.iterations);
    const bool one_sample = d.timing.rounds == 1 && d.timing.iterations == 1 && d.timing.warmup_ms <= 0;
    if (d.cpu_device && one_sample)
        facts.push_back("Times on a CPU device (run.hpp's cpu_timing): per scene, every chain bound once and run once, interleaved" +
                        std::string(d.fetch_floor ? " with its fetch and bandwidth floors" : "") +
                        ", no warm-up (a CPU has no idle clock to bring up); timestamps around every pass, which on a CPU device time "
                        "the CPU's own work; one sample per chain and scene, a variant's figure its median over the scenes");
    else
        facts.push_back("Times: per scene, every chain bound once (device-local memory), " + fixed(d.timing.warmup_ms, 0) +
                        " ms of continuous GPU work first, then " + std::to_string(d.timing.rounds) + " rounds of " +
                        (fewest == most ? std::to_string(most) : std::to_string(fewest) + "–" + std::to_string(most)) +
                        " back-to-back iterations of every chain, interleaved" + (d.fetch_floor ? " with their fetch and bandwidth floors" : "") +
                        (d.timing.budget_ms > 0 ? " (at most " + std::to_string(d.timing.iterations) + ", as many as fit " + fixed(d.timing.budget_ms, 0) + " ms)" : "") +
                        "; GPU timestamps around every pass; median and p10–p90 of the iterations");
    facts.push_back("SM clock during the timed rounds: " + detail::clocks_text(d.clocks));
    std::string unsettled;
    for (const scene_record& s : d.scenes)
        if (!s.settled) unsettled += (unsettled.empty() ? "" : ", ") + s.scene.name;
    if (!unsettled.empty())
        facts.push_back("**Warm-up did not settle** (two submissions 3 % apart) within " + fixed(d.timing.warmup_max_ms, 0) + " ms on: " + unsettled +
                        " — those scenes' times may include a clock change");
    double gpu = 0, wall = 0;
    for (const scene_record& s : d.scenes) gpu += s.timed_gpu_ms, wall += s.timed_wall_ms;
    if (wall > 0)
        facts.push_back("Timestamps against the host's clock: the timing rounds' timestamps span " + fixed(gpu, 1) + " ms of " + fixed(wall, 1) +
                        " ms wall clock (" + fixed(100.0 * gpu / wall, 1) + " %)" +
                        (gpu / wall > 0.8 && gpu / wall < 1.02 ? ": the GPU was kept busy, and its timestamps keep time"
                                                               : ": far from 100 %, so either the GPU idled inside the rounds or its timestamps do not keep time — read the times with care"));
    facts.push_back("Command: `" + meta.command + "`");
    return facts;
}

// What each column means.
inline std::string how_to_read(int frames)
{
    return "**How to read it.** Error is the RMSE of the variant's AO against the ray-traced reference over the pixels that show "
           "geometry (background excluded), the mean over the scenes the variant ran on. Half-resolution variants are scored at "
           "full resolution as displayed: through their depth-aware upsample pass, or, for `-nearest` variants, after nearest "
           "upsampling. *Default*: the variant's default parameters (seed presets, lengths scaled to "
           "the scene's AO radius). *Calibrated*: the output raised to the power p fitted on the *other* scenes (leave-one-out), "
           "so no scene is scored with a fit made on it. *After " + std::to_string(frames) + " frames*: the plain mean of the variant's first " +
           std::to_string(frames) + " frames, each turning the noise by the frame index's next rotation (and moving GTAO's and VBAO's inner steps by its "
           "next step offset), with a still camera — what "
           "TAA's history shows once it has that many frames, the default output being frame 0. *Bent normal °* (`-bn` variants): "
           "the mean angle between the variant's bent normal and the traced one (the cosine-weighted mean of the unoccluded "
           "directions), over the pixels that show geometry, the mean over the scenes; the strips add a row per such variant "
           "(reference | variant as normal-map colours | angle, yellow at 30°). Time is the median over scenes of each scene's median (p10–p90 likewise). "
           "*Floor* is the variant's fetch floor: its passes' texel fetches at the same positions with none of the shading "
           "(report/floor/), timed in the same rounds; *× floor* is time / floor, the median over scenes — near 1 the "
           "variant is bound by its memory traffic, far above it by its arithmetic. *BW floor* is its bandwidth floor: each "
           "pass's inputs read once at its own pixel and its output written once (report/floor/bandwidth/), the least any "
           "chain of these sizes and formats moves; *× BW* is time / bandwidth floor — how far the variant is from the "
           "memory system itself, not from its own fetch pattern. *Raw NaN/Inf* and *raw out of [0, 1]* count "
           "the values the passes computed before the guard that keeps the output finite and in range (all passes, all "
           "scenes), with how far the farthest lay outside [0, 1]; the output itself is always finite and in range. "
           "★ marks a Pareto-optimal variant: no other variant is both at least as fast and at least as accurate.";
}

// The scenes: size, radius, valid pixels, the reference's own noise, clocks; with
// `strips`, a last column linking each scene's strip.
inline text_table scenes_table(const report_data& d, const std::map<std::string, strip_file>* strips)
{
    using detail::fixed;
    text_table t{{"scene", "size", "AO radius", "valid pixels", "mean reference AO", "reference noise", "SM clock while timed"}, "llrrrrl", {}};
    if (strips) t.head.push_back("strip"), t.align += 'l';
    for (const scene_record& s : d.scenes) {
        t.rows.push_back({s.scene.name + (s.scene.renderer.point_cloud ? " (point cloud)" : ""),
                          std::to_string(s.scene.camera.width) + "×" + std::to_string(s.scene.camera.height), fixed(s.scene.ao_radius, 3),
                          std::to_string(s.valid_pixels) + (s.truth.untrusted ? " (" + std::to_string(s.truth.untrusted) + " left out)" : ""),
                          fixed(s.truth_mean, 4), fixed(s.truth.noise_rms, 4), s.clocks.samples ? fixed(s.clocks.median, 0) + " MHz" : "–"});
        if (strips) {
            const auto strip = strips->find(s.scene.name);
            t.rows.back().push_back(strip == strips->end() ? "" : "[png](" + strip->second.path + ")");
        }
    }
    return t;
}

inline std::string scenes_about()
{
    return "The reference's own noise (RMS of the per-pixel Monte-Carlo standard error) adds to a variant's RMSE in quadrature; "
           "it must stay well below the errors above. Valid pixels are those scored; a hit farther from the camera than float "
           "geometry can place rays of the AO radius (truth::reliable_extent) has no reference to trust, and is left out (the "
           "count in brackets).";
}

// The largest reference noise against the smallest calibrated error: the first must be far below the second.
inline std::string noise_against_best(const report_data& d)
{
    double best = std::numeric_limits<double>::infinity(), noise = 0;
    for (const variant_record& v : d.variants)
        if (std::isfinite(v.rmse_calibrated)) best = std::min(best, v.rmse_calibrated);
    for (const scene_record& s : d.scenes) noise = std::max(noise, s.truth.noise_rms);
    return "Largest reference noise: " + detail::fixed(noise, 4) + "; smallest mean calibrated RMSE of any variant: " + detail::fixed(best, 4) + ".";
}

inline std::string feature_saving_about()
{
    return "On the mesh-only scenes, each SSAO variant as scene selection makes it (the point-cloud fallback left out: the "
           "scenes have no point clouds) beside the same variant with the fallback compiled in. Instructions are the AO shader's "
           "SPIR-V after spirv-opt; times are the median over the mesh-only scenes of the whole chain, the two timed in the "
           "same rounds, interleaved; the ratio is selected / everything on per scene and round (median, p10–p90): a "
           "spread that straddles 1 is no saving; saved = 1 − selected / everything on.";
}

inline text_table feature_saving_table(const report_data& d)
{
    using detail::fixed;
    text_table t{{"selected variant", "AO instructions", "everything on", "saved", "ms", "everything on", "time ratio", "p10–p90", "RMSE", "everything on"},
                 "lrrrrrrrrr", {}};
    for (const feature_saving& f : d.savings)
        t.rows.push_back({"`" + f.selected + "`", std::to_string(f.selected_instructions), std::to_string(f.everything_on_instructions),
                          detail::saved(f.selected_instructions, f.everything_on_instructions), fixed(f.selected_ms, 3), fixed(f.everything_on_ms, 3),
                          fixed(f.ratio.median, 3), fixed(f.ratio.p10, 3) + "–" + fixed(f.ratio.p90, 3), fixed(f.selected_rmse, 4),
                          fixed(f.everything_on_rmse, 4)});
    return t;
}

inline std::string feature_saving_left_out(const report_data& d)
{
    std::string text = "Left out by selection: ";
    for (size_t i = 0; i < d.savings.front().left_out.size(); ++i) text += (i ? "; " : "") + d.savings.front().left_out[i];
    return text + ".";
}

// ---- In motion (motion.hpp) --------------------------------------------------------

inline std::string motion_about(const report_data& d)
{
    const motion_options& o = d.motion_settings;
    return "Each variant run as a renderer runs it along every scene that has a camera path (and moving objects): frame f's G-buffer "
           "with its motion vectors, the frame index f, the previous frame's camera, one binding whose history pass keeps its history. "
           "Frames " + std::to_string(o.first_scored) + " to " + std::to_string(o.frames - 1) + " are each scored against their own "
           "reference (" + std::to_string(o.grid * o.grid) + " rays per pixel). *Error*: the mean of those frames' RMSEs. *Ghosting*: "
           "the RMSE over pixels whose surface point came into view within the last " + std::to_string(o.ghost_window) + " frames (the "
           "truth's disocclusion: a point moved back by its object's motion is in view a frame earlier when it lies on that frame's "
           "screen and nothing hides it from that frame's eye). *Flicker*: the RMS of the frame-to-frame change of (AO − truth) at "
           "one surface point, over the points in view in both frames. Means over the scenes; a twin is the variant without its "
           "history pass.";
}

namespace detail {
// The mean of `field` over the motion runs of `variant`.
template <class F>
double motion_mean(const report_data& d, const std::string& variant, F field)
{
    double sum = 0, n = 0;
    for (const motion_record& r : d.motion)
        if (r.variant == variant) sum += field(r), n += 1;
    return n > 0 ? sum / n : std::nan("");
}

// The name of `variant` without its history extra ("" when it has none).
inline std::string motion_twin_name(const std::string& variant)
{
    for (const char* extra : {"-histmv", "-hist"}) {
        const size_t at = variant.find(extra);
        if (at != std::string::npos) return variant.substr(0, at) + variant.substr(at + std::string(extra).size());
    }
    return "";
}
} // namespace detail

// Per motion variant (in the order run): its means over the scenes, and beside a history
// variant its twin's ratios.
inline text_table motion_table(const report_data& d)
{
    using detail::fixed;
    text_table t{{"variant", "error", "ghosting", "flicker", "error / twin's", "ghosting / twin's", "flicker / twin's"}, "lrrrrrr", {}};
    std::vector<std::string> seen;
    for (const motion_record& r : d.motion) {
        if (std::find(seen.begin(), seen.end(), r.variant) != seen.end()) continue;
        seen.push_back(r.variant);
        auto mean = [&](const std::string& v, double motion_record::*field) { return detail::motion_mean(d, v, [&](const motion_record& m) { return m.*field; }); };
        const std::string twin = detail::motion_twin_name(r.variant);
        auto ratio = [&](double motion_record::*field) {
            const double a = mean(r.variant, field), b = twin.empty() ? std::nan("") : mean(twin, field);
            return std::isfinite(b) && b > 0 ? fixed(a / b, 2) : std::string("–");
        };
        t.rows.push_back({"`" + r.variant + "`", fixed(mean(r.variant, &motion_record::error), 4), fixed(mean(r.variant, &motion_record::ghosting), 4),
                          fixed(mean(r.variant, &motion_record::flicker), 4), ratio(&motion_record::error), ratio(&motion_record::ghosting),
                          ratio(&motion_record::flicker)});
    }
    return t;
}

// Per scene with a path: each variant's error / ghosting / flicker there.
inline text_table motion_scenes_table(const report_data& d)
{
    using detail::fixed;
    std::vector<std::string> scenes, variants;
    for (const motion_record& r : d.motion) {
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
        if (std::find(variants.begin(), variants.end(), r.variant) == variants.end()) variants.push_back(r.variant);
    }
    text_table t{{"variant"}, "l", {}};
    for (const std::string& s : scenes) t.head.push_back(s + ": error / ghosting / flicker"), t.align += "r";
    for (const std::string& v : variants) {
        std::vector<std::string> row{"`" + v + "`"};
        for (const std::string& s : scenes) {
            std::string cell = "–";
            for (const motion_record& r : d.motion)
                if (r.variant == v && r.scene == s) cell = fixed(r.error, 4) + " / " + fixed(r.ghosting, 4) + " / " + fixed(r.flicker, 4);
            row.push_back(cell);
        }
        t.rows.push_back(row);
    }
    return t;
}

// The runs that did not happen, one line per reason: how many, and the first three.
inline std::vector<std::string> not_run_lines(const report_data& d)
{
    std::map<std::string, std::vector<std::string>> skipped; // reason → "variant on scene"
    for (const variant_record& v : d.variants)
        for (size_t s = 0; s < v.runs.size(); ++s)
            if (!v.runs[s].ran()) skipped[v.runs[s].skipped].push_back("`" + v.name + "` on " + d.scenes[s].scene.name);
    std::vector<std::string> lines;
    for (const auto& entry : skipped) {
        std::string line = entry.first + ": " + std::to_string(entry.second.size()) + (entry.second.size() == 1 ? " run" : " runs") + " (";
        for (size_t i = 0; i < entry.second.size() && i < 3; ++i) line += (i ? ", " : "") + entry.second[i];
        lines.push_back(line + (entry.second.size() > 3 ? ", …" : "") + ")");
    }
    return lines;
}

} // namespace aogen_report
