// The emitted HLSL round-tripped: each compute pass's SM 5.0 and SM 6.0 HLSL (SPIRV-Cross's,
// as `aogen generate` writes it) compiled back to SPIR-V by glslang's HLSL front end
// (vulkan::hlsl_round_trip) and run under the variant's own passes on the Vulkan harness,
// against the variant's SPIR-V on the same inputs: every pixel within 1/255. This checks the
// HLSL's meaning as glslang reads it (bindings from registers, the cbuffer's packing, the
// texture/sampler pairs, the arithmetic), not what DXC or FXC would compile from it.
#include "harness.hpp"

#include <aogen/vulkan/hlsl_round_trip.hpp>

#include <iostream>

using namespace aogen;
using namespace aogen_test;

TEST_CASE("vulkan: the emitted HLSL (SM 5.0, 6.0) round-tripped through glslang gives the SPIR-V's AO within 1/255")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease(W, H, 0.6f, proj);
    const vulkan::gpu_gbuffer g(*ctx, host);
    const vulkan::chain_settings s = settings_for(proj);
    for (compile::target target : {compile::target::hlsl50, compile::target::hlsl60})
        for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "ssao-s8-full-box-recon-std-persp-cs",
                                 "gtao-2x3-half-bilateral-gbufworld-std-persp-cs", "gtao-4x4-full-denoise-gbufview-std-persp-cs",
                                 "gtao-2x2-half-denoise-gbufworld-std-persp-cs", "gtao-1x2-half-noblur-gbufworld-std-persp-cs-nearest",
                                 "vbao-3x3-half-bilateral-gbufworld-std-persp-cs", "ssao-s64-full-noblur-recon-std-persp-cs-pc-rc004"}) {
            const variant v = variant_from_name(name);
            INFO(compile::to_name(target) << " " << name);
            const std::unique_ptr<vulkan::pass_pipelines> round_trip = vulkan::hlsl_round_trip(*ctx, v, target);
            const auto [tw, th] = target_size(v, W, H);
            const vulkan::chain_result got = vulkan::bound_chain(*ctx, *round_trip, g, inputs_for(v, s, tw, th), tw, th).run_once();
            const vulkan::chain_result expected = vulkan::chain(*ctx, v).run(host, s);
            REQUIRE(got.width == expected.width);
            REQUIRE(got.ao.size() == expected.ao.size());
            size_t exact = 0;
            float worst = 0;
            for (size_t i = 0; i < got.ao.size(); ++i) {
                const float d = std::fabs(got.ao[i] - expected.ao[i]);
                worst = std::max(worst, d), exact += d == 0.0f;
            }
            std::cout << compile::to_name(target) << " round trip " << name << ": " << exact << " of " << got.ao.size()
                      << " pixels bit-identical, largest difference " << worst * 255 << "/255\n";
            CHECK(worst <= 1.0f / 255 + 1e-6f);
            CHECK(*std::min_element(got.ao.begin(), got.ao.end()) < 0.98f); // the crease is occluded: real images
        }
    require_clean(*ctx);
}
