// aogen/uniforms.hpp — the uniform blocks of the AO passes, and their bytes.
//
// Each pass reads its settings and camera from one uniform block. This header gathers the
// blocks' descriptions (for layout.hpp and declare.hpp) and the functions that pack a pass's
// params (params.hpp), camera, kernel and extras (the frame's turn of the noise, temporal.hpp;
// the finalize step's albedo) into the block's bytes under any rule set, so the same numbers
// reach a Vulkan std140 buffer, a D3D cbuffer or a WebGPU uniform:
//
//     aogen::uniforms::camera cam{world_to_view, aogen::perspective(0.577f, 16 / 9.f, 0.1f, 100)};
//     auto kernel = aogen::kernel::crytek(16, 1);
//     std::vector<uint8_t> bytes = aogen::uniforms::pack_ssao(aogen::ssao_params{}, cam, kernel,
//                                                             {960, 540}, aogen::layout::rules::std140);
//
// Blocks:
//   SsaoUniforms   hemisphere SSAO (seeds 000, 002, 003): camera, kernel[N], settings  techniques/ssao.hpp
//   GtaoUniforms   GTAO (seed 001): camera and settings; slices and steps compile-time techniques/gtao.hpp
//   VbaoUniforms   VBAO: camera, radius, thickness (world units), strength            techniques/vbao.hpp
//   SaoUniforms    SAO: camera, settings, spiral[N] (spiral.hpp)                      techniques/sao.hpp
//   BlurUniforms   the bilateral, box and denoise passes and the upsample             here
//   SsaoUniform    seed 004's block exactly (inv_proj, proj, radius, bias, _pad): 144 bytes   here
// An AO block is its technique's (each technique's header lists its members once, and both
// the block and its bytes are made from that list: uniforms_common.hpp); the camera members
// and the frame's extras every AO block shares are uniforms_common.hpp's.
#pragma once

#include "error.hpp"
#include "layout.hpp"
#include "layout_writer.hpp"
#include "math.hpp"
#include "params.hpp"
#include <aogen/techniques/gtao.hpp>
#include <aogen/techniques/sao.hpp>
#include <aogen/techniques/ssao.hpp>
#include <aogen/techniques/vbao.hpp>
#include "uniforms_common.hpp"

#include <cstdint>
#include <vector>

namespace aogen::uniforms {

// The blur passes: the inverse projection turns raw depth into view-space depth for the
// linear depth term; raw_depth_k is the seed-exact term's factor (1000); albedo is the
// finalize step's (a -mb variant whose last pass this is).
inline layout::block_desc blur_block()
{
    return {{"BlurUniforms",
             {{"inv_proj", "mat4"}, {"texel_size", "vec2"}, {"raw_depth_k", "float"}, {"linear_sharpness", "float"}, {"albedo", "float"}}},
            {}};
}

// Seed 004's SsaoUniform, member for member: 144 bytes under std140 and WGSL's uniform rules.
inline layout::block_desc pointcloud_block()
{
    return {{"SsaoUniform",
             {{"inv_proj", "mat4"}, {"proj", "mat4"}, {"radius", "float"}, {"bias", "float"}, {"_pad", "vec2"}}},
            {}};
}

// BlurUniforms bytes; `target_size` is the AO target's size in pixels; of `e`, the finalize
// settings (a blur pass turns no noise).
inline std::vector<uint8_t> pack_blur(const blur_params& p, const mat4& proj, vec2 target_size, const layout::struct_layout& block,
                                      const extras& e = {})
{
    validate(p);
    validate(e.finalize);
    require_finite_above("uniforms target width", target_size.x, 0, 65536);
    require_finite_above("uniforms target height", target_size.y, 0, 65536);
    layout::writer w(block);
    w.set("inv_proj", inverse(proj));
    w.set("texel_size", vec2{1.0f / target_size.x, 1.0f / target_size.y});
    w.set("raw_depth_k", p.raw_depth_k);
    w.set("linear_sharpness", p.linear_sharpness);
    w.set("albedo", e.finalize.albedo);
    return w.bytes();
}
// The same under `rules` (blur_block() laid out here).
inline std::vector<uint8_t> pack_blur(const blur_params& p, const mat4& proj, vec2 target_size, layout::rules rules, const extras& e = {})
{
    return pack_blur(p, proj, target_size, layout::compute(blur_block(), rules), e);
}

// Seed 004's SsaoUniform bytes (the padding member stays zero).
inline std::vector<uint8_t> pack_pointcloud(const ssao_params& p, const mat4& proj, layout::rules rules)
{
    validate(p);
    layout::writer w(layout::compute(pointcloud_block(), rules));
    w.set("inv_proj", inverse(proj));
    w.set("proj", proj);
    w.set("radius", p.radius);
    w.set("bias", p.bias);
    return w.bytes();
}

} // namespace aogen::uniforms
