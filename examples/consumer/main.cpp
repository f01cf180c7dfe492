// The smallest engine-side use of aogen::core: build the SSAO pass's data — a kernel,
// a noise tile and the uniform block as std140 bytes — and print its GLSL declaration;
// then generate the default variant's GLSL from the templates embedded in the package.
// Exits non-zero if the installed headers disagree with what the seeds specify.
#include <aogen/codegen.hpp>
#include <aogen/declare.hpp>
#include <aogen/kernel.hpp>
#include <aogen/noise.hpp>
#include <aogen/presets.hpp>
#include <aogen/uniforms.hpp>

#include <cstdio>

int main()
{
    const aogen::preset preset = aogen::presets::taos_ssao();
    const aogen::ssao_params& ssao = preset.settings.ssao;
    const auto kernel = aogen::kernel::crytek(preset.variant.samples, ssao.kernel_seed);
    const auto noise = aogen::noise::encode(aogen::noise::rotations(4, ssao.noise_seed),
                                            aogen::noise::encoding::rgba8_unorm);
    const aogen::uniforms::camera camera{aogen::mat4{}, aogen::perspective(0.577f, 16.0f / 9.0f, 0.1f, 100.0f)};
    const auto bytes = aogen::uniforms::pack_ssao(ssao, camera, kernel, {960, 540},
                                                  aogen::layout::rules::std140);
    const auto layout = aogen::layout::compute(aogen::uniforms::ssao_block(preset.variant.samples),
                                               aogen::layout::rules::std140);
    std::printf("%s", aogen::layout::declare(layout, aogen::layout::language::glsl).c_str());
    std::printf("kernel: %zu samples, noise: %zu bytes, uniforms: %zu bytes\n", kernel.size(), noise.size(),
                bytes.size());
    const bool seed_block_ok =
        aogen::layout::compute(aogen::uniforms::pointcloud_block(), aogen::layout::rules::wgsl_uniform).size == 144;
    const auto shaders = aogen::codegen::generate(aogen::codegen::make_plan(aogen::variant{})); // ao, blur_x, blur_y, upsample
    std::printf("%s: %zu shaders, %zu bytes of GLSL in the first\n", shaders.at(0).name.c_str(), shaders.size(),
                shaders.at(0).glsl.size());
    const bool codegen_ok = aogen::codegen::have_embedded_templates() && shaders.size() == 4 &&
                            shaders[0].glsl.find("#line 1 \"ssao.glsl\"") != std::string::npos;
    return kernel.size() == 16 && noise.size() == 64 && bytes.size() == layout.size && seed_block_ok && codegen_ok ? 0 : 1;
}
