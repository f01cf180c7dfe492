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

} // namespace aogen_report
