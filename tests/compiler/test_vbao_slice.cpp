// vbao.glsl's sectors, evaluated from the shader's own SPIR-V (spirv_eval.hpp: the AO pass
// with a test main(), folded by spirv-opt, the rest run on the CPU), against references the
// test computes independently: the cosine-weighted cumulative by midpoint quadrature, the
// sector masks of hand-worked wedges, and the whole hemisphere against the closed forms of
// docs/design.md § Ground truth (floor and infinite wall, a 60-degree wall, a 90-degree
// groove, an open plane) with exact horizons found analytically and an unbounded thickness
// (the back of every sample at -V: the heightfield limit, where VBAO must agree with GTAO's
// integral).
//
// The tolerance of the closed forms, 0.01: each slice's mask is exact but for its sector
// boundaries, each rounded to the nearest of 32 equal-measure sectors, so a slice's visible
// share is off by at most 1/64 per boundary inside the hemisphere -- one per side here (the
// far end of each wedge is the hemisphere's edge, c = 0 or 1 exactly): at most 1/32 per
// slice. Over 64 slices the boundaries fall at unrelated places within their sectors and
// the rounding errors largely cancel; 0.01 is a third of the worst case, and over five times
// the shader's largest error here (0.0018). Equal-angle sectors (the fault the test is there
// for, planted once) miss by 0.06-0.16, wherever the view is not along the normal.

#include <aogen/codegen.hpp>

#include <catch2/catch.hpp>

#include "spirv_eval.hpp"

#include <cmath>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_vbao_slice {

using namespace aogen;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double half_pi = pi / 2;

std::string num(double x) { return aogen::glsl_float(static_cast<float>(x)); }

std::vector<float> vbao_eval(const std::vector<std::string>& expressions)
{
    variant v;
    v.tech = technique::vbao;
    return aogen_test::evaluate_in_ao_pass(v, expressions, "vbao slice test");
}

// The share of the slice measure cos(t - n) |sin t| dt between n - pi/2 and theta, by the
// midpoint rule (independent of the shader's antiderivative).
double measure_share(double theta, double n)
{
    const int steps = 20000;
    const double lo = n - half_pi, hi = n + half_pi;
    double part = 0, whole = 0;
    for (int i = 0; i < steps; ++i) {
        const double t = lo + (i + 0.5) * (hi - lo) / steps;
        const double m = std::cos(t - n) * std::abs(std::sin(t));
        whole += m;
        if (t < theta) part += m;
    }
    return part / whole;
}

// The mask of a GLSL uint expression, read back in two 16-bit halves (a float holds each exactly).
std::vector<std::string> halves(const std::string& mask)
{
    return {"float((" + mask + ") & 0xffffu)", "float((" + mask + ") >> 16u)"};
}

struct dir3 {
    double x, y, z;
};
dir3 add(dir3 a, dir3 b, double s = 1) { return {a.x + s * b.x, a.y + s * b.y, a.z + s * b.z}; }
double dot3(dir3 a, dir3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
dir3 unit(dir3 a)
{
    const double l = std::sqrt(dot3(a, a));
    return {a.x / l, a.y / l, a.z / l};
}
dir3 cross3(dir3 a, dir3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
std::string vec(dir3 a) { return "vec3(" + num(a.x) + ", " + num(a.y) + ", " + num(a.z) + ")"; }

// The open directions are those with w . m >= 0 for every m (half-spaces through P). Walking
// from V (open) toward `toward` in the slice plane, w(t) = V cos t + toward sin t, each
// half-space's w . m = A cos t + B sin t = |(A, B)| cos(t - atan2(B, A)) stays >= 0 until
// t = atan2(B, A) + pi/2: the exact horizon is the first of those in [0, pi], else pi.
double horizon(dir3 V, dir3 toward, const std::vector<dir3>& half_spaces)
{
    double h = pi;
    for (const dir3& m : half_spaces) {
        const double t = std::atan2(dot3(toward, m), dot3(V, m)) + half_pi;
        if (t >= 0 && t < h) h = t; // t = 0: V on the half-space's boundary, the horizon at V
    }
    return h;
}

// AO at P (normal n, seen from V) whose open directions are `half_spaces`, from `slices`
// slices: per slice the shader's projected normal, the mask of the two wedges below the
// horizons reaching to -V (an unbounded thickness), its visible share and the slice weight,
// summed as ao_pass sums them.
double vbao_closed_form(dir3 n, dir3 V, const std::vector<dir3>& half_spaces, int slices)
{
    for (const dir3& m : half_spaces) REQUIRE(dot3(V, m) >= 0); // P is seen from V
    const dir3 e1 = unit(cross3(V, {0.31, 0.77, 0.55}));
    const dir3 e2 = cross3(V, e1);
    std::vector<std::string> e;
    for (int k = 0; k < slices; ++k) {
        const double phi = (k + 0.5) * pi / slices;
        const dir3 side = add({e1.x * std::cos(phi), e1.y * std::cos(phi), e1.z * std::cos(phi)}, e2, std::sin(phi));
        const double ahead = horizon(V, side, half_spaces), behind = -horizon(V, {-side.x, -side.y, -side.z}, half_spaces);
        const std::string projected = "ao_slice_projected_normal(" + vec(n) + ", " + vec(V) + ", " + vec(side) + ")";
        const std::string mask = "(ao_vbao_sectors(" + num(ahead) + ", " + num(pi) + ", " + projected + ".y) | ao_vbao_sectors(" +
                                 num(-pi) + ", " + num(behind) + ", " + projected + ".y))";
        e.push_back(projected + ".x * ao_slice_unoccluded(" + projected + ".y)");
        e.push_back("ao_vbao_slice_visible(" + mask + ")");
    }
    const std::vector<float> r = vbao_eval(e);
    double visible = 0, whole = 0;
    for (int k = 0; k < slices; ++k) visible += double(r[2 * k]) * r[2 * k + 1], whole += r[2 * k];
    REQUIRE(whole > 0);
    return visible / whole;
}

} // namespace

TEST_CASE("vbao sectors: the cumulative is the cosine-weighted share of the slice", "[vbao][glslang]")
{
    std::vector<std::string> e;
    std::vector<double> expected;
    for (double n : {-half_pi, -1.0, -0.3, 0.0, 0.6, 1.3, half_pi})
        for (double f : {0.0, 0.1, 0.25, 0.5, 0.7, 0.9, 1.0}) {
            const double theta = n - half_pi + f * pi;
            e.push_back("ao_vbao_cumulative(" + num(theta) + ", " + num(n) + ")");
            expected.push_back(measure_share(theta, n));
        }
    // Past the hemisphere: clamped to its edges.
    e.push_back("ao_vbao_cumulative(" + num(-pi) + ", 0.4)"), expected.push_back(0.0);
    e.push_back("ao_vbao_cumulative(" + num(pi) + ", 0.4)"), expected.push_back(1.0);
    e.push_back("ao_slice_unoccluded(0.0)"), expected.push_back(1.0);
    e.push_back("ao_slice_unoccluded(" + num(half_pi) + ")"), expected.push_back(half_pi);
    const std::vector<float> got = vbao_eval(e);
    for (size_t i = 0; i < got.size(); ++i) {
        INFO(e[i]);
        CHECK(got[i] == Approx(expected[i]).margin(2e-5));
    }
}

TEST_CASE("vbao sectors: wedges mark the sectors of their measure, rounded to the nearest boundary", "[vbao][glslang]")
{
    // With n = 0 the measure is |sin t| cos t, symmetric about 0: c(0) = 1/2 and, for t >= 0,
    // c(t) = (1 + sin^2 t) / 2, so c(45 degrees) = 3/4: sector boundaries 16 and 24.
    const double quarter = pi / 4;
    const std::vector<std::pair<std::string, uint32_t>> cases{
        {"ao_vbao_sectors(" + num(-half_pi) + ", " + num(half_pi) + ", 0.0)", 0xffffffffu}, // the whole hemisphere
        {"ao_vbao_sectors(" + num(-pi) + ", " + num(pi) + ", 0.0)", 0xffffffffu},           // clamped to it
        {"ao_vbao_sectors(0.0, " + num(half_pi) + ", 0.0)", 0xffff0000u},                   // the upper half of the measure
        {"ao_vbao_sectors(" + num(half_pi) + ", 0.0, 0.0)", 0xffff0000u},                   // either order
        {"ao_vbao_sectors(" + num(-half_pi) + ", 0.0, 0.0)", 0x0000ffffu},
        {"ao_vbao_sectors(" + num(quarter) + ", " + num(half_pi) + ", 0.0)", 0xff000000u},  // c from 3/4: sectors 24..31
        {"ao_vbao_sectors(0.0, " + num(quarter) + ", 0.0)", 0x00ff0000u},                   // sectors 16..23
        {"ao_vbao_sectors(0.3, 0.3, 0.0)", 0u},                                              // an empty wedge marks nothing
        {"ao_vbao_sectors(" + num(half_pi - 1e-3) + ", " + num(pi) + ", 0.0)", 0u},         // a plane's own tangent: nothing
        {"ao_vbao_sectors(" + num(1.2 + half_pi - 2e-3) + ", " + num(pi) + ", 1.2)", 0u},   // tilted: nothing either
        {"ao_vbao_sectors(" + num(-pi) + ", " + num(-1.2 - half_pi + 2e-3) + ", -1.2)", 0u},
    };
    std::vector<std::string> e;
    for (const auto& c : cases)
        for (const std::string& h : halves(c.first)) e.push_back(h);
    e.push_back("ao_vbao_slice_visible(0xffff0000u)");
    e.push_back("ao_vbao_slice_visible(0u)");
    e.push_back("ao_vbao_slice_visible(0xffffffffu)");
    const std::vector<float> got = vbao_eval(e);
    for (size_t i = 0; i < cases.size(); ++i) {
        INFO(cases[i].first);
        const uint32_t mask = uint32_t(got[2 * i]) | (uint32_t(got[2 * i + 1]) << 16);
        CHECK(mask == cases[i].second);
    }
    CHECK(got[2 * cases.size()] == 0.5f);
    CHECK(got[2 * cases.size() + 1] == 1.0f);
    CHECK(got[2 * cases.size() + 2] == 0.0f);
}

TEST_CASE("vbao sectors: a wedge's sectors follow the measure at every tilt", "[vbao][glslang]")
{
    // A wedge from theta to the hemisphere's edge marks 32 (1 - c(theta)) sectors, rounded.
    std::vector<std::string> e;
    std::vector<int> expected;
    for (double n : {-1.4, -0.7, 0.0, 0.5, 1.1})
        for (double f : {0.05, 0.2, 0.45, 0.6, 0.85}) {
            const double theta = n - half_pi + f * pi;
            e.push_back("float(bitCount(ao_vbao_sectors(" + num(theta) + ", " + num(pi) + ", " + num(n) + ")))");
            expected.push_back(32 - int(std::floor(32 * measure_share(theta, n) + 0.5)));
        }
    const std::vector<float> got = vbao_eval(e);
    for (size_t i = 0; i < got.size(); ++i) {
        INFO(e[i]);
        CHECK(int(got[i]) == expected[i]);
    }
}

TEST_CASE("vbao sectors: docs/design.md's closed forms from exact horizons and an unbounded thickness", "[vbao][glslang]")
{
    const dir3 up{0, 1, 0};
    const double alpha = pi / 3;
    const dir3 wall_90{-1, 0, 0}, wall_60{-std::sin(alpha), -std::cos(alpha), 0}; // into the open side
    const dir3 groove_a = unit({1, 1, 0}), groove_b = unit({-1, 1, 0});
    struct closed_form {
        const char* name;
        dir3 n, V;
        std::vector<dir3> open;
        double exact;
        int slices;
        double margin;
    };
    const std::vector<closed_form> cases{
        {"open plane, oblique view, 3 slices", up, unit({-0.3, 0.8, 0.5}), {up}, 1.0, 3, 1e-6},
        {"open plane, grazing view, 2 slices", up, unit({0.9, 0.1, 0.3}), {up}, 1.0, 2, 1e-6},
        {"floor + wall 90, oblique view", up, unit({-0.3, 0.8, 0.5}), {up, wall_90}, 0.5, 64, 0.01},
        {"floor + wall 90, view along n", up, up, {up, wall_90}, 0.5, 64, 0.01},
        {"floor + wall 90, low view", up, unit({-0.8, 0.3, -0.2}), {up, wall_90}, 0.5, 64, 0.01},
        {"floor + wall 60", up, unit({-0.5, 0.8, 0.2}), {up, wall_60}, (1 - std::cos(alpha)) / 2, 64, 0.01},
        {"90-degree groove apex", unit({0, 1, 0}), unit({0.2, 0.9, 0.4}), {groove_a, groove_b}, std::sqrt(0.5), 64, 0.01},
        {"90-degree groove apex, low view", unit({0, 1, 0}), unit({0.3, 0.5, -0.7}), {groove_a, groove_b}, std::sqrt(0.5), 64, 0.01},
    };
    for (const closed_form& c : cases) {
        INFO(c.name << ": exact " << c.exact);
        CHECK(vbao_closed_form(c.n, c.V, c.open, c.slices) == Approx(c.exact).margin(c.margin));
    }
}

} // namespace unity_test_vbao_slice
