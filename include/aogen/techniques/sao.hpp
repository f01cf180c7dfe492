// aogen/techniques/sao.hpp — SAO, scalable ambient obscurance (McGuire, Mara, Luebke 2012):
// its block, its bytes, its shaders' parts.
//
// WHAT
//   uniforms::sao_block(taps)   SaoUniforms: the camera, radius, bias, intensity, contrast,
//                               spiral[taps] (spiral.hpp)
//   uniforms::pack_sao(...)     its bytes under any rule set
//   techniques::sao             the table's row (descriptor.hpp): a 4 × 4 rotation tile,
//                               sao.glsl, SSAO's edge and plane bands
//
// USAGE
//     std::vector<uint8_t> bytes = aogen::uniforms::pack_sao(aogen::sao_params{}, cam, 16, {960, 540},
//                                                            aogen::layout::rules::std140);
//
// ERRORS
//   aogen::error: a tap count outside variant::samples_range, a setting out of range.
#pragma once

#include <aogen/spiral.hpp>
#include "descriptor.hpp"

#include <array>

namespace aogen {

namespace uniforms {

// SaoUniforms' settings, in block order after the camera members.
inline const std::array<settings_member<sao_params>, 4> sao_members{{
    {"radius", [](const sao_params& p, const extras&) { return p.radius; }},
    {"bias", [](const sao_params& p, const extras&) { return p.bias; }},
    {"intensity", [](const sao_params& p, const extras&) { return p.intensity; }},
    {"contrast", [](const sao_params& p, const extras&) { return p.contrast; }},
}};

// SAO's block: the camera, its settings, and its spiral of taps (spiral.hpp), N of them.
inline layout::block_desc sao_block(int taps)
{
    require_in("sao block taps", taps, variant::samples_range);
    layout::struct_desc s = block_of("SaoUniforms", sao_members);
    s.members.push_back({"spiral", "vec4", static_cast<uint32_t>(taps)});
    return {s, {}};
}

// SaoUniforms bytes for a spiral of `taps` (the variant's samples); SAO's noise is a
// rotation per pixel, like GTAO's.
inline std::vector<uint8_t> pack_sao(const sao_params& p, const camera& cam, int taps, vec2 target_size, const layout::struct_layout& block,
                                     int noise_size = 4, const extras& e = {})
{
    validate(p);
    layout::writer w = settings_writer(block, sao_members, p, cam, target_size, noise_size, e);
    w.set("spiral", spiral::taps(taps));
    return w.bytes();
}
// The same under `rules` (sao_block(taps) laid out here).
inline std::vector<uint8_t> pack_sao(const sao_params& p, const camera& cam, int taps, vec2 target_size, layout::rules rules,
                                     int noise_size = 4, const extras& e = {})
{
    return pack_sao(p, cam, taps, target_size, layout::compute(sao_block(taps), rules), noise_size, e);
}

} // namespace uniforms

namespace techniques {

inline constexpr technique_desc sao{
    technique::sao,
    [](const variant& v) { return uniforms::sao_block(v.samples); },
    [](const variant& v, const ao_settings& s, const uniforms::camera& camera, vec2 target_size, const layout::struct_layout& block,
       const uniforms::extras& e) { return uniforms::pack_sao(s.sao, camera, v.samples, target_size, block, rotation_tile_size(s), e); },
    rotation_tile_size, // a rotation per pixel, like GTAO's
    [](const variant&) { return std::vector<std::string>{"sao.glsl"}; },
    [](const variant& v) { return std::vector<define>{{"AO_SAO_SAMPLES", std::to_string(v.samples)}}; },
    [](const variant&) {
        // SAO's taps fade at the screen's border and at silhouettes over SSAO's smooth bands.
        return std::vector<define>{{"AO_SAO_EDGE_BAND_PIXELS", glsl_float(ssao_bands::edge_pixels)},
                                   {"AO_SAO_SELF_BAND_PIXELS", glsl_float(ssao_bands::self_pixels)},
                                   {"AO_DEPTH_PLANE_BAND", glsl_float(ssao_bands::plane_per_spread)},
                                   {"AO_SAO_EPSILON", glsl_float(sao_params::epsilon)}};
    },
    [](const variant&) { return 1.0; }, // the spiral turns whole
    [](const variant& v) { return "sao: " + std::to_string(v.samples) + " spiral taps"; },
    1, // taps per iteration: a sample reads one tap
};

} // namespace techniques
} // namespace aogen
