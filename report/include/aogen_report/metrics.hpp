// aogen_report/metrics.hpp — how far an AO image is from the ground truth.
//
// WHAT
//   compare(ao, truth, valid) measures a variant's AO against ray-traced ground truth
//   over the valid (non-background) pixels only:
//     rmse, mae         root-mean-square and mean absolute error
//     mean_signed       mean of (ao − truth): > 0 means too light (under-occluded)
//     p99_abs           the 99th percentile of |ao − truth| (nearest-rank)
//     non_finite        pixels whose AO is NaN or ±inf (counted, left out of the rest)
//     pixels            valid pixels with a finite AO
//   Sums are in double and in pixel order, so the same images give the same numbers.
//   compare_bent_normals(normals, truth, valid) measures bent normals (3 floats per pixel,
//   both in one space) by the angle between them over the valid pixels:
//     mean_degrees      the mean angle; a pixel whose normal is zero or not finite (none
//                       written where a surface is) counts as 90 degrees and in `missing`
//     p90_degrees       the 90th percentile (nearest-rank)
//
// USAGE
//     aogen_report::error_metrics m = aogen_report::compare(ao, truth, valid);
//     m.rmse; m.p99_abs; m.non_finite;
#pragma once

#include <aogen/error.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace aogen_report {

struct error_metrics {
    double rmse = 0, mae = 0, mean_signed = 0, p99_abs = 0;
    size_t non_finite = 0;
    size_t pixels = 0;
};

// `valid[i]` != 0 marks a pixel the truth covers (not background).
inline error_metrics compare(const std::vector<float>& ao, const std::vector<float>& truth,
                             const std::vector<uint8_t>& valid)
{
    if (ao.size() != truth.size() || ao.size() != valid.size())
        aogen::fail("metrics", "images of " + std::to_string(ao.size()) + ", " + std::to_string(truth.size()) +
                                   " and " + std::to_string(valid.size()) + " pixels",
                    "valid: AO, truth and mask of the same size");
    error_metrics m;
    std::vector<double> abs_errors;
    double squared = 0, absolute = 0, signed_sum = 0;
    for (size_t i = 0; i < ao.size(); ++i) {
        if (!valid[i]) continue;
        if (!std::isfinite(ao[i])) {
            ++m.non_finite;
            continue;
        }
        const double e = double(ao[i]) - double(truth[i]);
        squared += e * e;
        absolute += std::fabs(e);
        signed_sum += e;
        abs_errors.push_back(std::fabs(e));
    }
    m.pixels = abs_errors.size();
    if (m.pixels == 0) return m;
    const double n = double(m.pixels);
    m.rmse = std::sqrt(squared / n);
    m.mae = absolute / n;
    m.mean_signed = signed_sum / n;
    // Nearest rank: the smallest value with at least 99 % of the errors at or below it.
    const size_t rank = static_cast<size_t>(std::ceil(0.99 * n)); // 1-based
    std::nth_element(abs_errors.begin(), abs_errors.begin() + (rank - 1), abs_errors.end());
    m.p99_abs = abs_errors[rank - 1];
    return m;
}

struct bent_normal_metrics {
    double mean_degrees = std::numeric_limits<double>::quiet_NaN(), p90_degrees = mean_degrees;
    size_t missing = 0; // valid pixels without a normal: counted as 90 degrees
    size_t pixels = 0;  // valid pixels whose true bent normal is known
};

// The angle between directions a and b (3 floats each, any length) in degrees; NaN where
// either is zero or not finite.
inline double angle_degrees(const float* a, const float* b)
{
    const double aa = double(a[0]) * a[0] + double(a[1]) * a[1] + double(a[2]) * a[2];
    const double bb = double(b[0]) * b[0] + double(b[1]) * b[1] + double(b[2]) * b[2];
    if (!(aa > 0 && bb > 0 && std::isfinite(aa) && std::isfinite(bb))) return std::numeric_limits<double>::quiet_NaN();
    const double cosine = (double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2]) / std::sqrt(aa * bb);
    return std::acos(std::clamp(cosine, -1.0, 1.0)) * (180.0 / 3.14159265358979323846);
}

inline bent_normal_metrics compare_bent_normals(const std::vector<float>& normals, const std::vector<float>& truth, const std::vector<uint8_t>& valid)
{
    if (normals.size() != truth.size() || normals.size() != 3 * valid.size())
        aogen::fail("metrics", "bent normals of " + std::to_string(normals.size() / 3) + " and " + std::to_string(truth.size() / 3) +
                                   " pixels and a mask of " + std::to_string(valid.size()),
                    "valid: two images of 3 floats per pixel and a mask of the same size");
    bent_normal_metrics m;
    std::vector<double> angles;
    double sum = 0;
    for (size_t i = 0; i < valid.size(); ++i) {
        const float* t = &truth[3 * i];
        if (!valid[i] || !(std::isfinite(t[0]) && std::isfinite(t[1]) && std::isfinite(t[2]))) continue;
        double angle = angle_degrees(&normals[3 * i], t);
        if (std::isnan(angle)) angle = 90.0, ++m.missing;
        angles.push_back(angle);
        sum += angle;
    }
    m.pixels = angles.size();
    if (m.pixels == 0) return m;
    m.mean_degrees = sum / double(m.pixels);
    const size_t rank = static_cast<size_t>(std::ceil(0.9 * double(m.pixels))); // nearest rank, 1-based
    std::nth_element(angles.begin(), angles.begin() + (rank - 1), angles.end());
    m.p90_degrees = angles[rank - 1];
    return m;
}

} // namespace aogen_report
