// aogen/vulkan/timing.hpp — per-pass GPU times of a chain: the median of K runs after warm-up.
//
//     aogen::vulkan::chain c(ctx, v);
//     std::vector<double> ms = aogen::vulkan::median_pass_ms(c, g, s, 10, 2);  // one per pass
//
// Each run is chain::run (timestamp queries around every pass: a dispatch, or a render
// pass for fragment variants); `warmup` runs are discarded first. Empty when the device's
// queue has no timestamps. aogen::error for K < 1 or warmup < 0.
#pragma once

#include "chain.hpp"

#include <algorithm>
#include <vector>

namespace aogen::vulkan {

inline std::vector<double> median_pass_ms(chain& c, const gbuffer& g, const chain_settings& s, int runs, int warmup = 1)
{
    require_range("vulkan timing runs", runs, 1, 100000);
    require_range("vulkan timing warmup", warmup, 0, 100000);
    for (int i = 0; i < warmup; ++i) c.run(g, s);
    std::vector<std::vector<double>> per_pass;
    for (int i = 0; i < runs; ++i) {
        const chain_result r = c.run(g, s);
        if (r.pass_ms.empty()) return {};
        per_pass.resize(r.pass_ms.size());
        for (size_t p = 0; p < r.pass_ms.size(); ++p) per_pass[p].push_back(r.pass_ms[p]);
    }
    std::vector<double> out;
    for (std::vector<double>& t : per_pass) {
        std::sort(t.begin(), t.end());
        const size_t n = t.size();
        out.push_back(n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]));
    }
    return out;
}

} // namespace aogen::vulkan
