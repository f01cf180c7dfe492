// ssao.glsl's per-sample decisions, evaluated from the shader's own SPIR-V (spirv_eval.hpp:
// the AO pass with a test main(), folded by spirv-opt, the rest run on the CPU): each input
// is swept across its decision's threshold in steps of one ulp, and no step may move the
// pixel's output by more than 1/255 -- what a depth that rounds differently in another depth
// convention or on another GPU would otherwise do, by a whole vote times the strength (issue
// 23; the stability suite's depth_conventions case failed so for the tuned strength).
//
// The output a step moves is the shader's own: a swept sample's occlusion goes through
// ao_ssao_occluded and ao_ssao_output with N = 8 judged samples (the default matrix's
// fewest) and strength 8 (the top of aogen_tune's SSAO strength range), so any default the
// search picks is covered. Each sweep spans 2 x 96 ulps around the threshold the test works
// out itself in double precision (a float's rounding moves it by a few ulps); a coarse sweep
// across the band checks that the weight still does its job (0 on one side, 1 on the other).
//
// The seeds' variant (-step) keeps the seeds' step at the bias: there the same sweep must
// find one jump of a whole vote -- the check that would fail on the old shader, and that the
// seeds' presets still reproduce the seeds' formula. Each smooth decision has a mutant
// (tests/mutants/mutants.json) that plants the step back.

#include <aogen/params.hpp>
#include <aogen/variant.hpp>

#include <catch2/catch.hpp>

#include "spirv_eval.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_ssao_decisions {

using namespace aogen;

namespace {

std::string lit(float x)
{
    const std::string s = aogen_test::glsl_literal(x);
    REQUIRE(std::stof(s) == x); // the literal is the float itself, not a neighbour
    return s;
}

constexpr float samples = 8.0f;  // N judged
constexpr float strength = 8.0f; // tune.hpp's SSAO strength range tops out here

// The pixel's output when one of `samples` judged samples adds `occlusion` (a GLSL
// expression), the others none: the shader's own division and output form.
std::string pixel_output(const std::string& occlusion)
{
    return "ao_ssao_output(ao_ssao_occluded(" + occlusion + ", " + lit(samples) + "), " + lit(strength) + ", 1.0, 1.0)";
}

// `count` floats on each side of `centre`, one ulp apart, in increasing order.
std::vector<float> ulp_sweep(float centre, int count = 96)
{
    std::vector<float> xs{centre};
    for (int i = 0; i < count; ++i) xs.insert(xs.begin(), std::nextafter(xs.front(), -INFINITY));
    for (int i = 0; i < count; ++i) xs.push_back(std::nextafter(xs.back(), INFINITY));
    return xs;
}

// `count` + 1 evenly spaced floats from `lo` to `hi`.
std::vector<float> even_sweep(float lo, float hi, int count = 32)
{
    std::vector<float> xs;
    for (int i = 0; i <= count; ++i) xs.push_back(lo + (hi - lo) * float(i) / float(count));
    return xs;
}

// One sweep: the expression of x at each x.
struct sweep {
    std::string what;
    std::vector<float> xs;
    std::function<std::string(const std::string&)> expression;
};

// Every sweep evaluated in one test shader: their values, sweep by sweep.
std::vector<std::vector<float>> evaluate(const variant& v, const std::vector<sweep>& sweeps)
{
    std::vector<std::string> expressions;
    for (const sweep& s : sweeps)
        for (float x : s.xs) expressions.push_back(s.expression(lit(x)));
    const std::vector<float> all = aogen_test::evaluate_in_ao_pass(v, expressions, "ssao decisions test");
    std::vector<std::vector<float>> out;
    size_t at = 0;
    for (const sweep& s : sweeps) {
        out.emplace_back(all.begin() + long(at), all.begin() + long(at + s.xs.size()));
        at += s.xs.size();
    }
    return out;
}

// The largest move between neighbouring points of a sweep.
float largest_step(const std::vector<float>& values)
{
    float m = 0;
    for (size_t i = 1; i < values.size(); ++i) m = std::max(m, std::abs(values[i] - values[i - 1]));
    return m;
}

variant ssao_variant(ssao_decisions d, bool point_cloud = false)
{
    variant v;
    v.tech = technique::ssao;
    v.decisions = d;
    v.point_cloud_fallback = point_cloud;
    return v;
}

// The sample of every bias sweep: a pixel at view z -4.2, a scene point at -4.0 (0.2 in
// front of it, inside the radius 0.5), bias 0.025: the vote flips where the sample's z
// plus the bias passes the scene's.
constexpr float pixel_z = -4.2f, scene_z = -4.0f, radius = 0.5f, bias = 0.025f;

std::string occlusion_at_sample_z(const std::string& sample_z)
{
    return "ao_ssao_occlusion(" + lit(pixel_z) + ", " + sample_z + ", " + lit(scene_z) + ", " + lit(radius) + ", " + lit(bias) + ")";
}

// Four raw depths on a plane but for `bend` at d11: d00 0.5, d10 0.5 + a, d01 0.5 + b,
// d11 0.5 + a + b + bend; their plane test's threshold (a quarter of the spread plus the
// slack) is crossed at bend = (|a| + |b| + |a + b|) / 3 + slack, worked out here.
constexpr double quad_a = 2e-4, quad_b = 1e-4;
std::string quad_with_d11(const std::string& d11)
{
    // textureGather's order: (d01, d11, d10, d00)
    return "vec4(" + lit(float(0.5 + quad_b)) + ", " + d11 + ", " + lit(float(0.5 + quad_a)) + ", 0.5)";
}
float quad_threshold_d11()
{
    // planarity e = spread / 4 + slack with spread = a + b + (a + b + e): e = (2(a + b)/4 + slack) / (3/4)
    const double slack = 2.5e-7 * 0.5;
    const double e = (0.5 * (quad_a + quad_b) + slack) / 0.75;
    return float(0.5 + quad_a + quad_b + e);
}

} // namespace

TEST_CASE("ssao decisions: no ulp step of a sample's inputs moves the output by more than 1/255", "[ssao][decisions]")
{
    const variant v = ssao_variant(ssao_decisions::smooth);
    const float vote_threshold = scene_z - bias; // sample z where z + bias = scene z
    const float range_threshold = pixel_z + radius; // scene z where |pixel z - scene z| = radius (taos: the weight reaches 0)
    const std::vector<sweep> sweeps{
        {"the vote at the bias (the sample's z)", ulp_sweep(vote_threshold), [](const std::string& x) { return pixel_output(occlusion_at_sample_z(x)); }},
        {"the range check at the radius (the scene's z)", ulp_sweep(range_threshold),
         [](const std::string& x) { return pixel_output("ao_ssao_occlusion(" + lit(pixel_z) + ", " + lit(pixel_z - 1.0f) + ", " + x + ", " + lit(radius) + ", " + lit(bias) + ")"); }},
        {"the own texel's edge (the sample's screen x; pixel (10, 10))", ulp_sweep(11.0f),
         [](const std::string& x) { return pixel_output("ao_ssao_self_weight(vec2(" + x + ", 10.5), ivec2(10, 10))"); }},
        // At 0 an ulp is a denormal (no GLSL literal keeps one): steps of a millionth of a pixel.
        {"the screen's left border (the sample's screen x)", even_sweep(-1e-4f, 1e-4f, 200),
         [](const std::string& x) { return pixel_output("ao_ssao_screen_weight(vec2(" + x + ", 50.0), vec2(320.0, 180.0))"); }},
        {"the screen's right border", ulp_sweep(320.0f),
         [](const std::string& x) { return pixel_output("ao_ssao_screen_weight(vec2(" + x + ", 50.0), vec2(320.0, 180.0))"); }},
        {"the silhouette test (one texel's raw depth)", ulp_sweep(quad_threshold_d11()),
         [](const std::string& x) { return pixel_output("ao_depth_plane_weight(" + quad_with_d11(x) + ")"); }},
    };
    const std::vector<std::vector<float>> values = evaluate(v, sweeps);
    for (size_t i = 0; i < sweeps.size(); ++i) {
        INFO(sweeps[i].what << ": the output from " << values[i].front() << " to " << values[i].back());
        CHECK(largest_step(values[i]) <= 1.0f / 255.0f);
    }
}

TEST_CASE("ssao decisions: each weight goes from one outcome to the other across its band", "[ssao][decisions]")
{
    // Coarse sweeps over the band: the smooth weights still decide, they only do not jump.
    const variant v = ssao_variant(ssao_decisions::smooth);
    const float band = ssao_bands::vote_per_radius * radius;
    const float vote_threshold = scene_z - bias;
    const std::vector<sweep> sweeps{
        {"vote", even_sweep(vote_threshold - 2 * band, vote_threshold + band),
         [](const std::string& x) { return "ao_ssao_vote(" + lit(scene_z) + ", " + x + ", " + lit(bias) + ", " + lit(radius) + ")"; }},
        {"own texel", even_sweep(10.5f, 13.0f), [](const std::string& x) { return "ao_ssao_self_weight(vec2(" + x + ", 10.5), ivec2(10, 10))"; }},
        {"screen", even_sweep(-1.0f, 3.0f), [](const std::string& x) { return "ao_ssao_screen_weight(vec2(" + x + ", 50.0), vec2(320.0, 180.0))"; }},
        {"plane", even_sweep(float(0.5 + quad_a + quad_b), float(0.5 + 3 * (quad_a + quad_b))),
         [](const std::string& x) { return "ao_depth_plane_weight(" + quad_with_d11(x) + ")"; }},
    };
    const std::vector<std::vector<float>> w = evaluate(v, sweeps);
    // The vote: 0 while the sample is at least the bias behind the scene point, 1 a band past it.
    CHECK(w[0].front() == 1.0f); // the sample far behind the scene point: occluded
    CHECK(w[0].back() == 0.0f);
    CHECK(std::is_sorted(w[0].rbegin(), w[0].rend()));
    // The own texel (band an eighth of a pixel past the texel's edge at x = 11): 0 up to
    // x = 11, 1 from x = 11.125 on.
    CHECK(w[1].front() == 0.0f);
    CHECK(w[1][6] == 0.0f);  // x = 10.96875: inside its own texel
    CHECK(w[1][7] > 0.0f);   // x = 11.046875: past the edge, inside the band
    CHECK(w[1][7] < 0.5f);
    CHECK(w[1][8] == 1.0f);  // x = 11.125: the band's end
    CHECK(w[1].back() == 1.0f);
    CHECK(std::is_sorted(w[1].begin(), w[1].end()));
    // The screen: 0 off it, 1 a band inside.
    CHECK(w[2].front() == 0.0f);
    CHECK(w[2].back() == 1.0f);
    CHECK(std::is_sorted(w[2].begin(), w[2].end()));
    // The plane: 1 on the plane itself (d11 = 0.5 + a + b), 0 well past the threshold.
    CHECK(w[3].front() == 1.0f);
    CHECK(w[3].back() == 0.0f);
    CHECK(std::is_sorted(w[3].rbegin(), w[3].rend()));
}

TEST_CASE("ssao decisions: the seeds' variant keeps the seeds' step at the bias", "[ssao][decisions]")
{
    // -step (presets.hpp's seed variants): occluded exactly when scene z > sample z + bias, so
    // one ulp of the sample's z moves the pixel by a whole vote -- the range check's weight
    // (1 - smoothstep(0, 0.5, 0.2) = 0.648) times strength / N = 0.648.
    const variant v = ssao_variant(ssao_decisions::step);
    const std::vector<sweep> sweeps{{"vote", ulp_sweep(scene_z - bias), [](const std::string& x) { return pixel_output(occlusion_at_sample_z(x)); }}};
    const std::vector<float> out = evaluate(v, sweeps)[0];
    const double t = 0.2 / 0.5, weight = 1 - t * t * (3 - 2 * t);
    CHECK(largest_step(out) == Approx(weight * strength / samples).margin(1e-6));
    CHECK(out.front() == Approx(1 - weight * strength / samples).margin(1e-6)); // occluded
    CHECK(out.back() == 1.0f);                                                    // open
}

TEST_CASE("ssao decisions: the point-cloud fallback's tests move by at most 1/255 per ulp", "[ssao][decisions]")
{
    // The billboard weight mixes the cavity AO with the hemisphere's (ssao.glsl's ao_pass), so
    // a step of it moves the output by at most the step; a ring neighbour's cavity vote moves
    // the cavity AO by at most its step (one valid neighbour of eight).
    const float centre = 0.5f;
    const float same = point_cloud::same_depth_tolerance, cavity = point_cloud::cavity_threshold;
    auto same_at = [centre](const std::string& x) { return "ao_pc_same(" + x + ", " + lit(centre) + ")"; };
    auto closer_at = [centre](const std::string& x) { return "ao_pc_closer(" + x + ", " + lit(centre) + ")"; };
    const std::vector<sweep> sweeps{
        {"same depth", ulp_sweep(centre + same), same_at},
        {"cavity", ulp_sweep(centre - cavity), closer_at},
        {"same depth, coarse", even_sweep(centre, centre + (2 + ssao_bands::point_cloud_same_per_tolerance) * same), same_at},
        {"cavity, coarse", even_sweep(centre - 2 * cavity, centre), closer_at},
    };
    const std::vector<std::vector<float>> smooth = evaluate(ssao_variant(ssao_decisions::smooth, true), sweeps);
    CHECK(largest_step(smooth[0]) <= 1.0f / 255.0f);
    CHECK(largest_step(smooth[1]) <= 1.0f / 255.0f);
    CHECK(smooth[2].front() == 1.0f); // the centre's own depth: the same
    CHECK(smooth[2].back() == 0.0f);
    CHECK(smooth[3].front() == 1.0f); // twice the threshold closer: a cavity's rim
    CHECK(smooth[3].back() == 0.0f);
    // The seeds' variant: seed 004's steps, exactly at its constants.
    const std::vector<std::vector<float>> step = evaluate(ssao_variant(ssao_decisions::step, true), sweeps);
    CHECK(largest_step(step[0]) == 1.0f);
    CHECK(largest_step(step[1]) == 1.0f);
}

} // namespace unity_test_ssao_decisions
