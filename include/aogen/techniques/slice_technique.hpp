// aogen/techniques/slice_technique.hpp — what GTAO and VBAO share: slices and steps per side,
// a 4 × 4 rotation tile, common/slices.glsl's tap placement, a period of half a slice's turn.
//
// WHAT
//   The parts of their table rows (descriptor.hpp) the two slice techniques have in common,
//   each a function a row points at: count_defines (AO_<TECH>_SLICES, _STEPS),
//   constants, period_turns and counts_text.
//
// WHY
//   The two differ in what a slice integrates (horizons, a sector mask) and agree on how
//   slices and steps are laid out; written once, the two rows cannot drift apart.
#pragma once

#include "descriptor.hpp"

#include <string>
#include <vector>

namespace aogen::slice_technique {

// AO_<TECH>_SLICES and AO_<TECH>_STEPS.
inline std::vector<define> count_defines(const std::string& tech, const variant& v)
{
    return {{"AO_" + tech + "_SLICES", std::to_string(v.slices)}, {"AO_" + tech + "_STEPS", std::to_string(v.steps)}};
}

inline std::vector<define> constants(const variant&)
{
    return {{"AO_SLICE_TEXEL_CENTRE_PIXELS", glsl_float(slice_taps::texel_centre_pixels)}};
}

// Slices at s·π/slices: the pattern repeats after 1/(2·slices) of a turn.
inline double period_turns(const variant& v) { return 1.0 / (2.0 * double(v.slices)); }

inline std::string counts_text(const variant& v)
{
    return std::string(to_name(v.tech)) + ": " + std::to_string(v.slices) + " slices x " + std::to_string(v.steps) + " steps";
}

} // namespace aogen::slice_technique
