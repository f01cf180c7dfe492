// The Pareto front of hand-placed points.
#include <aogen_report/pareto.hpp>

#include <catch2/catch.hpp>

#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_pareto_test {

using aogen_report::pareto_optimal;

TEST_CASE("pareto: a point is optimal unless another is at least as fast and as accurate")
{
    //            0     1     2     3     4     5
    const std::vector<double> ms{1.0, 2.0, 2.0, 3.0, 0.5, 4.0};
    const std::vector<double> err{0.30, 0.10, 0.20, 0.10, 0.50, 0.05};
    // 2 is beaten by 1 (same time, lower error); 3 by 1 (faster, same error).
    CHECK(pareto_optimal(ms, err) == std::vector<bool>{true, true, false, false, true, true});
}

TEST_CASE("pareto: identical points are both optimal, unmeasured ones never are")
{
    const double nan = std::nan("");
    CHECK(pareto_optimal({1, 1, nan, 0.1}, {0.2, 0.2, 0.0, nan}) == std::vector<bool>{true, true, false, false});
    CHECK_THROWS_WITH(pareto_optimal({1, 2}, {0.1}), Catch::Contains("one time and one error per variant"));
}

} // namespace unity_pareto_test
