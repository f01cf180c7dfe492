// SAO's spiral of taps (aogen/spiral.hpp): shares of the radius (i + 1/2) / N, angles i times
// the golden angle, checked against libm's cos and sin and against the sunflower's spacing.
#include <aogen/spiral.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_spiral {

using namespace aogen;

TEST_CASE("spiral: tap i at (i + 1/2) / N of the radius, i golden angles round, unit directions", "[spiral]")
{
    const double pi = 3.14159265358979323846;
    const double golden = pi * (3.0 - std::sqrt(5.0)); // radians: 137.5 degrees
    for (int n : {1, 7, 16, 64, 256}) {
        const std::vector<vec4> s = spiral::taps(n);
        REQUIRE(s.size() == size_t(n));
        for (int i = 0; i < n; ++i) {
            INFO("tap " << i << " of " << n);
            CHECK(s[size_t(i)].z == float((i + 0.5) / n));
            CHECK(s[size_t(i)].x == Approx(std::cos(i * golden)).margin(2e-7));
            CHECK(s[size_t(i)].y == Approx(std::sin(i * golden)).margin(2e-7));
            CHECK(s[size_t(i)].w == 0.0f);
            CHECK(std::fabs(double(s[size_t(i)].x) * s[size_t(i)].x + double(s[size_t(i)].y) * s[size_t(i)].y - 1.0) < 1e-6);
        }
    }
    // Tap 1 at 137.5 degrees (cos -0.7374, sin 0.6755): the golden angle, not a whole number of turns.
    const std::vector<vec4> s = spiral::taps(2);
    CHECK(s[0].x == 1.0f);
    CHECK(s[0].y == 0.0f);
    CHECK(s[1].x == Approx(-0.7373688781).margin(1e-7));
    CHECK(s[1].y == Approx(0.6754902942).margin(1e-7));
}

TEST_CASE("spiral: every eighth of the circle holds an eighth of the taps, to one tap", "[spiral]")
{
    // The golden angle spreads any number of taps evenly round the circle (the three-distance
    // theorem): a whole number of turns per tap (the paper's table) does so only for the counts
    // it was searched for. A planted 1/2-turn angle would put every tap in two octants.
    for (int n : {8, 16, 32, 64, 256}) {
        const std::vector<vec4> s = spiral::taps(n);
        int octants[8] = {};
        const double pi = 3.14159265358979323846;
        for (const vec4& t : s) {
            double a = std::atan2(double(t.y), double(t.x));
            if (a < 0) a += 2 * pi;
            ++octants[std::min(7, int(a / (pi / 4)))];
        }
        for (int o = 0; o < 8; ++o) {
            INFO(n << " taps, octant " << o << ": " << octants[o]);
            CHECK(std::abs(octants[o] * 8 - n) <= 8);
        }
    }
}

TEST_CASE("spiral: a tap count outside 1..256 is refused by name", "[spiral][errors]")
{
    CHECK_THROWS_WITH(spiral::taps(0), Catch::Contains("spiral taps: 0 is out of range (valid: 1..256)"));
    CHECK_THROWS_WITH(spiral::taps(257), Catch::Contains("spiral taps: 257"));
}

} // namespace unity_test_spiral
