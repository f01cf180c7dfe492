// Planted faults in the emitted WGSL, kept as tests: each mutant must be seen by the same
// comparisons that hold the product bit-identical to the SPIR-V (wgsl_test.cpp: the naga round
// trip and Dawn), and the
// unmutated texts through the same path must pass it. A mutant that survives is a finding.
//   - two bindings swapped in the AO pass (normals <-> noise): both validators accept it;
//   - a constant changed: the bilateral blur's centre weight 0.196 (seed 000) read as 0.2.
#include "wgsl_support.hpp"

#include <aogen/wgsl_dawn.hpp>

using namespace aogen;
using namespace aogen_test;

TEST_CASE("wgsl: a planted wrong binding and a planted changed constant in the WGSL are seen by the round trip")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, 0.6f, proj);
    // The AO pass reads the noise tile where the normals belong and the normals where the
    // noise does (their bindings swapped): both validators accept it, the image is wrong.
    {
        const variant v = variant_from_name("gtao-2x3-half-noblur-gbufworld-std-persp-cs-nearest");
        std::vector<std::string> texts = emitted_texts(v, compile::target::wgsl);
        std::string& ao = texts[shader_index(v, pass_kind::ao)];
        ao = rebind(ao, "u_normals", binding_of(pass_family::ao, resource_role::noise, binding_model::webgpu));
        ao = rebind(ao, "u_noise", binding_of(pass_family::ao, resource_role::normals, binding_model::webgpu));
        CHECK_FALSE(against_spirv(*ctx, *vulkan::wgsl_passes(*ctx, v, texts), v, g, settings_for(proj)).bit_identical());
    }
    // The bilateral blur's centre weight 0.196 (seed 000) read as 0.2.
    {
        const variant v = variant_from_name("ssao-s16-full-bilateral-gbufworld-std-persp-cs");
        std::vector<std::string> texts = emitted_texts(v, compile::target::wgsl);
        std::string& blur = texts[shader_index(v, pass_kind::blur_x)];
        blur = replace_first(blur, "0.196", "0.2");
        CHECK_FALSE(against_spirv(*ctx, *vulkan::wgsl_passes(*ctx, v, texts), v, g, settings_for(proj)).bit_identical());
    }
    // And the unmutated texts through the same path are bit-identical: the check can pass.
    {
        const variant v = variant_from_name("ssao-s16-full-bilateral-gbufworld-std-persp-cs");
        CHECK(against_spirv(*ctx, *vulkan::wgsl_passes(*ctx, v, emitted_texts(v, compile::target::wgsl)), v, g, settings_for(proj)).bit_identical());
    }
    require_clean(*ctx);
}


TEST_CASE("wgsl: the same planted faults are seen on Dawn, and the unmutated WGSL is not")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, 0.6f, proj);
    const auto on_dawn = [&](const variant& v, const std::vector<std::string>& texts) {
        const auto [tw, th] = target_size(v, W, H);
        const std::vector<uint8_t> bytes = wgsl::run_variant_on_dawn(v, texts, g, inputs_for(v, settings_for(proj), tw, th)).ao;
        std::vector<float> ao(bytes.size());
        for (size_t i = 0; i < ao.size(); ++i) ao[i] = bytes[i] / 255.0f;
        const vulkan::chain_result expected = vulkan::chain(*ctx, v).run(g, settings_for(proj));
        REQUIRE(ao.size() == expected.ao.size());
        return difference_of(ao, expected.ao);
    };
    {
        const variant v = variant_from_name("gtao-2x3-half-noblur-gbufworld-std-persp-cs-nearest");
        std::vector<std::string> texts = emitted_texts(v, compile::target::wgsl);
        std::string& ao = texts[shader_index(v, pass_kind::ao)];
        ao = rebind(ao, "u_normals", binding_of(pass_family::ao, resource_role::noise, binding_model::webgpu));
        ao = rebind(ao, "u_noise", binding_of(pass_family::ao, resource_role::normals, binding_model::webgpu));
        CHECK_FALSE(on_dawn(v, texts).bit_identical());
    }
    {
        const variant v = variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-fs"); // a fragment chain
        std::vector<std::string> texts = emitted_texts(v, compile::target::wgsl);
        std::string& blur = texts[shader_index(v, pass_kind::blur_x)];
        blur = replace_first(blur, "0.196", "0.2");
        CHECK_FALSE(on_dawn(v, texts).bit_identical());
        CHECK(on_dawn(v, emitted_texts(v, compile::target::wgsl)).bit_identical());
    }
}
