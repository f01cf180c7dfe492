// Multi-bounce as a variant extra (-mb) and a finalize setting: the name and spec key, the
// define that only the chain's last pass gets, the albedo's range, the uniform member that
// carries it. What the shader does with it is tests/vulkan/multi_bounce_test.cpp's.
#include <aogen/chain_inputs.hpp>
#include <aogen/layout.hpp>
#include <aogen/variant.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

using namespace aogen;

namespace {

bool has_define(const variant& v, pass_kind pass, const std::string& name)
{
    for (const define& d : defines(v, pass))
        if (d.name == name) return true;
    return false;
}

float float_at(const std::vector<uint8_t>& bytes, const layout::block_desc& block, const std::string& member)
{
    for (const layout::member_layout& m : layout::compute(block, layout::rules::std140).members)
        if (m.name == member) {
            float f;
            std::memcpy(&f, bytes.data() + m.offset, sizeof f);
            return f;
        }
    FAIL("no member " << member);
    return 0;
}

} // namespace

TEST_CASE("multi-bounce: -mb names a variant of every technique and parses back", "[multi_bounce]")
{
    for (const char* name : {"gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb", "ssao-s16-half-bilateral-gbufworld-std-persp-fs-mb",
                             "vbao-2x3-half-denoise-recon-std-persp-cs-nearest-mip3-deint-mb-wg16x8", "sao-s8-full-noblur-gbufworld-std-persp-cs-mb"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        CHECK(v.multi_bounce);
        CHECK(to_name(v) == name);
        variant without = v;
        without.multi_bounce = false;
        CHECK(without != v);
    }
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb-mb"), Catch::Contains("'mb' appears twice"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb-deint"), Catch::Contains("not in canonical form"));
}

TEST_CASE("multi-bounce: only the chain's last pass gets AO_MULTI_BOUNCE", "[multi_bounce]")
{
    for (const char* name : {"gtao-2x3-full-noblur-gbufworld-std-persp-cs-mb", "ssao-s16-half-bilateral-gbufworld-std-persp-cs-mb",
                             "vbao-2x3-half-denoise-recon-std-persp-cs-nearest-mip3-mb", "sao-s16-full-box-gbufworld-std-persp-fs-mb"}) {
        const variant v = variant_from_name(name);
        const std::vector<pass_kind> chain = passes(v);
        for (pass_kind p : chain) {
            INFO(name << ", pass " << names::name_of(pass_kind_names, p, "pass"));
            CHECK(has_define(v, p, "AO_MULTI_BOUNCE") == (p == chain.back()));
        }
        variant twin = v;
        twin.multi_bounce = false;
        for (pass_kind p : passes(twin)) CHECK_FALSE(has_define(twin, p, "AO_MULTI_BOUNCE"));
    }
}

TEST_CASE("multi-bounce: the albedo is 0 to 1 and reaches every pass's block", "[multi_bounce]")
{
    CHECK(finalize_params{}.albedo == 0.5f);
    for (float bad : {-0.01f, 1.01f, std::nanf(""), INFINITY}) {
        finalize_params p;
        p.albedo = bad;
        CHECK_THROWS_WITH(validate(p), Catch::Contains("finalize.albedo") && Catch::Contains("valid: 0..1"));
        ao_settings s;
        s.finalize = p;
        CHECK_THROWS_WITH(validate(s), Catch::Contains("finalize.albedo"));
    }
    const variant v = variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb");
    chain_settings s;
    s.camera = {mat4{}, perspective(1, 1, 1, 3)};
    s.finalize.albedo = 0.75f;
    const chain_inputs in = inputs_for(v, s, 80, 45);
    REQUIRE(in.uniforms.size() == passes(v).size()); // ao, blur_x, blur_y, upsample
    CHECK(float_at(in.uniforms[0], uniforms::gtao_block(), "albedo") == 0.75f);
    for (size_t p = 1; p < in.uniforms.size(); ++p) CHECK(float_at(in.uniforms[p], uniforms::blur_block(), "albedo") == 0.75f);
    s.finalize.albedo = 2;
    CHECK_THROWS_WITH(inputs_for(v, s, 80, 45), Catch::Contains("finalize.albedo: 2 is out of range (valid: 0..1)"));
}
