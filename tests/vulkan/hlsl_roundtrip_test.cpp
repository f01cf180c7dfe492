// The emitted HLSL round-tripped: each pass's SM 5.0 and SM 6.0 HLSL (SPIRV-Cross's, compute
// or vertex + fragment,
// as `aogen generate` writes it) compiled back to SPIR-V by glslang's HLSL front end
// (vulkan::hlsl_round_trip) and run under the variant's own passes on the Vulkan harness,
// against the variant's SPIR-V on the same inputs: every pixel bit-identical. This checks the
// HLSL's meaning as glslang reads it (bindings from registers, the cbuffer's packing, the
// texture/sampler pairs, the arithmetic), not what DXC or FXC would compile from it.
#include "harness.hpp"

#include <aogen/ao_difference.hpp>
#include <aogen/vulkan/hlsl_round_trip.hpp>

#include <iostream>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_hlsl_roundtrip_test {

using namespace aogen;
using namespace aogen_test;

namespace {

// `v`'s emitted `target` HLSL, each text under an emitted-text mutant aimed at it planted
// (mutants/mutants.hpp: file "hlsl:<shader name>").
std::vector<std::string> hlsl_under_test(const codegen::plan& p, compile::target target)
{
    std::vector<std::string> texts = emitted_texts(p, target);
    const std::vector<codegen::shader_source> sources = codegen::generate(p);
    for (size_t i = 0; i < texts.size(); ++i) texts[i] = emitted_under_test(texts[i], "hlsl:" + sources[i].name);
    return texts;
}

} // namespace

TEST_CASE("vulkan: the emitted HLSL (SM 5.0, 6.0) round-tripped through glslang gives the SPIR-V's AO bit for bit")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease(W, H, 0.6f, proj);
    const vulkan::gpu_gbuffer g(*ctx, host);
    const vulkan::chain_settings s = settings_for(proj);
    for (compile::target target : {compile::target::hlsl, compile::target::hlsl60})
        for (const char* name : emitted_target_variants) {
            const variant v = variant_from_name(name);
            INFO(compile::to_name(target) << " " << name);
            const codegen::plan p = plan_under_test(v);
            const std::unique_ptr<vulkan::pass_pipelines> round_trip = vulkan::hlsl_passes(*ctx, p, target, hlsl_under_test(p, target));
            const vulkan::chain_result got = vulkan::bound_chain(*ctx, *round_trip, g, p.inputs(s, W, H)).run_once();
            const vulkan::chain_result expected = chain_under_test(*ctx, v).run(host, s);
            REQUIRE(got.width == expected.width);
            const ao_difference d = difference_of(got.ao, expected.ao);
            CHECK(first_difference(got.bent_normal, expected.bent_normal) == ""); // a -bn variant's, byte for byte (empty otherwise)
            CHECK(got.bent_normal.size() == (v.bent_normals ? 3 * got.ao.size() : 0));
            std::cout << compile::to_name(target) << " round trip " << name << ": " << d.identical << " of " << d.pixels
                      << " pixels bit-identical, largest difference " << d.largest * 255 << "/255\n";
            CHECK(d.within_one_step()); // issue 13's bound
            CHECK(d.bit_identical());   // glslang's SPIR-V from the HLSL does the same float operations
            CHECK(*std::min_element(got.ao.begin(), got.ao.end()) < 0.98f); // the crease is occluded: real images
        }
    require_clean(*ctx);
}

} // namespace unity_hlsl_roundtrip_test
