// The calibrated column: the fitted power recovers a known exponent, and each scene is
// scored with a power fitted on the other scenes only.
#include <aogen_report/calibrate.hpp>

#include <catch2/catch.hpp>

#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_calibrate_test {

using namespace aogen_report;

namespace {

// A scene whose truth is exactly ao^p for AO levels spread over (0, 1].
calibration_scene scene_with_power(double p, int levels = 200)
{
    std::vector<float> ao, truth;
    std::vector<uint8_t> valid;
    for (int i = 1; i <= levels; ++i) {
        ao.push_back(float(i) / levels);
        truth.push_back(float(std::pow(double(ao.back()), p)));
        valid.push_back(1);
    }
    return summarise(ao, truth, valid);
}

} // namespace

TEST_CASE("calibration: the fitted power recovers the exponent that maps AO onto the truth")
{
    for (double p : {0.25, 0.5, 1.0, 2.0, 3.7}) {
        INFO("p = " << p);
        const std::vector<calibration_scene> scenes{scene_with_power(p)};
        CHECK(fit_power(scenes) == Approx(p).epsilon(1e-3));
        CHECK(mean_squared_error(scenes[0], p) == Approx(0.0).margin(1e-9));
    }
}

TEST_CASE("calibration: summaries count valid finite pixels once per AO level")
{
    const std::vector<float> ao{0.5f, 0.5f, 1.0f, std::nanf(""), 0.25f};
    const std::vector<float> truth{0.4f, 0.6f, 1.0f, 0.3f, 0.9f};
    const std::vector<uint8_t> valid{1, 1, 1, 1, 0};
    const calibration_scene s = summarise(ao, truth, valid);
    REQUIRE(s.levels.size() == 2);
    CHECK(s.pixels == 3);
    CHECK(s.levels[0].ao == 0.5);
    CHECK(s.levels[0].count == 2);
    CHECK(s.levels[0].truth_sum == Approx(1.0));
    CHECK(s.levels[0].truth_squares == Approx(0.16 + 0.36));
    // MSE at p = 1 by hand: (0.1² + 0.1² + 0²) / 3.
    CHECK(mean_squared_error(s, 1.0) == Approx(0.02 / 3).epsilon(1e-6));
}

TEST_CASE("calibration: leave-one-out never fits a scene on itself")
{
    // Two scenes want p = 2, one wants p = 0.5: the odd one out is scored with 2, and each
    // p = 2 scene with the fit of the other two (between 0.5 and 2).
    const std::vector<calibration_scene> scenes{scene_with_power(2.0), scene_with_power(2.0), scene_with_power(0.5)};
    const std::vector<double> p = leave_one_out_powers(scenes);
    REQUIRE(p.size() == 3);
    CHECK(p[2] == Approx(2.0).epsilon(1e-3));
    CHECK(p[0] == Approx(fit_power({scenes[1], scenes[2]})).epsilon(1e-9));
    CHECK(p[0] > 0.5);
    CHECK(p[0] < 2.0);
    // One scene alone: nothing else to fit on.
    CHECK(leave_one_out_powers({scenes[0]}) == std::vector<double>{1.0});
}

TEST_CASE("calibration: ao^p keeps background ones and non-finite values")
{
    const std::vector<float> out = apply_power({1.0f, 0.25f, 0.0f, std::numeric_limits<float>::infinity(), 1.5f}, 0.5);
    CHECK(out[0] == 1.0f);
    CHECK(out[1] == Approx(0.5f));
    CHECK(out[2] == 0.0f);
    CHECK(std::isinf(out[3]));
    CHECK(out[4] == 1.0f); // clamped to [0, 1] first
}

} // namespace unity_calibrate_test
