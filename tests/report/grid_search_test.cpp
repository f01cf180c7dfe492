// The narrowing grid search (aogen_report/grid_search.hpp) against functions whose minimum
// is known in closed form.
#include <aogen_report/grid_search.hpp>

#include <catch2/catch.hpp>

#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_grid_search_test {

using aogen_report::narrowing_grid_search;
using aogen_report::search_axis;

TEST_CASE("grid search: finds a quadratic's minimum to within the last round's step", "[grid_search]")
{
    const std::vector<search_axis> axes{{"a", 0.0, 1.0}, {"b", 0.0, 3.0}};
    const auto f = [](const std::vector<double>& x) { return (x[0] - 0.37) * (x[0] - 0.37) + 2 * (x[1] - 1.9) * (x[1] - 1.9); };
    const auto r = narrowing_grid_search(axes, 5, 6, f);
    CHECK(r.evaluations == 6 * 25);
    // Steps shrink by half a range per round: 0.25, 0.125, ... of [0, 1] → 2^-7 in round 6.
    CHECK(std::fabs(r.best[0] - 0.37) <= 1.0 / 128);
    CHECK(std::fabs(r.best[1] - 1.9) <= 3.0 / 128);
    CHECK(r.value == Approx(f(r.best)));
}

TEST_CASE("grid search: a minimum on the range's edge stays inside the first range", "[grid_search]")
{
    const std::vector<search_axis> axes{{"a", 0.5, 2.0}};
    const auto r = narrowing_grid_search(axes, 4, 5, [](const std::vector<double>& x) { return x[0]; }); // lowest at lo
    CHECK(r.best[0] == 0.5);
    const auto s = narrowing_grid_search(axes, 3, 3, [](const std::vector<double>& x) { return -x[0]; }); // lowest at hi
    CHECK(s.best[0] == 2.0);
}

TEST_CASE("grid search: bad settings are errors", "[grid_search]")
{
    const auto f = [](const std::vector<double>&) { return 0.0; };
    CHECK_THROWS(narrowing_grid_search({}, 5, 3, f));
    CHECK_THROWS(narrowing_grid_search({{"a", 0, 1}}, 1, 3, f));
    CHECK_THROWS(narrowing_grid_search({{"a", 2, 1}}, 3, 3, f));
}

} // namespace unity_grid_search_test
