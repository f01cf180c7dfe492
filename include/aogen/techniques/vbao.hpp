// aogen/techniques/vbao.hpp — VBAO, visibility-bitmask AO (Therrien et al. 2023): its block,
// its bytes, its shaders' parts.
//
// WHAT
//   uniforms::vbao_block()   VbaoUniforms: the camera, radius, thickness (world units),
//                            strength, frame_step; slices and steps are compile-time
//   uniforms::pack_vbao(...) its bytes under any rule set
//   techniques::vbao         the table's row (descriptor.hpp): GTAO's slices with a 32-sector
//                            mask (common/slices.glsl, vbao.glsl)
//
// USAGE
//     std::vector<uint8_t> bytes = aogen::uniforms::pack_vbao(aogen::vbao_params{}, cam, {960, 540},
//                                                             aogen::layout::rules::std140);
//
// ERRORS
//   aogen::error: a setting out of range, a frame step outside 0..1.
#pragma once

#include "descriptor.hpp"
#include "slice_technique.hpp"

#include <array>

namespace aogen {

namespace uniforms {

// VbaoUniforms' settings, in block order after the camera members. `thickness` is in world
// units (vbao_params::thickness, a fraction of the radius, times the radius; at most 1e8:
// finite), so the shader needs no second multiply and the block says what the shader uses.
inline const std::array<settings_member<vbao_params>, 4> vbao_members{{
    {"radius", [](const vbao_params& p, const extras&) { return p.radius; }},
    {"thickness", [](const vbao_params& p, const extras&) { return p.thickness * p.radius; }},
    {"strength", [](const vbao_params& p, const extras&) { return p.strength; }},
    {"frame_step", frame_step_of<vbao_params>},
}};

inline layout::block_desc vbao_block() { return {block_of("VbaoUniforms", vbao_members), {}}; }

// VbaoUniforms bytes; like GTAO, a 4×4 rotation tile unless told.
inline std::vector<uint8_t> pack_vbao(const vbao_params& p, const camera& cam, vec2 target_size, const layout::struct_layout& block,
                                      int noise_size = 4, const extras& e = {})
{
    validate(p);
    return settings_writer(block, vbao_members, p, cam, target_size, noise_size, e).bytes();
}
// The same under `rules` (vbao_block() laid out here).
inline std::vector<uint8_t> pack_vbao(const vbao_params& p, const camera& cam, vec2 target_size, layout::rules rules,
                                      int noise_size = 4, const extras& e = {})
{
    return pack_vbao(p, cam, target_size, layout::compute(vbao_block(), rules), noise_size, e);
}

} // namespace uniforms

namespace techniques {

inline constexpr technique_desc vbao{
    technique::vbao,
    [](const variant&) { return uniforms::vbao_block(); },
    [](const variant&, const ao_settings& s, const uniforms::camera& camera, vec2 target_size, const layout::struct_layout& block,
       const uniforms::extras& e) { return uniforms::pack_vbao(s.vbao, camera, target_size, block, rotation_tile_size(s), e); },
    rotation_tile_size,
    [](const variant&) { return std::vector<std::string>{"common/slices.glsl", "vbao.glsl"}; },
    [](const variant& v) { return slice_technique::count_defines("VBAO", v); },
    slice_technique::constants,
    slice_technique::period_turns,
    slice_technique::counts_text,
    2, // taps per iteration: a step reads a tap on each side
};

} // namespace techniques
} // namespace aogen
