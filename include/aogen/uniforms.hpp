// aogen/uniforms.hpp — the uniform blocks of the AO passes, and their bytes.
//
// Each pass reads its settings and camera from one uniform block. This header holds
// the blocks' descriptions (for layout.hpp and declare.hpp) and packs a pass's params
// (params.hpp), camera, kernel and extras (the frame's turn of the noise, temporal.hpp; the
// finalize step's albedo) into the block's bytes under any rule set, so the same numbers
// reach a Vulkan std140 buffer, a D3D cbuffer or a WebGPU uniform:
//
//     aogen::uniforms::camera cam{world_to_view, aogen::perspective(0.577f, 16 / 9.f, 0.1f, 100)};
//     auto kernel = aogen::kernel::crytek(16, 1);
//     std::vector<uint8_t> bytes = aogen::uniforms::pack_ssao(aogen::ssao_params{}, cam, kernel,
//                                                             {960, 540}, aogen::layout::rules::std140);
//
// Blocks:
//   SsaoUniforms   hemisphere SSAO (seeds 000, 002, 003): camera, kernel[N], settings
//   GtaoUniforms   GTAO (seed 001): camera and settings; slices and steps are compile-time
//   VbaoUniforms   VBAO: camera, radius, thickness (world units), strength
//   SaoUniforms    SAO: camera, settings, spiral[N] (spiral.hpp)
//   BlurUniforms   the bilateral and box blur passes
//   SsaoUniform    seed 004's block exactly (inv_proj, proj, radius, bias, _pad): 144 bytes
#pragma once

#include "error.hpp"
#include "layout.hpp"
#include "layout_writer.hpp"
#include "math.hpp"
#include "params.hpp"
#include "spiral.hpp"
#include "variant.hpp"

#include <cstdint>
#include <vector>

namespace aogen::uniforms {

// What every pass needs of the camera. `world_to_view` rotates world-space G-buffer
// normals into view space; its translation is not used by the passes.
struct camera {
    mat4 world_to_view;
    mat4 proj; // view → clip, see math.hpp for the conventions
};

// The rotation of a still frame, frame 0 (temporal.hpp).
inline constexpr vec2 still_frame{1.0f, 0.0f};

// What the blocks carry besides the camera and each pass's own settings: this frame's turn
// of the noise (AO passes: temporal::frame_rotation; (1, 0) at frame 0, the still frame), the
// finalize step's settings (every pass: read by the last pass of a -mb variant) and, for the
// slice techniques, this frame's move of their steps (temporal::step_offset; 0 at frame 0).
struct extras {
    vec2 frame_rotation = still_frame;
    finalize_params finalize;
    float frame_step = 0.0f; // GTAO, VBAO: this frame's offset of the inner slice steps (temporal::step_offset)
};

// Members every AO pass block starts with: the projection both ways, the normal
// transform, the sizes that map a pixel to the noise tile and to uv, this frame's turn of
// the noise and the finalize step's albedo (extras).
inline std::vector<layout::member_desc> camera_members()
{
    return {{"proj", "mat4"},          {"inv_proj", "mat4"},   {"world_to_view", "mat4"},
            {"noise_scale", "vec2"},   // AO target size / noise tile size
            {"texel_size", "vec2"},    // 1 / AO target size
            {"frame_rotation", "vec2"}, // (cos, sin) of this frame's turn of the noise
            {"albedo", "float"}};       // finalize_params::albedo
}

inline layout::block_desc ssao_block(int samples)
{
    require_in("ssao block samples", samples, variant::ssao_samples_range);
    layout::struct_desc s{"SsaoUniforms", camera_members()};
    for (const char* name : {"radius", "bias", "strength", "power", "intensity"}) s.members.push_back({name, "float"});
    s.members.push_back({"kernel", "vec4", static_cast<uint32_t>(samples)});
    return {s, {}};
}

inline layout::block_desc gtao_block()
{
    layout::struct_desc s{"GtaoUniforms", camera_members()};
    for (const char* name : {"radius", "thickness_bias", "strength", "falloff_range", "thin_occluder", "frame_step"}) s.members.push_back({name, "float"});
    return {s, {}};
}

// VBAO's block: GtaoUniforms' camera, then its own settings. `thickness` is in world units
// (pack_vbao multiplies vbao_params::thickness, a fraction of the radius, by the radius), so
// the shader needs no second multiply and the block says what the shader uses.
inline layout::block_desc vbao_block()
{
    layout::struct_desc s{"VbaoUniforms", camera_members()};
    for (const char* name : {"radius", "thickness", "strength", "frame_step"}) s.members.push_back({name, "float"});
    return {s, {}};
}

// SAO's block: the camera, its settings, and its spiral of taps (spiral.hpp), N of them.
inline layout::block_desc sao_block(int taps)
{
    require_in("sao block taps", taps, variant::ssao_samples_range);
    layout::struct_desc s{"SaoUniforms", camera_members()};
    for (const char* name : {"radius", "bias", "intensity", "contrast"}) s.members.push_back({name, "float"});
    s.members.push_back({"spiral", "vec4", static_cast<uint32_t>(taps)});
    return {s, {}};
}

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

namespace detail {

inline void set_camera(layout::writer& w, const camera& cam, vec2 target_size, int noise_size, const extras& e)
{
    validate(e.finalize);
    require_finite_above("uniforms target width", target_size.x, 0, 65536);
    require_finite_above("uniforms target height", target_size.y, 0, 65536);
    w.set("proj", cam.proj);
    w.set("inv_proj", inverse(cam.proj));
    w.set("world_to_view", cam.world_to_view);
    w.set("noise_scale", vec2{target_size.x / noise_size, target_size.y / noise_size});
    w.set("texel_size", vec2{1.0f / target_size.x, 1.0f / target_size.y});
    w.set("frame_rotation", e.frame_rotation);
    w.set("albedo", e.finalize.albedo);
}

// The slice techniques' step offset, in steps: temporal::step_offset's [0, 1), or up to a
// whole step (1 puts the inner steps one step in, the first onto the pixel).
inline void set_frame_step(layout::writer& w, const extras& e)
{
    require_finite_range("uniforms frame_step", e.frame_step, 0, 1);
    w.set("frame_step", e.frame_step);
}

} // namespace detail

// SsaoUniforms bytes. `kernel` holds the variant's samples (its size is the block's N, in
// variant::ssao_samples_range); `target_size` is the AO target's size in pixels (half the
// screen at half resolution); `e` the frame's turn of the noise and the finalize settings.
inline std::vector<uint8_t> pack_ssao(const ssao_params& p, const camera& cam, const std::vector<vec4>& kernel,
                                      vec2 target_size, layout::rules rules, const extras& e = {})
{
    validate(p);
    const int_range n = variant::ssao_samples_range;
    if (kernel.size() < size_t(n.lo) || kernel.size() > size_t(n.hi))
        fail("ssao kernel", std::to_string(kernel.size()) + " samples given", "valid: " + to_string(n) + " samples, the variant's ssao_samples");
    layout::writer w(layout::compute(ssao_block(int(kernel.size())), rules));
    detail::set_camera(w, cam, target_size, p.noise_size, e);
    w.set("radius", p.radius);
    w.set("bias", p.bias);
    w.set("strength", p.strength);
    w.set("power", p.power);
    w.set("intensity", p.intensity);
    w.set("kernel", kernel);
    return w.bytes();
}

// SaoUniforms bytes for a spiral of `taps` (the variant's ssao_samples); SAO's noise is a
// rotation per pixel, like GTAO's.
inline std::vector<uint8_t> pack_sao(const sao_params& p, const camera& cam, int taps, vec2 target_size, layout::rules rules,
                                     int noise_size = 4, const extras& e = {})
{
    validate(p);
    layout::writer w(layout::compute(sao_block(taps), rules));
    detail::set_camera(w, cam, target_size, noise_size, e);
    w.set("radius", p.radius);
    w.set("bias", p.bias);
    w.set("intensity", p.intensity);
    w.set("contrast", p.contrast);
    w.set("spiral", spiral::taps(taps));
    return w.bytes();
}

// GtaoUniforms bytes; GTAO uses no noise tile of its own beyond a 4×4 rotation.
inline std::vector<uint8_t> pack_gtao(const gtao_params& p, const camera& cam, vec2 target_size, layout::rules rules,
                                      int noise_size = 4, const extras& e = {})
{
    validate(p);
    layout::writer w(layout::compute(gtao_block(), rules));
    detail::set_camera(w, cam, target_size, noise_size, e);
    w.set("radius", p.radius);
    w.set("thickness_bias", p.thickness_bias);
    w.set("strength", p.strength);
    w.set("falloff_range", p.falloff_range);
    w.set("thin_occluder", p.thin_occluder);
    detail::set_frame_step(w, e);
    return w.bytes();
}

// VbaoUniforms bytes; like GTAO, a 4×4 rotation tile unless told.
inline std::vector<uint8_t> pack_vbao(const vbao_params& p, const camera& cam, vec2 target_size, layout::rules rules,
                                      int noise_size = 4, const extras& e = {})
{
    validate(p);
    layout::writer w(layout::compute(vbao_block(), rules));
    detail::set_camera(w, cam, target_size, noise_size, e);
    w.set("radius", p.radius);
    w.set("thickness", p.thickness * p.radius); // at most 1e8: finite
    w.set("strength", p.strength);
    detail::set_frame_step(w, e);
    return w.bytes();
}

// BlurUniforms bytes; `target_size` is the AO target's size in pixels; of `e`, the finalize
// settings (a blur pass turns no noise).
inline std::vector<uint8_t> pack_blur(const blur_params& p, const mat4& proj, vec2 target_size, layout::rules rules, const extras& e = {})
{
    validate(p);
    validate(e.finalize);
    require_finite_above("uniforms target width", target_size.x, 0, 65536);
    require_finite_above("uniforms target height", target_size.y, 0, 65536);
    layout::writer w(layout::compute(blur_block(), rules));
    w.set("inv_proj", inverse(proj));
    w.set("texel_size", vec2{1.0f / target_size.x, 1.0f / target_size.y});
    w.set("raw_depth_k", p.raw_depth_k);
    w.set("linear_sharpness", p.linear_sharpness);
    w.set("albedo", e.finalize.albedo);
    return w.bytes();
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
