// aogen/random.hpp — deterministic random numbers and the sampling primitives built on them.
//
// WHAT
//   aogen::random::pcg32      O'Neill's PCG32 (64-bit LCG state, XSH RR output), seeded
//                             exactly like pcg-c's pcg32_srandom_r(initstate, initseq).
//   aogen::random::splitmix64 Vigna's SplitMix64 finaliser, used to spread user seeds.
//   aogen::random::seeded     a pcg32 for (user seed, purpose stream): what kernels and noise use.
//   draw_in_unit_disk         a point strictly inside the unit disk, in exact fixed point.
//   cos_sin_turns             (cos 2πt, sin 2πt) with only +, ×, fma: the same bits everywhere.
//
// USAGE
//     #include <aogen/random.hpp>
//     aogen::random::pcg32 rng(42u, 54u);     // == pcg32_srandom_r(&rng, 42u, 54u)
//     uint32_t bits = rng.next_u32();         // 0xa15c02b7, the reference first output
//     float u = rng.next_float();             // in [0, 1), a multiple of 2^-24
//
//     auto rng2 = aogen::random::seeded(user_seed, aogen::random::stream::kernel_cosine);
//     aogen::random::disk_point p = aogen::random::draw_in_unit_disk(rng2);
//
// WHY
//   * Same inputs, same bytes (docs/design.md § Determinism). std::mt19937 is portable, but every
//     std::uniform_*_distribution is implementation-defined: libstdc++, libc++ and MSVC
//     turn the same engine output into different numbers. So aogen owns the whole chain:
//     the generator (PCG32, small and well tested), the float conversion (top 24 bits
//     × 2^-24, exact, never rounds up to 1) and every transform after it.
//   * libm's sin/cos/cbrt are not required to be correctly rounded and do differ by an ulp
//     between glibc, musl, macOS and MSVC. The sampling code therefore uses only integer
//     arithmetic, IEEE +, −, ×, ÷, sqrt (all correctly rounded), and std::fma, which the C
//     and C++ standards define as one rounding of the exact a·b + c. cos_sin_turns is a
//     Taylor polynomial evaluated with explicit fma, so a compiler that contracts a·b + c
//     into an fma on its own (GCC's default on AArch64) has nothing left to contract.
//   * Assumed: IEEE binary32/binary64 evaluated at their own precision (FLT_EVAL_METHOD 0:
//     every x86-64, AArch64 and RISC-V compiler; not 32-bit x87 code). The kernel and noise
//     tests' pinned bits pass unchanged with GCC and Clang at -O0 and at -O3 -march=native
//     -ffp-contract=fast (hardware FMA, contraction allowed).
#pragma once

#include <cmath>
#include <cstdint>

namespace aogen::random {

// SplitMix64's output function (Steele, Lea, Flood 2014; Vigna's constants): a bijection on
// 64-bit integers that turns nearby seeds (0, 1, 2, ...) into unrelated ones.
constexpr uint64_t splitmix64(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// PCG32: pcg32_random_r / pcg32_srandom_r from pcg-c, bit for bit.
class pcg32 {
public:
    static constexpr uint64_t multiplier = 6364136223846793005ull;

    // pcg32_srandom_r(initstate = seed, initseq = stream). Streams select one of 2^63
    // distinct sequences; the top bit of `stream` is irrelevant (inc = stream·2 + 1). The
    // default stream is the one of pcg-c's PCG32_INITIALIZER (inc 0xda3e39cb94b95bdb).
    constexpr explicit pcg32(uint64_t seed, uint64_t stream = 0xda3e39cb94b95bdbull >> 1)
        : state_(0), increment_((stream << 1u) | 1u)
    {
        step();
        state_ += seed;
        step();
    }

    // Next 32 random bits: XSH RR of the state before stepping.
    constexpr uint32_t next_u32()
    {
        const uint64_t old_state = state_;
        step();
        const auto xorshifted = static_cast<uint32_t>(((old_state >> 18u) ^ old_state) >> 27u);
        const auto rotation = static_cast<uint32_t>(old_state >> 59u);
        return (xorshifted >> rotation) | (xorshifted << ((32u - rotation) & 31u));
    }

    // Two draws, the first one in the high half (the order is part of the contract).
    constexpr uint64_t next_u64()
    {
        const uint64_t high = next_u32();
        const uint64_t low = next_u32();
        return (high << 32u) | low;
    }

    // Top 24 bits: an integer in [0, 2^24), every value equally likely.
    constexpr uint32_t next_u24() { return next_u32() >> 8u; }

    // Uniform in [0, 1) on the grid k·2^-24. 24 bits fit a float's significand, so the
    // conversion is exact and the result can never round up to 1.0f.
    constexpr float next_float() { return static_cast<float>(next_u24()) * (1.0f / 16777216.0f); }

    // Uniform integer in [0, bound), bound ≥ 1, without modulo bias (pcg32_boundedrand_r).
    constexpr uint32_t next_below(uint32_t bound)
    {
        const uint32_t threshold = (0u - bound) % bound;
        for (;;) {
            const uint32_t r = next_u32();
            if (r >= threshold) return r % bound;
        }
    }

private:
    constexpr void step() { state_ = state_ * multiplier + increment_; }

    uint64_t state_;
    uint64_t increment_;
};

// One stream per purpose, so that the same user seed gives independent kernels and noise
// (the values are arbitrary and frozen: changing one changes generated data).
namespace stream {
inline constexpr uint64_t kernel_crytek = 0x6b65726e656c3031ull;     // "kernel01"
inline constexpr uint64_t kernel_cosine = 0x6b65726e656c3032ull;     // "kernel02"
inline constexpr uint64_t kernel_hammersley = 0x6b65726e656c3033ull; // "kernel03"
inline constexpr uint64_t noise_random = 0x6e6f697365303031ull;      // "noise001"
inline constexpr uint64_t noise_r2 = 0x6e6f697365303032ull;          // "noise002"
} // namespace stream

// The generator aogen uses for a user-facing seed: the seed goes through splitmix64 first
// so that seeds 0, 1, 2, ... start far apart.
constexpr pcg32 seeded(uint64_t seed, uint64_t purpose_stream)
{
    return pcg32(splitmix64(seed), purpose_stream);
}

// Fixed point with 24 fraction bits: a coordinate c stands for c · 2^-24.
inline constexpr int64_t fixed_one = int64_t{1} << 24;

// Uniform in [-1, 1) as fixed point: an integer in [-2^24, 2^24), step 2 (exact).
constexpr int64_t draw_signed_fixed(pcg32& rng)
{
    return 2 * static_cast<int64_t>(rng.next_u24()) - fixed_one;
}

// A point of the unit disk, in fixed point: (x, y) · 2^-24, with x² + y² = norm2 exactly.
struct disk_point {
    int64_t x = 0, y = 0;
    uint64_t norm2 = 0; // in (0, 2^48): strictly inside the disk, never the centre
};

// Uniform point strictly inside the unit disk, by rejection from the square [-1, 1)².
// Integer arithmetic decides acceptance, so the same draws are accepted everywhere; the
// centre is rejected too, so the point can always be normalised. Expected 1.27 tries.
constexpr disk_point draw_in_unit_disk(pcg32& rng)
{
    constexpr uint64_t one_squared = uint64_t{1} << 48;
    for (;;) {
        const int64_t x = draw_signed_fixed(rng); // sequenced: x is drawn before y
        const int64_t y = draw_signed_fixed(rng);
        const auto norm2 = static_cast<uint64_t>(x * x + y * y);
        if (norm2 > 0 && norm2 < one_squared) return {x, y, norm2};
    }
}

// cos and sin of a whole angle.
struct cos_sin {
    double c = 1, s = 0;
};

// (cos 2πt, sin 2πt) for any finite t (in turns), to about 1 ulp of double, with the same
// bits on every platform: reduce to the nearest quarter turn (exact), evaluate Taylor
// polynomials on |angle| ≤ π/4 by Horner with explicit fma, then rotate by whole quarter
// turns (swaps and negations only). Rounded to float, the results are the correctly
// rounded cos/sin in all but rare near-tie cases — and, more importantly, identical everywhere.
inline cos_sin cos_sin_turns(double turns)
{
    const double quarters = turns * 4.0;                 // exact (power of two)
    const double nearest = std::floor(quarters + 0.5);   // nearest quarter turn
    const double remainder = quarters - nearest;         // exact, in [-0.5, 0.5]
    constexpr double half_pi = 1.5707963267948966192;
    const double a = remainder * half_pi;                // |a| ≤ π/4
    const double a2 = a * a;

    // 1/n! for n = 2..18; |a|^19/19! < 1e-19, far below double's ulp of 1.
    constexpr double f2 = 1.0 / 2, f3 = f2 / 3, f4 = f3 / 4, f5 = f4 / 5, f6 = f5 / 6,
                     f7 = f6 / 7, f8 = f7 / 8, f9 = f8 / 9, f10 = f9 / 10, f11 = f10 / 11,
                     f12 = f11 / 12, f13 = f12 / 13, f14 = f13 / 14, f15 = f14 / 15,
                     f16 = f15 / 16, f17 = f16 / 17, f18 = f17 / 18;

    double sin_poly = f17;    // sin a = a + a³·(−1/3! + a²/5! − a⁴/7! + ...)
    sin_poly = std::fma(sin_poly, a2, -f15);
    sin_poly = std::fma(sin_poly, a2, f13);
    sin_poly = std::fma(sin_poly, a2, -f11);
    sin_poly = std::fma(sin_poly, a2, f9);
    sin_poly = std::fma(sin_poly, a2, -f7);
    sin_poly = std::fma(sin_poly, a2, f5);
    sin_poly = std::fma(sin_poly, a2, -f3);
    const double sin_a = std::fma(sin_poly, a2 * a, a);  // a + a³·(...), one rounding

    double cos_poly = f18;    // cos a = 1 − a²/2! + a⁴/4! − ...
    cos_poly = std::fma(cos_poly, a2, -f16);
    cos_poly = std::fma(cos_poly, a2, f14);
    cos_poly = std::fma(cos_poly, a2, -f12);
    cos_poly = std::fma(cos_poly, a2, f10);
    cos_poly = std::fma(cos_poly, a2, -f8);
    cos_poly = std::fma(cos_poly, a2, f6);
    cos_poly = std::fma(cos_poly, a2, -f4);
    cos_poly = std::fma(cos_poly, a2, f2);
    const double cos_a = std::fma(-cos_poly, a2, 1.0);

    // Rotate by `nearest` quarter turns: (c, s) → (−s, c) per quarter.
    const double quarter = nearest - 4.0 * std::floor(nearest * 0.25); // 0..3, exact
    if (quarter == 0.0) return {cos_a, sin_a};
    if (quarter == 1.0) return {-sin_a, cos_a};
    if (quarter == 2.0) return {-cos_a, -sin_a};
    return {sin_a, -cos_a};
}

} // namespace aogen::random
