// aogen/parallel.hpp — a parallel loop over indices that survives an exception.
//
// WHAT
//   aogen::parallel_for(n, f, threads) calls f(i) once for every i in [0, n), on up to
//   `threads` threads (the calling thread one of them; default: every core), and returns
//   when all calls have returned. The first exception any call threw is rethrown on the
//   calling thread once every thread has stopped.
//
// USAGE
//     #include <aogen/parallel.hpp>
//     std::vector<float> ao(n);
//     aogen::parallel_for(n, [&](size_t i) { ao[i] = trace(i); });   // results by index
//
// WHY
//   A std::thread still running when its owner unwinds calls std::terminate: an exception in
//   one ray or one compile would abort the whole program instead of reaching the error
//   message that names the input. Here every thread catches, the pool is always joined,
//   and the caller sees one ordinary exception. Indices are handed out one at a time, so the
//   work balances; results that depend on i alone (a pixel's rays seeded by its index) are
//   the same for any thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace aogen {

template <class F>
void parallel_for(size_t n, F f, unsigned threads = std::thread::hardware_concurrency())
{
    std::atomic<size_t> next{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    const auto work = [&] {
        for (size_t i = next++; i < n; i = next++) {
            try {
                f(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    const unsigned count = unsigned(std::min<size_t>(std::max(1u, threads), std::max<size_t>(1, n)));
    for (unsigned t = 1; t < count; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

} // namespace aogen
