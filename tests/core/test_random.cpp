// Tests for aogen/random.hpp: PCG32 against pcg-c's published demo output, SplitMix64
// against its reference outputs, and the exact sampling primitives.
#include <aogen/random.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <string>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_random {

using aogen::random::pcg32;

TEST_CASE("pcg32 reproduces pcg32_srandom_r(42, 54) from pcg-c's demo", "[random]")
{
    // pcg32-demo, round 1, "32bit:" line.
    pcg32 rng(42u, 54u);
    const uint32_t expected[] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    for (uint32_t value : expected) CHECK(rng.next_u32() == value);

    // The demo goes on with pcg32_boundedrand_r: 65 coins (1 = H), 33 dice rolls.
    std::string coins;
    for (int i = 0; i < 65; ++i) coins += rng.next_below(2) ? 'H' : 'T';
    CHECK(coins == "HHTTTHTHHHTHTTTHHHHHTTTHHHTHTHTHTTHTTTHHHHHHTTTTHHTTTTTHTTTTTTTHT");
    std::string rolls;
    for (int i = 0; i < 33; ++i) rolls += std::to_string(rng.next_below(6) + 1) + ' ';
    CHECK(rolls == "3 4 1 1 2 2 3 2 4 3 2 4 3 3 5 2 3 1 3 1 5 1 4 1 5 6 4 6 6 2 6 3 3 ");

    // Then a 52-card Fisher–Yates shuffle, then round 2's "32bit:" line.
    for (uint32_t i = 52; i > 1; --i) (void)rng.next_below(i);
    const uint32_t round2[] = {0x74ab93adu, 0x1c1da000u, 0x494ff896u,
                               0x34462f2fu, 0xd308a3e5u, 0x0fa83babu};
    for (uint32_t value : round2) CHECK(rng.next_u32() == value);
}

TEST_CASE("splitmix64 matches the reference generator's first outputs", "[random]")
{
    // splitmix64.c with x = 0: next() returns mix(x += golden), twice.
    CHECK(aogen::random::splitmix64(0) == 0xe220a8397b1dcdafull);
    CHECK(aogen::random::splitmix64(0x9e3779b97f4a7c15ull) == 0x6e789e6aa1b965f4ull);
}

TEST_CASE("pcg32 float and 64-bit conversions are defined by the 32-bit stream", "[random]")
{
    pcg32 a(7u, 3u), b(7u, 3u);
    for (int i = 0; i < 1000; ++i) {
        const uint32_t bits = b.next_u32();
        const float value = a.next_float();
        CHECK(value == static_cast<float>(bits >> 8) / 16777216.0f);
        CHECK(value >= 0.0f);
        CHECK(value < 1.0f);
    }
    const uint64_t high = b.next_u32(), low = b.next_u32();
    CHECK(a.next_u64() == ((high << 32) | low));

    // The largest draw stays below 1: (2^24 − 1) · 2^-24.
    CHECK(static_cast<float>(0xffffffu) * (1.0f / 16777216.0f) < 1.0f);
}

TEST_CASE("pcg32 streams and seeds give different sequences", "[random]")
{
    pcg32 a(1u, 1u), b(1u, 2u), c(2u, 1u);
    const uint32_t first = a.next_u32();
    CHECK(first != b.next_u32());
    CHECK(first != c.next_u32());
    auto s0 = aogen::random::seeded(0, aogen::random::stream::kernel_crytek);
    auto s1 = aogen::random::seeded(1, aogen::random::stream::kernel_crytek);
    auto s0_other = aogen::random::seeded(0, aogen::random::stream::noise_random);
    const uint32_t v0 = s0.next_u32();
    CHECK(v0 != s1.next_u32());
    CHECK(v0 != s0_other.next_u32());
}

TEST_CASE("next_below stays in range and hits every value", "[random]")
{
    pcg32 rng(5u);
    int seen[7] = {};
    for (int i = 0; i < 700; ++i) {
        const uint32_t v = rng.next_below(7);
        REQUIRE(v < 7);
        ++seen[v];
    }
    for (int count : seen) CHECK(count > 50);
    CHECK(rng.next_below(1) == 0);
}

TEST_CASE("draw_in_unit_disk returns exact points strictly inside the disk", "[random]")
{
    pcg32 rng(11u);
    double sum_x = 0, sum_y = 0;
    const int n = 20000;
    int inner = 0;
    for (int i = 0; i < n; ++i) {
        const auto p = aogen::random::draw_in_unit_disk(rng);
        REQUIRE(static_cast<uint64_t>(p.x * p.x + p.y * p.y) == p.norm2);
        REQUIRE(p.norm2 > 0);
        REQUIRE(p.norm2 < (uint64_t{1} << 48));
        sum_x += static_cast<double>(p.x) / 16777216.0;
        sum_y += static_cast<double>(p.y) / 16777216.0;
        if (p.norm2 < (uint64_t{1} << 47)) ++inner; // r² < 1/2: half the area
    }
    // Var(x) = 1/4 for the uniform disk: sd of the mean = 0.5/sqrt(n) ≈ 0.0035; 5 sd.
    CHECK(std::fabs(sum_x / n) < 0.018);
    CHECK(std::fabs(sum_y / n) < 0.018);
    // Binomial(n, 1/2): sd = sqrt(n)/2 ≈ 71; 5 sd.
    CHECK(std::abs(inner - n / 2) < 355);
}

TEST_CASE("cos_sin_turns agrees with libm and is exact at quarter turns", "[random]")
{
    using aogen::random::cos_sin_turns;
    const double pi = 3.14159265358979323846;
    double worst = 0;
    for (int i = 0; i <= 20000; ++i) {
        const double turns = -1.0 + 3.0 * i / 20000.0; // also negative and > 1
        const auto cs = cos_sin_turns(turns);
        const double angle = 2 * pi * turns;
        worst = std::fmax(worst, std::fabs(cs.c - std::cos(angle)));
        worst = std::fmax(worst, std::fabs(cs.s - std::sin(angle)));
    }
    // libm's own argument 2π·t carries up to ~2e-15 of error for |t| ≤ 2.
    CHECK(worst < 4e-15);

    CHECK(cos_sin_turns(0.0).c == 1.0);
    CHECK(cos_sin_turns(0.0).s == 0.0);
    CHECK(cos_sin_turns(0.25).c == 0.0);
    CHECK(cos_sin_turns(0.25).s == 1.0);
    CHECK(cos_sin_turns(0.5).c == -1.0);
    CHECK(cos_sin_turns(0.75).s == -1.0);
    // cos(π/4) = sin(π/4) = sqrt(1/2), within an ulp.
    CHECK(std::fabs(cos_sin_turns(0.125).c - std::sqrt(0.5)) < 2e-16);
    CHECK(std::fabs(cos_sin_turns(0.125).s - std::sqrt(0.5)) < 2e-16);
    // sin(π/6) = 1/2.
    CHECK(std::fabs(cos_sin_turns(1.0 / 12.0).s - 0.5) < 2e-16);
}

} // namespace unity_test_random
