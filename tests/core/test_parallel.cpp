// aogen::parallel_for: every index once, and an exception in one call reaches the caller
// after every thread has stopped (a thread left running as the stack unwinds would call
// std::terminate: the reference tracer once aborted so on a bad ray grid).
#include <aogen/parallel.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <stdexcept>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_parallel {

TEST_CASE("parallel: every index runs exactly once, on any thread count", "[parallel]")
{
    for (unsigned threads : {1u, 2u, 7u}) {
        std::vector<std::atomic<int>> calls(1000);
        aogen::parallel_for(calls.size(), [&](size_t i) { ++calls[i]; }, threads);
        for (const std::atomic<int>& c : calls) CHECK(c.load() == 1);
    }
    int none = 0;
    aogen::parallel_for(0, [&](size_t) { ++none; });
    CHECK(none == 0);
}

TEST_CASE("parallel: the first exception is rethrown once every thread has stopped", "[parallel]")
{
    for (unsigned threads : {1u, 4u}) {
        std::atomic<int> ran{0};
        CHECK_THROWS_WITH(aogen::parallel_for(
                              100,
                              [&](size_t i) {
                                  ++ran;
                                  if (i == 17) throw std::runtime_error("index 17");
                              },
                              threads),
                          "index 17");
        CHECK(ran.load() == 100); // the others still ran: a failure does not leave work half done in a thread
    }
}

} // namespace unity_test_parallel
