// aogen_report/markdown.hpp — report.md: the tables a person reads.
//
//     std::string text = aogen_report::report_markdown(data, meta, strip_files);
//
// Sections: how it was measured (device, clocks, timing) and how to read it; the variants
// sorted by time with their spread, fetch and bandwidth floors and time / floor, default and calibrated
// RMSE, Pareto marks and raw NaN/Inf and out-of-range counts; the scenes with the
// reference's own noise and the clocks seen; per scene, every variant's metrics; the
// feature saving; what was skipped and why. `strip_files` maps a scene name
// to its image strip (relative path) and the variants in its rows.
#pragma once

#include "report_sections.hpp"

#include <map>
#include <sstream>

namespace aogen_report {

namespace detail {

// How it was measured, how to read it, and the plot.
inline void write_measurement(std::ostream& md, const report_data& d, const report_meta& meta)
{
    if (!meta.complete) md << partial_notice(d) << "\n\n";
    for (const std::string& fact : measurement_facts(d, meta)) md << "- " << fact << "\n";
    md << "\n" << how_to_read(d.frames) << "\n\n";
    md << "![error against time](error_vs_time.svg)\n\nThe same plot in [report.html](report.html) names every point on hover, "
          "with a table to sort and filter and every variant's images on every scene.\n\n";
}

// Every variant, fastest first, with its time, floor, errors and raw counts.
inline void write_variants(std::ostream& md, const report_data& d)
{
    md << "## Variants, fastest first\n\n";
    md << "| variant | ms | p10–p90 | floor ms | × floor | BW floor ms | × BW | RMSE default | ★ | RMSE calibrated | ★ | RMSE after " << d.frames
       << " frames | ★ | bent normal ° | AO instructions | per tap | raw NaN/Inf | raw out of [0, 1] |\n";
    md << "|---|---:|---:|---:|---:|---:|---:|---:|:-:|---:|:-:|---:|:-:|---:|---:|---:|---:|---:|\n";
    for (size_t i : detail::by_time(d.variants)) {
        const variant_record& v = d.variants[i];
        md << "| `" << v.name << "` | " << fixed(v.ms, 3) << " | " << detail::range(v.ms_p10, v.ms_p90) << " | " << fixed(v.floor_ms, 3) << " | "
           << fixed(v.floor_ratio, 2) << " | " << fixed(v.bandwidth_ms, 3) << " | " << fixed(v.bandwidth_ratio, 2) << " | " << fixed(v.rmse, 4) << " | " << (v.pareto ? "★" : "") << " | " << fixed(v.rmse_calibrated, 4)
           << " | " << (v.pareto_calibrated ? "★" : "") << " | " << fixed(v.rmse_accumulated, 4) << " | " << (v.pareto_accumulated ? "★" : "") << " | "
           << fixed(v.bent_degrees, 1, "") << " | " << v.ao_instructions << " | " << fixed(v.ao_tap_instructions, 1) << " | " << detail::raw_non_finite(v.raw, v.raw_measured)
           << " | " << detail::raw_range(v.raw, v.raw_measured) << " |\n";
    }
}

// The scenes: size, radius, valid pixels, the reference's own noise, clocks, strips.
inline void write_scenes(std::ostream& md, const report_data& d, const std::map<std::string, strip_file>& strips)
{
    md << "\n## Scenes\n\n" << scenes_about() << "\n\n" << markdown_table(scenes_table(d, &strips));
    md << "\n" << noise_against_best(d) << "\n\n";
    md << "Each scene's strip shows, per row, reference | variant (default parameters) | |variant − reference| (black 0, yellow ≥ "
       << fixed(heat_full_scale, 2) << "; background in blue-grey), for the variants Pareto-optimal on that scene by time and "
          "calibrated error, fastest first; then, for each variant with bent normals (`-bn`), reference | variant bent normal "
          "(normal-map colours, world space) | the angle between them (black 0°, yellow ≥ "
       << fixed(bent_heat_full_scale_degrees, 0) << "°).\n";
}

// Per scene, every variant that ran on it.
inline void write_per_scene(std::ostream& md, const report_data& d, const std::map<std::string, strip_file>& strips)
{
    md << "\n## Per scene\n\n";
    md << "Columns: median ms and p10–p90; time / fetch floor; time / bandwidth floor; default RMSE, MAE, mean signed error (> 0: too light), "
          "99th-percentile |error|; calibrated RMSE and its power p; RMSE of the mean of the first "
       << d.frames << " frames; the bent normals' mean angle to the truth's, in degrees (-bn variants); raw NaN/Inf and out-of-range values (all passes).\n";
    for (size_t s = 0; s < d.scenes.size(); ++s) {
        md << "\n### " << d.scenes[s].scene.name << "\n\n";
        const auto strip = strips.find(d.scenes[s].scene.name);
        if (strip != strips.end()) {
            md << "![" << d.scenes[s].scene.name << ": reference | variant | error](" << strip->second.path << ")\n\nRows: ";
            for (size_t k = 0; k < strip->second.variants.size(); ++k) md << (k ? ", " : "") << "`" << strip->second.variants[k] << "`";
            md << ".\n\n";
        }
        md << "| variant | ms | p10–p90 | × floor | × BW | RMSE | MAE | signed | p99 | RMSE cal. | p | RMSE " << d.frames << " fr. | bent ° | raw NaN/Inf | raw out of [0, 1] |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (size_t i : detail::by_time(d.variants)) {
            const variant_record& v = d.variants[i];
            const run_record& r = v.runs[s];
            if (!r.ran()) continue;
            aogen::vulkan::raw_counts raw;
            for (const aogen::vulkan::raw_counts& c : r.raw) raw += c;
            md << "| `" << v.name << "` | " << fixed(r.ms.median, 3) << " | " << detail::range(r.ms.p10, r.ms.p90) << " | "
               << fixed(r.ms.median / r.floor_ms.median, 2) << " | " << fixed(r.ms.median / r.bandwidth_ms.median, 2) << " | " << fixed(r.plain.rmse, 4) << " | " << fixed(r.plain.mae, 4) << " | "
               << fixed(r.plain.mean_signed, 4) << " | " << fixed(r.plain.p99_abs, 3) << " | " << fixed(r.calibrated.rmse, 4) << " | "
               << fixed(r.power, 2) << " | " << fixed(r.accumulated.rmse, 4) << " | " << fixed(r.bent.mean_degrees, 1, "") << " | " << detail::raw_non_finite(raw, !r.raw.empty()) << " | "
               << detail::raw_range(raw, !r.raw.empty())
               << " |\n";
        }
    }
}

// What leaving the point-cloud fallback out saves on mesh-only scenes.
inline void write_feature_saving(std::ostream& md, const report_data& d)
{
    md << "\n## Leaving features out\n\n";
    if (d.savings.empty()) md << "No SSAO variant without the point-cloud fallback, or no mesh-only scene: nothing to compare.\n";
    else md << feature_saving_about() << "\n\n" << markdown_table(feature_saving_table(d)) << "\n" << feature_saving_left_out(d) << "\n";
}

// The report in motion (motion.hpp).
inline void write_motion(std::ostream& md, const report_data& d)
{
    if (d.motion.empty()) return;
    md << "\n## In motion\n\n" << motion_about(d) << "\n\n![error in motion against time](motion_vs_time.svg)\n\n" << markdown_table(motion_table(d)) << "\n"
       << markdown_table(motion_scenes_table(d));
}

// The runs that did not happen, grouped by why.
inline void write_not_run(std::ostream& md, const report_data& d)
{
    const std::vector<std::string> lines = not_run_lines(d);
    if (lines.empty()) return;
    md << "\n## Not run\n\n";
    for (const std::string& line : lines) md << "- " << line << "\n";
}

} // namespace detail

inline std::string report_markdown(const report_data& d, const report_meta& meta, const std::map<std::string, strip_file>& strips)
{
    std::ostringstream md;
    md << "# aogen report: AO error against run time\n\n";
    detail::write_measurement(md, d, meta);
    detail::write_variants(md, d);
    detail::write_scenes(md, d, strips);
    detail::write_per_scene(md, d, strips);
    detail::write_feature_saving(md, d);
    detail::write_motion(md, d);
    detail::write_not_run(md, d);
    return md.str();
}

} // namespace aogen_report
