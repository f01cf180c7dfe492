// Uses the header `aogen_add_shader_variants` generated: SPIR-V to hand to
// vkCreateShaderModule, binding numbers, and the uniform struct to fill — checked
// against aogen's own layout of the same block.
#include <aogen_variants.hpp>

#include <aogen/layout.hpp>
#include <aogen/uniforms.hpp>

#include <cstdio>

namespace ssao = aogen_variants::ssao_s16_half_bilateral_gbufview_std_persp_cs;

int main()
{
    static_assert(ssao::ao_comp_spv[0] == 0x07230203u, "SPIR-V magic number");
    static_assert(ssao::ao_comp_binding_u == 0 && ssao::ao_comp_binding_u_depth == 1, "bindings");
    const auto layout = aogen::layout::compute(aogen::uniforms::ssao_block(16), aogen::layout::rules::std140);
    std::printf("%s: ao pass %zu SPIR-V words, SsaoUniforms %zu bytes (layout %u)\n", ssao::name,
                sizeof ssao::ao_comp_spv / 4, sizeof(ssao::SsaoUniforms), layout.size);
    return sizeof(ssao::SsaoUniforms) == layout.size ? 0 : 1;
}
