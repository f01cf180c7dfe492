// aogen/half.hpp — IEEE 754 binary16 ("half") conversions, bit exact.
//
// WHAT
//   uint16_t aogen::float_to_half(float)      correctly rounded: to nearest, ties to even;
//                                             subnormal halves; |x| ≥ 65520 → ±inf;
//                                             NaN → quiet NaN with the same sign.
//   float    aogen::half_to_float(uint16_t)   exact (every half is a float).
//
// USAGE
//     #include <aogen/half.hpp>
//     uint16_t one = aogen::float_to_half(1.0f);     // 0x3C00
//     float back = aogen::half_to_float(0x3800);     // 0.5f
//     // Upload as little-endian: bytes (h & 0xFF), (h >> 8).
//
// WHY
//   GPU formats such as RGBA16F want halves, and the noise tiles and generated data must be
//   the same bytes on every compiler. `_Float16` and F16C are not available everywhere, and
//   hardware conversions obey the current rounding mode; this is pure integer code on the
//   float's bits, so the result depends on nothing but the input. The tests compare it
//   with the compiler's own _Float16 conversion where one exists.
//
//   Rounding works on the float's bits: for a normal half, rebias the exponent and drop 13
//   significand bits; for a subnormal half, shift the full significand (with its implicit
//   bit) right; in both cases round the dropped bits to nearest, ties to even. A carry out
//   of the significand correctly bumps the exponent (up to inf).
//
//   NaN payloads: the top 10 payload bits are kept and the quiet bit is set, so a NaN never
//   turns into infinity (as x86 F16C and ARM do).
#pragma once

#include <cstdint>
#include <cstring>

namespace aogen {

namespace half_detail {

inline uint32_t float_bits(float value)
{
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

inline float bits_to_float(uint32_t bits)
{
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

// `value >> shift`, rounded to nearest with ties to even (1 ≤ shift ≤ 31).
constexpr uint32_t shift_right_round_even(uint32_t value, unsigned shift)
{
    const uint32_t kept = value >> shift;
    const uint32_t dropped = value & ((uint32_t{1} << shift) - 1);
    const uint32_t halfway = uint32_t{1} << (shift - 1);
    const bool round_up = dropped > halfway || (dropped == halfway && (kept & 1u));
    return kept + (round_up ? 1u : 0u);
}

// Thresholds on |x|'s float bits.
inline constexpr uint32_t float_infinity = 0x7f800000u;
inline constexpr uint32_t half_overflow = 0x477ff000u;   // 65520 = 65504 + ½ ulp: rounds to inf
inline constexpr uint32_t half_min_normal = 0x38800000u; // 2^-14
inline constexpr uint32_t half_below_min_half = 0x33000000u; // 2^-25: at or below, rounds to 0
inline constexpr uint32_t exponent_rebias = (127u - 15u) << 23; // float bias 127, half bias 15

} // namespace half_detail

inline uint16_t float_to_half(float value)
{
    using namespace half_detail;
    const uint32_t bits = float_bits(value);
    const auto sign = static_cast<uint16_t>((bits >> 16) & 0x8000u);
    const uint32_t magnitude = bits & 0x7fffffffu;

    if (magnitude > float_infinity) // NaN: quiet, sign and top payload bits kept
        return static_cast<uint16_t>(sign | 0x7e00u | ((magnitude >> 13) & 0x03ffu));
    if (magnitude >= half_overflow) return static_cast<uint16_t>(sign | 0x7c00u); // ±inf
    if (magnitude >= half_min_normal)
        return static_cast<uint16_t>(sign | shift_right_round_even(magnitude - exponent_rebias, 13));
    if (magnitude <= half_below_min_half) return sign; // ±0 (2^-25 itself is a tie → even 0)

    // Subnormal half: value = significand · 2^(exponent − 150); in units of 2^-24 that is
    // significand >> (126 − exponent). Here exponent is 102..112, so the shift is 14..24.
    const uint32_t exponent = magnitude >> 23;
    const uint32_t significand = (magnitude & 0x007fffffu) | 0x00800000u;
    return static_cast<uint16_t>(sign | shift_right_round_even(significand, 126u - exponent));
}

inline float half_to_float(uint16_t half)
{
    using namespace half_detail;
    const uint32_t sign = static_cast<uint32_t>(half & 0x8000u) << 16;
    const uint32_t exponent = (half >> 10) & 0x1fu;
    const uint32_t significand = half & 0x03ffu;

    if (exponent == 0x1fu) return bits_to_float(sign | float_infinity | (significand << 13));
    if (exponent != 0)
        return bits_to_float(sign | (((exponent << 23) | (significand << 13)) + exponent_rebias));
    // Zero or subnormal: significand · 2^-24, exact in float.
    const float magnitude = static_cast<float>(significand) * (1.0f / 16777216.0f);
    return sign ? -magnitude : magnitude;
}

} // namespace aogen
