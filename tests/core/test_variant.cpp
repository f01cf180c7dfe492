// Variants: names round-trip and are unique per distinct variant, invalid names and
// values are errors naming the axis, defines follow the contract the templates read,
// scene selection leaves out what the scene does not need, and the default matrix is
// the set.
#include <aogen/matrix.hpp>
#include <aogen/plan.hpp>
#include <aogen/quality.hpp>
#include <aogen/selection.hpp>
#include <aogen/variant.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <set>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_variant {

using namespace aogen;
using aogen_test::error_of;
using Catch::Contains;
using Catch::EndsWith;

namespace {

// Many variants: every choice axis with two sample counts and two slice/step counts.
std::vector<variant> broad_set()
{
    variant_matrix m;
    m.techniques = {technique::ssao, technique::gtao, technique::vbao};
    m.samples = {1, 256};
    m.slices = {1, 16};
    m.steps = {16};
    m.blur = {blur_mode::bilateral, blur_mode::box, blur_mode::none};
    m.blur_depth = {bilateral_depth::linear, bilateral_depth::seed_raw};
    m.normals = {normal_source::gbuffer_world, normal_source::gbuffer_view, normal_source::reconstructed};
    m.point_cloud_fallback = {false, true};
    m.depth = {depth_convention::standard, depth_convention::reversed, depth_convention::reversed_infinite};
    m.projection = {projection_kind::perspective, projection_kind::orthographic};
    m.half_resolution = {false, true};
    m.stage = {pipeline_stage::compute, pipeline_stage::fragment};
    m.range_check = {ssao_range_check::taos, ssao_range_check::seed004};
    m.output = {ssao_output::strength, ssao_output::power_intensity};
    m.fp16 = {false, true};
    return expand(m);
}

} // namespace

TEST_CASE("variant: the history pass is -hist or -histmv, runs after the blur and before the upsample in either stage, and is refused by name where it cannot run", "[variant]")
{
    const variant cam = variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist");
    CHECK(cam.history == history_mode::camera);
    CHECK(passes(cam) == std::vector<pass_kind>{pass_kind::ao, pass_kind::blur_denoise, pass_kind::history, pass_kind::upsample});
    const variant mv = variant_from_name("ssao-s16-full-noblur-gbufworld-std-persp-cs-mb-histmv-wg16x16");
    CHECK(mv.history == history_mode::motion_vectors);
    CHECK(passes(mv) == std::vector<pass_kind>{pass_kind::ao, pass_kind::history});
    CHECK(applies_multi_bounce(mv, pass_kind::history));
    CHECK(!applies_multi_bounce(mv, pass_kind::ao));
    CHECK(cam != variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs"));
    CHECK(to_name(cam) == "gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist");
    CHECK_THROWS_WITH(variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist-histmv"), Contains("a second history extra") && Contains("valid: one of hist, histmv"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-hist-hist"), Contains("appears twice"));
    const variant fs = variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-fs-histmv"); // two colour attachments
    CHECK(passes(fs) == std::vector<pass_kind>{pass_kind::ao, pass_kind::blur_denoise, pass_kind::history, pass_kind::upsample});
    CHECK_THROWS_WITH(variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-bn-hist"), Contains("history: is not available with bent normals"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-wg8x8-hist"), Contains("not in canonical form"));
    variant bad = cam;
    bad.history = static_cast<history_mode>(7);
    CHECK_THROWS_WITH(validate(bad), Contains("history") && Contains("valid: off, camera, motion_vectors"));
    // A matrix skips what cannot run, as it does for bent normals.
    variant_matrix m;
    m.techniques = {technique::gtao};
    m.stage = {pipeline_stage::compute, pipeline_stage::fragment};
    m.bent_normals = {false, true};
    m.history = {history_mode::off, history_mode::camera, history_mode::motion_vectors};
    CHECK(expand(m).size() == 3 + 3 + 1); // fs and cs: off, hist, histmv; cs-bn: off
}

TEST_CASE("variant: the 3x3 denoise is -denoise3, one pass after the AO pass, compute only, without bent normals, its AO pass writing rgba8", "[variant]")
{
    const variant v = variant_from_name("gtao-3x3-full-denoise3-gbufworld-std-persp-cs");
    CHECK(v.blur == blur_mode::denoise3);
    CHECK(passes(v) == std::vector<pass_kind>{pass_kind::ao, pass_kind::blur_denoise3});
    CHECK(passes(variant_from_name("ssao-s16-half-denoise3-gbufworld-std-persp-cs-hist")) ==
          std::vector<pass_kind>{pass_kind::ao, pass_kind::blur_denoise3, pass_kind::history, pass_kind::upsample});
    CHECK_THROWS_WITH(variant_from_name("gtao-2x2-half-denoise3-gbufworld-std-persp-fs"),
                      EndsWith("blur denoise3: needs the compute stage (its AO pass writes the edges beside the AO, in its storage image) "
                               "(valid: denoise3 with the compute stage, or denoise, bilateral, box, none with the fragment stage)"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x2-half-denoise3-gbufworld-std-persp-cs-bn"),
                      Contains("blur denoise3: is not available with bent normals") && Contains("valid: denoise3 without -bn"));
    // Its tile of (2x + 2)(2y + 2) words fits the 16 KiB every device has up to (x + 1)(y + 1) = 1024.
    CHECK(denoise3_tile_bytes(8, 8) == 18 * 18 * 4);
    CHECK_NOTHROW(variant_from_name("gtao-3x3-full-denoise3-gbufworld-std-persp-cs-wg32x30"));
    CHECK_THROWS_WITH(variant_from_name("gtao-3x3-full-denoise3-gbufworld-std-persp-cs-wg32x32"),
                      EndsWith("blur denoise3: needs 17424 bytes of shared memory in 32x32 groups, over the 16384 every device has "
                               "(valid: workgroups with (x + 1) * (y + 1) <= 1024, e.g. wg16x16, wg32x16)"));
    CHECK_NOTHROW(variant_from_name("gtao-3x3-full-denoise-gbufworld-std-persp-cs-wg32x32"));
    // A matrix skips what cannot run.
    variant_matrix m;
    m.blur = {blur_mode::denoise3};
    m.stage = {pipeline_stage::compute, pipeline_stage::fragment};
    m.bent_normals = {false, true};
    m.techniques = {technique::gtao};
    CHECK(expand(m).size() == 1);
    // Its AO pass writes (ao, right edge, lower edge): r8 widens to rgba8, r32f is refused.
    CHECK(codegen::output_format_of(v, {}) == "rgba8");
    codegen::options r32f;
    r32f.output_format = "r32f";
    CHECK_THROWS_WITH(codegen::output_format_of(v, r32f), Contains("a -denoise3 variant's AO pass writes three (AO, right edge, lower edge)") &&
                                                              Contains("valid with -denoise3: r8 (widened to rgba8), rgba8, rgba16f"));
    CHECK(codegen::output_format_of(variant_from_name("gtao-3x3-full-denoise-gbufworld-std-persp-cs"), r32f) == "r32f");
}

TEST_CASE("variant: the default's name is the one docs/design.md spells", "[variant]")
{
    CHECK(to_name(variant{}) == "ssao-s16-half-bilateral-gbufworld-std-persp-cs");
    variant v;
    v.tech = technique::gtao;
    v.stage = pipeline_stage::fragment;
    v.blur = blur_mode::box;
    CHECK(to_name(v) == "gtao-2x3-half-box-gbufworld-std-persp-fs");
    v.tech = technique::vbao;
    CHECK(to_name(v) == "vbao-2x3-half-box-gbufworld-std-persp-fs");
}

TEST_CASE("variant: vbao shares gtao's slice x step token, keeps its counts, and gtao's names are unchanged", "[variant]")
{
    const variant v = variant_from_name("vbao-9x3-full-bilateral-gbufview-rev-ortho-cs-fp16");
    CHECK(v.tech == technique::vbao);
    CHECK(v.slices == 9);
    CHECK(v.steps == 3);
    CHECK(!v.half_resolution);
    CHECK(to_name(variant_from_name(to_name(v))) == "vbao-9x3-full-bilateral-gbufview-rev-ortho-cs-fp16");
    // Same axes, other technique: another variant, another name, another hash.
    variant g = v;
    g.tech = technique::gtao;
    CHECK(g != v);
    CHECK(hash(g) != hash(v));
    CHECK(to_name(g) == "gtao-9x3-full-bilateral-gbufview-rev-ortho-cs-fp16");
    // Its defines: VBAO's counts and technique, no GTAO or SSAO define.
    std::set<std::string> names;
    for (const define& d : defines(v, pass_kind::ao)) names.insert(d.name + "=" + d.value);
    CHECK(names.count("AO_TECHNIQUE_VBAO="));
    CHECK(names.count("AO_VBAO_SLICES=9"));
    CHECK(names.count("AO_VBAO_STEPS=3"));
    for (const std::string& n : names) CHECK((n.rfind("AO_GTAO", 0) != 0 && n.rfind("AO_SSAO", 0) != 0));
    // SSAO's axes are irrelevant to it, as to GTAO.
    variant a = v;
    a.samples = 64, a.range_check = ssao_range_check::seed004;
    CHECK(a == v);
    CHECK_THAT(error_of([] { variant_from_name("vbao-17x3-half-bilateral-gbufworld-std-persp-cs"); }), Contains("vbao slices: 17 is out of range"));
    CHECK_THAT(error_of([] { variant_from_name("vbao-2x3-half-bilateral-gbufworld-std-persp-cs-pc"); }),
               Contains("not available with vbao"));
    CHECK_THAT(error_of([] { variant_from_name("vbao-s16-half-bilateral-gbufworld-std-persp-cs"); }), Contains("is not slices x steps"));
}

TEST_CASE("variant: sao shares ssao's sample token, refuses fp16 and the point-cloud fallback, ignores ssao's own axes", "[variant]")
{
    const variant v = variant_from_name("sao-s12-full-denoise-recon-revinf-ortho-cs-mip3");
    CHECK(v.tech == technique::sao);
    CHECK(v.samples == 12);
    CHECK(v.depth_mips == 3);
    CHECK(to_name(variant_from_name(to_name(v))) == "sao-s12-full-denoise-recon-revinf-ortho-cs-mip3");
    variant s = v;
    s.tech = technique::ssao;
    CHECK(s != v);
    CHECK(to_name(s) == "ssao-s12-full-denoise-recon-revinf-ortho-cs-mip3");
    // Its defines: SAO's tap count and technique, none of SSAO's.
    std::set<std::string> names;
    for (const define& d : defines(v, pass_kind::ao)) names.insert(d.name + "=" + d.value);
    CHECK(names.count("AO_TECHNIQUE_SAO="));
    CHECK(names.count("AO_SAO_SAMPLES=12"));
    for (const std::string& n : names) CHECK((n.rfind("AO_SSAO", 0) != 0 && n.rfind("AO_RANGE_CHECK", 0) != 0 && n.rfind("AO_OUTPUT", 0) != 0));
    // SSAO's range check, output and decisions, and the slice counts, are not SAO's.
    variant a = v;
    a.range_check = ssao_range_check::seed004, a.output = ssao_output::power_intensity, a.decisions = ssao_decisions::step, a.slices = 7;
    CHECK(a == v);
    variant b = v;
    b.samples = 13;
    CHECK(b != v);
    CHECK_THAT(error_of([] { variant_from_name("sao-s0-half-bilateral-gbufworld-std-persp-cs"); }), Contains("sao taps: 0 is out of range"));
    CHECK_THAT(error_of([] { variant_from_name("sao-2x3-half-bilateral-gbufworld-std-persp-cs"); }), Contains("is not a sample count"));
    CHECK_THAT(error_of([] { variant_from_name("sao-s16-half-bilateral-gbufworld-std-persp-cs-pc"); }), Contains("not available with sao"));
    CHECK_THAT(error_of([] { variant_from_name("sao-s16-half-bilateral-gbufworld-std-persp-cs-fp16"); }),
               Contains("fp16: is not available with sao") && Contains("valid: off with sao"));
    CHECK_THAT(error_of([] { variant_from_name("sao-s16-half-bilateral-gbufworld-std-persp-cs-step"); }), Contains("is not in canonical form"));
}

TEST_CASE("variant: every name parses back into the same variant, and names are unique", "[variant]")
{
    const std::vector<variant> all = broad_set();
    REQUIRE(all.size() > 2000);
    std::set<std::string> names, hashes;
    for (const variant& v : all) {
        const std::string name = to_name(v);
        INFO(name);
        CHECK(variant_from_name(name) == v);
        CHECK(to_name(variant_from_name(name)) == name);
        names.insert(name);
        hashes.insert(hash(v));
    }
    CHECK(names.size() == all.size());  // expand() returned distinct variants: distinct names
    CHECK(hashes.size() == all.size());
}

TEST_CASE("variant: canonical form ignores the axes a technique does not use", "[variant]")
{
    variant a, b;
    a.tech = b.tech = technique::gtao;
    b.samples = 64;
    b.blur_depth = bilateral_depth::seed_raw; // bilateral is on: this one counts
    CHECK(a != b);
    a.blur_depth = bilateral_depth::seed_raw;
    CHECK(a == b);
    CHECK(to_name(a) == to_name(b));
    variant c;
    c.blur = blur_mode::none;
    c.blur_depth = bilateral_depth::seed_raw;  // no bilateral blur: irrelevant
    CHECK(to_name(c) == "ssao-s16-half-noblur-gbufworld-std-persp-cs");
}

TEST_CASE("variant: invalid names name the token and the valid values", "[variant][errors]")
{
    CHECK_THAT(error_of([] { variant_from_name("ssao-s16-half-blurry-gbufworld-std-persp-cs"); }),
               Contains("'blurry' is not a known name") && Contains("bilateral, box, noblur"));
    CHECK_THAT(error_of([] { variant_from_name("ssao-s0-half-bilateral-gbufworld-std-persp-cs"); }),
               Contains("ssao samples: 0 is out of range (valid: 1..256)"));
    CHECK_THAT(error_of([] { variant_from_name("hbao-s16-half-bilateral-gbufworld-std-persp-cs"); }),
               Contains("'hbao' is not a known name (valid: ssao, gtao, vbao, sao)"));
    CHECK_THAT(error_of([] { variant_from_name("gtao-2x17-half-bilateral-gbufworld-std-persp-cs"); }),
               Contains("gtao steps: 17 is out of range (valid: 1..16)"));
    CHECK_THAT(error_of([] { variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-cs-fast"); }),
               Contains("'fast' is not a known extra"));
    CHECK_THAT(error_of([] { variant_from_name("ssao-s16-half"); }), Contains("too few"));
    CHECK_THAT(error_of([] { variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-cs-wg8x8"); }),
               Contains("not in canonical form") && Contains("valid: ssao-s16-half-bilateral-gbufworld-std-persp-cs"));
    CHECK_THAT(error_of([] { variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-pc"); }),
               Contains("point-cloud fallback"));
    CHECK_THAT(error_of([] { variant_from_name("gtao-2x3-half-denoise-gbufworld-std-persp-fs-deint"); }),
               Contains("deinterleaved: dispatch needs the compute stage") && Contains("valid: off with the fragment stage"));
    CHECK_THAT(error_of([] { variant_from_name("gtao-2x3-half-denoise-gbufworld-std-persp-cs-deint-wg6x8"); }),
               Contains("deinterleaved: dispatch needs workgroup sides that are multiples of 4, not 6x8") && Contains("valid: e.g. wg8x8"));
    CHECK(to_name(variant_from_name("gtao-2x3-half-denoise-gbufworld-std-persp-cs-deint-wg16x8")) ==
          "gtao-2x3-half-denoise-gbufworld-std-persp-cs-deint-wg16x8");
    CHECK(variant_from_name("gtao-2x3-half-denoise-gbufworld-std-persp-cs-deint").deinterleaved);
    variant v;
    v.workgroup_x = 64;
    CHECK_THAT(error_of([&] { validate(v); }), Contains("workgroup x: 64 is out of range (valid: 1..32)"));
    v.workgroup_x = 32, v.workgroup_y = 32;
    CHECK_NOTHROW(validate(v));
    v.blur = static_cast<blur_mode>(9);
    CHECK_THAT(error_of([&] { validate(v); }), Contains("blur: 9 is not a valid value"));
}

TEST_CASE("variant: each pass gets exactly one define per choice axis", "[variant]")
{
    for (const variant& v : broad_set()) {
        for (pass_kind pass : passes(v)) {
            std::set<std::string> groups;
            for (const define& d : defines(v, pass)) {
                INFO(to_name(v) << " " << d.name);
                const std::string group = d.name.substr(0, d.name.find('_', 3));
                if (d.value.empty() && d.name != "AO_HALF_RESOLUTION" && d.name != "AO_POINT_CLOUD_FALLBACK")
                    CHECK(groups.insert(group).second);
            }
        }
    }
    const std::vector<define> ao = defines(variant_from_name("ssao-s32-half-bilateral-recon-rev-ortho-cs-pc"), pass_kind::ao);
    auto has = [&](const char* name, const char* value) {
        for (const define& d : ao)
            if (d.name == name) return d.value == value;
        return false;
    };
    CHECK(has("AO_SSAO_SAMPLES", "32"));
    CHECK(has("AO_NORMALS_RECONSTRUCTED", ""));
    CHECK(has("AO_DEPTH_REVERSED", ""));
    CHECK(has("AO_PROJECTION_ORTHOGRAPHIC", ""));
    CHECK(has("AO_POINT_CLOUD_FALLBACK", ""));
    CHECK(has("AO_WORKGROUP_X", "8"));
    // Half resolution ends with the depth-aware upsample; -nearest and full resolution have none.
    CHECK(passes(variant{}) == std::vector<pass_kind>{pass_kind::ao, pass_kind::blur_x, pass_kind::blur_y, pass_kind::upsample});
    CHECK(passes(variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-cs-nearest")) ==
          std::vector<pass_kind>{pass_kind::ao, pass_kind::blur_x, pass_kind::blur_y});
    CHECK(passes(variant_from_name("gtao-2x3-full-denoise-gbufworld-std-persp-cs")) == std::vector<pass_kind>{pass_kind::ao, pass_kind::blur_denoise});
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-full-denoise-gbufworld-std-persp-cs-nearest"),
                      Catch::Contains("not in canonical form") && Catch::Contains("valid: gtao-2x3-full-denoise-gbufworld-std-persp-cs"));
    // fp16: the AO pass only (the blurs stay 32-bit), and only when asked for.
    const variant half = variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16");
    CHECK(half.fp16);
    auto defines_fp16 = [](const variant& v, pass_kind pass) {
        for (const define& d : defines(v, pass))
            if (d.name == "AO_FP16") return true;
        return false;
    };
    CHECK(defines_fp16(half, pass_kind::ao));
    CHECK_FALSE(defines_fp16(half, pass_kind::blur_x));
    CHECK_FALSE(defines_fp16(variant{}, pass_kind::ao));
}

TEST_CASE("selection: a mesh-only scene leaves the point-cloud fallback out, and says why", "[variant][selection]")
{
    variant base = variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-cs-pc");
    scene_needs scene;
    const selection s = select(base, scene);
    CHECK_FALSE(s.v.point_cloud_fallback);
    bool found = false;
    for (const left_out_feature& f : s.features.left_out)
        if (f.feature == "point-cloud fallback") found = f.why == "the scene has no point clouds";
    CHECK(found);

    scene.normals = normal_source::reconstructed;
    scene.point_clouds = true;
    scene.depth = depth_convention::reversed_infinite;
    scene.blur = blur_mode::none;
    scene.half_resolution_ok = false;
    const selection t = select(variant{}, scene);
    CHECK(to_name(t.v) == "ssao-s16-full-noblur-recon-revinf-persp-cs-pc");
    std::set<std::string> left;
    for (const left_out_feature& f : t.features.left_out) left.insert(f.feature);
    CHECK(left.count("normal buffer input"));
    CHECK(left.count("bilateral blur"));
    CHECK(left.count("box blur"));
    CHECK(left.count("edge-aware denoise"));
    CHECK(left.count("depth-aware upsample")); // full resolution: nothing to upsample
    CHECK_FALSE(left.count("point-cloud fallback"));
    // Half resolution compiles the upsample in, unless -nearest leaves it to the caller.
    auto compiled = [](const variant& v) {
        const feature_list f = features(v);
        return std::set<std::string>(f.compiled.begin(), f.compiled.end());
    };
    CHECK(compiled(variant{}).count("depth-aware upsample"));
    CHECK_FALSE(compiled(variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-cs-nearest")).count("depth-aware upsample"));
}

TEST_CASE("matrix: the default matrix is the issue's set", "[variant][matrix]")
{
    const std::vector<variant> m = default_matrix();
    CHECK(m.size() == 32 + 60 + 4 + 5 + 12 + 5 + 5);
    int ssao_cs = 0, gtao_cs = 0, gtao_bent = 0, vbao_cs = 0, sao_cs = 0, fs = 0, denoise3 = 0;
    for (const variant& v : m) {
        if (v.blur == blur_mode::denoise3) ++denoise3;
        else if (v.stage == pipeline_stage::fragment) ++fs;
        else if (v.tech == technique::ssao) ++ssao_cs;
        else if (v.tech == technique::gtao) ++(v.bent_normals ? gtao_bent : gtao_cs);
        else if (v.tech == technique::vbao) ++(v.bent_normals ? gtao_bent : vbao_cs);
        else ++sao_cs;
    }
    CHECK(ssao_cs == 32); // 4 sample counts x 4 blurs x full/half
    CHECK(gtao_cs == 60); // 5 slice counts x 3 step counts x 4 blurs
    CHECK(gtao_bent == 5); // with bent normals: GTAO 2x2, 3x3, 4x4 half denoise, 3x3 full noblur, VBAO High (test_bent_normals.cpp)
    CHECK(vbao_cs == 5);
    CHECK(sao_cs == 12); // 3 tap counts x bilateral/denoise x full/half
    CHECK(fs == 4);
    CHECK(denoise3 == 5); // GTAO 2x2, 3x3 half and 3x3 full, SSAO and SAO s16 half
    // VBAO last, so that the others keep their order: the quality presets, then High at full resolution.
    std::vector<std::string> vbao;
    for (size_t i = 96; i < 101; ++i) vbao.push_back(to_name(m[i]));
    CHECK(vbao == std::vector<std::string>{"vbao-1x2-half-bilateral-gbufworld-std-persp-cs", "vbao-2x2-half-bilateral-gbufworld-std-persp-cs",
                                           "vbao-3x3-half-bilateral-gbufworld-std-persp-cs", "vbao-9x3-half-bilateral-gbufworld-std-persp-cs",
                                           "vbao-3x3-full-bilateral-gbufworld-std-persp-cs"});
    CHECK(to_name(m.front()) == "ssao-s8-full-bilateral-gbufworld-std-persp-cs");
    // SAO after VBAO, then the bent-normal variants.
    CHECK(to_name(m[101]) == "sao-s8-full-bilateral-gbufworld-std-persp-cs");
    CHECK(to_name(m[112]) == "sao-s32-half-denoise-gbufworld-std-persp-cs");
    CHECK(to_name(m[117]) == "vbao-3x3-half-bilateral-gbufworld-std-persp-cs-bn");
    // The 3x3 denoise's variants last.
    CHECK(to_name(m[118]) == "gtao-2x2-half-denoise3-gbufworld-std-persp-cs");
    CHECK(to_name(m.back()) == "sao-s16-half-denoise3-gbufworld-std-persp-cs");
}

TEST_CASE("quality: XeGTAO's four levels by name, applied to GTAO and VBAO only, and named back", "[variant][quality]")
{
    variant v;
    v.tech = technique::gtao;
    const std::array<std::pair<const char*, std::pair<int, int>>, 4> expected{{{"low", {1, 2}}, {"medium", {2, 2}}, {"high", {3, 3}}, {"ultra", {9, 3}}}};
    for (technique t : {technique::gtao, technique::vbao})
    for (const auto& [name, counts] : expected) {
        v.tech = t;
        INFO(name);
        apply_quality(v, quality_preset_from_name(name));
        CHECK(v.slices == counts.first);
        CHECK(v.steps == counts.second);
        CHECK(quality_name_of(v) == name);
        validate(v);
    }
    v.slices = 2, v.steps = 3; // the default 2x3 is no preset
    CHECK(quality_name_of(v).empty());
    CHECK(quality_name_of(variant{}).empty());
    CHECK_THAT(error_of([] { quality_preset_from_name("epic"); }), Contains("'epic' is not a quality preset (valid: low, medium, high, ultra)"));
    variant ssao;
    CHECK_THAT(error_of([&] { apply_quality(ssao, quality_preset_from_name("high")); }), Contains("sets slices and steps, and the variant is ssao (valid: technique gtao or vbao)"));
}

TEST_CASE("variant: a pipeline stage's AO pass compiles as that shader stage", "[variant]")
{
    CHECK(aogen::stage_of(aogen::pipeline_stage::compute) == aogen::shader_stage::compute);
    CHECK(aogen::stage_of(aogen::pipeline_stage::fragment) == aogen::shader_stage::fragment);
}

} // namespace unity_test_variant
