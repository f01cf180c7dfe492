// The stability suite's scale invariance (aogen_report/stability.hpp, case scale_invariance)
// run here on one variant of each technique, with the templates a planted mutant may replace
// (tests/mutants/mutants.json): AO is a ratio of lengths, so the box on its floor at 10⁻⁶ …
// 10⁶ of its size, its camera and AO radius scaled with it, must give the same AO within one
// step of the 8-bit output (1/255) at every pixel. An absolute length in a shader — a fixed
// bias, an epsilon compared with a distance — breaks it at one end of the range; the mutants
// plant three (ctest -L mutants) and this test must fail on each. A history variant's own
// checks (suite.hpp's history_failure) run here too, on two cases.
#include "mutants/mutants.hpp"

#include <aogen_report/run.hpp>
#include <aogen_report/suite.hpp>
#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include <iostream>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_suite_test {

namespace {

aogen_report::suite_data run_scale_case(const std::string& variant)
{
    aogen_report::suite_settings s;
    s.cases = {aogen_report::builtin_case("scale_invariance")};
    s.variants = {aogen::variant_from_name(variant)};
    s.grid = 2; // the case is judged pixel by pixel against itself: its reference is not read
    s.templates = aogen_test::template_under_test;
    return aogen_report::run_suite(s);
}

} // namespace

TEST_CASE("report: the report plans each variant once: its diagnostic build and its floors are that plan under other options", "[report][plan]")
{
    // Before, the report planned each variant four times (shipped, diagnostic, two floors).
    // A fragment or point-cloud variant's floors are the compute shaders of its compute twin,
    // another variant: that one is planned once too, for both floors.
    size_t twins = 0;
    for (const aogen::variant& v : aogen::default_matrix()) {
        INFO(aogen::to_name(v));
        const unsigned long before = aogen::codegen::detail::plans_made();
        const aogen_report::detail::generated_variant g = aogen_report::detail::generate_variant(v, true);
        const bool own_twin = aogen_report::floor_variant(v) == v;
        twins += !own_twin;
        CHECK(aogen::codegen::detail::plans_made() - before == (own_twin ? 1u : 2u));
        CHECK(g.diagnostic.name() == g.shipped.name());
        CHECK(g.diagnostic.source_options().diagnostics);
        REQUIRE(g.floors.size() == 2);
        CHECK(g.floors[0].sources.size() == g.floors[1].sources.size());
        const unsigned long twin_only = aogen::codegen::detail::plans_made();
        aogen_report::detail::generate_variant(v, false);
        CHECK(aogen::codegen::detail::plans_made() - twin_only == 1); // no floors: one plan
    }
    CHECK(twins > 0); // the matrix has fragment variants: both cases were seen
}

TEST_CASE("stability: each technique gives the same AO, pixel by pixel, at 1e-6 ... 1e6 of the scene's size", "[suite]")
{
    for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "gtao-2x2-half-denoise-gbufworld-std-persp-cs",
                             "vbao-2x3-half-bilateral-gbufworld-std-persp-cs", "sao-s16-half-denoise-gbufworld-std-persp-cs"}) {
        const aogen_report::suite_data d = run_scale_case(name);
        REQUIRE(d.cases.size() == 1);
        REQUIRE(d.cases[0].runs.size() == 1);
        const aogen_report::suite_run& r = d.cases[0].runs[0];
        INFO(name << ": " << r.decided_by);
        REQUIRE(r.ran());
        CHECK(r.raw.nan == 0);
        CHECK(r.raw.inf == 0);
        CHECK(r.scale_max <= 1.0 / 255.0);
        CHECK(r.pass);
    }
}

TEST_CASE("stability: a history variant passes its own checks: planted NaN and infinities dropped, a reset and a turn of 180 degrees this frame alone, another size refused", "[suite]")
{
    aogen_report::suite_settings s;
    s.cases = {aogen_report::builtin_case("image_8x8"), aogen_report::builtin_case("nan_depth_texel")};
    s.variants = {aogen::variant_from_name("gtao-1x4-half-noblur-gbufworld-std-persp-cs-histmv"),
                  aogen::variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-fs-hist")};
    s.grid = 8;
    s.templates = aogen_test::template_under_test;
    const aogen_report::suite_data d = aogen_report::run_suite(s);
    REQUIRE(d.cases.size() == 2);
    for (const aogen_report::suite_case_record& c : d.cases)
        for (const aogen_report::suite_run& r : c.runs) {
            INFO(c.c.name << ", " << r.variant << ": " << r.decided_by);
            REQUIRE(r.ran());
            CHECK(r.history == "");
            CHECK(r.pass);
        }
}

TEST_CASE("stability: the scale factors are the powers of ten from 1e-6 to 1e6 but 1", "[suite]")
{
    const std::vector<double> k = aogen_report::scale_factors();
    REQUIRE(k.size() == 12);
    CHECK(k.front() == Approx(1e-6).epsilon(1e-12));
    CHECK(k.back() == Approx(1e6).epsilon(1e-12));
    for (double f : k) CHECK(f != 1.0);
}

} // namespace unity_suite_test
