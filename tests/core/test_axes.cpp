// Tests for aogen/axes.hpp and the counts of variant.hpp: every axis enum's names round-trip,
// unknown names and values are errors listing the valid ones, and a variant's counts are
// bounded by the ranges written beside them.
#include <aogen/axes.hpp>
#include <aogen/variant.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <limits>
#include <string>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_axes {

using Catch::Contains;
using aogen_test::error_of;

namespace {

// Every entry of `table` names its value both ways.
template <class Table, class FromName>
void check_round_trip(const Table& table, FromName from_name)
{
    for (const auto& e : table) {
        INFO(e.name);
        CHECK(std::string(aogen::to_name(e.value)) == e.name);
        CHECK(from_name(e.name) == e.value);
    }
}

} // namespace

TEST_CASE("axes: enum names round-trip, '-' reading as '_'", "[axes]")
{
    check_round_trip(aogen::technique_names, [](std::string_view n) { return aogen::technique_from_name(n); });
    check_round_trip(aogen::blur_mode_names, [](std::string_view n) { return aogen::blur_mode_from_name(n); });
    check_round_trip(aogen::bilateral_depth_names, [](std::string_view n) { return aogen::bilateral_depth_from_name(n); });
    check_round_trip(aogen::ssao_output_names, [](std::string_view n) { return aogen::ssao_output_from_name(n); });
    check_round_trip(aogen::ssao_range_check_names, [](std::string_view n) { return aogen::ssao_range_check_from_name(n); });
    check_round_trip(aogen::normal_source_names, [](std::string_view n) { return aogen::normal_source_from_name(n); });
    check_round_trip(aogen::upsample_mode_names, [](std::string_view n) { return aogen::upsample_mode_from_name(n); });
    CHECK(std::string(aogen::to_name(aogen::depth_convention::reversed_infinite)) == "reversed_infinite");
    CHECK(std::string(aogen::to_name(aogen::pipeline_stage::fragment)) == "fragment");
    CHECK(std::string(aogen::to_name(aogen::projection_kind::orthographic)) == "orthographic");

    // docs/design.md § Variant axes writes "gbuffer-world".
    CHECK(aogen::normal_source_from_name("gbuffer-world") == aogen::normal_source::gbuffer_world);
    CHECK(aogen::ssao_output_from_name("power-intensity") == aogen::ssao_output::power_intensity);
}

TEST_CASE("axes: unknown names and values are errors naming the axis and listing the valid names", "[axes]")
{
    CHECK(error_of([] { aogen::blur_mode_from_name("gaussian"); }) ==
          "blur: 'gaussian' is not a known name (valid: bilateral, box, none, denoise, denoise3)");
    CHECK(error_of([] { aogen::blur_mode_from_name("Bilateral", "--blur"); }) ==
          "--blur: 'Bilateral' is not a known name (valid: bilateral, box, none, denoise, denoise3)");
    CHECK_THAT(error_of([] { aogen::bilateral_depth_from_name(""); }),
               Contains("bilateral depth: '' is not a known name") && Contains("seed_raw, linear"));
    CHECK_THAT(error_of([] { aogen::ssao_range_check_from_name("seed"); }),
               Contains("range check: 'seed'") && Contains("taos, seed004"));
    CHECK_THAT(error_of([] { aogen::ssao_output_from_name("power"); }),
               Contains("output: 'power'") && Contains("strength, power_intensity"));
    CHECK_THAT(error_of([] { aogen::normal_source_from_name("world"); }),
               Contains("normals: 'world' is not a known name") && Contains("gbuffer_world, gbuffer_view, reconstructed"));
    CHECK_THAT(error_of([] { aogen::technique_from_name("hbao"); }), Contains("technique: 'hbao'") && Contains("ssao, gtao, vbao"));

    CHECK(error_of([] { aogen::to_name(static_cast<aogen::blur_mode>(5)); }) ==
          "blur: 5 is not a valid value (valid: bilateral, box, none, denoise, denoise3)");
    CHECK_THAT(error_of([] { aogen::to_name(static_cast<aogen::ssao_output>(-1)); }), Contains("output: -1 is not a valid value"));
}

TEST_CASE("axes: a variant holding an enum value outside its list is an error naming the axis", "[axes]")
{
    using aogen::variant;
    auto message = [](void (*plant)(variant&)) {
        variant v;
        plant(v);
        return error_of([&] { aogen::validate(v); });
    };
    CHECK_THAT(message([](variant& v) { v.output = static_cast<aogen::ssao_output>(2); }),
               Contains("output: 2 is not a valid value") && Contains("(valid: strength, power_intensity)"));
    CHECK_THAT(message([](variant& v) { v.range_check = static_cast<aogen::ssao_range_check>(-1); }),
               Contains("range check: -1 is not a valid value") && Contains("(valid: taos, seed004)"));
    CHECK_THAT(message([](variant& v) { v.normals = static_cast<aogen::normal_source>(3); }),
               Contains("normals: 3 is not a valid value") && Contains("(valid: gbuffer_world, gbuffer_view, reconstructed)"));
    CHECK_THAT(message([](variant& v) { v.blur_depth = static_cast<aogen::bilateral_depth>(2); }),
               Contains("bilateral depth: 2 is not a valid value") && Contains("(valid: seed_raw, linear)"));
    CHECK_THAT(message([](variant& v) { v.blur = static_cast<aogen::blur_mode>(-5); }),
               Contains("blur: -5 is not a valid value") && Contains("(valid: bilateral, box, none, denoise, denoise3)"));
    CHECK_THAT(message([](variant& v) { v.upsample = static_cast<aogen::upsample_mode>(9); }), Contains("upsample: 9 is not a valid value"));
}

TEST_CASE("axes: a variant's counts are bounded by the ranges beside them", "[axes]")
{
    using aogen::variant;
    CHECK(aogen::to_string(variant::samples_range) == "1..256");
    CHECK(aogen::to_string(variant::slices_range) == "1..16");
    CHECK(aogen::to_string(variant::steps_range) == "1..16");
    CHECK(aogen::to_string(variant::workgroup_side_range) == "1..32");
    struct count {
        const char* subject;
        aogen::int_range range;
        int variant::*field;
        aogen::technique tech;
    };
    for (const count& c : {count{"ssao samples", variant::samples_range, &variant::samples, aogen::technique::ssao},
                           count{"gtao slices", variant::slices_range, &variant::slices, aogen::technique::gtao},
                           count{"vbao steps", variant::steps_range, &variant::steps, aogen::technique::vbao}}) {
        INFO(c.subject);
        for (int bad : {c.range.lo - 1, c.range.hi + 1, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()}) {
            variant v;
            v.tech = c.tech;
            v.*c.field = bad;
            CHECK(error_of([&] { aogen::validate(v); }) ==
                  std::string(c.subject) + ": " + std::to_string(bad) + " is out of range (valid: " + aogen::to_string(c.range) + ")");
        }
        for (int good : {c.range.lo, c.range.hi}) {
            variant v;
            v.tech = c.tech;
            v.*c.field = good;
            CHECK_NOTHROW(aogen::validate(v));
        }
    }
}

} // namespace unity_test_axes
