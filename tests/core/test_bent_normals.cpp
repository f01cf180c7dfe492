// Bent normals as a variant extra (-bn): the name and where it is valid, the define every
// pass but the prefilter gets, the four-channel output it needs (codegen::output_format_of),
// the default matrix's share, and the encoding aogen/bent_normals.hpp reads back. What the
// shaders compute is tests/vulkan/bent_normal_test.cpp's and, against the truth,
// tests/accuracy/bent_normal_test.cpp's.
#include <aogen/bent_normals.hpp>
#include <aogen/codegen.hpp>
#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_bent_normals {

using namespace aogen;

namespace {

// The format of each compute pass's output image in `v`'s plan with options `o`.
std::vector<std::string> output_formats(const variant& v, const codegen::options& o)
{
    std::vector<std::string> formats;
    const codegen::plan p = codegen::make_plan(v, o);
    for (const codegen::shader_plan& s : p.shaders())
        for (const codegen::resource& r : s.resources)
            if (r.role == resource_role::output) formats.push_back(r.format);
    return formats;
}

} // namespace

TEST_CASE("bent normals: -bn names a GTAO or VBAO compute variant and parses back", "[bent_normals]")
{
    for (const char* name : {"gtao-3x3-half-denoise-gbufworld-std-persp-cs-bn", "gtao-2x2-full-noblur-recon-rev-ortho-cs-fp16-bn-mb",
                             "vbao-3x3-half-bilateral-gbufworld-std-persp-cs-bn",
                             "gtao-1x2-half-box-gbufview-std-persp-cs-nearest-mip4-deint-bn"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        CHECK(v.bent_normals);
        CHECK(to_name(v) == name);
    }
    variant v = variant_from_name("gtao-3x3-half-denoise-gbufworld-std-persp-cs");
    CHECK_FALSE(v.bent_normals);
    v.bent_normals = true;
    CHECK(to_name(v) == "gtao-3x3-half-denoise-gbufworld-std-persp-cs-bn");
}

TEST_CASE("bent normals: -bn is for GTAO and VBAO in the compute stage: refused by name elsewhere with what is valid", "[bent_normals]")
{
    for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs-bn", "sao-s16-half-denoise-gbufworld-std-persp-cs-bn"}) {
        INFO(name);
        CHECK_THROWS_WITH(variant_from_name(name), Catch::Contains("bent normals") && Catch::Contains("valid: gtao, vbao, or off"));
    }
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-fs-bn"),
                      Catch::Contains("bent normals") && Catch::Contains("compute") && Catch::Contains("valid: off with the fragment stage"));
}

TEST_CASE("bent normals: AO_BENT_NORMALS is defined in every pass that reads or writes AO and only with -bn", "[bent_normals]")
{
    const variant v = variant_from_name("gtao-2x2-half-bilateral-gbufworld-std-persp-cs-mip4-bn");
    variant twin = v;
    twin.bent_normals = false;
    const auto bent = [](const define& d) { return d.name == "AO_BENT_NORMALS"; };
    for (pass_kind pass : passes(v)) {
        INFO(names::name_of(pass_kind_names, pass, "pass"));
        const std::vector<define> with = defines(v, pass), without = defines(twin, pass);
        CHECK(std::any_of(with.begin(), with.end(), bent) == (pass != pass_kind::prefilter));
        CHECK(std::none_of(without.begin(), without.end(), bent));
    }
}

TEST_CASE("bent normals: a -bn variant writes four channels: r8 widens to rgba8 while rgba8 and rgba16f stay and r32f is refused by name",
          "[bent_normals]")
{
    const variant v = variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs-mip4-bn");
    variant twin = v;
    twin.bent_normals = false;
    codegen::options o;
    // The prefilter's r32f depth atlas is not an AO image: it keeps its format.
    CHECK(output_formats(v, o) == std::vector<std::string>{"r32f", "rgba8", "rgba8", "rgba8"});
    CHECK(output_formats(twin, o) == std::vector<std::string>{"r32f", "r8", "r8", "r8"});
    for (const char* kept : {"rgba8", "rgba16f"}) {
        o.output_format = kept;
        CHECK(output_formats(v, o) == std::vector<std::string>{"r32f", kept, kept, kept});
    }
    // What the shader declares follows: AO_OUTPUT_FORMAT rgba8 in every AO pass's source.
    for (const codegen::shader_source& s : codegen::generate(codegen::make_plan(v)))
        if (s.pass != pass_kind::prefilter) CHECK(s.glsl.find("#define AO_OUTPUT_FORMAT rgba8\n") != std::string::npos);
    o.output_format = "r32f";
    CHECK_THROWS_WITH(codegen::make_plan(v, o), Catch::Contains("r32f") && Catch::Contains("-bn") && Catch::Contains("valid with -bn"));
    CHECK_THROWS_WITH(codegen::resources(v, pass_kind::ao, shader_stage::compute, o), Catch::Contains("valid with -bn"));
    CHECK_NOTHROW(codegen::make_plan(twin, o));
}

TEST_CASE("bent normals: the default matrix scores five -bn variants with the issue's gtao-3x3-half-denoise among them", "[bent_normals]")
{
    std::vector<std::string> with;
    for (const variant& v : default_matrix())
        if (v.bent_normals) with.push_back(to_name(v));
    CHECK(with == std::vector<std::string>{"gtao-2x2-half-denoise-gbufworld-std-persp-cs-bn", "gtao-3x3-half-denoise-gbufworld-std-persp-cs-bn",
                                           "gtao-4x4-half-denoise-gbufworld-std-persp-cs-bn", "gtao-3x3-full-noblur-gbufworld-std-persp-cs-bn",
                                           "vbao-3x3-half-bilateral-gbufworld-std-persp-cs-bn"});
}

TEST_CASE("bent normals: decode_bent_normal reads the shader's encoding back within half a degree and byte 128 as none", "[bent_normals]")
{
    // The shader's encoding (common/core.glsl's ao_encode_normal), rounded to 8 bits as a
    // UNORM store rounds: (127 n + 128) / 255.
    const auto unorm = [](float x) { return uint8_t(std::lround((x * (127.0f / 255.0f) + 128.0f / 255.0f) * 255.0f)); };
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        // Directions spread over the sphere (a Fibonacci lattice).
        const double z = 1.0 - 2.0 * (i + 0.5) / 2000.0, r = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
        const vec3 n{float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)};
        const vec3 d = decode_bent_normal(unorm(n.x), unorm(n.y), unorm(n.z));
        CHECK(std::fabs(std::sqrt(dot(d, d)) - 1.0f) < 1e-5f);
        worst = std::max(worst, std::acos(std::min(1.0, double(dot(n, d)))) * 180.0 / 3.14159265358979);
    }
    INFO("worst angle after the round trip: " << worst << " degrees");
    CHECK(worst < 0.5);
    const vec3 none = decode_bent_normal(128, 128, 128);
    CHECK((none.x == 0.0f && none.y == 0.0f && none.z == 0.0f));
    const uint8_t texels[8] = {200, 128, 255, 128, 255, 128, 128, 128}; // (AO, +y) then AO 1 with none
    const std::vector<float> both = decode_bent_normals(texels, 2);
    REQUIRE(both.size() == 6);
    CHECK(both[0] == 0.0f); // byte 128 is zero exactly
    CHECK(both[1] == 1.0f);
    CHECK(both[2] == 0.0f);
    // A zero component is a whole byte, not a rounding's midpoint: +-1e-6 encode alike.
    CHECK(unorm(1e-6f) == 128);
    CHECK(unorm(-1e-6f) == 128);
    CHECK((both[3] == 0.0f && both[4] == 0.0f && both[5] == 0.0f));
}

} // namespace unity_test_bent_normals
