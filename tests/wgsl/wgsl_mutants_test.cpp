// Planted faults in the emitted WGSL, kept as tests: each mutant must be seen by the same
// comparisons that hold the product bit-identical to the SPIR-V (wgsl_test.cpp: the naga round
// trip and Dawn), and the unmutated texts through the same path must pass it. A mutant that survives is a finding.
//   - two bindings swapped in the AO pass (normals <-> noise): both validators accept it;
//   - a constant changed: the bilateral blur's centre weight 0.196 (seed 000) read as 0.2.
#include "wgsl_support.hpp"

using namespace aogen;
using namespace aogen_test;

namespace {

// `v`'s WGSL with its AO pass reading the noise tile where the normals belong and the normals
// where the noise does (their bindings swapped): both validators accept it, the image is wrong.
std::vector<std::string> normals_and_noise_swapped(const variant& v)
{
    std::vector<std::string> texts = emitted_texts(codegen::make_plan(v), compile::target::wgsl);
    std::string& ao = texts[shader_index(v, pass_kind::ao)];
    ao = rebind(ao, "u_normals", binding_of(pass_family::ao, resource_role::noise, binding_model::webgpu));
    ao = rebind(ao, "u_noise", binding_of(pass_family::ao, resource_role::normals, binding_model::webgpu));
    return texts;
}

// `v`'s WGSL with the bilateral blur's centre weight 0.196 (seed 000) read as 0.2.
std::vector<std::string> blur_weight_changed(const variant& v)
{
    std::vector<std::string> texts = emitted_texts(codegen::make_plan(v), compile::target::wgsl);
    std::string& blur = texts[shader_index(v, pass_kind::blur_x)];
    blur = replace_first(blur, "0.196", "0.2");
    return texts;
}

// The harness's analytic crease, 64 × 40, and its settings.
struct analytic_crease {
    mat4 proj = perspective(0.6f, 64.0f / 40.0f, 0.1f, 100.0f);
    vulkan::gbuffer g = crease(64, 40, 0.6f, proj);
    vulkan::chain_settings settings = settings_for(proj);
};

} // namespace

TEST_CASE("wgsl: a planted wrong binding and a planted changed constant in the WGSL are seen by the round trip")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const analytic_crease c;
    const auto round_trip = [&](const variant& v, const std::vector<std::string>& texts) {
        return against_spirv(*ctx, *vulkan::wgsl_passes(*ctx, codegen::make_plan(v), texts), v, c.g, c.settings);
    };
    const variant gtao = variant_from_name("gtao-2x3-half-noblur-gbufworld-std-persp-cs-nearest");
    const variant ssao = variant_from_name("ssao-s16-full-bilateral-gbufworld-std-persp-cs");
    CHECK_FALSE(round_trip(gtao, normals_and_noise_swapped(gtao)).bit_identical());
    CHECK_FALSE(round_trip(ssao, blur_weight_changed(ssao)).bit_identical());
    // The unmutated texts through the same path are bit-identical: the check can pass.
    CHECK(round_trip(ssao, emitted_texts(codegen::make_plan(ssao), compile::target::wgsl)).bit_identical());
    require_clean(*ctx);
}

TEST_CASE("wgsl: the same planted faults are seen on Dawn, and the unmutated WGSL is not")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const analytic_crease c;
    const variant gtao = variant_from_name("gtao-2x3-half-noblur-gbufworld-std-persp-cs-nearest");
    const variant ssao = variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-fs"); // a fragment chain
    CHECK_FALSE(dawn_against_spirv(*ctx, gtao, normals_and_noise_swapped(gtao), c.g, c.settings).bit_identical());
    CHECK_FALSE(dawn_against_spirv(*ctx, ssao, blur_weight_changed(ssao), c.g, c.settings).bit_identical());
    CHECK(dawn_against_spirv(*ctx, ssao, emitted_texts(codegen::make_plan(ssao), compile::target::wgsl), c.g, c.settings).bit_identical());
}
