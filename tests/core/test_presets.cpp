// Tests for aogen/presets.hpp: each seed's preset holds the seed's numbers, every number in
// one place -- what is compiled in on the variant, what is uploaded in the settings -- and
// the default matrix's seed variants are the presets'.
#include <aogen/matrix.hpp>
#include <aogen/presets.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_presets {

using Catch::Contains;
using aogen_test::error_of;

TEST_CASE("presets: Taos SSAO holds seeds 000/002's numbers", "[presets]")
{
    const aogen::preset p = aogen::presets::taos_ssao();
    CHECK_NOTHROW(aogen::validate(p));
    CHECK(std::string(p.name) == "taos_ssao");
    const aogen::variant& v = p.variant;
    CHECK(v.tech == aogen::technique::ssao);
    CHECK(v.samples == 16);                             // "A 16-sample kernel"
    CHECK(v.half_resolution);                                // "AO pass at half resolution"
    CHECK(v.range_check == aogen::ssao_range_check::taos);
    CHECK(v.output == aogen::ssao_output::strength);
    CHECK(v.normals == aogen::normal_source::gbuffer_world);
    CHECK_FALSE(v.point_cloud_fallback);
    CHECK(v.blur == aogen::blur_mode::bilateral);            // 'quality' (default)
    CHECK(v.blur_depth == aogen::bilateral_depth::seed_raw); // exp(-|Δdepth| * 1000)
    const aogen::ao_settings& s = p.settings;
    CHECK(s.ssao.noise_size == 4);                           // "A 4×4 tile of random 2D rotation vectors"
    CHECK(s.ssao.kernel == "crytek");                        // "classic Crytek-style"
    CHECK(s.blur.raw_depth_k == 1000.0f);
    // Not in the seeds; our choices, pinned so a change is deliberate.
    CHECK(s.ssao.radius == 0.5f);
    CHECK(s.ssao.bias == 0.025f);
    CHECK(s.ssao.strength == 1.0f);
}

TEST_CASE("presets: Taos GTAO holds seed 001's numbers", "[presets]")
{
    const aogen::preset p = aogen::presets::taos_gtao();
    CHECK_NOTHROW(aogen::validate(p));
    CHECK(std::string(p.name) == "taos_gtao");
    CHECK(p.variant.tech == aogen::technique::gtao);
    CHECK(p.settings.gtao.radius == 1.0f);
    CHECK(p.settings.gtao.thickness_bias == 0.1f);
    CHECK(p.settings.gtao.strength == 2.0f);
    // Seed 001 has a hard cut-off and plain distances: no falloff, no thin-occluder term.
    CHECK(p.settings.gtao.falloff_range == 0.0f);
    CHECK(p.settings.gtao.thin_occluder == 0.0f);
    // Slices × steps: the variant's default (docs/design.md § Variant axes).
    CHECK(p.variant.slices == 2);
    CHECK(p.variant.steps == 3);
    // "the same separable bilateral / box-blur pipelines as SSAO"
    CHECK(p.variant.blur == aogen::blur_mode::bilateral);
    CHECK(p.variant.blur_depth == aogen::bilateral_depth::seed_raw);
    CHECK(p.settings.blur.raw_depth_k == 1000.0f);
}

TEST_CASE("presets: Unique Engine holds seed 003's numbers", "[presets]")
{
    const aogen::preset p = aogen::presets::unique_engine_ssao();
    CHECK_NOTHROW(aogen::validate(p));
    CHECK(std::string(p.name) == "unique_engine_ssao");
    CHECK(p.settings.ssao.radius == 0.5f);
    CHECK(p.settings.ssao.bias == 0.025f);
    CHECK(p.settings.ssao.power == 1.0f);
    CHECK(p.settings.ssao.intensity == 1.0f);
    CHECK(p.variant.samples == 32);
    CHECK(p.variant.output == aogen::ssao_output::power_intensity);
    CHECK(p.variant.normals == aogen::normal_source::gbuffer_view);
    CHECK(p.variant.blur == aogen::blur_mode::bilateral);
}

TEST_CASE("presets: the point-cloud viewer holds seed 004's numbers", "[presets]")
{
    const aogen::preset p = aogen::presets::pointcloud_viewer_ssao();
    CHECK_NOTHROW(aogen::validate(p));
    CHECK(std::string(p.name) == "pointcloud_viewer_ssao");
    CHECK(p.variant.samples == 64);
    CHECK(p.variant.range_check == aogen::ssao_range_check::seed004);
    CHECK(p.variant.output == aogen::ssao_output::strength); // ao = 1 - occlusion/64
    CHECK(p.settings.ssao.strength == 1.0f);
    CHECK(p.settings.ssao.noise_size == 4);                   // "tiled 4x4 noise texture"
    CHECK_FALSE(p.variant.half_resolution);
    CHECK(p.variant.normals == aogen::normal_source::reconstructed);
    CHECK(p.variant.point_cloud_fallback);
    CHECK(p.variant.blur == aogen::blur_mode::none);
}

TEST_CASE("presets: the seeds' engines run fragment passes without aogen's upsample, and the matrix's seed variants are theirs", "[presets]")
{
    // The names the default matrix holds for the seeds (report results key on them); the SSAO
    // seeds carry -step since smooth decisions became the default (issue 23).
    const std::vector<std::string> expected{
        "ssao-s16-half-bilateral-gbufworld-std-persp-fs-rawdepth-step-nearest", // Taos SSAOPass
        "gtao-2x3-half-bilateral-gbufworld-std-persp-fs-rawdepth-nearest",      // Taos GTAOPass
        "ssao-s32-half-bilateral-gbufview-std-persp-fs-powint-step-nearest",    // Unique Engine UeSSAOPass
        "ssao-s64-full-noblur-recon-std-persp-fs-pc-rc004-step",                // point-cloud ssao.wgsl
    };
    std::vector<std::string> presets, matrix;
    for (const aogen::preset& p : aogen::presets::seeds()) presets.push_back(aogen::to_name(p.variant));
    for (const aogen::variant& v : aogen::seed_variants()) matrix.push_back(aogen::to_name(v));
    CHECK(presets == expected);
    CHECK(matrix == expected);
}

TEST_CASE("presets: validating a preset names the part that is wrong", "[presets]")
{
    aogen::preset p = aogen::presets::taos_ssao();
    p.settings.blur.raw_depth_k = -1.0f;
    CHECK_THAT(error_of([&] { aogen::validate(p); }), Contains("blur.raw_depth_k: -1"));
    p = aogen::presets::taos_gtao();
    p.variant.slices = 17;
    CHECK_THAT(error_of([&] { aogen::validate(p); }), Contains("gtao slices: 17 is out of range (valid: 1..16)"));
}

} // namespace unity_test_presets
