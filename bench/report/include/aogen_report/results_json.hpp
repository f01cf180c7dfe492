// aogen_report/results_json.hpp — every number of a report, machine-readable.
//
//     std::string text = aogen_report::results_json(data, meta);   // results.json
//
// Layout (numbers as measured; NaN times, when the device has no timestamps, are null):
//   { "aogen_report": 1, "device": ..., "command": ..., "rays_per_pixel": ..., "runs": ..., "warmup": ...,
//     "calibration": "ao^p, p fitted on the other scenes (leave-one-out)",
//     "scenes":   [{name, width, height, ao_radius, valid_pixels, truth_mean, truth_noise_rms, point_cloud}],
//     "variants": [{name, hash, technique, stage, passes, spirv_instructions, ao_instructions,
//                   ms, rmse, rmse_calibrated, non_finite, pareto, pareto_calibrated,
//                   scenes: [{scene, skipped | {ms, pass_ms, power,
//                             default: {rmse, mae, mean_signed, p99_abs, non_finite, pixels},
//                             calibrated: {...}}]}],
//     "feature_saving": [{selected, everything_on, selected_instructions, everything_on_instructions,
//                         selected_ms, everything_on_ms, selected_rmse, everything_on_rmse, left_out}] }
#pragma once

#include "run.hpp"

#include <nlohmann/json.hpp>

namespace aogen_report {

struct report_meta {
    std::string command; // how the report was made, for whoever reads it later
};

namespace detail {

inline nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

inline nlohmann::json metrics_json(const error_metrics& m)
{
    return {{"rmse", m.rmse}, {"mae", m.mae}, {"mean_signed", m.mean_signed}, {"p99_abs", m.p99_abs},
            {"non_finite", m.non_finite}, {"pixels", m.pixels}};
}

} // namespace detail

inline std::string results_json(const report_data& d, const report_meta& meta)
{
    nlohmann::json j;
    j["aogen_report"] = 1;
    j["device"] = d.device;
    j["command"] = meta.command;
    j["rays_per_pixel"] = d.grid * d.grid;
    j["runs"] = d.runs;
    j["warmup"] = d.warmup;
    j["calibration"] = "ao^p, p fitted on the other scenes (leave-one-out), least squares, each scene weighted equally";
    j["scenes"] = nlohmann::json::array();
    for (const scene_record& s : d.scenes)
        j["scenes"].push_back({{"name", s.scene.name},
                               {"width", s.scene.camera.width},
                               {"height", s.scene.camera.height},
                               {"ao_radius", s.scene.ao_radius},
                               {"valid_pixels", s.valid_pixels},
                               {"truth_mean", s.truth_mean},
                               {"truth_noise_rms", s.truth.noise_rms},
                               {"point_cloud", s.scene.renderer.point_cloud}});
    j["variants"] = nlohmann::json::array();
    for (const variant_record& v : d.variants) {
        nlohmann::json per_scene = nlohmann::json::array();
        for (size_t s = 0; s < v.runs.size(); ++s) {
            const run_record& r = v.runs[s];
            nlohmann::json e{{"scene", d.scenes[s].scene.name}};
            if (!r.ran()) e["skipped"] = r.skipped;
            else {
                e["ms"] = detail::number(r.ms);
                e["pass_ms"] = r.pass_ms;
                e["power"] = r.power;
                e["default"] = detail::metrics_json(r.plain);
                e["calibrated"] = detail::metrics_json(r.calibrated);
            }
            per_scene.push_back(e);
        }
        j["variants"].push_back({{"name", v.name},
                                 {"hash", aogen::hash(v.v)},
                                 {"technique", aogen::names::name_of(aogen::technique_names, v.v.tech, "technique")},
                                 {"stage", aogen::names::name_of(aogen::pipeline_stage_names, v.v.stage, "stage")},
                                 {"passes", v.passes},
                                 {"spirv_instructions", v.instructions},
                                 {"ao_instructions", v.ao_instructions},
                                 {"ms", detail::number(v.ms)},
                                 {"rmse", detail::number(v.rmse)},
                                 {"rmse_calibrated", detail::number(v.rmse_calibrated)},
                                 {"non_finite", v.non_finite},
                                 {"pareto", v.pareto},
                                 {"pareto_calibrated", v.pareto_calibrated},
                                 {"scenes", per_scene}});
    }
    j["feature_saving"] = nlohmann::json::array();
    for (const feature_saving& f : d.savings)
        j["feature_saving"].push_back({{"selected", f.selected},
                                       {"everything_on", f.everything_on},
                                       {"selected_instructions", f.selected_instructions},
                                       {"everything_on_instructions", f.everything_on_instructions},
                                       {"selected_ms", detail::number(f.selected_ms)},
                                       {"everything_on_ms", detail::number(f.everything_on_ms)},
                                       {"selected_rmse", f.selected_rmse},
                                       {"everything_on_rmse", f.everything_on_rmse},
                                       {"left_out", f.left_out}});
    return j.dump(2) + "\n";
}

} // namespace aogen_report
