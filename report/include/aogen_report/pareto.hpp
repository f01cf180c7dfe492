// aogen_report/pareto.hpp — which variants are worth running: those no other variant beats
// on both run time and error.
//
//     std::vector<bool> best = aogen_report::pareto_optimal(ms, rmse);
//
// Point i is Pareto-optimal when no point j is at least as fast and at least as accurate
// and strictly better in one of the two. Points with a non-finite time or error are never
// optimal and never dominate (a variant that was not measured is not a trade-off).
#pragma once

#include <aogen/error.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace aogen_report {

inline std::vector<bool> pareto_optimal(const std::vector<double>& time, const std::vector<double>& error)
{
    if (time.size() != error.size())
        aogen::fail("pareto", std::to_string(time.size()) + " times and " + std::to_string(error.size()) + " errors",
                    "valid: one time and one error per variant");
    const size_t n = time.size();
    const auto finite = [&](size_t i) { return std::isfinite(time[i]) && std::isfinite(error[i]); };
    std::vector<bool> optimal(n, false);
    for (size_t i = 0; i < n; ++i) {
        if (!finite(i)) continue;
        bool dominated = false;
        for (size_t j = 0; j < n && !dominated; ++j)
            dominated = j != i && finite(j) && time[j] <= time[i] && error[j] <= error[i] && (time[j] < time[i] || error[j] < error[i]);
        optimal[i] = !dominated;
    }
    return optimal;
}

} // namespace aogen_report
