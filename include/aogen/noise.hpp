// aogen/noise.hpp — SSAO noise tiles: per-pixel rotations of the sample kernel, bit-exact.
//
// WHAT
//   A tile is size × size texels (row-major: texel (x, y) is texels[y * size + x]), each
//   (cos θ, sin θ, 0, 1): a rotation about the surface normal. The SSAO shader repeats the
//   tile over the screen and builds its TBN frame from the texel's xy, so neighbouring
//   pixels use differently rotated kernels and the blur turns banding into fine noise.
//
//   Patterns (`pattern`):
//     random  the seeds' tile (seed 000 "generateNoise"): θ uniform and independent per texel.
//     r2      stratified angles in an R2 arrangement: the N² texels get the N² evenly spaced
//             angles (k + offset)/N² turns, k = 0..N²−1, each exactly once, and which texel
//             gets which k is the rank of Roberts' R2 dither value fract(x·α1 + y·α2),
//             α = (1/g, 1/g²), g the plastic number. Why: the seeds blur the AO with a 4×4
//             box (or a 7-tap bilateral) over exactly one 4×4 tile, so the blurred value
//             averages the kernel over the tile's rotations. With random angles those can
//             bunch up (a 16-sample kernel in effect rotated a few times); with stratified
//             angles the 16 rotations cover the circle evenly — the same effect as a 16×
//             larger stratified kernel — so the variance after the blur is lower at the same
//             sample count. R2's ranking also keeps adjacent texels far apart in angle
//             (so a smaller, bilateral-clipped blur footprint still sees varied rotations):
//             inside the tile, 4-neighbours differ by at least 0.2 turn for every size
//             2..64 (tested). Across the edge where the tile repeats, this holds for the
//             default size 4 (and 2, 7, 11, 12, 16, ...) but not for every size: R2 is not
//             periodic, so prefer 4 or 16 when that matters.
//   Seed: random draws every angle from PCG32; r2 with seed 0 is the plain arrangement
//   (offset 0, so texel of rank 0 is (1, 0, 0, 1)); another seed shifts the R2 values
//   (which texel gets which rank) and rotates all angles by a random fraction of a step.
//
//   Encodings (`encoding`), little-endian bytes ready for a texture upload:
//     rgba32f      the floats as they are                                   16 bytes/texel
//     rgba16f      correctly rounded halves (aogen/half.hpp)                 8 bytes/texel
//     rg16f        x and y only, as halves                                   4 bytes/texel
//     rgba8_unorm  round(c·0.5 + 0.5)·255 per channel: decode with ·2 − 1    4 bytes/texel
//                  in the shader (seed 004 does); w = 1 → 255, z = 0 → 128
//     rgba8_snorm  round(clamp(c, −1, 1)·127): −1 → 0x81, 1 → 0x7F          4 bytes/texel
//   Rounding to integers is to nearest with halves away from zero; a NaN channel becomes 0
//   in the 8-bit encodings (the Vulkan rule for float → normalized conversion).
//
// USAGE
//     #include <aogen/noise.hpp>
//     aogen::noise::tile t = aogen::noise::rotations(4, 0);               // the seeds' tile
//     std::vector<uint8_t> bytes = aogen::noise::encode(t, aogen::noise::encoding::rgba8_unorm);
//     // upload: width = height = t.size, format aogen::noise::vulkan_format_name(...)
//     auto s = aogen::noise::generate(aogen::noise::pattern_from_name("r2"), 4, 0);
//
// WHY (determinism)
//   Same seed, same bytes on every compiler, standard library and libm. The random pattern
//   draws a uniform point of the unit disk by rejection (exact integer test, PCG32 draws)
//   and normalises it: its direction is uniform in θ, and no libm cos/sin (which differ by
//   an ulp between libraries) is involved. The r2 pattern needs cos/sin of given angles and
//   uses random::cos_sin_turns (polynomial with explicit fma, same bits everywhere); its
//   R2 values are 0.64 fixed-point integers, so ranking them is exact. Bytes are written one
//   by one from the bit patterns, so the output is little-endian on every host.
#pragma once

#include "error.hpp"
#include "half.hpp"
#include "math.hpp"
#include "names.hpp"
#include "random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::noise {

inline constexpr int default_size = 4;
inline constexpr int min_size = 1;
inline constexpr int max_size = 64;

struct tile {
    int size = 0;
    std::vector<vec4> texels; // row-major: texel (x, y) at y * size + x

    const vec4& at(int x, int y) const { return texels[static_cast<size_t>(y) * static_cast<size_t>(size) + static_cast<size_t>(x)]; }
};

enum class pattern { random, r2 };
enum class encoding { rgba32f, rgba16f, rg16f, rgba8_unorm, rgba8_snorm };

// Their names, for command lines and manifests (see names.hpp; to_name and *_from_name below).
inline constexpr std::array<enum_name<pattern>, 2> pattern_names{{
    {pattern::random, "random"},
    {pattern::r2, "r2"},
}};
inline constexpr std::array<enum_name<encoding>, 5> encoding_names{{
    {encoding::rgba32f, "rgba32f"},
    {encoding::rgba16f, "rgba16f"},
    {encoding::rg16f, "rg16f"},
    {encoding::rgba8_unorm, "rgba8_unorm"},
    {encoding::rgba8_snorm, "rgba8_snorm"},
}};
static_assert(names::distinct(pattern_names) && names::distinct(encoding_names));

namespace detail {

inline void require_size(int size) { aogen::require_range("noise size", size, min_size, max_size); }

inline size_t texel_count(int size) { return static_cast<size_t>(size) * static_cast<size_t>(size); }

// (c, s, 0, 1) in float; adding +0 turns −0 into +0 so that a zero has one bit pattern.
inline vec4 rotation_texel(double c, double s)
{
    return {static_cast<float>(c) + 0.0f, static_cast<float>(s) + 0.0f, 0.0f, 1.0f};
}

// R2 dither constants 1/g and 1/g² (g = 1.3247179572..., the plastic number) as 0.64
// fixed-point fractions, rounded to nearest. Wrapping uint64 arithmetic is the "fract".
inline constexpr uint64_t r2_alpha_x = 0xc13fa9a902a6328full; // 0.75487766624669276005
inline constexpr uint64_t r2_alpha_y = 0x91e10da5c79e7b1dull; // 0.56984029099805326591

inline void append_u16(std::vector<uint8_t>& out, uint16_t value)
{
    out.push_back(static_cast<uint8_t>(value & 0xffu));
    out.push_back(static_cast<uint8_t>(value >> 8));
}

inline void append_f32(std::vector<uint8_t>& out, float value)
{
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int byte = 0; byte < 4; ++byte) out.push_back(static_cast<uint8_t>((bits >> (8 * byte)) & 0xffu));
}

// c·0.5 + 0.5 mapped to 0..255, to nearest. c·0.5 is exact, so no fusing can change it.
inline uint8_t to_unorm8(float c)
{
    if (std::isnan(c)) return 0;
    const double clamped = std::clamp(static_cast<double>(c), -1.0, 1.0);
    return static_cast<uint8_t>(std::lround((clamped * 0.5 + 0.5) * 255.0));
}

// clamp(c, −1, 1)·127 to nearest, as a two's complement byte.
inline uint8_t to_snorm8(float c)
{
    if (std::isnan(c)) return 0;
    const double clamped = std::clamp(static_cast<double>(c), -1.0, 1.0);
    const auto value = static_cast<int>(std::lround(clamped * 127.0));
    return static_cast<uint8_t>(static_cast<unsigned>(value) & 0xffu);
}

} // namespace detail

// The seeds' tile: θ uniform per texel, as the normalised direction of a uniform point
// of the unit disk (no trig; see WHY).
inline tile rotations(int size = default_size, uint64_t seed = 0)
{
    detail::require_size(size);
    random::pcg32 rng = random::seeded(seed, random::stream::noise_random);
    tile result{size, {}};
    result.texels.reserve(detail::texel_count(size));
    for (size_t i = 0; i < detail::texel_count(size); ++i) {
        const random::disk_point p = random::draw_in_unit_disk(rng);
        const double norm = std::sqrt(static_cast<double>(p.norm2));
        result.texels.push_back(detail::rotation_texel(static_cast<double>(p.x) / norm,
                                                       static_cast<double>(p.y) / norm));
    }
    return result;
}

// Stratified angles, arranged by rank of the R2 dither value (see the pattern notes).
inline tile r2(int size = default_size, uint64_t seed = 0)
{
    detail::require_size(size);
    uint64_t value_shift = 0;   // added to every R2 value: rotates the ranking
    double angle_offset = 0.0;  // in steps of 1/N² turn, in [0, 1)
    if (seed != 0) {
        random::pcg32 rng = random::seeded(seed, random::stream::noise_r2);
        value_shift = rng.next_u64();
        angle_offset = rng.next_float();
    }
    const size_t count = detail::texel_count(size);
    std::vector<uint64_t> values(count);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            values[static_cast<size_t>(y) * static_cast<size_t>(size) + static_cast<size_t>(x)] =
                static_cast<uint64_t>(x) * detail::r2_alpha_x + static_cast<uint64_t>(y) * detail::r2_alpha_y +
                value_shift;

    // Texel indices sorted by value; ties (none occur for sizes ≤ 64) broken by index.
    std::vector<size_t> by_value(count);
    std::iota(by_value.begin(), by_value.end(), size_t{0});
    std::stable_sort(by_value.begin(), by_value.end(),
                     [&](size_t a, size_t b) { return values[a] < values[b]; });

    tile result{size, std::vector<vec4>(count)};
    for (size_t rank = 0; rank < count; ++rank) {
        // (rank + offset) / N²: the sum is exact (< 2^13 with a 24-bit fraction), one division.
        const double turns = (static_cast<double>(rank) + angle_offset) / static_cast<double>(count);
        const random::cos_sin angle = random::cos_sin_turns(turns);
        result.texels[by_value[rank]] = detail::rotation_texel(angle.c, angle.s);
    }
    return result;
}

inline tile generate(pattern kind, int size = default_size, uint64_t seed = 0)
{
    switch (kind) {
    case pattern::random: return rotations(size, seed);
    case pattern::r2: return r2(size, seed);
    }
    names::fail_unlisted(pattern_names, kind, "noise pattern");
}

// ---- encodings ----

inline int bytes_per_texel(encoding format)
{
    switch (format) {
    case encoding::rgba32f: return 16;
    case encoding::rgba16f: return 8;
    case encoding::rg16f: return 4;
    case encoding::rgba8_unorm: return 4;
    case encoding::rgba8_snorm: return 4;
    }
    names::fail_unlisted(encoding_names, format, "noise encoding");
}

// The matching VkFormat enumerator's name, for manifests and documentation.
inline std::string_view vulkan_format_name(encoding format)
{
    switch (format) {
    case encoding::rgba32f: return "VK_FORMAT_R32G32B32A32_SFLOAT";
    case encoding::rgba16f: return "VK_FORMAT_R16G16B16A16_SFLOAT";
    case encoding::rg16f: return "VK_FORMAT_R16G16_SFLOAT";
    case encoding::rgba8_unorm: return "VK_FORMAT_R8G8B8A8_UNORM";
    case encoding::rgba8_snorm: return "VK_FORMAT_R8G8B8A8_SNORM";
    }
    names::fail_unlisted(encoding_names, format, "noise encoding");
}

// The matching WebGPU texture format (seed 004 is WGSL).
inline std::string_view webgpu_format_name(encoding format)
{
    switch (format) {
    case encoding::rgba32f: return "rgba32float";
    case encoding::rgba16f: return "rgba16float";
    case encoding::rg16f: return "rg16float";
    case encoding::rgba8_unorm: return "rgba8unorm";
    case encoding::rgba8_snorm: return "rgba8snorm";
    }
    names::fail_unlisted(encoding_names, format, "noise encoding");
}

// The tile's texels as little-endian bytes in `format`, row by row, no row padding.
inline std::vector<uint8_t> encode(const tile& noise, encoding format)
{
    const int bytes = bytes_per_texel(format); // also rejects an invalid format
    if (noise.size < min_size || noise.size > max_size)
        aogen::require_range("noise tile size", noise.size, min_size, max_size);
    if (noise.texels.size() != detail::texel_count(noise.size))
        aogen::fail("noise tile texels", std::to_string(noise.texels.size()) + " texels",
                    "valid: size × size = " + std::to_string(detail::texel_count(noise.size)));

    std::vector<uint8_t> out;
    out.reserve(noise.texels.size() * static_cast<size_t>(bytes));
    for (const vec4& t : noise.texels) {
        const float channels[4] = {t.x, t.y, t.z, t.w};
        switch (format) {
        case encoding::rgba32f:
            for (float c : channels) detail::append_f32(out, c);
            break;
        case encoding::rgba16f:
            for (float c : channels) detail::append_u16(out, float_to_half(c));
            break;
        case encoding::rg16f:
            detail::append_u16(out, float_to_half(t.x));
            detail::append_u16(out, float_to_half(t.y));
            break;
        case encoding::rgba8_unorm:
            for (float c : channels) out.push_back(detail::to_unorm8(c));
            break;
        case encoding::rgba8_snorm:
            for (float c : channels) out.push_back(detail::to_snorm8(c));
            break;
        }
    }
    return out;
}

// ---- names, for command lines and manifests ----

inline std::string_view to_name(pattern kind)
{
    return names::name_of(pattern_names, kind, "noise pattern");
}

inline pattern pattern_from_name(std::string_view name)
{
    return names::value_of(pattern_names, name, "noise pattern");
}

inline std::string_view to_name(encoding format)
{
    return names::name_of(encoding_names, format, "noise encoding");
}

inline encoding encoding_from_name(std::string_view name)
{
    return names::value_of(encoding_names, name, "noise encoding");
}

} // namespace aogen::noise
