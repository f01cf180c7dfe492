// aogen/kernel.hpp — hemisphere sample kernels for SSAO, bit-exact for a given seed.
//
// WHAT
//   A kernel is `count` points in the unit hemisphere z ≥ 0 of tangent space (z along the
//   surface normal), returned as vec4 {x, y, z, 0}: ready to upload as a vec4 array in a
//   std140 uniform block or a storage buffer. The shader rotates them per pixel into the
//   surface's frame (TBN) and scales them by the AO radius.
//
//   Three point distributions (`distribution`):
//     crytek      the seeds' kernel (seed 000 "generateKernel"): x, y uniform in [-1, 1),
//                 z uniform in [0, 1), normalised; times a random length in [0, 1).
//                 Directions lean towards the cube's diagonals, not cosine-weighted.
//     cosine      cosine-weighted unit directions (Malley's method: a uniform point of the
//                 unit disk, lifted to the hemisphere: z = sqrt(1 − x² − y²)).
//     hammersley  the Hammersley point set (i/N, radical inverse of i in base 2) mapped to
//                 cosine-weighted directions the same way (i/N → azimuth, radical inverse →
//                 squared disk radius), with a seeded Cranley–Patterson rotation (seed 0
//                 gives the plain, unrotated set). Low discrepancy: less noise than random
//                 directions at the same sample count.
//   Two radial laws (`scale_law`), a factor per sample index i of N:
//     crytek      0.1 + 0.9·(i/N)², i.e. lerp(0.1, 1, (i/N)²): more samples near the origin,
//                 where occluders matter most (seed 000).
//     none        1: cosine and hammersley points lie on the unit hemisphere (length 1);
//                 crytek points keep their random length in [0, 1).
//   So for every distribution and law, |sample_i| ≤ factor_i (up to float rounding).
//
// USAGE
//     #include <aogen/kernel.hpp>
//     std::vector<aogen::vec4> k = aogen::kernel::crytek(16, 0);          // the seeds' kernel
//     auto h = aogen::kernel::hammersley(32, 0, aogen::kernel::scale_law::crytek);
//     auto d = aogen::kernel::distribution_from_name("cosine");          // for command lines
//     auto g = aogen::kernel::generate(d, 64, 7, aogen::kernel::scale_law::none);
//     // upload g.data(), g.size() * sizeof(aogen::vec4) bytes
//
// WHY
//   * Same seed, same bits on every compiler, standard library and libm (docs/design.md
//     § Determinism). Random numbers come from aogen/random.hpp's PCG32, never from
//     std::*_distribution. Random points are accepted or rejected in exact integer
//     arithmetic, so every platform keeps the same draws. The cosine kernel uses rejection
//     sampling in the unit disk instead of the usual concentric or polar map, because those
//     need sin/cos, and libm's sin/cos differ by an ulp between libraries. Hammersley points
//     need an angle; it goes through random::cos_sin_turns, a polynomial evaluated with
//     explicit fma, so it is identical everywhere too. Everything else is integer math or
//     one IEEE operation at a time (+, ×, ÷, sqrt are correctly rounded) in double, rounded
//     to float once at the end, with no a·b + c pattern a compiler could fuse differently.
//   * The crytek factor is computed as (N² + 9i²) / (10N²): the same number as
//     0.1 + 0.9·(i/N)², but as one correctly rounded division of exact integers.
//   * A zero-length draw in the crytek kernel (x = y = z = 0, probability 2^-72) would make
//     the normalisation divide by zero; it is redrawn, which keeps the output deterministic.
//   * count is limited to 1..256: more samples than that are better spent on several
//     frames or a different technique, and 256 vec4s is 4 KiB, inside every uniform limit.
#pragma once

#include "error.hpp"
#include "math.hpp"
#include "names.hpp"
#include "random.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::kernel {

inline constexpr int min_count = 1;
inline constexpr int max_count = 256;

enum class distribution { crytek, cosine, hammersley };
enum class scale_law { crytek, none };

// Their names, for command lines and manifests (see names.hpp; to_name and *_from_name below).
inline constexpr std::array<enum_name<distribution>, 3> distribution_names{{
    {distribution::crytek, "crytek"},
    {distribution::cosine, "cosine"},
    {distribution::hammersley, "hammersley"},
}};
inline constexpr std::array<enum_name<scale_law>, 2> scale_law_names{{
    {scale_law::crytek, "crytek"},
    {scale_law::none, "none"},
}};
static_assert(names::distinct(distribution_names) && names::distinct(scale_law_names));

namespace detail {

inline void require_count(int count) { aogen::require_range("kernel count", count, min_count, max_count); }

// The crytek factor of sample `index` of `count`: (N² + 9i²) / (10N²) = 0.1 + 0.9·(i/N)².
// Both integers are below 2^24, so they are exact floats and the division rounds once.
inline float crytek_factor(int index, int count)
{
    const long long n2 = static_cast<long long>(count) * count;
    const long long i2 = static_cast<long long>(index) * index;
    return static_cast<float>(n2 + 9 * i2) / static_cast<float>(10 * n2);
}

inline float scale_factor(scale_law law, int index, int count)
{
    return law == scale_law::crytek ? crytek_factor(index, count) : 1.0f;
}

// Rounds to float; adding +0 turns −0 into +0 so that a zero has one bit pattern.
inline float to_float(double value) { return static_cast<float>(value) + 0.0f; }

// A unit direction in double, scaled by `length` and rounded to float once per component.
inline vec4 scaled_sample(double x, double y, double z, double length)
{
    return {to_float(x * length), to_float(y * length), to_float(z * length), 0.0f};
}

inline constexpr double inverse_fixed_one = 1.0 / 16777216.0; // 2^-24

// Seed 000's direction: (x, y, z) with x, y uniform in [-1, 1) and z uniform in [0, 1), all
// on the 2^-24 grid, normalised. Returns the fixed-point coordinates; redraws (0, 0, 0).
struct box_point {
    int64_t x, y, z;
    uint64_t norm2; // x² + y² + z², exact, > 0
};

inline box_point draw_in_half_box(random::pcg32& rng)
{
    for (;;) {
        const int64_t x = random::draw_signed_fixed(rng); // sequenced: x, y, then z
        const int64_t y = random::draw_signed_fixed(rng);
        const int64_t z = rng.next_u24();
        const auto norm2 = static_cast<uint64_t>(x * x + y * y + z * z); // < 3·2^48: exact
        if (norm2 != 0) return {x, y, z, norm2};
    }
}

// Bit reversal of a 32-bit integer: the base-2 radical inverse of i, as a 0.32 fraction.
constexpr uint32_t reverse_bits(uint32_t v)
{
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

} // namespace detail

// Seed 000's kernel: random direction in the hemisphere times a random length in [0, 1),
// times the crytek factor (scale_law::none leaves the factor out).
inline std::vector<vec4> crytek(int count, uint64_t seed, scale_law law = scale_law::crytek)
{
    detail::require_count(count);
    random::pcg32 rng = random::seeded(seed, random::stream::kernel_crytek);
    std::vector<vec4> samples;
    samples.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        const detail::box_point p = detail::draw_in_half_box(rng);
        const double random_length = rng.next_float(); // drawn after the direction
        const double norm = std::sqrt(static_cast<double>(p.norm2));
        const double length = random_length * detail::scale_factor(law, i, count);
        samples.push_back(detail::scaled_sample(static_cast<double>(p.x) / norm,
                                                static_cast<double>(p.y) / norm,
                                                static_cast<double>(p.z) / norm, length));
    }
    return samples;
}

// Cosine-weighted unit directions (Malley: uniform in the unit disk, lifted), each scaled
// by the law's factor.
inline std::vector<vec4> cosine(int count, uint64_t seed, scale_law law = scale_law::crytek)
{
    detail::require_count(count);
    random::pcg32 rng = random::seeded(seed, random::stream::kernel_cosine);
    std::vector<vec4> samples;
    samples.reserve(static_cast<size_t>(count));
    constexpr uint64_t one_squared = uint64_t{1} << 48;
    for (int i = 0; i < count; ++i) {
        const random::disk_point p = random::draw_in_unit_disk(rng);
        // z² = 1 − x² − y², exactly, in fixed point: (2^48 − norm2) · 2^-48.
        const double z = std::sqrt(static_cast<double>(one_squared - p.norm2)) * detail::inverse_fixed_one;
        samples.push_back(detail::scaled_sample(static_cast<double>(p.x) * detail::inverse_fixed_one,
                                                static_cast<double>(p.y) * detail::inverse_fixed_one, z,
                                                detail::scale_factor(law, i, count)));
    }
    return samples;
}

// Hammersley points (a = i/N, b = radical inverse of i in base 2), Cranley–Patterson
// rotated by a seeded offset (none for seed 0), mapped to cosine-weighted directions:
// azimuth 2πa, disk radius sqrt(b), z = sqrt(1 − b). The index-ordered coordinate is the
// azimuth on purpose: the crytek factor grows with i, and tying it to the azimuth (which
// the per-pixel noise rotation randomises) is harmless, whereas tying it to the elevation
// would point every short sample along the normal and every long one sideways.
// All in 0.32 fixed point, so the rotation ("+ offset mod 1") is exact integer wrapping.
inline std::vector<vec4> hammersley(int count, uint64_t seed, scale_law law = scale_law::crytek)
{
    detail::require_count(count);
    uint32_t offset_a = 0, offset_b = 0;
    if (seed != 0) {
        random::pcg32 rng = random::seeded(seed, random::stream::kernel_hammersley);
        offset_a = rng.next_u32();
        offset_b = rng.next_u32();
    }
    constexpr double inverse_2_16 = 1.0 / 65536.0;
    constexpr double inverse_2_32 = 1.0 / 4294967296.0;
    std::vector<vec4> samples;
    samples.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        const auto index = static_cast<uint32_t>(i);
        // floor(i · 2^32 / N) + offset, wrapping mod 2^32.
        const uint32_t a = static_cast<uint32_t>((uint64_t{index} << 32) / static_cast<uint64_t>(count)) + offset_a;
        const uint32_t b = detail::reverse_bits(index) + offset_b;
        // sqrt(b·2^-32) = sqrt(b)·2^-16, and 1 − b·2^-32 = (2^32 − b)·2^-32: exact arguments.
        const double radius = std::sqrt(static_cast<double>(b)) * inverse_2_16;
        const double z = std::sqrt(static_cast<double>((uint64_t{1} << 32) - b)) * inverse_2_16;
        const random::cos_sin angle = random::cos_sin_turns(static_cast<double>(a) * inverse_2_32);
        samples.push_back(detail::scaled_sample(radius * angle.c, radius * angle.s, z,
                                                detail::scale_factor(law, i, count)));
    }
    return samples;
}

inline std::vector<vec4> generate(distribution kind, int count, uint64_t seed,
                                  scale_law law = scale_law::crytek)
{
    names::require_listed(scale_law_names, law, "kernel scale law");
    switch (kind) {
    case distribution::crytek: return crytek(count, seed, law);
    case distribution::cosine: return cosine(count, seed, law);
    case distribution::hammersley: return hammersley(count, seed, law);
    }
    names::fail_unlisted(distribution_names, kind, "kernel distribution");
}

// ---- names, for command lines and manifests ----

inline std::string_view to_name(distribution kind)
{
    return names::name_of(distribution_names, kind, "kernel distribution");
}

inline distribution distribution_from_name(std::string_view name)
{
    return names::value_of(distribution_names, name, "kernel distribution");
}

inline std::string_view to_name(scale_law law)
{
    return names::name_of(scale_law_names, law, "kernel scale law");
}

inline scale_law scale_law_from_name(std::string_view name)
{
    return names::value_of(scale_law_names, name, "kernel scale law");
}

} // namespace aogen::kernel
