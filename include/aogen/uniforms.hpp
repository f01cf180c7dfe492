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
//   HistoryUniforms  the history pass: this and the previous frame's camera, the blend  here
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

#include <cmath>
#include <cstdint>
#include <cstring>
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

// The history pass (history.glsl): this frame's inverse projection (common/depth.glsl's view
// positions), the rigid move from this frame's view space to the previous frame's and the
// previous projection (where a static point was), the motion vectors' scale to a uv offset,
// and history_params as the shader reads them.
inline layout::block_desc history_block()
{
    return {{"HistoryUniforms",
             {{"inv_proj", "mat4"},
              {"view_to_previous_view", "mat4"},
              {"previous_proj", "mat4"},
              {"motion_scale", "vec2"},     // previous uv = uv + motion_scale * motion vector
              {"blend", "float"},           // history_params::blend
              {"clamp_kind", "int"},        // history_clamp: 0 none, 1 range, 2 min_max, 3 variance
              {"clamp_width", "float"},     // the chosen clamp's width (range, widening or gamma)
              {"depth_tolerance", "float"}, // log2(1 + history_params::depth_tolerance): the test is on log2 depth
              {"reset", "float"},           // 1: the history is not read (a cut, a resize, the first frame)
              {"albedo", "float"}}},        // finalize_params::albedo
            {}};
}

// What the history pass reads of the frame besides its settings.
struct history_frame {
    camera current;            // this frame's
    camera previous;           // the previous frame's (a still camera: the same)
    vec2 screen_size{1, 1};    // the G-buffer's, in pixels (motion vectors in pixels)
    bool reset = false;        // ignore the history this frame
};

// The uv offset per unit of a motion vector of convention `c` on a screen of `screen` pixels:
// previous uv = uv + scale * motion vector, in aogen's uv (y down, the screen's [0, 1]).
inline vec2 motion_scale(const motion_convention& c, vec2 screen)
{
    const float unit_x = c.units == motion_units::uv ? 1.0f : c.units == motion_units::ndc ? 0.5f : 1.0f / screen.x;
    const float unit_y = c.units == motion_units::uv ? 1.0f : c.units == motion_units::ndc ? 0.5f : 1.0f / screen.y;
    const float sign = c.direction == motion_direction::current_to_previous ? 1.0f : -1.0f;
    const float flip = c.y == motion_y::up ? -1.0f : 1.0f;
    return {sign * unit_x, sign * flip * unit_y};
}

// HistoryUniforms bytes for settings `p` and frame `f`; of `e`, the finalize settings.
inline std::vector<uint8_t> pack_history(const history_params& p, const history_frame& f, const layout::struct_layout& block,
                                         const extras& e = {})
{
    validate(p);
    validate(e.finalize);
    require_finite_above("uniforms screen width", f.screen_size.x, 0, 65536);
    require_finite_above("uniforms screen height", f.screen_size.y, 0, 65536);
    layout::writer w(block);
    w.set("inv_proj", inverse(f.current.proj));
    // A camera that stood still moves nothing, exactly: M·M⁻¹ in floats is the identity only
    // to a few ulps, which would put a still pixel's history a hair off its own texel.
    const bool still = std::memcmp(&f.previous.world_to_view, &f.current.world_to_view, sizeof(mat4)) == 0;
    w.set("view_to_previous_view", still ? mat4{} : f.previous.world_to_view * inverse(f.current.world_to_view));
    w.set("previous_proj", f.previous.proj);
    w.set("motion_scale", motion_scale(p.motion, f.screen_size));
    w.set("blend", p.blend);
    w.set("clamp_kind", static_cast<int32_t>(p.clamp));
    w.set("clamp_width", p.clamp == history_clamp::range ? p.range : p.clamp == history_clamp::min_max ? p.min_max_widening : p.variance_gamma);
    w.set("depth_tolerance", std::log2(1.0f + p.depth_tolerance));
    w.set("reset", f.reset ? 1.0f : 0.0f);
    w.set("albedo", e.finalize.albedo);
    return w.bytes();
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
