// aogen_report/calibrate.hpp — the report's calibrated error column: each variant's AO
// raised to the power p that best fits the ground truth on the *other* scenes.
//
// WHY
//   A variant's default parameters (SSAO strength 1, GTAO visibility², ...) decide how dark
//   its AO is, and a renderer tunes that by eye. Calibration separates "how dark" from "how
//   right": p minimises the squared error of ao^p against the truth, each scene weighted
//   equally, and a scene is always scored with the p fitted on the scenes other than itself
//   (leave-one-out), so no scene is scored on a fit made on it. ao^p is what a
//   strength/power setting does: GTAO's strength is exactly that exponent
//   (visibility^(strength·p)); for SSAO's linear strength form it is the nearest one-knob
//   equivalent, applied to the output.
//
// HOW
//   The AO comes back from the GPU quantised (R8: 256 levels), so a scene is summarised
//   once, per distinct AO value a, by the count n, Σt and Σt² of the truths t at those
//   pixels; then its mean squared error at any p costs one pow per level:
//       MSE(p) = Σ_a (n·a^(2p) − 2·a^p·Σt + Σt²) / N.
//   p is searched in log space on [1/8, 8]: a 65-point scan, then golden-section search
//   between the best scan point's neighbours. Everything is in a fixed order, so the same
//   images give the same p.
//
// USAGE
//     std::vector<aogen_report::calibration_scene> scenes;
//     scenes.push_back(aogen_report::summarise(ao, truth, valid));   // one per scene
//     std::vector<double> p = aogen_report::leave_one_out_powers(scenes);
//     std::vector<float> calibrated = aogen_report::apply_power(ao, p[s]);
#pragma once

#include <aogen/error.hpp>

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace aogen_report {

inline constexpr double calibration_power_min = 1.0 / 8.0;
inline constexpr double calibration_power_max = 8.0;

// One scene's valid pixels, summarised per distinct AO value.
struct calibration_scene {
    struct level {
        double ao = 0;
        double count = 0, truth_sum = 0, truth_squares = 0;
    };
    std::vector<level> levels; // ascending AO
    double pixels = 0;
};

// Summarises the valid, finite pixels of one scene (AO clamped to [0, 1], as ao^p needs).
// AO read back from an R8 target holds only the 256 values k/255: those are binned by k
// directly; any other value goes through a sorted map. Both give the levels in ascending
// order with the sums taken in pixel order, so the summary is the same either way.
inline calibration_scene summarise(const std::vector<float>& ao, const std::vector<float>& truth, const std::vector<uint8_t>& valid)
{
    if (ao.size() != truth.size() || ao.size() != valid.size())
        aogen::fail("calibration", "images of " + std::to_string(ao.size()) + ", " + std::to_string(truth.size()) + " and " +
                                       std::to_string(valid.size()) + " pixels",
                    "valid: AO, truth and mask of the same size");
    calibration_scene::level unorm8[256] = {};
    std::map<float, calibration_scene::level> other;
    for (size_t i = 0; i < ao.size(); ++i) {
        if (!valid[i] || !std::isfinite(ao[i])) continue;
        const float a = std::fmin(std::fmax(ao[i], 0.0f), 1.0f);
        const long k = std::lround(a * 255.0f);
        calibration_scene::level& l = float(k) / 255.0f == a ? unorm8[k] : other[a];
        l.ao = a;
        l.count += 1;
        l.truth_sum += truth[i];
        l.truth_squares += double(truth[i]) * truth[i];
    }
    for (int k = 0; k < 256; ++k)
        if (unorm8[k].count > 0) other.emplace(unorm8[k].ao, unorm8[k]);
    calibration_scene s;
    for (const auto& entry : other) {
        s.levels.push_back(entry.second);
        s.pixels += entry.second.count;
    }
    return s;
}

// Mean squared error of ao^p against the truth over one scene's pixels.
inline double mean_squared_error(const calibration_scene& s, double p)
{
    if (s.pixels == 0) return 0;
    double sum = 0;
    for (const calibration_scene::level& l : s.levels) {
        const double a = std::pow(l.ao, p);
        sum += l.count * a * a - 2 * a * l.truth_sum + l.truth_squares;
    }
    return sum / s.pixels;
}

// The p in [1/8, 8] minimising the mean over `scenes` of each one's MSE, skipping scene
// `skip` (−1: none). 1 when no scene has pixels (nothing to fit on).
inline double fit_power(const std::vector<calibration_scene>& scenes, int skip = -1)
{
    int fitted = 0;
    for (size_t s = 0; s < scenes.size(); ++s)
        if (int(s) != skip && scenes[s].pixels > 0) ++fitted;
    if (fitted == 0) return 1.0;
    const auto cost = [&](double log_p) {
        double sum = 0;
        for (size_t s = 0; s < scenes.size(); ++s)
            if (int(s) != skip && scenes[s].pixels > 0) sum += mean_squared_error(scenes[s], std::exp(log_p));
        return sum / fitted;
    };
    const double lo = std::log(calibration_power_min), hi = std::log(calibration_power_max);
    const int scan = 64;
    int best = 0;
    double best_cost = cost(lo);
    for (int k = 1; k <= scan; ++k) {
        const double c = cost(lo + (hi - lo) * k / scan);
        if (c < best_cost) best = k, best_cost = c;
    }
    // Golden-section search between the neighbours of the best scan point.
    double a = lo + (hi - lo) * std::max(best - 1, 0) / scan;
    double b = lo + (hi - lo) * std::min(best + 1, scan) / scan;
    const double g = (std::sqrt(5.0) - 1) / 2;
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double c1 = cost(x1), c2 = cost(x2);
    for (int i = 0; i < 48; ++i) {
        if (c1 <= c2) b = x2, x2 = x1, c2 = c1, x1 = b - g * (b - a), c1 = cost(x1);
        else a = x1, x1 = x2, c1 = c2, x2 = a + g * (b - a), c2 = cost(x2);
    }
    const double log_p = 0.5 * (a + b);
    return cost(log_p) <= best_cost ? std::exp(log_p) : std::exp(lo + (hi - lo) * best / scan);
}

// For each scene, the power fitted on all the others.
inline std::vector<double> leave_one_out_powers(const std::vector<calibration_scene>& scenes)
{
    std::vector<double> p;
    for (size_t s = 0; s < scenes.size(); ++s) p.push_back(fit_power(scenes, int(s)));
    return p;
}

// a^p (a clamped to [0, 1] first); a non-finite value stays as it is, so the metrics still
// count it.
inline float apply_power(float a, double p)
{
    return std::isfinite(a) ? float(std::pow(std::fmin(std::fmax(double(a), 0.0), 1.0), p)) : a;
}

// ao^p per pixel (apply_power of each).
inline std::vector<float> apply_power(const std::vector<float>& ao, double p)
{
    std::vector<float> out(ao.size());
    for (size_t i = 0; i < ao.size(); ++i) out[i] = apply_power(ao[i], p);
    return out;
}

} // namespace aogen_report
