// Tests for aogen/noise.hpp: pinned texels, rotation texels, size errors, byte-exact
// encodings against hand-computed bytes, names, and the r2 tile's stratification.
#include <aogen/noise.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_noise {

namespace noise = aogen::noise;
using aogen::vec4;

using aogen_test::bits_of;

namespace {

const double pi = 3.14159265358979323846;

// The texel's angle in turns, in [0, 1).
double turns_of(vec4 v)
{
    const double turns = std::atan2(static_cast<double>(v.y), static_cast<double>(v.x)) / (2 * pi);
    return turns < 0 ? turns + 1 : turns;
}

double circular_distance(double a, double b)
{
    const double d = std::fabs(a - b);
    return std::fmin(d, 1 - d);
}

// Largest gap between consecutive angles on the circle, in turns.
double largest_gap(const noise::tile& t)
{
    std::vector<double> angles;
    for (const vec4& v : t.texels) angles.push_back(turns_of(v));
    std::sort(angles.begin(), angles.end());
    double gap = angles.front() + 1 - angles.back();
    for (size_t i = 1; i < angles.size(); ++i) gap = std::fmax(gap, angles[i] - angles[i - 1]);
    return gap;
}

// Smallest angle difference between horizontally or vertically adjacent texels of one tile.
double closest_neighbours(const noise::tile& t)
{
    double closest = 1;
    for (int y = 0; y < t.size; ++y)
        for (int x = 0; x < t.size; ++x) {
            if (x + 1 < t.size) closest = std::fmin(closest, circular_distance(turns_of(t.at(x, y)), turns_of(t.at(x + 1, y))));
            if (y + 1 < t.size) closest = std::fmin(closest, circular_distance(turns_of(t.at(x, y)), turns_of(t.at(x, y + 1))));
        }
    return closest;
}

std::vector<uint8_t> bytes(std::initializer_list<int> values)
{
    std::vector<uint8_t> out;
    for (int v : values) out.push_back(static_cast<uint8_t>(v));
    return out;
}

noise::tile one_texel(vec4 v) { return noise::tile{1, {v}}; }

const noise::pattern all_patterns[] = {noise::pattern::random, noise::pattern::r2};
const noise::encoding all_encodings[] = {noise::encoding::rgba32f, noise::encoding::rgba16f, noise::encoding::rg16f,
                                         noise::encoding::rgba8_unorm, noise::encoding::rgba8_snorm};

} // namespace

TEST_CASE("noise golden texels", "[noise]")
{
    // Computed once by this implementation and frozen (see test_kernel.cpp for why).
    const noise::tile t = noise::rotations(4, 0);
    REQUIRE(t.size == 4);
    REQUIRE(t.texels.size() == 16);
    const uint32_t expected[3][2] = {{0x3f7bcf07u, 0xbe38899eu}, {0x3f267e24u, 0x3f4276bbu}, {0xbf43622fu, 0xbf256996u}};
    for (int i = 0; i < 3; ++i) {
        CHECK(bits_of(t.texels[i].x) == expected[i][0]);
        CHECK(bits_of(t.texels[i].y) == expected[i][1]);
    }
    // r2 with seed 0: 16 angles k/16 turn; (0,0) has rank 0, so it is exactly (1, 0).
    const noise::tile r = noise::r2(4, 0);
    CHECK(bits_of(r.at(0, 0).x) == 0x3f800000u);
    CHECK(bits_of(r.at(0, 0).y) == 0x00000000u);
}

TEST_CASE("r2 tile ranks texels by the R2 dither value", "[noise]")
{
    // Independent oracle in double: value(x, y) = fract(x/g + y/g²), g the plastic number;
    // the texel of rank k has angle k/N² turn (seed 0).
    const double g = 1.32471795724474602596;
    for (int size : {2, 3, 4, 8, 16}) {
        const noise::tile t = noise::r2(size, 0);
        std::vector<std::pair<double, int>> ranked;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const double value = x / g + y / (g * g);
                ranked.push_back({value - std::floor(value), y * size + x});
            }
        std::sort(ranked.begin(), ranked.end());
        for (size_t k = 0; k < ranked.size(); ++k) {
            const vec4 v = t.texels[static_cast<size_t>(ranked[k].second)];
            const double expected = 2 * pi * static_cast<double>(k) / (size * size);
            INFO("size " << size << " rank " << k);
            CHECK(v.x == Approx(std::cos(expected)).margin(1e-7));
            CHECK(v.y == Approx(std::sin(expected)).margin(1e-7));
        }
    }
}

TEST_CASE("every texel is a rotation (cos, sin, 0, 1)", "[noise]")
{
    for (auto kind : all_patterns)
        for (int size : {1, 2, 4, 7, 64})
            for (uint64_t seed : {0ull, 1ull, 77ull}) {
                const noise::tile t = noise::generate(kind, size, seed);
                INFO(std::string(noise::to_name(kind)) << " size " << size << " seed " << seed);
                REQUIRE(t.size == size);
                REQUIRE(t.texels.size() == static_cast<size_t>(size * size));
                for (const vec4& v : t.texels) {
                    REQUIRE(std::hypot(static_cast<double>(v.x), static_cast<double>(v.y)) == Approx(1.0).epsilon(1e-6));
                    REQUIRE(v.z == 0.0f);
                    REQUIRE(v.w == 1.0f);
                }
            }
}

TEST_CASE("noise is deterministic, seeds and patterns differ", "[noise]")
{
    for (auto kind : all_patterns) {
        const auto a = noise::generate(kind, 4, 5), again = noise::generate(kind, 4, 5), b = noise::generate(kind, 4, 6);
        CHECK(noise::encode(a, noise::encoding::rgba32f) == noise::encode(again, noise::encoding::rgba32f));
        CHECK(noise::encode(a, noise::encoding::rgba32f) != noise::encode(b, noise::encoding::rgba32f));
    }
    CHECK(noise::encode(noise::rotations(4, 5), noise::encoding::rgba32f) !=
          noise::encode(noise::r2(4, 5), noise::encoding::rgba32f));
    CHECK(noise::encode(noise::rotations(), noise::encoding::rgba32f) ==
          noise::encode(noise::rotations(noise::default_size, 0), noise::encoding::rgba32f));
}

TEST_CASE("random tile angles are uniform", "[noise][statistics]")
{
    // 4096 texels: E[cos] = E[sin] = 0 with Var 1/2: sd of the mean 0.011; 4 sd. Each quarter
    // turn holds Binomial(4096, 1/4): sd 27.7; 4 sd.
    const noise::tile t = noise::rotations(64, 3);
    double sum_c = 0, sum_s = 0;
    int quarters[4] = {};
    for (const vec4& v : t.texels) {
        sum_c += v.x;
        sum_s += v.y;
        ++quarters[std::min(3, static_cast<int>(turns_of(v) * 4))];
    }
    CHECK(std::fabs(sum_c / 4096) < 0.045);
    CHECK(std::fabs(sum_s / 4096) < 0.045);
    for (int q : quarters) CHECK(std::abs(q - 1024) < 111);
}

TEST_CASE("r2 tile angles are stratified, random ones are not", "[noise][statistics]")
{
    // r2: the N² angles are evenly spaced, so the largest gap is exactly 1/N² turn — the
    // smallest possible for N² angles. A random tile's largest gap is larger (for these
    // seeds; for i.i.d. angles the expected largest gap of 16 is about 3.4/16).
    for (int size : {2, 4, 8, 64})
        for (uint64_t seed : {0ull, 3ull, 1000ull}) {
            const double step = 1.0 / (size * size);
            CHECK(largest_gap(noise::r2(size, seed)) == Approx(step).margin(1e-6));
            if (size <= 8) CHECK(largest_gap(noise::rotations(size, seed)) > 1.5 * step);
        }
    // Inside an r2 tile, adjacent texels are at least 0.2 turn apart; a random tile has
    // near-equal neighbours (for these seeds, under 0.05 turn).
    for (int size = 2; size <= 64; ++size)
        for (uint64_t seed : {0ull, 1ull, 2ull})
            REQUIRE(closest_neighbours(noise::r2(size, seed)) > 0.2 - 1e-6);
    for (uint64_t seed : {0ull, 1ull, 2ull}) CHECK(closest_neighbours(noise::rotations(4, seed)) < 0.05);
}

TEST_CASE("noise size outside 1..64 is rejected with the valid range", "[noise]")
{
    for (auto kind : all_patterns)
        for (int size : {0, 65, -3}) {
            try {
                (void)noise::generate(kind, size, 0);
                FAIL("size " << size << " was accepted");
            } catch (const aogen::error& e) {
                const std::string message = e.what();
                CHECK(message.find("noise size") != std::string::npos);
                CHECK(message.find(std::to_string(size)) != std::string::npos);
                CHECK(message.find("1..64") != std::string::npos);
            }
        }
    CHECK_NOTHROW(noise::rotations(1, 0));
    CHECK_NOTHROW(noise::r2(64, 0));
}

TEST_CASE("encodings: bytes computed by hand", "[noise]")
{
    const noise::tile unit_x = one_texel({1, 0, 0, 1});
    CHECK(noise::encode(unit_x, noise::encoding::rgba8_unorm) == bytes({255, 128, 128, 255}));
    CHECK(noise::encode(unit_x, noise::encoding::rgba8_snorm) == bytes({127, 0, 0, 127}));
    CHECK(noise::encode(unit_x, noise::encoding::rgba16f) == bytes({0x00, 0x3c, 0x00, 0x00, 0x00, 0x00, 0x00, 0x3c}));
    CHECK(noise::encode(unit_x, noise::encoding::rg16f) == bytes({0x00, 0x3c, 0x00, 0x00}));
    CHECK(noise::encode(unit_x, noise::encoding::rgba32f) ==
          bytes({0, 0, 0x80, 0x3f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x80, 0x3f}));

    // (−1, 0.5, −0.5, 1): unorm 0, round(191.25) = 191, round(63.75) = 64, 255;
    // snorm −127 = 0x81, round(63.5) = 64, −64 = 0xC0, 127; halves 0xBC00, 0x3800, 0xB800.
    const noise::tile mixed = one_texel({-1, 0.5f, -0.5f, 1});
    CHECK(noise::encode(mixed, noise::encoding::rgba8_unorm) == bytes({0, 191, 64, 255}));
    CHECK(noise::encode(mixed, noise::encoding::rgba8_snorm) == bytes({0x81, 0x40, 0xc0, 0x7f}));
    CHECK(noise::encode(mixed, noise::encoding::rgba16f) == bytes({0x00, 0xbc, 0x00, 0x38, 0x00, 0xb8, 0x00, 0x3c}));
    CHECK(noise::encode(mixed, noise::encoding::rg16f) == bytes({0x00, 0xbc, 0x00, 0x38}));

    // Out of range clamps in the 8-bit encodings; NaN becomes 0 (Vulkan's rule).
    const noise::tile wild = one_texel({2, -3, std::nanf(""), 0.1f});
    CHECK(noise::encode(wild, noise::encoding::rgba8_unorm) == bytes({255, 0, 0, 140})); // 0.55·255 = 140.25
    CHECK(noise::encode(wild, noise::encoding::rgba8_snorm) == bytes({127, 0x81, 0, 13})); // 12.7 → 13
    // 0.1 as a half is 0x2E66 (0.0999755859375, the nearest).
    const auto wild16 = noise::encode(wild, noise::encoding::rg16f);
    CHECK(wild16 == bytes({0x00, 0x40, 0x00, 0xc2}));
}

TEST_CASE("encodings: sizes, texel order and consistency with the texels", "[noise]")
{
    const noise::tile t = noise::rotations(4, 8);
    for (auto format : all_encodings) {
        const auto encoded = noise::encode(t, format);
        CHECK(encoded.size() == 16u * static_cast<size_t>(noise::bytes_per_texel(format)));
    }
    const auto f32 = noise::encode(t, noise::encoding::rgba32f);
    const auto f16 = noise::encode(t, noise::encoding::rgba16f);
    const auto rg = noise::encode(t, noise::encoding::rg16f);
    const auto unorm = noise::encode(t, noise::encoding::rgba8_unorm);
    const auto snorm = noise::encode(t, noise::encoding::rgba8_snorm);
    for (size_t i = 0; i < 16; ++i) {
        const vec4 v = t.texels[i];
        float x;
        std::memcpy(&x, &f32[16 * i], 4); // little-endian host
        CHECK(x == v.x);
        const uint16_t hx = static_cast<uint16_t>(f16[8 * i] | (f16[8 * i + 1] << 8));
        const uint16_t hy = static_cast<uint16_t>(rg[4 * i + 2] | (rg[4 * i + 3] << 8));
        CHECK(hx == aogen::float_to_half(v.x));
        CHECK(hy == aogen::float_to_half(v.y));
        CHECK(std::fabs(aogen::half_to_float(hx) - v.x) <= 0.0005f); // ½ ulp of half below 1
        CHECK(std::fabs(unorm[4 * i] / 255.0 * 2 - 1 - v.x) <= 1.0 / 255 + 1e-9);
        CHECK(unorm[4 * i + 2] == 128);
        CHECK(unorm[4 * i + 3] == 255);
        CHECK(std::fabs(static_cast<int8_t>(snorm[4 * i + 1]) / 127.0 - v.y) <= 0.5 / 127 + 1e-9);
        CHECK(snorm[4 * i + 2] == 0);
        CHECK(snorm[4 * i + 3] == 127);
    }
}

TEST_CASE("encode rejects malformed tiles", "[noise]")
{
    noise::tile bad{2, {vec4{1, 0, 0, 1}}};
    CHECK_THROWS_WITH(noise::encode(bad, noise::encoding::rgba8_unorm),
                      "noise tile texels: 1 texels (valid: size × size = 4)");
    noise::tile empty{0, {}};
    CHECK_THROWS_AS(noise::encode(empty, noise::encoding::rgba32f), aogen::error);
    CHECK_THROWS_AS(noise::encode(noise::rotations(4, 0), static_cast<noise::encoding>(9)), aogen::error);
}

TEST_CASE("noise names round-trip, unknown names list the valid ones", "[noise]")
{
    for (auto kind : all_patterns) CHECK(noise::pattern_from_name(noise::to_name(kind)) == kind);
    for (auto format : all_encodings) CHECK(noise::encoding_from_name(noise::to_name(format)) == format);
    CHECK(noise::to_name(noise::encoding::rgba8_unorm) == "rgba8_unorm");
    CHECK(noise::vulkan_format_name(noise::encoding::rgba16f) == "VK_FORMAT_R16G16B16A16_SFLOAT");
    CHECK(noise::vulkan_format_name(noise::encoding::rg16f) == "VK_FORMAT_R16G16_SFLOAT");
    CHECK(noise::vulkan_format_name(noise::encoding::rgba8_snorm) == "VK_FORMAT_R8G8B8A8_SNORM");
    CHECK(noise::webgpu_format_name(noise::encoding::rgba8_unorm) == "rgba8unorm");
    CHECK_THROWS_WITH(noise::pattern_from_name("blue"), "noise pattern: 'blue' is not a known name (valid: random, r2)");
    CHECK_THROWS_WITH(noise::encoding_from_name("rgba16"),
                      "noise encoding: 'rgba16' is not a known name "
                      "(valid: rgba32f, rgba16f, rg16f, rgba8_unorm, rgba8_snorm)");
    CHECK_THROWS_WITH(noise::encode(noise::rotations(4, 0), static_cast<noise::encoding>(9)),
                      "noise encoding: 9 is not a valid value "
                      "(valid: rgba32f, rgba16f, rg16f, rgba8_unorm, rgba8_snorm)");
    CHECK_THROWS_WITH(noise::generate(static_cast<noise::pattern>(2), 4, 0),
                      "noise pattern: 2 is not a valid value (valid: random, r2)");
}

} // namespace unity_test_noise
