// aogen_report/grid_search.hpp — the narrowing grid search tune.hpp fits parameters with.
//
//     std::vector<aogen_report::search_axis> axes{{"strength", 0.25, 3.0}, {"radius_scale", 0.5, 2.0}};
//     aogen_report::grid_search_result r = aogen_report::narrowing_grid_search(axes, 5, 3, f);
//     r.best;  // one value per axis, the lowest f found; r.value, r.evaluations
//
// Each round evaluates f at every combination of `points` values spread evenly over each
// axis's current range (points^axes evaluations), keeps the lowest, and shrinks every range
// to one grid step either side of it (never outside the axis's first range). XeGTAO's
// auto-tune narrows the same way. f must be deterministic; ties keep the first found.
#pragma once

#include <aogen/error.hpp>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace aogen_report {

struct search_axis {
    std::string name;
    double lo, hi; // the first round's range
};

struct grid_search_result {
    std::vector<double> best;
    double value = 0;
    size_t evaluations = 0;
};

inline grid_search_result narrowing_grid_search(const std::vector<search_axis>& axes, int points, int rounds,
                                                const std::function<double(const std::vector<double>&)>& f)
{
    if (axes.empty() || points < 2 || rounds < 1)
        aogen::fail("grid search", "needs an axis, 2 points per axis and 1 round", "valid: axes non-empty, points >= 2, rounds >= 1");
    const size_t n = axes.size();
    std::vector<double> lo(n), hi(n);
    for (size_t i = 0; i < n; ++i) {
        if (!(axes[i].lo <= axes[i].hi)) aogen::fail("grid search axis " + axes[i].name, "has lo > hi", "valid: lo <= hi");
        lo[i] = axes[i].lo, hi[i] = axes[i].hi;
    }
    grid_search_result r;
    r.best = lo;
    bool found = false;
    size_t combos = 1;
    for (size_t i = 0; i < n; ++i) combos *= size_t(points);
    for (int round = 0; round < rounds; ++round) {
        std::vector<double> step(n);
        for (size_t i = 0; i < n; ++i) step[i] = (hi[i] - lo[i]) / double(points - 1);
        for (size_t k = 0; k < combos; ++k) {
            std::vector<double> x(n);
            size_t rest = k;
            for (size_t i = 0; i < n; ++i) x[i] = lo[i] + step[i] * double(rest % size_t(points)), rest /= size_t(points);
            const double value = f(x);
            ++r.evaluations;
            if (!found || value < r.value) r.value = value, r.best = x, found = true;
        }
        for (size_t i = 0; i < n; ++i) {
            lo[i] = std::max(axes[i].lo, r.best[i] - step[i]);
            hi[i] = std::min(axes[i].hi, r.best[i] + step[i]);
        }
    }
    return r;
}

} // namespace aogen_report
