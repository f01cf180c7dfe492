// Tests for aogen/half.hpp: known encodings, then a comparison with the compiler's own
// _Float16 conversions (correctly rounded, from libgcc or the hardware) where it has them.
#include <aogen/half.hpp>
#include <aogen/random.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_half {

using aogen::float_to_half;
using aogen::half_to_float;

using aogen_test::bits_of;
using aogen_test::float_from_bits;

namespace {

bool half_is_nan(uint16_t h) { return (h & 0x7c00u) == 0x7c00u && (h & 0x03ffu) != 0; }

} // namespace

TEST_CASE("float_to_half: known encodings", "[half]")
{
    CHECK(float_to_half(1.0f) == 0x3c00);
    CHECK(float_to_half(0.5f) == 0x3800);
    CHECK(float_to_half(-2.0f) == 0xc000);
    CHECK(float_to_half(0.0f) == 0x0000);
    CHECK(float_to_half(-0.0f) == 0x8000);
    CHECK(float_to_half(65504.0f) == 0x7bff);               // largest half
    CHECK(float_to_half(65519.99609375f) == 0x7bff);        // just below the overflow tie
    CHECK(float_to_half(65520.0f) == 0x7c00);               // tie, 0x7bff is odd → inf
    CHECK(float_to_half(-1e9f) == 0xfc00);
    CHECK(float_to_half(std::numeric_limits<float>::infinity()) == 0x7c00);
    CHECK(float_to_half(-std::numeric_limits<float>::infinity()) == 0xfc00);
    CHECK(float_to_half(std::ldexp(1.0f, -14)) == 0x0400);  // smallest normal
    CHECK(float_to_half(std::ldexp(1.0f, -24)) == 0x0001);  // smallest subnormal
    CHECK(float_to_half(std::ldexp(1.0f, -25)) == 0x0000);  // tie between 0 and 1 → 0
    CHECK(float_to_half(std::nextafter(std::ldexp(1.0f, -25), 1.0f)) == 0x0001);
    CHECK(float_to_half(std::ldexp(1.5f, -24)) == 0x0002);  // tie 1.5 → 2 (even)
    CHECK(float_to_half(std::ldexp(2.5f, -24)) == 0x0002);  // tie 2.5 → 2 (even)
    CHECK(float_to_half(std::ldexp(1023.5f, -24)) == 0x0400); // subnormal rounds up to normal
    CHECK(float_to_half(1.0f + std::ldexp(1.0f, -11)) == 0x3c00);     // tie → even
    CHECK(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)) == 0x3c02); // tie → even
    CHECK(float_to_half(1e-10f) == 0x0000);
    CHECK(float_to_half(-1e-10f) == 0x8000);
    CHECK(float_to_half(0.1f) == 0x2e66);
}

TEST_CASE("float_to_half: NaN stays a quiet NaN with its sign", "[half]")
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (uint32_t bits : {bits_of(nan), bits_of(-nan), 0x7f800001u, 0xff800001u, 0x7fc00000u,
                          0x7fbfffffu, 0x7f802000u}) {
        const uint16_t h = float_to_half(float_from_bits(bits));
        CHECK(half_is_nan(h));
        CHECK((h & 0x0200u) != 0);                            // quiet bit
        CHECK((h & 0x8000u) == ((bits >> 16) & 0x8000u));      // sign kept
    }
}

TEST_CASE("half_to_float: known values, and every half round-trips", "[half]")
{
    CHECK(half_to_float(0x3c00) == 1.0f);
    CHECK(half_to_float(0x3800) == 0.5f);
    CHECK(half_to_float(0x7bff) == 65504.0f);
    CHECK(half_to_float(0x0001) == std::ldexp(1.0f, -24));
    CHECK(half_to_float(0x03ff) == std::ldexp(1023.0f, -24));
    CHECK(half_to_float(0x0400) == std::ldexp(1.0f, -14));
    CHECK(std::isinf(half_to_float(0x7c00)));
    CHECK(half_to_float(0xfc00) < 0);
    CHECK(std::signbit(half_to_float(0x8000)));
    CHECK(std::isnan(half_to_float(0x7e00)));

    for (uint32_t h = 0; h <= 0xffff; ++h) {
        const auto half = static_cast<uint16_t>(h);
        const float value = half_to_float(half);
        if (half_is_nan(half)) {
            REQUIRE(std::isnan(value));
            const uint16_t back = float_to_half(value);
            REQUIRE(half_is_nan(back));
            REQUIRE((back & 0x8000u) == (half & 0x8000u));
            // A quiet NaN keeps its payload exactly.
            if (half & 0x0200u) REQUIRE(back == half);
        } else {
            REQUIRE(float_to_half(value) == half);
        }
    }
}

#ifdef __FLT16_MANT_DIG__

namespace {

uint16_t compiler_float_to_half(float value)
{
    volatile float in = value; // convert at run time, not by constant folding
    const _Float16 h = static_cast<_Float16>(in);
    uint16_t bits;
    std::memcpy(&bits, &h, sizeof bits);
    return bits;
}

float compiler_half_to_float(uint16_t bits)
{
    _Float16 h;
    std::memcpy(&h, &bits, sizeof h);
    volatile _Float16 in = h;
    return static_cast<float>(in);
}

// Same half, or both NaN with the same sign (payload handling may differ).
bool same_half(uint16_t ours, uint16_t theirs)
{
    if (half_is_nan(theirs)) return half_is_nan(ours) && (ours & 0x8000u) == (theirs & 0x8000u);
    return ours == theirs;
}

} // namespace

TEST_CASE("half_to_float matches _Float16 for all 2^16 halves", "[half]")
{
    for (uint32_t h = 0; h <= 0xffff; ++h) {
        const auto half = static_cast<uint16_t>(h);
        const float ours = half_to_float(half), theirs = compiler_half_to_float(half);
        if (std::isnan(theirs)) {
            REQUIRE(std::isnan(ours));
            REQUIRE(std::signbit(ours) == std::signbit(theirs));
        } else {
            REQUIRE(bits_of(ours) == bits_of(theirs));
        }
    }
}

TEST_CASE("float_to_half matches _Float16 near every half and its rounding boundaries", "[half]")
{
    // For every finite half h ≥ 0: the float of h and of the midpoint to the next half
    // (an exact tie), each with its float neighbours up to 3 ulps away, both signs.
    // This covers every tie, every subnormal and the overflow threshold 65520.
    long checked = 0;
    for (uint32_t h = 0; h < 0x7c00; ++h) {
        const float here = half_to_float(static_cast<uint16_t>(h));
        const float next = half_to_float(static_cast<uint16_t>(h + 1)); // 0x7c00 → inf
        const float midpoint = std::isinf(next) ? 65520.0f : (here + next) * 0.5f;
        for (float center : {here, midpoint}) {
            const uint32_t center_bits = bits_of(center);
            for (int delta = -3; delta <= 3; ++delta) {
                if (center_bits == 0 && delta < 0) continue;
                const uint32_t bits = center_bits + static_cast<uint32_t>(delta);
                for (uint32_t sign : {0u, 0x80000000u}) {
                    const float value = float_from_bits(bits | sign);
                    REQUIRE(same_half(float_to_half(value), compiler_float_to_half(value)));
                    ++checked;
                }
            }
        }
    }
    CHECK(checked > 800000);
}

TEST_CASE("float_to_half matches _Float16 on special and random floats", "[half]")
{
    const float inf = std::numeric_limits<float>::infinity();
    for (float value : {0.0f, -0.0f, inf, -inf, std::numeric_limits<float>::quiet_NaN(),
                        -std::numeric_limits<float>::quiet_NaN(), float_from_bits(0x7f800001u),
                        std::numeric_limits<float>::max(), std::numeric_limits<float>::min(),
                        std::numeric_limits<float>::denorm_min(), 65504.0f, 65520.0f, 65536.0f,
                        1e-8f, 3e-8f, 6e-8f, 0.1f, 1.0f / 3.0f})
        CHECK(same_half(float_to_half(value), compiler_float_to_half(value)));

    // 2^21 random bit patterns over all floats, and 2^21 within the half range.
    aogen::random::pcg32 rng(2024u, 16u);
    for (int i = 0; i < (1 << 21); ++i) {
        const float any = float_from_bits(rng.next_u32());
        REQUIRE(same_half(float_to_half(any), compiler_float_to_half(any)));
        // exponents 100..143 cover zero-rounding, subnormal, normal and overflow halves
        const uint32_t bits = rng.next_u32();
        const uint32_t exponent = 100u + (bits >> 23) % 44u;
        const float near = float_from_bits((bits & 0x807fffffu) | (exponent << 23));
        REQUIRE(same_half(float_to_half(near), compiler_float_to_half(near)));
    }
}

#endif // __FLT16_MANT_DIG__

} // namespace unity_test_half
