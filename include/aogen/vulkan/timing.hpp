// aogen/vulkan/timing.hpp — GPU times of bound chains, taken as a frame loop runs them.
//
// WHAT
//   time_chains(ctx, chains, options) times one or more bound chains (bound_chain.hpp):
//     1. warm-up: the chains are recorded back to back, untimed, and submitted again and
//        again — at least options.warmup_ms of wall-clock time of continuous GPU work, and
//        then until two submissions of the same size agree within 3 % (settled), at most
//        options.warmup_max_ms — so the GPU leaves its idle clock before anything is
//        timed. Measured on an NVIDIA H200 (aogen_clock_probe, BENCHMARKS.md): idle at
//        345 MHz, a chain runs 4.6× slow; the clock jumps to 1980 MHz after 250–300 ms of
//        continuous work, holds through idle gaps of 1 s and has dropped after 2 s. Each
//        submission is made longer (up to ~1/4 of the warm-up) until the GPU spends far
//        more time working than waiting for the next submission.
//     2. rounds: options.rounds command buffers, each holding `iterations` iterations of
//        every chain, interleaved — A B C A B C ... — with a timestamp before
//        the first pass and after every pass of every iteration (bound_chain::record). So
//        chains that are compared are timed in the same state of the clock, a clock still
//        ramping favours none of them, and there are no gaps between iterations for it to
//        drop in. `iterations` is options.iterations, or, with options.budget_ms > 0, as
//        many (at least 1, at most options.iterations) as fit the budget: the warm-up's
//        last submission says what one iteration of every chain costs. So one setting
//        serves a GPU, where 20 iterations of a hundred chains take milliseconds, and a
//        CPU device, where one takes half a second.
//   Per chain: per pass and for the whole chain the median, 10th and 90th percentile
//   (nearest rank) over all rounds × iterations, each iteration's total, and each round's
//   median (round_ms: a drift across rounds means the clock was not settled).
//   A second source for the timestamps themselves: rounds_gpu_ms is the span from each
//   round's first timestamp to its last, rounds_wall_ms the host's wall clock from submit
//   to fence, summed over the rounds. A GPU kept busy back to back has a span just under
//   the wall time; timestamps that run slow or fast (a driver quirk, a wrong period) or
//   a GPU that idles inside a round show as a ratio far from 1.
//   Never touches the device's clock or power settings: it only keeps the GPU busy.
//   Devices whose queue has no timestamps give empty results.
//
// USAGE
//     std::unique_ptr<aogen::vulkan::bound_chain> a = chain_a.bind(g, s), b = chain_b.bind(g, s);
//     aogen::vulkan::timing_options o;                  // 5 rounds × 20 iterations, 500 ms+ warm-up, no budget
//     aogen::vulkan::timing_result t = aogen::vulkan::time_chains(ctx, {a.get(), b.get()}, o);
//     t.chains[0].total.median;                         // ms
//     t.chains[1].passes[0].p90;                        // ms, the AO pass of chain b
//
// ERRORS
//   aogen::error: rounds or iterations outside 1..100000, a negative warm-up, no chains, a
//   failing Vulkan call.
#pragma once

#include "bound_chain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

namespace aogen::vulkan {

struct timing_options {
    int rounds = 5;              // command buffers of timed iterations
    int iterations = 20;         // iterations of every chain in each round, interleaved (the most, with a budget)
    double warmup_ms = 500;      // continuous untimed GPU work first (wall clock), at least...
    double budget_ms = 0;        // > 0: fewer iterations where rounds × iterations would take longer
    double warmup_max_ms = 5000; // ...and until settled, at most this
};

// A distribution of times, in milliseconds: median, 10th and 90th percentiles.
struct spread {
    double median = std::numeric_limits<double>::quiet_NaN();
    double p10 = std::numeric_limits<double>::quiet_NaN();
    double p90 = std::numeric_limits<double>::quiet_NaN();
};

// The nearest-rank percentile q (0..100) of `v` (sorted here); NaN when empty.
inline double percentile(std::vector<double> v, double q)
{
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const size_t rank = std::max<size_t>(1, static_cast<size_t>(std::ceil(q / 100.0 * double(v.size()))));
    return v[std::min(rank, v.size()) - 1];
}

// The median (the mean of the middle two for an even count), p10 and p90 of `v`.
inline spread spread_of(std::vector<double> v)
{
    spread s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    s.p10 = percentile(v, 10);
    s.p90 = percentile(v, 90);
    return s;
}

struct chain_times {
    std::vector<spread> passes;    // per pass
    spread total;                  // the whole chain, per iteration
    std::vector<double> total_ms;  // every iteration's total, round by round
    std::vector<double> round_ms;  // each round's median total
};

struct timing_result {
    std::vector<chain_times> chains; // in the order given; empty without timestamps
    double warmup_ms = 0;            // warm-up actually run (wall clock)
    int warmup_submissions = 0;
    bool settled = false;            // the warm-up's last two submissions agreed (or there was no warm-up)
    std::chrono::steady_clock::time_point rounds_begin, rounds_end; // when the timed rounds ran (host clock)
    int iterations = 0;              // per round, as run (options.iterations, or fewer under a budget)
    double rounds_gpu_ms = 0;        // Σ over rounds of last − first timestamp
    double rounds_wall_ms = 0;       // Σ over rounds of submit-to-fence wall clock
};

namespace detail {

// One primary command buffer of a pool of `sc`, begun (reusable: not one-time).
inline VkCommandBuffer begin_reusable(context& ctx, resource_scope& sc)
{
    VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cpci.queueFamilyIndex = ctx.queue_family();
    cpci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    VkCommandPool pool;
    check(vkCreateCommandPool(ctx.device(), &cpci, nullptr, &pool), "vkCreateCommandPool");
    sc.own(pool, vkDestroyCommandPool);
    VkCommandBufferAllocateInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cbi.commandPool = pool;
    cbi.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cbi.commandBufferCount = 1;
    VkCommandBuffer cb;
    check(vkAllocateCommandBuffers(ctx.device(), &cbi, &cb), "vkAllocateCommandBuffers");
    return cb;
}

inline void begin(VkCommandBuffer cb)
{
    check(vkResetCommandBuffer(cb, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo bbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bbi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cb, &bbi), "vkBeginCommandBuffer");
}

// Ends, submits and waits for `cb` (the fence reset for the next use).
inline void submit_and_wait(context& ctx, VkCommandBuffer cb, VkFence fence)
{
    check(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cb;
    check(vkQueueSubmit(ctx.queue(), 1, &si, fence), "vkQueueSubmit");
    check(vkWaitForFences(ctx.device(), 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetFences(ctx.device(), 1, &fence), "vkResetFences");
}

// `ticks` timestamp ticks in ms (masked to the queue's valid bits).
inline double ticks_ms(const context& ctx, uint64_t ticks)
{
    const uint64_t mask = ctx.timestamp_valid_bits() >= 64 ? ~0ull : (1ull << ctx.timestamp_valid_bits()) - 1;
    return double(ticks & mask) * ctx.timestamp_period_ns() * 1e-6;
}

inline double elapsed_ms(std::chrono::steady_clock::time_point since)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

// Records `repeats` untimed iterations of every chain, submits and waits: the wall-clock ms.
inline double run_untimed(context& ctx, const std::vector<const bound_chain*>& chains, int repeats, VkCommandBuffer cb, VkFence fence)
{
    const auto submitted = std::chrono::steady_clock::now();
    begin(cb);
    for (int k = 0; k < repeats; ++k)
        for (const bound_chain* c : chains) c->record(cb);
    submit_and_wait(ctx, cb, fence);
    return elapsed_ms(submitted);
}

// Keeps the GPU busy with `chains` for at least o.warmup_ms of wall-clock time, then until
// settled (two submissions of the same size within 3 % of each other), at most
// o.warmup_max_ms; returns the wall-clock ms one iteration of every chain took in the last
// submission (0 when the warm-up allowed none).
inline double warm_up(context& ctx, const std::vector<const bound_chain*>& chains, const timing_options& o, VkCommandBuffer cb,
                      VkFence fence, timing_result& out)
{
    const auto start = std::chrono::steady_clock::now();
    int repeats = 1; // iterations of every chain per submission
    double per_iteration = 0, previous = 0;
    out.settled = o.warmup_ms <= 0;
    while (elapsed_ms(start) < o.warmup_ms || (!out.settled && elapsed_ms(start) < std::max(o.warmup_ms, o.warmup_max_ms))) {
        const double took = run_untimed(ctx, chains, repeats, cb, fence);
        ++out.warmup_submissions;
        per_iteration = took / repeats;
        // Longer submissions until one fills a quarter of the warm-up: the host's turnaround
        // between them is then a small fraction of the GPU's working time.
        if (took < o.warmup_ms / 4 && repeats < (1 << 16)) {
            repeats *= 2;
            previous = 0; // a different size: not comparable
            continue;
        }
        out.settled = previous > 0 && std::fabs(per_iteration - previous) <= 0.03 * previous;
        previous = per_iteration;
    }
    out.warmup_ms = elapsed_ms(start);
    return per_iteration;
}

// Iterations per round: o.iterations, or as many as fit o.budget_ms (at least 1).
inline int iterations_for(const timing_options& o, double per_iteration_ms)
{
    if (!(o.budget_ms > 0) || !(per_iteration_ms > 0)) return o.iterations;
    const double fit = o.budget_ms / (o.rounds * per_iteration_ms);
    return fit >= o.iterations ? o.iterations : std::max(1, int(fit));
}

} // namespace detail

inline timing_result time_chains(context& ctx, const std::vector<const bound_chain*>& chains, const timing_options& o = {})
{
    require_range("vulkan timing rounds", o.rounds, 1, 100000);
    require_range("vulkan timing iterations", o.iterations, 1, 100000);
    if (!(o.warmup_ms >= 0)) fail("vulkan timing warmup_ms", format_number(o.warmup_ms) + " is out of range", "valid: >= 0");
    if (!(o.budget_ms >= 0)) fail("vulkan timing budget_ms", format_number(o.budget_ms) + " is out of range", "valid: >= 0 (0: no budget)");
    if (!(o.warmup_max_ms >= 0)) fail("vulkan timing warmup_max_ms", format_number(o.warmup_max_ms) + " is out of range", "valid: >= 0");
    if (chains.empty()) fail("vulkan timing", "no chains", "valid: at least one bound chain");
    timing_result out;
    if (ctx.timestamp_valid_bits() == 0) return out;

    resource_scope sc(ctx);
    VkCommandBuffer cb = detail::begin_reusable(ctx, sc);
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    check(vkCreateFence(ctx.device(), &fci, nullptr, &fence), "vkCreateFence");
    sc.own(fence, vkDestroyFence);

    double per_iteration_ms = detail::warm_up(ctx, chains, o, cb, fence, out);
    if (o.budget_ms > 0 && per_iteration_ms == 0) per_iteration_ms = detail::run_untimed(ctx, chains, 1, cb, fence); // to size the rounds
    out.iterations = detail::iterations_for(o, per_iteration_ms);

    // Query slots of one round: iteration k of chain c starts at first[c] + k * per_iteration.
    std::vector<uint32_t> first(chains.size());
    uint32_t per_iteration = 0;
    for (size_t c = 0; c < chains.size(); ++c) first[c] = per_iteration, per_iteration += chains[c]->queries();
    const uint32_t queries = per_iteration * static_cast<uint32_t>(out.iterations);
    VkQueryPoolCreateInfo qpi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qpi.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qpi.queryCount = queries;
    VkQueryPool pool;
    check(vkCreateQueryPool(ctx.device(), &qpi, nullptr, &pool), "vkCreateQueryPool");
    sc.own(pool, vkDestroyQueryPool);

    std::vector<std::vector<std::vector<double>>> per_pass(chains.size()); // [chain][pass][sample]
    out.chains.resize(chains.size());
    for (size_t c = 0; c < chains.size(); ++c) per_pass[c].resize(chains[c]->passes().size());
    out.rounds_begin = std::chrono::steady_clock::now();
    for (int round = 0; round < o.rounds; ++round) {
        detail::begin(cb);
        vkCmdResetQueryPool(cb, pool, 0, queries);
        for (int k = 0; k < out.iterations; ++k)
            for (size_t c = 0; c < chains.size(); ++c) chains[c]->record(cb, {pool, first[c] + static_cast<uint32_t>(k) * per_iteration});
        const auto submitted = std::chrono::steady_clock::now();
        detail::submit_and_wait(ctx, cb, fence);
        out.rounds_wall_ms += detail::elapsed_ms(submitted);
        const std::vector<uint64_t> ticks = read_queries(ctx, pool, queries);
        out.rounds_gpu_ms += detail::ticks_ms(ctx, ticks.back() - ticks.front());
        for (size_t c = 0; c < chains.size(); ++c) {
            std::vector<double> totals;
            for (int k = 0; k < out.iterations; ++k) {
                const std::vector<double> ms = chains[c]->pass_ms(ticks, first[c] + static_cast<size_t>(k) * per_iteration);
                double total = 0;
                for (size_t p = 0; p < ms.size(); ++p) per_pass[c][p].push_back(ms[p]), total += ms[p];
                totals.push_back(total);
            }
            out.chains[c].round_ms.push_back(spread_of(totals).median);
            out.chains[c].total_ms.insert(out.chains[c].total_ms.end(), totals.begin(), totals.end());
        }
    }
    out.rounds_end = std::chrono::steady_clock::now();
    for (size_t c = 0; c < chains.size(); ++c) {
        for (const std::vector<double>& samples : per_pass[c]) out.chains[c].passes.push_back(spread_of(samples));
        out.chains[c].total = spread_of(out.chains[c].total_ms);
    }
    return out;
}

// One chain alone.
inline chain_times time_chain(context& ctx, const bound_chain& c, const timing_options& o = {})
{
    timing_result r = time_chains(ctx, {&c}, o);
    return r.chains.empty() ? chain_times{} : r.chains.front();
}

} // namespace aogen::vulkan
