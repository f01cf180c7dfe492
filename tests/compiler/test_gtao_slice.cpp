// gtao.glsl's slice integral, evaluated from the shader's own GLSL, against integrals the
// test computes independently: the 1D slice integral by quadrature, and the whole
// hemisphere against the closed forms of docs/design.md § Ground truth (floor and infinite
// wall, a tilted wall, a 90-degree groove, an open plane) with exact horizons.
//
// How the GLSL is evaluated without a GPU: the GTAO AO pass is generated as usual, with
// entry_compute.glsl replaced by a test entry point whose main() calls gtao.glsl's
// functions (ao_slice_projected_normal, ao_gtao_slice_integral, ao_slice_unoccluded)
// with constant arguments and stores each result into a buffer. glslang compiles it;
// spirv-opt's performance passes inline the calls and fold most of the arithmetic to
// constants (SPIRV-Tools folds float arithmetic and GLSL.std.450's acos, atan2, cos,
// sqrt, clamp, ... in host float arithmetic). What they leave -- straight-line float
// arithmetic, such as the Fma instructions the folder makes of a multiply and an add
// before their operands are known -- run_main() evaluates, in float; anything else
// (a branch, an instruction it does not know) fails the test, naming it. The values
// compared are the shader's own SPIR-V's, not a C++ transcription of its formulas.

#include <aogen/codegen.hpp>
#include <aogen/compile.hpp>

#include <catch2/catch.hpp>

#include "spirv_eval.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_gtao_slice {

using namespace aogen;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double half_pi = pi / 2;

std::string lit(double x) { return aogen_test::glsl_literal(x); }

// Each GLSL float expression evaluated with gtao.glsl (and the files before it) in scope.
std::vector<float> evaluate(const std::vector<std::string>& expressions)
{
    variant v;
    v.tech = technique::gtao;
    REQUIRE(codegen::generate(codegen::make_plan(v))[0].glsl.find("ao_half ao_gtao_slice_integral(") != std::string::npos); // ao_half: float here (no fp16)
    return aogen_test::evaluate_in_ao_pass(v, expressions, "gtao slice test");
}

// ---- independent references ---------------------------------------------------------------

// integral_a^b cos(t - n) |sin t| dt by composite Simpson, split at 0.
double slice_quadrature(double a, double b, double n)
{
    auto simpson = [n](double lo, double hi) {
        const int steps = 2000;
        const double h = (hi - lo) / steps;
        double sum = 0;
        for (int i = 0; i <= steps; ++i) {
            const double t = lo + i * h;
            const double f = std::cos(t - n) * std::abs(std::sin(t));
            sum += f * (i == 0 || i == steps ? 1 : i % 2 ? 4 : 2);
        }
        return sum * h / 3;
    };
    if (a < 0 && b > 0) return simpson(a, 0) + simpson(0, b);
    return simpson(a, b);
}

struct vec3d {
    double x = 0, y = 0, z = 0;
};
vec3d operator+(vec3d a, vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
vec3d operator*(vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(vec3d a, vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
vec3d cross(vec3d a, vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
vec3d normalize(vec3d a) { return a * (1 / std::sqrt(dot(a, a))); }
std::string glsl(vec3d a) { return "vec3(" + lit(a.x) + ", " + lit(a.y) + ", " + lit(a.z) + ")"; }

using visible_set = std::function<bool(vec3d)>;

// Walking from V toward `toward` (unit, perpendicular to V) in the slice plane: the first
// angle at which the direction leaves the visible set (pi if it never does). The visible
// sets here are intersections of half-spaces, so along a slice they are one arc around V,
// and this is that arc's end: the exact horizon on that side.
double first_hidden(vec3d V, vec3d toward, const visible_set& visible)
{
    auto direction = [&](double t) { return V * std::cos(t) + toward * std::sin(t); };
    const int steps = 4096;
    double previous = 0;
    for (int i = 1; i <= steps; ++i) {
        const double t = pi * i / steps;
        if (!visible(direction(t))) {
            double lo = previous, hi = t;
            for (int k = 0; k < 60; ++k) {
                const double mid = 0.5 * (lo + hi);
                (visible(direction(mid)) ? lo : hi) = mid;
            }
            return hi;
        }
        previous = t;
    }
    return pi;
}

// AO at a point with normal n, seen from direction V, whose unoccluded directions are
// `visible` (a subset of n's hemisphere), from `slices` slices with exact horizons, each
// slice's projected normal and integrals computed by the shader's functions. The sums
// are ao_pass's: sum |n_p| a / sum |n_p| (cos n + n sin n).
double shader_ao(vec3d n, vec3d V, const visible_set& visible, int slices)
{
    REQUIRE(visible(V));
    const vec3d e1 = normalize(cross(V, vec3d{0.31, 0.77, 0.55}));
    const vec3d e2 = cross(V, e1);
    std::vector<std::string> expressions;
    for (int k = 0; k < slices; ++k) {
        const double phi = (k + 0.5) * pi / slices;
        const vec3d side = e1 * std::cos(phi) + e2 * std::sin(phi);
        const double cos_ahead = std::cos(first_hidden(V, side, visible));
        const double cos_behind = std::cos(first_hidden(V, side * -1.0, visible));
        const std::string projected = "ao_slice_projected_normal(" + glsl(n) + ", " + glsl(V) + ", " + glsl(side) + ")";
        expressions.push_back(projected + ".x");
        expressions.push_back("ao_gtao_slice_integral(" + projected + ".y, " + lit(cos_behind) + ", " + lit(cos_ahead) + ")");
        expressions.push_back("ao_slice_unoccluded(" + projected + ".y)");
    }
    const std::vector<float> r = evaluate(expressions);
    double visibility = 0, unoccluded = 0;
    for (int k = 0; k < slices; ++k) {
        visibility += double(r[3 * k]) * r[3 * k + 1];
        unoccluded += double(r[3 * k]) * r[3 * k + 2];
    }
    REQUIRE(unoccluded > 0);
    return visibility / unoccluded;
}

} // namespace

TEST_CASE("gtao slice integral: the shader's a(h-, n) + a(h+, n) against quadrature of cos(t - n) |sin t|",
          "[gtao][glslang]")
{
    const std::vector<double> normals{-half_pi, -1.2, -0.5, 0.0, 0.3, 1.0, half_pi};
    const std::vector<double> cosines{-1.0, -0.6, 0.0, 0.4, 0.9, 1.0};
    std::vector<std::string> expressions;
    std::vector<double> expected;
    for (double n : normals) {
        for (double c_behind : cosines)
            for (double c_ahead : cosines) {
                // The visible arc: from each horizon toward V, inside n's hemisphere.
                const double h_ahead = std::clamp(std::acos(c_ahead), n - half_pi, n + half_pi);
                const double h_behind = std::clamp(-std::acos(c_behind), n - half_pi, n + half_pi);
                expressions.push_back("ao_gtao_slice_integral(" + lit(n) + ", " + lit(c_behind) + ", " + lit(c_ahead) + ")");
                expected.push_back(slice_quadrature(h_behind, h_ahead, n));
            }
        // The unoccluded slice, both ways: no horizons, and the closed form.
        expressions.push_back("ao_gtao_slice_integral(" + lit(n) + ", -1.0, -1.0)");
        expected.push_back(slice_quadrature(n - half_pi, n + half_pi, n));
        expressions.push_back("ao_slice_unoccluded(" + lit(n) + ")");
        expected.push_back(slice_quadrature(n - half_pi, n + half_pi, n));
    }
    const std::vector<float> got = evaluate(expressions);
    for (size_t i = 0; i < got.size(); ++i) {
        INFO(expressions[i]);
        CHECK(got[i] == Approx(expected[i]).margin(2e-6));
    }
    // cos n + n sin n: 1 facing V, pi/2 for a normal in the view plane.
    CHECK(evaluate({"ao_slice_unoccluded(0.0)"})[0] == Approx(1.0).margin(1e-6));
    CHECK(evaluate({"ao_slice_unoccluded(" + lit(half_pi) + ")"})[0] == Approx(half_pi).margin(1e-6));
}

TEST_CASE("gtao slice integral: horizons outside [-1, 1], NaN and infinity, degenerate projected normals",
          "[gtao][glslang]")
{
    const std::string nan = "uintBitsToFloat(0x7fc00000u)", inf = "uintBitsToFloat(0x7f800000u)";
    const std::vector<float> r = evaluate({
        "ao_gtao_slice_integral(0.4, " + nan + ", " + nan + ")", // 0: no horizons
        "ao_gtao_slice_integral(0.4, -1.0, -1.0)",               // 1
        "ao_gtao_slice_integral(0.4, -7.0, 3.0)",                // 2: clamped to -1, 1
        "ao_gtao_slice_integral(0.4, -1.0, 1.0)",                // 3
        "ao_gtao_slice_integral(0.4, " + inf + ", -" + inf + ")", // 4: not finite: no horizons
        "ao_gtao_slice_integral(9.0, 0.5, 0.5)",                 // 5: n clamped to pi/2
        "ao_gtao_slice_integral(" + lit(half_pi) + ", 0.5, 0.5)", // 6
        // Projected normals: perpendicular to the slice plane; in the view plane; tilted.
        "ao_slice_projected_normal(vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).x", // 7
        "ao_slice_projected_normal(vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).y", // 8
        "ao_slice_projected_normal(vec3(-1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).x", // 9
        "ao_slice_projected_normal(vec3(-1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).y", // 10
        "ao_slice_projected_normal(vec3(0.6, 0.0, 0.8), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).x",  // 11
        "ao_slice_projected_normal(vec3(0.6, 0.0, 0.8), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).y",  // 12
        "ao_gtao_slice_integral(0.4, 1.0, 1.0)", // 13: both horizons at V: nothing visible
    });
    for (float x : r) CHECK(std::isfinite(x));
    CHECK(r[0] == r[1]);
    CHECK(r[2] == r[3]);
    CHECK(r[3] == Approx(slice_quadrature(0.4 - half_pi, 0.0, 0.4)).margin(2e-6)); // behind open, ahead closed at V
    CHECK(r[4] == r[1]);
    CHECK(r[5] == r[6]);
    CHECK(r[7] == 0.0f);
    CHECK(r[8] == 0.0f);
    CHECK(r[9] == Approx(1.0).margin(1e-6));
    CHECK(r[10] == Approx(-half_pi).margin(1e-6));
    CHECK(r[11] == Approx(1.0).margin(1e-6));
    CHECK(r[12] == Approx(std::atan2(0.6, 0.8)).margin(1e-6));
    CHECK(r[13] == Approx(0.0).margin(1e-7));
}

TEST_CASE("gtao slice integral: docs/design.md's closed forms from exact horizons", "[gtao][glslang]")
{
    const vec3d up{0, 1, 0};
    auto above = [](vec3d normal) { return [normal](vec3d w) { return dot(w, normal) >= 0; }; };
    auto both = [](visible_set a, visible_set b) { return [a, b](vec3d w) { return a(w) && b(w); }; };
    struct closed_form {
        const char* name;
        vec3d n, V;
        visible_set visible;
        double exact;
        int slices;
        double margin;
    };
    // Floor point next to an infinite wall at interior angle alpha (any distance): the
    // open directions are above the floor and on the floor's side of the wall's plane;
    // AO = (1 - cos alpha) / 2.
    const double alpha = pi / 3;
    const vec3d wall_90{-1, 0, 0}, wall_60{-std::sin(alpha), -std::cos(alpha), 0}; // into the open side
    // Apex of a 90-degree groove, normal along the bisector: sin 45 degrees.
    const vec3d groove_a = normalize({1, 1, 0}), groove_b = normalize({-1, 1, 0});
    const std::vector<closed_form> cases{
        {"open plane, oblique view, 3 slices", up, normalize({-0.3, 0.8, 0.5}), above(up), 1.0, 3, 1e-5},
        {"open plane, grazing view, 2 slices", up, normalize({0.9, 0.1, 0.3}), above(up), 1.0, 2, 1e-5},
        {"floor + wall 90, oblique view", up, normalize({-0.3, 0.8, 0.5}), both(above(up), above(wall_90)), 0.5, 64, 2e-4},
        {"floor + wall 90, view along n", up, up, both(above(up), above(wall_90)), 0.5, 64, 2e-4},
        {"floor + wall 90, low view", up, normalize({-0.8, 0.3, -0.2}), both(above(up), above(wall_90)), 0.5, 64, 2e-4},
        {"floor + wall 60", up, normalize({-0.5, 0.8, 0.2}), both(above(up), above(wall_60)), (1 - std::cos(alpha)) / 2, 64,
         1e-3},
        {"90-degree groove apex", normalize(groove_a + groove_b), normalize({0.2, 0.9, 0.4}),
         both(above(groove_a), above(groove_b)), std::sqrt(0.5), 64, 2e-4},
    };
    for (const closed_form& c : cases) {
        INFO(c.name << ": exact " << c.exact);
        const double ao = shader_ao(c.n, c.V, c.visible, c.slices);
        CHECK(ao == Approx(c.exact).margin(c.margin));
    }
}

TEST_CASE("gtao slice steps: frame 0's steps at j / N of the radius, later frames' inner steps moved inward", "[gtao][glslang]")
{
    // common/slices.glsl's ao_slice_step_pixels(j, N, radius, s): radius (j - s) / N for j < N,
    // the radius itself for j = N (the temporal step offset s, in [0, 1) of a step).
    struct step_case {
        int j, steps;
        double radius, offset, pixels;
    };
    const step_case cases[] = {
        {1, 2, 10, 0, 5},      {2, 2, 10, 0, 10},     {1, 4, 8, 0, 2},      {3, 4, 8, 0, 6},      {4, 4, 8, 0, 8},
        {1, 2, 10, 0.5, 2.5},  {2, 2, 10, 0.5, 10},   {1, 1, 7, 0.75, 7},   {3, 4, 8, 0.25, 5.5}, {4, 4, 8, 0.25, 8},
        {1, 3, 30, 0.875, 1.25}, {2, 3, 30, 0.875, 11.25}, {3, 3, 30, 0.875, 30},
    };
    std::vector<std::string> expressions;
    for (const step_case& c : cases)
        expressions.push_back("ao_slice_step_pixels(" + std::to_string(c.j) + ", " + std::to_string(c.steps) + ", " + lit(c.radius) + ", " +
                              lit(c.offset) + ")");
    const std::vector<float> got = evaluate(expressions);
    for (size_t i = 0; i < std::size(cases); ++i) {
        INFO(expressions[i]);
        CHECK(got[i] == Approx(cases[i].pixels).margin(1e-5));
    }
}

} // namespace unity_test_gtao_slice
