// aogen_report/summary.hpp — the report's summaries of its records: the calibrated column,
// each variant's means and medians over its scenes, the Pareto marks, the feature saving.
//
//     aogen_report::detail::summarise_all(data, twin_of);   // after every scene
//
// The calibrated column: ao^p, p fitted on the other scenes (calibrate.hpp). Per variant:
// the mean RMSE over the scenes it ran on (of the single frame, calibrated, and after the
// report's frames), the mean of its bent normals' mean angular error (-bn variants: over the
// scenes with a surface pixel), the median of its per-scene median times, p10
// and p90, its fetch floor and time / floor. Pareto-optimal variants by time against
// default, calibrated and accumulated RMSE (pareto.hpp). The feature saving: each SSAO variant without
// the point-cloud fallback against its twin with it on the mesh-only scenes.
#pragma once

#include "calibrate.hpp"
#include "metrics.hpp"
#include "pareto.hpp"
#include "records.hpp"

#include <aogen/parallel.hpp>
#include <aogen/selection.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace aogen_report {

namespace detail {

inline double median(std::vector<double> v)
{
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    return aogen::vulkan::spread_of(std::move(v)).median;
}

// The calibrated column of one variant: leave-one-out powers over the scenes it ran on.
// apply_power(ao.full(W, H), p): the read-back AO raised to `p` at the screen's size, the
// power taken once per 8-bit level instead of once per pixel (apply_power's own expression on
// the same 256 values k / 255: the same floats). Calibration runs after every scene for every
// scene so far, and the per-pixel pow was most of it.
inline std::vector<float> powered_full(const ao_readback& ao, double p, int W, int H)
{
    float level[256];
    for (int k = 0; k < 256; ++k) level[k] = apply_power(float(k) / 255.0f, p);
    std::vector<float> powered(ao.unorm.size());
    for (size_t i = 0; i < powered.size(); ++i) powered[i] = level[ao.unorm[i]];
    return upsample(powered, ao.width, ao.height, ao.factor, W, H);
}

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
        r.calibrated = compare(powered_full(r.ao, r.power, truth.width, truth.height), truth.ao, truth.valid);
    }
}

inline void summarise_variant(variant_record& v)
{
    double plain = 0, calibrated = 0, accumulated = 0, bent = 0;
    int count = 0, bent_count = 0;
    std::vector<double> ms, p10, p90, floors, ratios, bandwidths, bandwidth_ratios;
    v.raw = {};
    v.raw_measured = false;
    for (const run_record& r : v.runs) {
        if (!r.ran()) continue;
        plain += r.plain.rmse, calibrated += r.calibrated.rmse, accumulated += r.accumulated.rmse, ++count;
        if (r.bent.pixels > 0) bent += r.bent.mean_degrees, ++bent_count;
        for (const aogen::vulkan::raw_counts& c : r.raw) v.raw += c;
        v.raw_measured = v.raw_measured || !r.raw.empty();
        ms.push_back(r.ms.median), p10.push_back(r.ms.p10), p90.push_back(r.ms.p90);
        floors.push_back(r.floor_ms.median), ratios.push_back(r.ms.median / r.floor_ms.median);
        bandwidths.push_back(r.bandwidth_ms.median), bandwidth_ratios.push_back(r.ms.median / r.bandwidth_ms.median);
    }
    if (count > 0) v.rmse = plain / count, v.rmse_calibrated = calibrated / count, v.rmse_accumulated = accumulated / count;
    if (bent_count > 0) v.bent_degrees = bent / bent_count;
    v.ms = median(ms), v.ms_p10 = median(p10), v.ms_p90 = median(p90);
    v.floor_ms = median(floors), v.floor_ratio = median(ratios);
    v.bandwidth_ms = median(bandwidths), v.bandwidth_ratio = median(bandwidth_ratios);
}

inline void mark_pareto(std::vector<variant_record>& variants)
{
    std::vector<double> ms, plain, calibrated, accumulated;
    for (const variant_record& v : variants)
        ms.push_back(v.ms), plain.push_back(v.rmse), calibrated.push_back(v.rmse_calibrated), accumulated.push_back(v.rmse_accumulated);
    const std::vector<bool> p = pareto_optimal(ms, plain), pc = pareto_optimal(ms, calibrated), pa = pareto_optimal(ms, accumulated);
    for (size_t i = 0; i < variants.size(); ++i) variants[i].pareto = p[i], variants[i].pareto_calibrated = pc[i], variants[i].pareto_accumulated = pa[i];
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
        summarise_variant(v);
    });
    mark_pareto(out.variants);
    out.savings.clear();
    for (size_t t = 0; t < out.twins.size(); ++t) {
        const std::optional<feature_saving> f = compare_twin(out.variants[size_t(twin_of[t])], out.twins[t], out.scenes.size());
        if (f) out.savings.push_back(*f);
    }
}

} // namespace detail

} // namespace aogen_report
