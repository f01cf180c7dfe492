// common/core.glsl's written-out arithmetic (ao_lerp, ao_acos, ao_atan2), evaluated from the
// shader's own SPIR-V (spirv_eval.hpp: spirv-opt folds the calls with constant arguments in
// host float arithmetic), against the C++ library's double-precision acos and atan2. They
// replace GLSL's mix, acos and atan so that every target computes the same operations
// (docs/webgpu.md § GL runner); this checks that they are as accurate as a float result can be.

#include <aogen/codegen.hpp>

#include <catch2/catch.hpp>

#include "spirv_eval.hpp"

#include <cmath>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_core_math {

using namespace aogen;

namespace {

std::string lit(double x) { return aogen_test::glsl_literal(x); }

std::vector<float> evaluate(const std::vector<std::string>& expressions)
{
    variant v;
    v.tech = technique::gtao; // any AO pass: core.glsl comes first in all of them
    return aogen_test::evaluate_in_ao_pass(v, expressions, "core math test");
}

// Two ulps of a float at pi: the polynomials' own error (< 1.3e-8) plus float rounding.
constexpr double tolerance = 4.8e-7;

} // namespace

TEST_CASE("compiler: ao_acos is acos to float precision on [-1, 1], exact at -1, 0 and 1")
{
    std::vector<double> xs;
    for (int k = 0; k <= 200; ++k) xs.push_back(-1.0 + k / 100.0);
    for (double x : {0.999999, -0.999999, 1e-6, -1e-6}) xs.push_back(x);
    std::vector<std::string> expressions;
    for (double x : xs) expressions.push_back("ao_acos(" + lit(x) + ")");
    const std::vector<float> got = evaluate(expressions);
    REQUIRE(got.size() == xs.size());
    double worst = 0;
    for (size_t i = 0; i < xs.size(); ++i) {
        const double want = std::acos(double(float(xs[i])));
        INFO("acos(" << xs[i] << ") = " << want << ", ao_acos " << got[i]);
        CHECK(std::fabs(got[i] - want) <= tolerance);
        worst = std::max(worst, std::fabs(got[i] - want));
    }
    INFO("largest error " << worst);
    CHECK(got[100] == static_cast<float>(M_PI / 2)); // x = 0
    CHECK(got[200] == 0.0f);                          // x = 1
    CHECK(got[0] == static_cast<float>(M_PI));        // x = -1
}

TEST_CASE("compiler: ao_atan2 is atan2 to float precision around the circle, 0 at the origin")
{
    std::vector<double> ys, xs;
    for (int k = 0; k < 144; ++k) {
        const double angle = -M_PI + (k + 0.37) * (2 * M_PI / 144); // off the axes and diagonals
        const double r = 0.01 + k * 0.7;                             // and at many scales
        ys.push_back(r * std::sin(angle)), xs.push_back(r * std::cos(angle));
    }
    for (double a : {0.0, M_PI / 4, M_PI / 2, 3 * M_PI / 4}) ys.push_back(std::sin(a)), xs.push_back(std::cos(a));
    std::vector<std::string> expressions;
    for (size_t i = 0; i < xs.size(); ++i) expressions.push_back("ao_atan2(" + lit(ys[i]) + ", " + lit(xs[i]) + ")");
    expressions.push_back("ao_atan2(0.0, 0.0)");
    const std::vector<float> got = evaluate(expressions);
    REQUIRE(got.size() == xs.size() + 1);
    for (size_t i = 0; i < xs.size(); ++i) {
        const double want = std::atan2(double(float(ys[i])), double(float(xs[i])));
        INFO("atan2(" << ys[i] << ", " << xs[i] << ") = " << want << ", ao_atan2 " << got[i]);
        CHECK(std::fabs(got[i] - want) <= tolerance);
    }
    CHECK(got.back() == 0.0f);
}

TEST_CASE("compiler: ao_lerp is a + (b - a) t: the ends exactly, the middle")
{
    const std::vector<float> got = evaluate({"ao_lerp(0.25, 0.75, 0.0)", "ao_lerp(0.25, 0.75, 1.0)", "ao_lerp(2.0, 4.0, 0.5)", "ao_lerp(1.0, -1.0, 0.25)"});
    REQUIRE(got.size() == 4);
    CHECK(got[0] == 0.25f);
    CHECK(got[1] == 0.75f);
    CHECK(got[2] == 3.0f);
    CHECK(got[3] == 0.5f);
}

} // namespace unity_test_core_math
