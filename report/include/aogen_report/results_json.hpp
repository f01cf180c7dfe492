// aogen_report/results_json.hpp — every number of a report, machine-readable.
//
//     std::string text = aogen_report::results_json(data, meta);   // results.json
//
// Layout (numbers as measured; times NaN — no timestamps, not timed — are null; "ms" is
// always a median, "_p10"/"_p90" the nearest-rank percentiles of the same samples):
//   { "aogen_report": 2, "device", "command", "rays_per_pixel", "frames", "complete": bool,
//     "timing": {rounds, iterations, warmup_ms, budget_ms, fetch_floor},   // iterations: the most per round
//     "clocks": {max_sm_mhz, min, median, max, samples},        // SM MHz while timing (nvidia-smi)
//     "phases_s": {compile, trace, score, time, summarise, write (the partial sets), motion, runs},
//     "calibration": "...",
//     "scenes":   [{name, width, height, ao_radius, valid_pixels, untrusted_pixels, truth_mean, truth_noise_rms, point_cloud, clocks,
//                   timed_gpu_ms, timed_wall_ms,     // the timing rounds: timestamp span against host wall clock
//                   iterations, settled}],           // per round, as the budget allowed; warm-up settled
//     "variants": [{name, hash, technique, stage, passes, spirv_instructions, ao_instructions,
//                   ao_tap_instructions,               // the AO pass's tap loop per tap (aogen/loops.hpp), 0: none
//                   ms, ms_p10, ms_p90, floor_ms, floor_ratio, bandwidth_ms, bandwidth_ratio, rmse, rmse_calibrated,
//                   rmse_accumulated,                  // of the mean of "frames" frames (temporal.hpp)
//                   bent_degrees,                      // -bn: mean over scenes of the bent normals' mean angle to the truth's; else null
//                   raw: {measured, nan, inf, below_zero, above_one, max_excess}, pareto, pareto_calibrated, pareto_accumulated,
//                   scenes: [{scene, skipped | {ms, ms_p10, ms_p90, pass_ms, floor_ms, bandwidth_ms, power,
//                             raw: [{nan, inf, below_zero, above_one, max_excess} per pass],
//                             default: {rmse, mae, mean_signed, p99_abs, non_finite, pixels},
//                             calibrated: {...}, accumulated: {...},
//                             bent_normal: {mean_degrees, p90_degrees, missing, pixels}}]}],   // -bn variants only
//     "feature_saving": [{selected, everything_on, selected_instructions, everything_on_instructions,
//                         selected_ms, everything_on_ms, ratio, ratio_p10, ratio_p90,
//                         selected_rmse, everything_on_rmse, left_out}],
//     "history": {blend, clamp, range, widening, gamma, depth_tolerance},  // the history pass's settings (--history)
//     "motion": {frames, first_scored, ghost_window, rays_per_pixel,     // the report in motion (motion.hpp)
//                runs: [{variant, scene, error, ghosting, flicker, ghost_pixels, flicker_pixels, rmse: [per scored frame],
//                        ms (one frame's time on the last frame; null where not timed)}]} }
// "raw" counts what each pass computed before its finite/range guard (diagnostics.hpp);
// "non_finite" of the metrics counts the shipped output, which the guard keeps finite.
#pragma once

#include "records.hpp"

#include <nlohmann/json.hpp>

namespace aogen_report {

struct report_meta {
    std::string command;   // how the report was made, for whoever reads it later
    bool complete = true;  // false while scenes are still to come (written after each scene)
};

namespace detail {

inline nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

inline nlohmann::json metrics_json(const error_metrics& m)
{
    return {{"rmse", m.rmse}, {"mae", m.mae}, {"mean_signed", m.mean_signed}, {"p99_abs", m.p99_abs},
            {"non_finite", m.non_finite}, {"pixels", m.pixels}};
}

inline nlohmann::json raw_json(const aogen::vulkan::raw_counts& r)
{
    return {{"nan", r.nan}, {"inf", r.inf}, {"below_zero", r.below_zero}, {"above_one", r.above_one}, {"max_excess", r.max_excess}};
}

inline nlohmann::json clocks_json(const clock_record& c)
{
    return {{"min", number(c.min)}, {"median", number(c.median)}, {"max", number(c.max)}, {"samples", c.samples}};
}

inline nlohmann::json run_json(const run_record& r, const std::string& scene)
{
    nlohmann::json e{{"scene", scene}};
    if (!r.ran()) {
        e["skipped"] = r.skipped;
        return e;
    }
    std::vector<nlohmann::json> passes, raw;
    for (const aogen::vulkan::spread& p : r.pass_ms) passes.push_back(number(p.median));
    for (const aogen::vulkan::raw_counts& c : r.raw) raw.push_back(raw_json(c));
    e["ms"] = number(r.ms.median);
    e["ms_p10"] = number(r.ms.p10);
    e["ms_p90"] = number(r.ms.p90);
    e["pass_ms"] = passes;
    e["floor_ms"] = number(r.floor_ms.median);
    e["bandwidth_ms"] = number(r.bandwidth_ms.median);
    e["power"] = r.power;
    e["raw"] = raw;
    e["default"] = metrics_json(r.plain);
    e["calibrated"] = metrics_json(r.calibrated);
    e["accumulated"] = metrics_json(r.accumulated);
    if (r.bent.pixels > 0)
        e["bent_normal"] = {{"mean_degrees", number(r.bent.mean_degrees)}, {"p90_degrees", number(r.bent.p90_degrees)},
                            {"missing", r.bent.missing}, {"pixels", r.bent.pixels}};
    return e;
}

inline nlohmann::json variant_json(const variant_record& v, const std::vector<scene_record>& scenes)
{
    nlohmann::json per_scene = nlohmann::json::array();
    for (size_t s = 0; s < v.runs.size(); ++s) per_scene.push_back(run_json(v.runs[s], scenes[s].scene.name));
    nlohmann::json raw = raw_json(v.raw);
    raw["measured"] = v.raw_measured;
    return {{"name", v.name},
            {"hash", aogen::hash(v.v)},
            {"technique", aogen::names::name_of(aogen::technique_names, v.v.tech, "technique")},
            {"stage", aogen::names::name_of(aogen::pipeline_stage_names, v.v.stage, "stage")},
            {"passes", v.passes},
            {"spirv_instructions", v.instructions},
            {"ao_instructions", v.ao_instructions},
            {"ao_tap_instructions", v.ao_tap_instructions},
            {"ms", number(v.ms)},
            {"ms_p10", number(v.ms_p10)},
            {"ms_p90", number(v.ms_p90)},
            {"floor_ms", number(v.floor_ms)},
            {"floor_ratio", number(v.floor_ratio)},
            {"bandwidth_ms", number(v.bandwidth_ms)},
            {"bandwidth_ratio", number(v.bandwidth_ratio)},
            {"rmse", number(v.rmse)},
            {"rmse_calibrated", number(v.rmse_calibrated)},
            {"rmse_accumulated", number(v.rmse_accumulated)},
            {"bent_degrees", number(v.bent_degrees)},
            {"raw", raw},
            {"pareto", v.pareto},
            {"pareto_calibrated", v.pareto_calibrated},
            {"pareto_accumulated", v.pareto_accumulated},
            {"scenes", per_scene}};
}

// The report in motion (motion.hpp): what ran, and per variant and scene its figures.
inline nlohmann::json motion_json(const report_data& d)
{
    const motion_options& o = d.motion_settings;
    nlohmann::json runs = nlohmann::json::array();
    for (const motion_record& r : d.motion)
        runs.push_back({{"variant", r.variant}, {"scene", r.scene}, {"error", r.error}, {"ghosting", r.ghosting}, {"flicker", r.flicker},
                        {"ghost_pixels", r.ghost_pixels}, {"flicker_pixels", r.flicker_pixels}, {"rmse", r.rmse},
                        {"ms", std::isfinite(r.ms) ? nlohmann::json(r.ms) : nlohmann::json()}});
    return {{"frames", o.frames}, {"first_scored", o.first_scored}, {"ghost_window", o.ghost_window}, {"rays_per_pixel", o.grid * o.grid}, {"runs", runs}};
}

} // namespace detail

inline std::string results_json(const report_data& d, const report_meta& meta)
{
    nlohmann::json j;
    j["aogen_report"] = 2;
    j["device"] = d.device;
    j["command"] = meta.command;
    j["complete"] = meta.complete;
    j["rays_per_pixel"] = d.grid * d.grid;
    j["frames"] = d.frames;
    j["timing"] = {{"rounds", d.timing.rounds}, {"iterations", d.timing.iterations}, {"warmup_ms", d.timing.warmup_ms},
                   {"budget_ms", d.timing.budget_ms}, {"fetch_floor", d.fetch_floor}, {"cpu_device", d.cpu_device}};
    j["clocks"] = detail::clocks_json(d.clocks);
    j["clocks"]["max_sm_mhz"] = detail::number(d.max_sm_mhz > 0 ? d.max_sm_mhz : std::nan(""));
    j["phases_s"] = {{"compile", d.phases.compile}, {"trace", d.phases.trace},         {"score", d.phases.score}, {"time", d.phases.time},
                     {"summarise", d.phases.summarise}, {"write", d.phases.write}, {"motion", d.phases.motion}, {"runs", d.phases.runs}};
    j["calibration"] = "ao^p, p fitted on the other scenes (leave-one-out), least squares, each scene weighted equally";
    j["scenes"] = nlohmann::json::array();
    for (const scene_record& s : d.scenes)
        j["scenes"].push_back({{"name", s.scene.name},
                               {"width", s.scene.camera.width},
                               {"height", s.scene.camera.height},
                               {"ao_radius", s.scene.ao_radius},
                               {"valid_pixels", s.valid_pixels},
                               {"untrusted_pixels", s.truth.untrusted},
                               {"truth_mean", s.truth_mean},
                               {"truth_noise_rms", s.truth.noise_rms},
                               {"point_cloud", s.scene.renderer.point_cloud},
                               {"clocks", detail::clocks_json(s.clocks)},
                               {"timed_gpu_ms", s.timed_gpu_ms},
                               {"timed_wall_ms", s.timed_wall_ms},
                               {"iterations", s.iterations},
                               {"settled", s.settled}});
    j["variants"] = nlohmann::json::array();
    for (const variant_record& v : d.variants) j["variants"].push_back(detail::variant_json(v, d.scenes));
    j["feature_saving"] = nlohmann::json::array();
    for (const feature_saving& f : d.savings)
        j["feature_saving"].push_back({{"selected", f.selected},
                                       {"everything_on", f.everything_on},
                                       {"selected_instructions", f.selected_instructions},
                                       {"everything_on_instructions", f.everything_on_instructions},
                                       {"selected_ms", detail::number(f.selected_ms)},
                                       {"everything_on_ms", detail::number(f.everything_on_ms)},
                                       {"ratio", detail::number(f.ratio.median)},
                                       {"ratio_p10", detail::number(f.ratio.p10)},
                                       {"ratio_p90", detail::number(f.ratio.p90)},
                                       {"selected_rmse", f.selected_rmse},
                                       {"everything_on_rmse", f.everything_on_rmse},
                                       {"left_out", f.left_out}});
    j["history"] = {{"blend", d.history.blend}, {"clamp", aogen::names::name_of(aogen::history_clamp_names, d.history.clamp, "history clamp")},
                    {"range", d.history.range}, {"widening", d.history.min_max_widening}, {"gamma", d.history.variance_gamma},
                    {"depth_tolerance", d.history.depth_tolerance}};
    j["motion"] = detail::motion_json(d);
    return j.dump(2) + "\n";
}

} // namespace aogen_report
