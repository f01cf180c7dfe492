// Multi-bounce as a variant extra (-mb, or -mbg with the albedo G-buffer) and a finalize
// setting: the name and spec key, the define that only the chain's last pass gets, the
// albedo's range, the uniform member that carries it, the albedo binding -mbg's last pass
// alone declares. What the shader does with it is tests/vulkan/multi_bounce_test.cpp's.
#include <aogen/chain_inputs.hpp>
#include <aogen/layout.hpp>
#include <aogen/plan.hpp>
#include <aogen/variant.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_multi_bounce {

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

TEST_CASE("multi-bounce: -mb and -mbg name variants of every technique and parse back", "[multi_bounce]")
{
    struct named {
        const char* name;
        multi_bounce_mode mode;
    };
    for (const named& n : {named{"gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb", multi_bounce_mode::uniform_albedo},
                           named{"ssao-s16-half-bilateral-gbufworld-std-persp-fs-mb", multi_bounce_mode::uniform_albedo},
                           named{"vbao-2x3-half-denoise-recon-std-persp-cs-nearest-mip3-deint-mb-wg16x8", multi_bounce_mode::uniform_albedo},
                           named{"sao-s8-full-noblur-gbufworld-std-persp-cs-mb", multi_bounce_mode::uniform_albedo},
                           named{"gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mbg", multi_bounce_mode::gbuffer_albedo},
                           named{"ssao-s16-half-bilateral-gbufworld-std-persp-fs-mbg", multi_bounce_mode::gbuffer_albedo},
                           named{"vbao-2x3-half-denoise-recon-std-persp-cs-nearest-mip3-deint-bn-mbg-wg16x8", multi_bounce_mode::gbuffer_albedo}}) {
        INFO(n.name);
        const variant v = variant_from_name(n.name);
        CHECK(v.multi_bounce == n.mode);
        CHECK(to_name(v) == n.name);
        for (multi_bounce_mode other : {multi_bounce_mode::off, multi_bounce_mode::uniform_albedo, multi_bounce_mode::gbuffer_albedo}) {
            variant twin = v;
            twin.multi_bounce = other;
            CHECK((twin == v) == (other == n.mode));
        }
    }
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb-mb"), Catch::Contains("'mb' appears twice"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb-deint"), Catch::Contains("not in canonical form"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb-mbg"),
                      Catch::Contains("'mbg' is a second multi-bounce extra") && Catch::Contains("valid: one of mb, mbg"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mbg-mb"), Catch::Contains("'mb' is a second multi-bounce extra"));
    CHECK_THROWS_WITH(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mbg-bn"), Catch::Contains("not in canonical form"));
    variant bad;
    bad.multi_bounce = static_cast<multi_bounce_mode>(7);
    CHECK_THROWS_WITH(validate(bad), Catch::Contains("multi-bounce") && Catch::Contains("valid: off, on, gbuffer"));
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
        twin.multi_bounce = multi_bounce_mode::off;
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
    const codegen::plan p = codegen::make_plan(v);
    const chain_inputs in = p.inputs(s, 80, 45);
    REQUIRE(in.uniforms.size() == passes(v).size()); // ao, blur_x, blur_y, upsample
    CHECK(float_at(in.uniforms[0], uniforms::gtao_block(), "albedo") == 0.75f);
    for (size_t p = 1; p < in.uniforms.size(); ++p) CHECK(float_at(in.uniforms[p], uniforms::blur_block(), "albedo") == 0.75f);
    s.finalize.albedo = 2;
    CHECK_THROWS_WITH(p.inputs(s, 80, 45), Catch::Contains("finalize.albedo: 2 is out of range (valid: 0..1)"));
}

TEST_CASE("multi-bounce: only a -mbg chain's last pass declares the albedo, at its fixed binding", "[multi_bounce]")
{
    // The binding numbers bindings.hpp's table gives the albedo, written out: a role added
    // after the others, so that none of theirs moved.
    struct expected_binding {
        pass_family family;
        binding_model model;
        uint32_t binding;
    };
    for (const expected_binding& e : {expected_binding{pass_family::ao, binding_model::vulkan, 7}, expected_binding{pass_family::ao, binding_model::webgpu, 9},
                                      expected_binding{pass_family::filter, binding_model::vulkan, 5}, expected_binding{pass_family::filter, binding_model::webgpu, 7}})
        CHECK(binding_of(e.family, resource_role::gbuffer_albedo, e.model) == e.binding);
    CHECK_FALSE(sampler_binding_of(pass_family::ao, resource_role::gbuffer_albedo, binding_model::webgpu)); // read with textureLoad
    for (const char* name : {"gtao-2x3-full-noblur-gbufworld-std-persp-cs-mbg", "ssao-s16-half-bilateral-gbufworld-std-persp-cs-mbg",
                             "vbao-2x3-half-denoise-recon-std-persp-cs-nearest-mip3-mbg", "sao-s16-full-box-gbufworld-std-persp-fs-mbg"}) {
        const variant v = variant_from_name(name);
        variant uniform = v;
        uniform.multi_bounce = multi_bounce_mode::uniform_albedo;
        const std::vector<pass_kind> chain = passes(v);
        for (binding_model model : {binding_model::vulkan, binding_model::webgpu})
            for (pass_kind p : chain) {
                INFO(name << ", pass " << names::name_of(pass_kind_names, p, "pass"));
                codegen::options o;
                o.model = model;
                if (model == binding_model::webgpu) o.output_format = "rgba8"; // WebGPU stores no r8
                const shader_stage stage = codegen::stages(v).back();
                auto albedo_of = [&](const variant& x) {
                    std::vector<uint32_t> b;
                    for (const codegen::resource& r : codegen::resources(x, p, stage, o))
                        if (r.role == resource_role::gbuffer_albedo) b.push_back(r.binding);
                    return b;
                };
                const std::vector<uint32_t> declared = albedo_of(v);
                CHECK(declared.size() == (p == chain.back() ? 1u : 0u));
                if (!declared.empty()) CHECK(declared[0] == binding_of(family_of(p), resource_role::gbuffer_albedo, model));
                CHECK(albedo_of(uniform).empty()); // -mb reads its uniform
                CHECK(has_define(v, p, "AO_MULTI_BOUNCE") == (p == chain.back()));
            }
    }
}

} // namespace unity_test_multi_bounce
