// aogen/temporal.hpp — the frame index: how consecutive frames turn an AO pass's noise so
// that an average over frames (TAA's history, or a plain mean) converges toward the integral.
//
// WHAT
//   Every AO pass rotates its samples per pixel by the noise tile (noise.hpp; GTAO's and
//   VBAO's slice directions, SSAO's kernel, SAO's spiral). Frame f turns every pixel's
//   rotation by one more angle, the same for the whole screen, uploaded as the uniform
//   member `frame_rotation` = (cos, sin) of that angle (uniforms.hpp):
//     frame_rotation(v, f)    the rotation of frame f for variant v; (1, 0) exactly at f = 0,
//                             so frame 0 is the single-frame output bit for bit
//     offset_turns(seq, f)    frame f's fraction of the period, in [0, 1)
//     period_turns(v)         the angle after which v's samples repeat, in turns
//   The angle is offset_turns(f) × period_turns(v). The period: a slice technique with S
//   slices draws them at s·π/S (common/slices.glsl), so its slice set repeats every 1/(2S)
//   turn and a frame offset only matters modulo that; SSAO's kernel and SAO's spiral have no
//   symmetry, so theirs is a whole turn.
//   The slice techniques (GTAO, VBAO) also move their steps along each slice: frame f puts
//   every inner step j < N of a slice's march at (j − s)/N of the radius instead of j/N,
//   s = step_offset(f) in [0, 1), uploaded as the member `frame_step` (0 at frame 0):
//     step_offset(seq, f)     frame f's step offset, in steps; 0 at f = 0
//   so the frames' inner steps cover each step's whole stratum ((j − 1)/N, j/N] of the
//   radius rather than its one end. The outermost step stays at the radius, so every frame
//   searches to its full reach: horizons are maxima over the steps, and the step that
//   reaches farthest is the one that sees a wall's top — moving it inward lightens every
//   frame, which no number of frames averages back (measured: BENCHMARKS.md § Reference measurements).
//
//   Sequences (`sequence`; the default is van_der_corput, the others are what it was
//   measured against — tests/accuracy's "temporal" cases print the three side by side):
//     van_der_corput  the base-2 radical inverse of f: 0, 1/2, 1/4, 3/4, 1/8, ... Any 2^k
//                     consecutive frames from 0 are the 2^k evenly spaced offsets, so every
//                     pixel's rotations after N = 2^k frames are exactly stratified over the
//                     period, and in between every prefix is as even as a prefix can be.
//                     The step offset is the second dimension of Sobol's sequence (0, 1/2,
//                     3/4, 1/4, 5/8, 1/8, ...), whose first is van der Corput's: the pairs
//                     (turn, step) of the first 2^k frames put one frame in every box of
//                     every 2^a × 2^b grid with a + b = k (a (0, 2)-sequence in base 2), so
//                     turns and steps are stratified together, not only each alone.
//     golden_ratio    fract(f·(√5 − 1)/2): even for every N, never exactly stratified; its
//                     step offset fract(f·α), α = 1/ρ² (ρ the plastic number, R2's second
//                     coordinate), an irrational apart from the golden ratio's.
//     white           an independent uniform offset per frame (PCG32): what a renderer gets
//                     from a fresh random seed each frame; converges as 1/√N at best. Its
//                     step offset is the stream's next draw.
//
// USAGE
//     #include <aogen/temporal.hpp>
//     aogen::vec2 r = aogen::temporal::frame_rotation(v, frame_count);   // each frame
//     float s = aogen::temporal::step_offset(aogen::temporal::sequence::van_der_corput, frame_count);
//     // pack them with the pass's uniforms (uniforms::extras{r, finalize, s}), or set
//     // chain_settings::frame and let plan::inputs do it.
//
// WHY
//   The rotation is computed here, on the host, with random::cos_sin_turns (the same bits on
//   every platform) rather than from an index in the shader: no transcendental per pixel,
//   no shader-compiler cos(0) to trust, and a frame-0 rotation of exactly (1, 0), whose
//   products in the shader are exact — today's single-frame output stays what it was. The
//   step offset likewise: 0 at frame 0, and (j − 0)/N is j/N to the bit.
#pragma once

#include "axes.hpp"
#include "math.hpp"
#include "names.hpp"
#include "random.hpp"
#include "range.hpp"
#include "techniques.hpp"
#include "variant.hpp"

#include <array>
#include <cstdint>
#include <string_view>

namespace aogen::temporal {

enum class sequence { van_der_corput, golden_ratio, white };
inline constexpr std::array<enum_name<sequence>, 3> sequence_names{{
    {sequence::van_der_corput, "van_der_corput"},
    {sequence::golden_ratio, "golden_ratio"},
    {sequence::white, "white"},
}};
static_assert(names::distinct(sequence_names));

inline const char* to_name(sequence s) { return names::name_of(sequence_names, s, "frame sequence"); }
inline sequence sequence_from_name(std::string_view name, std::string_view subject = "frame sequence")
{
    return names::value_of(sequence_names, name, subject);
}

// The PCG32 stream of the white sequence ("frames01").
inline constexpr uint64_t white_stream = 0x6672616d65733031ull;

// Frame f's offset as a fraction of the period, in [0, 1); 0 at frame 0 for every sequence.
// Exact multiples of 2^-32 (van der Corput, golden ratio) or 2^-24 (white), so the same on
// every platform.
inline double offset_turns(sequence s, uint32_t frame)
{
    if (frame == 0) return 0.0;
    switch (s) {
    case sequence::van_der_corput: {
        uint32_t bits = frame; // reversed: bit k of the frame becomes the fraction's bit k + 1
        bits = ((bits >> 1) & 0x55555555u) | ((bits & 0x55555555u) << 1);
        bits = ((bits >> 2) & 0x33333333u) | ((bits & 0x33333333u) << 2);
        bits = ((bits >> 4) & 0x0f0f0f0fu) | ((bits & 0x0f0f0f0fu) << 4);
        bits = ((bits >> 8) & 0x00ff00ffu) | ((bits & 0x00ff00ffu) << 8);
        bits = (bits >> 16) | (bits << 16);
        return double(bits) * 0x1p-32;
    }
    case sequence::golden_ratio: {
        constexpr uint32_t golden = 0x9e3779b9u; // (√5 − 1)/2 as a 0.32 fixed-point fraction
        return double(uint32_t(frame * golden)) * 0x1p-32; // wrapping: the fract
    }
    case sequence::white: {
        random::pcg32 rng = random::seeded(frame, white_stream);
        return double(rng.next_float());
    }
    }
    names::fail_unlisted(sequence_names, s, "frame sequence");
}

// Frame f's step offset for the slice techniques' inner steps (WHAT), in steps, in [0, 1);
// 0 at frame 0 for every sequence. Multiples of 2^-24 (the top 24 bits of the 0.32
// fraction: exact in a float, never rounded up to 1).
inline float step_offset(sequence s, uint32_t frame)
{
    if (frame == 0) return 0.0f;
    switch (s) {
    case sequence::van_der_corput: {
        // Sobol's second dimension: the XOR of the direction numbers v_k of f's set bits,
        // v_0 = 1/2, v_k = v_(k-1) xor v_(k-1)/2 (the Pascal matrix mod 2, polynomial x + 1).
        uint32_t x = 0, direction = 0x80000000u;
        for (uint32_t bits = frame; bits != 0; bits >>= 1, direction ^= direction >> 1)
            if (bits & 1u) x ^= direction;
        return float(x >> 8) * 0x1p-24f;
    }
    case sequence::golden_ratio: {
        constexpr uint32_t alpha = 0x91e10da6u; // 1/ρ² = 0.5698402909980532... as a 0.32 fixed-point fraction
        return float(uint32_t(frame * alpha) >> 8) * 0x1p-24f; // wrapping: the fract
    }
    case sequence::white: {
        random::pcg32 rng = random::seeded(frame, white_stream);
        rng.next_float(); // the frame's turn (offset_turns)
        return rng.next_float();
    }
    }
    names::fail_unlisted(sequence_names, s, "frame sequence");
}

// The angle, in turns, after which `v`'s samples repeat: its technique's (techniques.hpp):
// 1/(2·slices) for GTAO and VBAO (slices at s·π/slices), a whole turn for SSAO's kernel and
// SAO's spiral.
inline double period_turns(const variant& v) { return technique_of(v.tech).period_turns(v); }

// The rotation (cos, sin) frame `frame` adds to every pixel's noise rotation in `v`'s AO
// pass; exactly (1, 0) at frame 0.
inline vec2 frame_rotation(const variant& v, uint32_t frame, sequence s = sequence::van_der_corput)
{
    const random::cos_sin r = random::cos_sin_turns(offset_turns(s, frame) * period_turns(v));
    return {float(r.c) + 0.0f, float(r.s) + 0.0f}; // + 0: a zero has one bit pattern
}

} // namespace aogen::temporal
