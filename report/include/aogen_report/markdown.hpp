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

#include "number_text.hpp"
#include "results_json.hpp"

#include <map>
#include <numeric>
#include <sstream>

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

// How it was measured: device, scenes, reference, timing, clocks, and whether the GPU's
// timestamps kept time.
inline void write_measurement(std::ostream& md, const report_data& d, const report_meta& meta)
{
    const scene_record& first = d.scenes.front();
    if (!meta.complete) md << "**Partial report**: written after scene " << d.scenes.size() << "; the run goes on (or was interrupted).\n\n";
    md << "- Device: **" << d.device << "**";
    if (d.max_sm_mhz > 0) md << " (maximum SM clock " << fixed(d.max_sm_mhz, 0) << " MHz)";
    md << "\n- " << d.scenes.size() << " scenes at " << first.scene.camera.width << "×" << first.scene.camera.height << ", " << d.variants.size()
       << " variants\n";
    md << "- Reference: Embree, " << d.grid * d.grid << " stratified cosine-distributed rays per pixel\n";
    int fewest = d.timing.iterations, most = 0;
    for (const scene_record& s : d.scenes) fewest = std::min(fewest, s.iterations), most = std::max(most, s.iterations);
    md << "- Times: per scene, every chain bound once (device-local memory), " << fixed(d.timing.warmup_ms, 0)
       << " ms of continuous GPU work first, then " << d.timing.rounds << " rounds of "
       << (fewest == most ? std::to_string(most) : std::to_string(fewest) + "–" + std::to_string(most))
       << " back-to-back iterations of every chain, interleaved" << (d.fetch_floor ? " with their fetch and bandwidth floors" : "")
       << (d.timing.budget_ms > 0 ? " (at most " + std::to_string(d.timing.iterations) + ", as many as fit " + fixed(d.timing.budget_ms, 0) + " ms)" : "")
       << "; GPU timestamps around every pass; median and p10–p90 of the iterations\n";
    md << "- SM clock during the timed rounds: " << detail::clocks_text(d.clocks) << "\n";
    std::string unsettled;
    for (const scene_record& s : d.scenes)
        if (!s.settled) unsettled += (unsettled.empty() ? "" : ", ") + s.scene.name;
    if (!unsettled.empty())
        md << "- **Warm-up did not settle** (two submissions 3 % apart) within " << fixed(d.timing.warmup_max_ms, 0) << " ms on: " << unsettled
           << " — those scenes' times may include a clock change\n";
    double gpu = 0, wall = 0;
    for (const scene_record& s : d.scenes) gpu += s.timed_gpu_ms, wall += s.timed_wall_ms;
    if (wall > 0)
        md << "- Timestamps against the host's clock: the timing rounds' timestamps span " << fixed(gpu, 1) << " ms of " << fixed(wall, 1)
           << " ms wall clock (" << fixed(100.0 * gpu / wall, 1) << " %)"
           << (gpu / wall > 0.8 && gpu / wall < 1.02 ? ": the GPU was kept busy, and its timestamps keep time\n"
                                                     : ": far from 100 %, so either the GPU idled inside the rounds or its timestamps do not keep time — read the times with care\n");
    md << "- Command: `" << meta.command << "`\n\n";
}

// What each column means, and the plot.
inline void write_how_to_read(std::ostream& md)
{
    md << "**How to read it.** Error is the RMSE of the variant's AO against the ray-traced reference over the pixels that show "
          "geometry (background excluded), the mean over the scenes the variant ran on. Half-resolution variants are scored at "
          "full resolution as displayed: through their depth-aware upsample pass, or, for `-nearest` variants, after nearest "
          "upsampling. *Default*: the variant's default parameters (seed presets, lengths scaled to "
          "the scene's AO radius). *Calibrated*: the output raised to the power p fitted on the *other* scenes (leave-one-out), "
          "so no scene is scored with a fit made on it. Time is the median over scenes of each scene's median (p10–p90 likewise). "
          "*Floor* is the variant's fetch floor: its passes' texel fetches at the same positions with none of the shading "
          "(report/floor/), timed in the same rounds; *× floor* is time / floor, the median over scenes — near 1 the "
          "variant is bound by its memory traffic, far above it by its arithmetic. *BW floor* is its bandwidth floor: each "
          "pass's inputs read once at its own pixel and its output written once (report/floor/bandwidth/), the least any "
          "chain of these sizes and formats moves; *× BW* is time / bandwidth floor — how far the variant is from the "
          "memory system itself, not from its own fetch pattern. *Raw NaN/Inf* and *raw out of [0, 1]* count "
          "the values the passes computed before the guard that keeps the output finite and in range (all passes, all "
          "scenes), with how far the farthest lay outside [0, 1]; the output itself is always finite and in range. "
          "★ marks a Pareto-optimal variant: no other variant is both at least as fast and at least as accurate.\n\n";
    md << "![error against time](error_vs_time.png)\n\n";
}

// Every variant, fastest first, with its time, floor, errors and raw counts.
inline void write_variants(std::ostream& md, const report_data& d)
{
    md << "## Variants, fastest first\n\n";
    md << "| variant | ms | p10–p90 | floor ms | × floor | BW floor ms | × BW | RMSE default | ★ | RMSE calibrated | ★ | AO instructions | raw NaN/Inf | raw out of [0, 1] |\n";
    md << "|---|---:|---:|---:|---:|---:|---:|---:|:-:|---:|:-:|---:|---:|---:|\n";
    for (size_t i : detail::by_time(d.variants)) {
        const variant_record& v = d.variants[i];
        md << "| `" << v.name << "` | " << fixed(v.ms, 3) << " | " << detail::range(v.ms_p10, v.ms_p90) << " | " << fixed(v.floor_ms, 3) << " | "
           << fixed(v.floor_ratio, 2) << " | " << fixed(v.bandwidth_ms, 3) << " | " << fixed(v.bandwidth_ratio, 2) << " | " << fixed(v.rmse, 4) << " | " << (v.pareto ? "★" : "") << " | " << fixed(v.rmse_calibrated, 4)
           << " | " << (v.pareto_calibrated ? "★" : "") << " | " << v.ao_instructions << " | " << detail::raw_non_finite(v.raw, v.raw_measured)
           << " | " << detail::raw_range(v.raw, v.raw_measured) << " |\n";
    }
}

// The scenes: size, radius, valid pixels, the reference's own noise, clocks, strips.
inline void write_scenes(std::ostream& md, const report_data& d, const std::map<std::string, strip_file>& strips)
{
    md << "\n## Scenes\n\n";
    md << "The reference's own noise (RMS of the per-pixel Monte-Carlo standard error) adds to a variant's RMSE in quadrature; "
          "it must stay well below the errors above.\n\n";
    md << "Valid pixels are those scored; a hit farther from the camera than float geometry can place rays of the AO radius "
          "(truth::reliable_extent) has no reference to trust, and is left out (the count in brackets).\n\n";
    md << "| scene | size | AO radius | valid pixels | mean reference AO | reference noise | SM clock while timed | strip |\n";
    md << "|---|---|---:|---:|---:|---:|---|---|\n";
    for (const scene_record& s : d.scenes) {
        const auto strip = strips.find(s.scene.name);
        md << "| " << s.scene.name << (s.scene.renderer.point_cloud ? " (point cloud)" : "") << " | " << s.scene.camera.width << "×"
           << s.scene.camera.height << " | " << fixed(s.scene.ao_radius, 3) << " | " << s.valid_pixels
           << (s.truth.untrusted ? " (" + std::to_string(s.truth.untrusted) + " left out)" : "") << " | " << fixed(s.truth_mean, 4)
           << " | " << fixed(s.truth.noise_rms, 4) << " | " << (s.clocks.samples ? fixed(s.clocks.median, 0) + " MHz" : "–") << " | "
           << (strip == strips.end() ? "" : "[png](" + strip->second.path + ")") << " |\n";
    }
    double best = std::numeric_limits<double>::infinity(), noise = 0;
    for (const variant_record& v : d.variants)
        if (std::isfinite(v.rmse_calibrated)) best = std::min(best, v.rmse_calibrated);
    for (const scene_record& s : d.scenes) noise = std::max(noise, s.truth.noise_rms);
    md << "\nLargest reference noise: " << fixed(noise, 4) << "; smallest mean calibrated RMSE of any variant: " << fixed(best, 4) << ".\n\n";

    md << "Each scene's strip shows, per row, reference | variant (default parameters) | |variant − reference| (black 0, yellow ≥ "
       << fixed(heat_full_scale, 2) << "; background in blue-grey), for the variants Pareto-optimal on that scene by time and "
          "calibrated error, fastest first.\n";
}

// Per scene, every variant that ran on it.
inline void write_per_scene(std::ostream& md, const report_data& d, const std::map<std::string, strip_file>& strips)
{
    md << "\n## Per scene\n\n";
    md << "Columns: median ms and p10–p90; time / fetch floor; time / bandwidth floor; default RMSE, MAE, mean signed error (> 0: too light), "
          "99th-percentile |error|; calibrated RMSE and its power p; raw NaN/Inf and out-of-range values (all passes).\n";
    for (size_t s = 0; s < d.scenes.size(); ++s) {
        md << "\n### " << d.scenes[s].scene.name << "\n\n";
        const auto strip = strips.find(d.scenes[s].scene.name);
        if (strip != strips.end()) {
            md << "![" << d.scenes[s].scene.name << ": reference | variant | error](" << strip->second.path << ")\n\nRows: ";
            for (size_t k = 0; k < strip->second.variants.size(); ++k) md << (k ? ", " : "") << "`" << strip->second.variants[k] << "`";
            md << ".\n\n";
        }
        md << "| variant | ms | p10–p90 | × floor | × BW | RMSE | MAE | signed | p99 | RMSE cal. | p | raw NaN/Inf | raw out of [0, 1] |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (size_t i : detail::by_time(d.variants)) {
            const variant_record& v = d.variants[i];
            const run_record& r = v.runs[s];
            if (!r.ran()) continue;
            aogen::vulkan::raw_counts raw;
            for (const aogen::vulkan::raw_counts& c : r.raw) raw += c;
            md << "| `" << v.name << "` | " << fixed(r.ms.median, 3) << " | " << detail::range(r.ms.p10, r.ms.p90) << " | "
               << fixed(r.ms.median / r.floor_ms.median, 2) << " | " << fixed(r.ms.median / r.bandwidth_ms.median, 2) << " | " << fixed(r.plain.rmse, 4) << " | " << fixed(r.plain.mae, 4) << " | "
               << fixed(r.plain.mean_signed, 4) << " | " << fixed(r.plain.p99_abs, 3) << " | " << fixed(r.calibrated.rmse, 4) << " | "
               << fixed(r.power, 2) << " | " << detail::raw_non_finite(raw, !r.raw.empty()) << " | " << detail::raw_range(raw, !r.raw.empty())
               << " |\n";
        }
    }
}

// What leaving the point-cloud fallback out saves on mesh-only scenes.
inline void write_feature_saving(std::ostream& md, const report_data& d)
{
    md << "\n## Leaving features out\n\n";
    if (d.savings.empty()) md << "No SSAO variant without the point-cloud fallback, or no mesh-only scene: nothing to compare.\n";
    else {
        md << "On the mesh-only scenes, each SSAO variant as scene selection makes it (the point-cloud fallback left out: the "
              "scenes have no point clouds) beside the same variant with the fallback compiled in. Instructions are the AO shader's "
              "SPIR-V after spirv-opt; times are the median over the mesh-only scenes of the whole chain, the two timed in the "
              "same rounds, interleaved; the ratio is selected / everything on per scene and round (median, p10–p90): a "
              "spread that straddles 1 is no saving; saved = 1 − selected / everything on.\n\n";
        md << "| selected variant | AO instructions | everything on | saved | ms | everything on | time ratio | p10–p90 | RMSE | everything on |\n";
        md << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const feature_saving& f : d.savings)
            md << "| `" << f.selected << "` | " << f.selected_instructions << " | " << f.everything_on_instructions << " | "
               << detail::saved(f.selected_instructions, f.everything_on_instructions) << " | " << fixed(f.selected_ms, 3) << " | "
               << fixed(f.everything_on_ms, 3) << " | " << fixed(f.ratio.median, 3) << " | " << fixed(f.ratio.p10, 3) << "–" << fixed(f.ratio.p90, 3)
               << " | " << fixed(f.selected_rmse, 4) << " | " << fixed(f.everything_on_rmse, 4) << " |\n";
        md << "\nLeft out by selection: ";
        for (size_t i = 0; i < d.savings.front().left_out.size(); ++i) md << (i ? "; " : "") << d.savings.front().left_out[i];
        md << ".\n";
    }
}

// The runs that did not happen, grouped by why.
inline void write_not_run(std::ostream& md, const report_data& d)
{
    std::map<std::string, std::vector<std::string>> skipped; // reason → "variant on scene"
    for (const variant_record& v : d.variants)
        for (size_t s = 0; s < v.runs.size(); ++s)
            if (!v.runs[s].ran()) skipped[v.runs[s].skipped].push_back("`" + v.name + "` on " + d.scenes[s].scene.name);
    if (!skipped.empty()) {
        md << "\n## Not run\n\n";
        for (const auto& entry : skipped) {
            md << "- " << entry.first << ": " << entry.second.size() << (entry.second.size() == 1 ? " run" : " runs") << " (";
            for (size_t i = 0; i < entry.second.size() && i < 3; ++i) md << (i ? ", " : "") << entry.second[i];
            md << (entry.second.size() > 3 ? ", …" : "") << ")\n";
        }
    }
}

} // namespace detail

inline std::string report_markdown(const report_data& d, const report_meta& meta, const std::map<std::string, strip_file>& strips)
{
    std::ostringstream md;
    md << "# aogen report: AO error against run time\n\n";
    detail::write_measurement(md, d, meta);
    detail::write_how_to_read(md);
    detail::write_variants(md, d);
    detail::write_scenes(md, d, strips);
    detail::write_per_scene(md, d, strips);
    detail::write_feature_saving(md, d);
    detail::write_not_run(md, d);
    return md.str();
}

} // namespace aogen_report
