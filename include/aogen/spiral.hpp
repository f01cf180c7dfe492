// aogen/spiral.hpp — the spiral of screen-space taps scalable ambient obscurance reads.
//
// WHAT
//   SAO (McGuire, Mara, Luebke, HPG 2012; templates/sao.glsl) reads `taps` depth samples per
//   pixel on a spiral around it: tap i at the share
//       alpha_i = (i + 1/2) / taps
//   of the pixel's screen-space radius, at the angle i · golden angle (turns: (3 − √5)/2),
//   the whole spiral turned by the pixel's noise rotation. spiral(taps) returns them as
//   vec4 {cos θ_i, sin θ_i, alpha_i, 0}, ready to upload as the vec4 array `spiral` of the
//   SaoUniforms block (uniforms.hpp), as SSAO's kernel rides in SsaoUniforms.
//
// USAGE
//     #include <aogen/spiral.hpp>
//     std::vector<aogen::vec4> s = aogen::spiral::taps(16);   // s[0] = {1, 0, 1/32, 0}
//
// WHY
//   * Radii linear in i, as the paper's: taps crowd the pixel, where the Alchemy estimator's
//     1 / |v|² weights (sao.glsl) make nearby occluders matter most, and each tap covers a
//     ring of its own width.
//   * The golden angle, where the paper searches an integer number of turns per tap count
//     (a table of one number per count): consecutive taps are 137.5° apart and no two ever
//     line up, for every count, so there is nothing to tabulate (Vogel's sunflower spiral).
//   * No sin/cos in the shader, and the same bits everywhere: the angles go through
//     random::cos_sin_turns (a polynomial with explicit fma) and alpha_i is one correctly
//     rounded division of exact integers.
#pragma once

#include "error.hpp"
#include "math.hpp"
#include "random.hpp"

#include <cmath>
#include <vector>

namespace aogen::spiral {

inline constexpr int min_taps = 1;
inline constexpr int max_taps = 256;

// The golden angle in turns, (3 − √5) / 2 = 0.3819660112501051 (sqrt correctly rounded).
inline double golden_turns() { return (3.0 - std::sqrt(5.0)) / 2.0; }

// The taps of a spiral of `count` (1..256): {cos θ_i, sin θ_i, alpha_i, 0}.
inline std::vector<vec4> taps(int count)
{
    require_range("spiral taps", count, min_taps, max_taps);
    std::vector<vec4> out;
    out.reserve(size_t(count));
    const double g = golden_turns();
    for (int i = 0; i < count; ++i) {
        const double turns = double(i) * g; // exact integer times g, one rounding
        const random::cos_sin cs = random::cos_sin_turns(turns - std::floor(turns));
        const double alpha = double(2 * i + 1) / double(2 * count);
        out.push_back({float(cs.c) + 0.0f, float(cs.s) + 0.0f, float(alpha), 0.0f});
    }
    return out;
}

} // namespace aogen::spiral
