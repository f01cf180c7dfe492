// aogen/techniques/gtao.hpp — GTAO (seed 001; Jimenez et al. 2016): its block, its bytes, its
// shaders' parts.
//
// WHAT
//   uniforms::gtao_block()   GtaoUniforms: the camera, radius, thickness_bias, strength,
//                            falloff_range, thin_occluder, frame_step; slices and steps are
//                            compile-time (AO_GTAO_SLICES, AO_GTAO_STEPS)
//   uniforms::pack_gtao(...) its bytes under any rule set
//   techniques::gtao         the table's row (descriptor.hpp): a 4 × 4 rotation tile,
//                            common/slices.glsl and gtao.glsl, a period of half a slice's turn
//
// USAGE
//     std::vector<uint8_t> bytes = aogen::uniforms::pack_gtao(aogen::gtao_params{}, cam, {960, 540},
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

// GtaoUniforms' settings, in block order after the camera members.
inline const std::array<settings_member<gtao_params>, 6> gtao_members{{
    {"radius", [](const gtao_params& p, const extras&) { return p.radius; }},
    {"thickness_bias", [](const gtao_params& p, const extras&) { return p.thickness_bias; }},
    {"strength", [](const gtao_params& p, const extras&) { return p.strength; }},
    {"falloff_range", [](const gtao_params& p, const extras&) { return p.falloff_range; }},
    {"thin_occluder", [](const gtao_params& p, const extras&) { return p.thin_occluder; }},
    {"frame_step", frame_step_of<gtao_params>},
}};

inline layout::block_desc gtao_block() { return {block_of("GtaoUniforms", gtao_members), {}}; }

// GtaoUniforms bytes; GTAO uses no noise tile of its own beyond a 4×4 rotation.
inline std::vector<uint8_t> pack_gtao(const gtao_params& p, const camera& cam, vec2 target_size, const layout::struct_layout& block,
                                      int noise_size = 4, const extras& e = {})
{
    validate(p);
    return settings_writer(block, gtao_members, p, cam, target_size, noise_size, e).bytes();
}
// The same under `rules` (gtao_block() laid out here).
inline std::vector<uint8_t> pack_gtao(const gtao_params& p, const camera& cam, vec2 target_size, layout::rules rules,
                                      int noise_size = 4, const extras& e = {})
{
    return pack_gtao(p, cam, target_size, layout::compute(gtao_block(), rules), noise_size, e);
}

} // namespace uniforms

namespace techniques {

inline constexpr technique_desc gtao{
    technique::gtao,
    [](const variant&) { return uniforms::gtao_block(); },
    [](const variant&, const ao_settings& s, const uniforms::camera& camera, vec2 target_size, const layout::struct_layout& block,
       const uniforms::extras& e) { return uniforms::pack_gtao(s.gtao, camera, target_size, block, rotation_tile_size(s), e); },
    rotation_tile_size,
    [](const variant&) { return std::vector<std::string>{"common/slices.glsl", "gtao.glsl"}; },
    [](const variant& v) { return slice_technique::count_defines("GTAO", v); },
    slice_technique::constants,
    slice_technique::period_turns,
    slice_technique::counts_text,
    2, // taps per iteration: a step reads a tap on each side
};

} // namespace techniques
} // namespace aogen
