// aogen/uniforms_common.hpp — what every AO pass's uniform block shares: the camera, the frame's
// extras, and the member tables a technique's block is made from.
//
// WHAT
//   camera               the view and projection every pass reads
//   extras               this frame's turn of the noise and move of the slice steps
//                        (temporal.hpp) and the finalize step's settings (multi-bounce)
//   camera_members()     the members every AO block starts with
//   settings_member<P>   one member of a technique's block after the camera: its name, its
//                        type and how its value is read from the technique's params P and
//                        the frame's extras. A technique (techniques/*.hpp) lists its members
//                        once, and both its block's description (block_of) and its bytes
//                        (write_settings) are made from that one list, so a member cannot be
//                        declared in one order and written in another.
//
// USAGE
//     // a technique's table (techniques/gtao.hpp):
//     inline const std::array<uniforms::settings_member<gtao_params>, 2> members{{
//         {"radius", [](const gtao_params& p, const uniforms::extras&) { return p.radius; }},
//         {"frame_step", uniforms::frame_step_of<gtao_params>}}};
//     layout::block_desc b{uniforms::block_of("GtaoUniforms", members), {}};
//     std::vector<uint8_t> bytes = uniforms::settings_writer(b, members, p, cam, size, 4, rules, e).bytes();
//
// ERRORS
//   aogen::error: a target size outside (0, 65536], a finalize setting or frame step outside
//   its range, each naming the value.
//
// WHY
//   Its own header, below the techniques' (techniques/*.hpp) and the blocks' (uniforms.hpp),
//   because each technique's block is written from it and no technique's block is here.
#pragma once

#include "error.hpp"
#include "layout.hpp"
#include "layout_writer.hpp"
#include "math.hpp"
#include "params.hpp"

#include <string>
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

// One float member of a technique's block after the camera members: its name in the block
// (and in the shader, `u.<name>`) and its value for params `P` and the frame's extras.
template <class P>
struct settings_member {
    const char* name;
    float (*value)(const P& params, const extras& e);
};

// The slice techniques' step offset, in steps: temporal::step_offset's [0, 1), or up to a
// whole step (1 puts the inner steps one step in, the first onto the pixel). An
// aogen::error naming `uniforms frame_step` outside that.
template <class P>
float frame_step_of(const P&, const extras& e)
{
    require_finite_range("uniforms frame_step", e.frame_step, 0, 1);
    return e.frame_step;
}

// The block `type`: the camera members, then `members` in their order, each a float.
template <class Members>
layout::struct_desc block_of(const char* type, const Members& members)
{
    layout::struct_desc s{type, camera_members()};
    for (const auto& m : members) s.members.push_back({m.name, "float"});
    return s;
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

} // namespace detail

// Writes each of `members`' values for `p` and `e` into `w`, in the members' order.
template <class Members, class P>
void write_settings(layout::writer& w, const Members& members, const P& p, const extras& e)
{
    for (const auto& m : members) w.set(m.name, m.value(p, e));
}

// A writer of `block`, a technique's block laid out (by a plan once, or by its pack_* under
// the rules asked for), with the camera members and `members`' values for `p` and `e`
// written: what is left to write is its arrays, if it has any. `p` is validated by the caller.
template <class Members, class P>
layout::writer settings_writer(const layout::struct_layout& block, const Members& members, const P& p, const camera& cam,
                               vec2 target_size, int noise_size, const extras& e)
{
    layout::writer w(block);
    detail::set_camera(w, cam, target_size, noise_size, e);
    write_settings(w, members, p, e);
    return w;
}

} // namespace aogen::uniforms
