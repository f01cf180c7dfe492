// Tests for aogen/params.hpp: every run-time setting's range is enforced with a message
// naming the field, the value and the range, boundaries pass, and the defaults are the
// documented ones. The presets are test_presets.cpp's, the axis enums test_axes.cpp's.
#include <aogen/params.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_params {

using Catch::Contains;

using aogen_test::error_of;

namespace {

template <class P>
struct float_field {
    const char* name;  // as it appears in messages, with the struct prefix
    aogen::float_range range;
    std::function<void(P&, float)> set;
};

template <class P>
struct int_field {
    const char* name;
    aogen::int_range range;
    std::function<void(P&, int)> set;
};

constexpr float k_inf = std::numeric_limits<float>::infinity();
constexpr float k_nan = std::numeric_limits<float>::quiet_NaN();

// Every way a float field can be wrong is rejected; both ends of its range are accepted.
template <class P>
void check_float_fields(const std::vector<float_field<P>>& fields)
{
    for (const auto& f : fields) {
        INFO("field " << f.name);
        const std::string valid = "(valid: " + aogen::to_string(f.range) + ")";

        for (float bad : {k_nan, k_inf, -k_inf}) {
            P p;
            f.set(p, bad);
            const std::string message = error_of([&] { aogen::validate(p); });
            CHECK_THAT(message, Contains(std::string(f.name) + ": ") &&
                                    Contains("is not a finite number") && Contains(valid));
        }

        std::vector<float> out_of_range = {std::nextafter(f.range.lo, -k_inf), f.range.lo - 1.0f,
                                           std::nextafter(f.range.hi, k_inf), f.range.hi * 2.0f};
        if (f.range.lo_excluded) out_of_range.push_back(f.range.lo);
        for (float bad : out_of_range) {
            P p;
            f.set(p, bad);
            const std::string message = error_of([&] { aogen::validate(p); });
            CHECK_THAT(message, Contains(std::string(f.name) + ": " + aogen::format_number(bad) +
                                         " is out of range") &&
                                    Contains(valid));
        }

        const float lowest_ok = f.range.lo_excluded ? std::nextafter(f.range.lo, k_inf) : f.range.lo;
        for (float good : {lowest_ok, f.range.hi}) {
            P p;
            f.set(p, good);
            CHECK_NOTHROW(aogen::validate(p));
        }
    }
}

template <class P>
void check_int_fields(const std::vector<int_field<P>>& fields)
{
    for (const auto& f : fields) {
        INFO("field " << f.name);
        const std::string valid = "(valid: " + aogen::to_string(f.range) + ")";
        for (int bad : {f.range.lo - 1, f.range.hi + 1, 0, -1, std::numeric_limits<int>::min(),
                        std::numeric_limits<int>::max()}) {
            if (f.range.contains(bad)) continue;
            P p;
            f.set(p, bad);
            const std::string message = error_of([&] { aogen::validate(p); });
            CHECK_THAT(message, Contains(std::string(f.name) + ": " + std::to_string(bad) +
                                         " is out of range") &&
                                    Contains(valid));
        }
        for (int good : {f.range.lo, f.range.hi}) {
            P p;
            f.set(p, good);
            CHECK_NOTHROW(aogen::validate(p));
        }
    }
}

} // namespace

TEST_CASE("params: bilateral blur weights are the seed's, and do not sum to 1", "[params]")
{
    using B = aogen::blur_params;
    STATIC_REQUIRE(B::bilateral_taps == 7);
    STATIC_REQUIRE(B::bilateral_weights.size() == 4);  // centre + 3 per side
    CHECK(B::bilateral_weights[0] == 0.196f);
    CHECK(B::bilateral_weights[1] == 0.175f);
    CHECK(B::bilateral_weights[2] == 0.122f);
    CHECK(B::bilateral_weights[3] == 0.067f);
    // 0.196 + 2·(0.175 + 0.122 + 0.067) = 0.924, not 1: the seed's weights are not
    // normalized, so the blur must divide by the weight sum it accumulated (which the
    // depth term lowers further) rather than assume 1.
    float sum = B::bilateral_weights[0];
    for (std::size_t i = 1; i < B::bilateral_weights.size(); ++i) sum += 2.0f * B::bilateral_weights[i];
    CHECK(sum == Approx(0.924f).margin(1e-6));
    CHECK(B::bilateral_weight_sum == Approx(0.924f).margin(1e-6));
    CHECK(B::box_size == 4);
}

TEST_CASE("params: the point-cloud fallback's constants are seed 004's", "[params]")
{
    CHECK(aogen::point_cloud::background_depth == 0.9999f);
    CHECK(aogen::point_cloud::same_depth_tolerance == 0.000005f);
    CHECK(aogen::point_cloud::cavity_threshold == 0.0002f);
    CHECK(aogen::point_cloud::ring_pixels == 3);
}

TEST_CASE("params: defaults validate and follow docs/design.md, GTAO's strength and thickness tuned", "[params]")
{
    const aogen::ssao_params s;
    const aogen::gtao_params g;
    const aogen::blur_params b;
    CHECK_NOTHROW(aogen::validate(s));
    CHECK_NOTHROW(aogen::validate(g));
    CHECK_NOTHROW(aogen::validate(b));
    CHECK(s.noise_size == 4);
    CHECK(s.kernel == "crytek");
    CHECK(g.radius == 1.0f);
    // Tuned against the ray-traced reference (params.hpp; BENCHMARKS.md), not seed 001's.
    CHECK(g.thickness_bias == 0.075f);
    CHECK(g.strength == 1.109375f);
    CHECK(aogen::gtao_params::radius_per_ao_radius == 0.78125f);
    // Falloff and thin-occluder compensation: the search (BENCHMARKS.md) kept both off.
    CHECK(g.falloff_range == 0.0f);
    CHECK(g.thin_occluder == 0.0f);
    // VBAO's, tuned the same way (params.hpp).
    const aogen::vbao_params vb;
    CHECK_NOTHROW(aogen::validate(vb));
    CHECK(aogen::vbao_params::radius_per_ao_radius == 1.15625f);
    CHECK(vb.thickness == 1.634375f);
    CHECK(vb.strength == 1.28125f);
    // SAO's, tuned the same way (params.hpp; BENCHMARKS.md, 2026-12-05).
    const aogen::sao_params sa;
    CHECK_NOTHROW(aogen::validate(sa));
    CHECK(aogen::sao_params::radius_per_ao_radius == 2.6875f);
    CHECK(sa.intensity == 1.21875f);
    CHECK(sa.bias == 0.05f);
    CHECK(sa.contrast == 1.0f);
    CHECK(b.raw_depth_k == 1000.0f);
    CHECK(b.linear_sharpness == 10.0f);
    CHECK_NOTHROW(aogen::validate(aogen::ao_settings{}));
}

// ---------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------

TEST_CASE("params: messages read <struct>.<field>: <value> <problem> (valid: <range>)", "[params]")
{
    aogen::ssao_params s;
    s.radius = k_nan;
    CHECK(error_of([&] { aogen::validate(s); }) ==
          "ssao.radius: nan is not a finite number (valid: > 0 and <= 1e+15)");
    s.radius = 0.0f;
    CHECK(error_of([&] { aogen::validate(s); }) ==
          "ssao.radius: 0 is out of range (valid: > 0 and <= 1e+15)");
    s = {};
    s.bias = -0.1f;  // printed as the float it is, not 0.10000000149011612
    CHECK(error_of([&] { aogen::validate(s); }) ==
          "ssao.bias: -0.1 is out of range (valid: 0..1e+15)");

    aogen::gtao_params g;
    g.strength = -k_inf;
    CHECK(error_of([&] { aogen::validate(g); }) ==
          "gtao.strength: -inf is not a finite number (valid: > 0 and <= 100)");

    aogen::blur_params b;
    b.linear_sharpness = -2.0f;
    CHECK(error_of([&] { aogen::validate(b); }) == "blur.linear_sharpness: -2 is out of range (valid: 0..1e+12)");

    // A caller reading nested input names its own prefix.
    s = {};
    s.radius = -1.0f;
    CHECK_THAT(error_of([&] { aogen::validate(s, "variants[3].ssao"); }),
               Contains("variants[3].ssao.radius: -1 is out of range"));
    // All settings together prefix each part with its struct.
    aogen::ao_settings all;
    all.blur.raw_depth_k = -1.0f;
    CHECK_THAT(error_of([&] { aogen::validate(all); }), Contains("blur.raw_depth_k: -1"));
    all = {};
    all.vbao.thickness = 200.0f;
    CHECK(error_of([&] { aogen::validate(all); }) == "vbao.thickness: 200 is out of range (valid: > 0 and <= 100)");
}

TEST_CASE("params: every ssao field rejects bad values and accepts its bounds", "[params]")
{
    using P = aogen::ssao_params;
    check_float_fields<P>({
        {"ssao.radius", P::radius_range, [](P& p, float v) { p.radius = v; }},
        {"ssao.bias", P::bias_range, [](P& p, float v) { p.bias = v; }},
        {"ssao.strength", P::strength_range, [](P& p, float v) { p.strength = v; }},
        {"ssao.power", P::power_range, [](P& p, float v) { p.power = v; }},
        {"ssao.intensity", P::intensity_range, [](P& p, float v) { p.intensity = v; }},
    });
    check_int_fields<P>({
        {"ssao.noise_size", P::noise_size_range, [](P& p, int v) { p.noise_size = v; }},
    });

    // The documented ranges themselves.
    CHECK(aogen::to_string(P::radius_range) == "> 0 and <= 1e+15");
    CHECK(aogen::to_string(P::bias_range) == "0..1e+15");
    CHECK(aogen::to_string(P::power_range) == "> 0 and <= 100");
    CHECK(aogen::to_string(P::noise_size_range) == "1..64");

    SECTION("kernel names")
    {
        for (const char* bad : {"", "Crytek", "cry tek", "crytek\n", "hemi-sphere"}) {
            // (the newline is echoed escaped: "'crytek\x0a'")
            P p;
            p.kernel = bad;
            CHECK_THAT(error_of([&] { aogen::validate(p); }),
                       Contains("ssao.kernel: " + aogen::quote(bad) + " is not a kernel name") &&
                           Contains("(valid: 1..32 characters of a-z, 0-9 and _, e.g. crytek)"));
        }
        P p;
        p.kernel = std::string(33, 'a');
        CHECK_THAT(error_of([&] { aogen::validate(p); }), Contains("ssao.kernel"));
        for (const std::string& good : {std::string("crytek"), std::string("a"), std::string(32, 'z'),
                                        std::string("cosine_2")}) {
            p.kernel = good;
            CHECK_NOTHROW(aogen::validate(p));
        }
    }

    SECTION("seeds take any value")
    {
        P p;
        p.kernel_seed = 0;
        p.noise_seed = 0xffffffffu;
        CHECK_NOTHROW(aogen::validate(p));
    }
}

TEST_CASE("params: every gtao field rejects bad values and accepts its bounds", "[params]")
{
    using P = aogen::gtao_params;
    check_float_fields<P>({
        {"gtao.radius", P::radius_range, [](P& p, float v) { p.radius = v; }},
        {"gtao.thickness_bias", P::thickness_bias_range, [](P& p, float v) { p.thickness_bias = v; }},
        {"gtao.strength", P::strength_range, [](P& p, float v) { p.strength = v; }},
        {"gtao.falloff_range", P::falloff_range_range, [](P& p, float v) { p.falloff_range = v; }},
        {"gtao.thin_occluder", P::thin_occluder_range, [](P& p, float v) { p.thin_occluder = v; }},
    });
}

TEST_CASE("params: every vbao field rejects bad values and accepts its bounds", "[params]")
{
    using P = aogen::vbao_params;
    check_float_fields<P>({
        {"vbao.radius", P::radius_range, [](P& p, float v) { p.radius = v; }},
        {"vbao.thickness", P::thickness_range, [](P& p, float v) { p.thickness = v; }},
        {"vbao.strength", P::strength_range, [](P& p, float v) { p.strength = v; }},
    });
    CHECK(aogen::to_string(P::thickness_range) == "> 0 and <= 100");
    P p;
    CHECK_NOTHROW(aogen::validate(p));
    p.thickness = 0; // nothing would occlude
    CHECK_THAT(error_of([&] { aogen::validate(p); }), Contains("vbao.thickness: 0 is out of range (valid: > 0 and <= 100)"));
    p.thickness = 1e3f;
    CHECK_THAT(error_of([&] { aogen::validate(p, "settings.vbao"); }), Contains("settings.vbao.thickness: 1000 is out of range"));
}

TEST_CASE("params: every sao field rejects bad values and accepts its bounds", "[params]")
{
    using P = aogen::sao_params;
    check_float_fields<P>({
        {"sao.radius", P::radius_range, [](P& p, float v) { p.radius = v; }},
        {"sao.bias", P::bias_range, [](P& p, float v) { p.bias = v; }},
        {"sao.intensity", P::intensity_range, [](P& p, float v) { p.intensity = v; }},
        {"sao.contrast", P::contrast_range, [](P& p, float v) { p.contrast = v; }},
    });
    P p;
    p.contrast = 0; // pow(0, 0) is undefined
    CHECK(error_of([&] { aogen::validate(p); }) == "sao.contrast: 0 is out of range (valid: > 0 and <= 100)");
    p = {};
    p.bias = 1.5f; // a share of the radius
    CHECK(error_of([&] { aogen::validate(p); }) == "sao.bias: 1.5 is out of range (valid: 0..1)");
    aogen::ao_settings all;
    all.sao.intensity = -1.0f;
    CHECK_THAT(error_of([&] { aogen::validate(all); }), Contains("sao.intensity: -1 is out of range"));
}

TEST_CASE("params: every blur field rejects bad values and accepts its bounds", "[params]")
{
    using P = aogen::blur_params;
    check_float_fields<P>({
        {"blur.raw_depth_k", P::raw_depth_k_range, [](P& p, float v) { p.raw_depth_k = v; }},
        {"blur.linear_sharpness", P::linear_sharpness_range,
         [](P& p, float v) { p.linear_sharpness = v; }},
    });

}

} // namespace unity_test_params
