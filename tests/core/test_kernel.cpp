// Tests for aogen/kernel.hpp: pinned bits, the seeds' length law for every distribution,
// errors, names, and statistics of the cosine-weighted directions.
#include <aogen/kernel.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_kernel {

namespace kernel = aogen::kernel;
using aogen::vec4;

using aogen_test::bits_of;

namespace {

double length_of(vec4 v)
{
    const double x = v.x, y = v.y, z = v.z;
    return std::sqrt(x * x + y * y + z * z);
}

double crytek_factor(int i, int n)
{
    const double t = static_cast<double>(i) / n;
    return 0.1 + 0.9 * t * t;
}

struct bits3 {
    uint32_t x, y, z;
};

void check_bits(const std::vector<vec4>& samples, std::initializer_list<bits3> expected)
{
    size_t i = 0;
    for (const bits3& e : expected) {
        INFO("sample " << i);
        CHECK(bits_of(samples[i].x) == e.x);
        CHECK(bits_of(samples[i].y) == e.y);
        CHECK(bits_of(samples[i].z) == e.z);
        CHECK(bits_of(samples[i].w) == 0u);
        ++i;
    }
}

const kernel::distribution all_distributions[] = {kernel::distribution::crytek, kernel::distribution::cosine,
                                                  kernel::distribution::hammersley};

} // namespace

// Bits computed once by this implementation and frozen: any change to the generator,
// the draw order or the arithmetic changes every kernel users have baked, so it must show.
TEST_CASE("kernel golden bits", "[kernel]")
{
    check_bits(kernel::crytek(16, 0), {{0x3c1a01c6u, 0x3bc690bfu, 0x3c1dcb7fu},
                                       {0x3cd78934u, 0x3ceab7bcu, 0x3c79d300u},
                                       {0x3da32788u, 0x3d68b24au, 0x3c1b0564u}});
    check_bits(kernel::cosine(16, 0), {{0xbd0af4a3u, 0xbdb0a203u, 0x3d19d71cu},
                                       {0x3d243cb9u, 0x3d5afc32u, 0x3da1e6a4u},
                                       {0xbd7ac6f0u, 0x3c44e637u, 0x3dc38d85u}});
    check_bits(kernel::hammersley(16, 0), {{0x00000000u, 0x00000000u, 0x3dcccccdu},
                                           {0x3d8a7ee5u, 0x3ce57797u, 0x3d95e819u},
                                           {0x3d252e1eu, 0x3d252e1eu, 0x3dca4db5u}});
    check_bits(kernel::hammersley(16, 7), {{0x3daf63a1u, 0x3b5a52dbu, 0x3d530bd8u},
                                           {0x3d3a80cbu, 0x3cabc832u, 0x3db97b92u},
                                           {0x3d9d66e2u, 0x3daa24b3u, 0x3c6887c1u}});
}

TEST_CASE("hammersley with seed 0 is the plain Hammersley set, mapped cosine-weighted", "[kernel]")
{
    // Independent oracle in double with libm: sample i has azimuth 2π·i/N, squared disk
    // radius b = radical inverse of i in base 2, z = sqrt(1 − b), times the crytek factor.
    const int n = 64;
    const auto samples = kernel::hammersley(n, 0, kernel::scale_law::crytek);
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < n; ++i) {
        double b = 0, digit = 0.5;
        for (int k = i; k > 0; k >>= 1, digit *= 0.5)
            if (k & 1) b += digit;
        const double azimuth = 2 * pi * i / n, radius = std::sqrt(b), f = crytek_factor(i, n);
        INFO("sample " << i);
        CHECK(samples[i].x == Approx(radius * std::cos(azimuth) * f).margin(1e-7));
        CHECK(samples[i].y == Approx(radius * std::sin(azimuth) * f).margin(1e-7));
        CHECK(samples[i].z == Approx(std::sqrt(1 - b) * f).margin(1e-7));
    }
    // Sample 0 points along the normal with length 0.1 exactly (as a float).
    CHECK(samples[0].x == 0.0f);
    CHECK(samples[0].y == 0.0f);
    CHECK(samples[0].z == 0.1f);
}

TEST_CASE("every distribution obeys seed 000's law with the crytek scale", "[kernel]")
{
    for (auto kind : all_distributions) {
        for (int count : {1, 2, 7, 16, 64, 256}) {
            for (uint64_t seed : {0ull, 1ull, 12345ull, 0xffffffffffffffffull}) {
                const auto samples = kernel::generate(kind, count, seed, kernel::scale_law::crytek);
                INFO(std::string(kernel::to_name(kind)) << " count " << count << " seed " << seed);
                REQUIRE(samples.size() == static_cast<size_t>(count));
                double shortest = 1e9, longest = 0;
                for (int i = 0; i < count; ++i) {
                    const vec4 s = samples[i];
                    REQUIRE(std::isfinite(s.x));
                    REQUIRE(std::isfinite(s.y));
                    REQUIRE(s.z >= 0.0f);
                    REQUIRE(s.w == 0.0f);
                    const double length = length_of(s);
                    REQUIRE(length <= crytek_factor(i, count) + 1e-6);
                    shortest = std::fmin(shortest, length);
                    longest = std::fmax(longest, length);
                }
                if (count >= 2 && kind != kernel::distribution::hammersley) CHECK(shortest < longest);
            }
        }
    }
}

TEST_CASE("cosine and hammersley lengths are exactly the crytek factor", "[kernel]")
{
    for (auto kind : {kernel::distribution::cosine, kernel::distribution::hammersley}) {
        const auto samples = kernel::generate(kind, 32, 3);
        for (int i = 0; i < 32; ++i) CHECK(length_of(samples[i]) == Approx(crytek_factor(i, 32)).epsilon(1e-6));
    }
}

TEST_CASE("scale_law::none: unit directions, or the crytek kernel's own random lengths", "[kernel]")
{
    for (auto kind : {kernel::distribution::cosine, kernel::distribution::hammersley})
        for (const vec4& s : kernel::generate(kind, 64, 9, kernel::scale_law::none)) {
            CHECK(length_of(s) == Approx(1.0).epsilon(1e-6));
            CHECK(s.z >= 0.0f);
        }
    // crytek: a random length in [0, 1) each, so spread over (0, 1).
    const auto crytek = kernel::crytek(256, 9, kernel::scale_law::none);
    double sum = 0;
    for (const vec4& s : crytek) {
        const double length = length_of(s);
        CHECK(length < 1.0);
        sum += length;
    }
    // Mean of U[0,1) over 256: 0.5 ± 0.018 (sd); 5 sd.
    CHECK(std::fabs(sum / 256 - 0.5) < 0.09);
}

TEST_CASE("kernels are deterministic, seeds and distributions differ", "[kernel]")
{
    for (auto kind : all_distributions) {
        const auto a = kernel::generate(kind, 16, 1), again = kernel::generate(kind, 16, 1);
        const auto b = kernel::generate(kind, 16, 2);
        CHECK(std::memcmp(a.data(), again.data(), a.size() * sizeof(vec4)) == 0);
        CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(vec4)) != 0);
    }
    const auto crytek = kernel::crytek(16, 1), cosine = kernel::cosine(16, 1);
    CHECK(std::memcmp(crytek.data(), cosine.data(), crytek.size() * sizeof(vec4)) != 0);
    // The named functions and generate() agree.
    const auto direct = kernel::hammersley(8, 4, kernel::scale_law::none);
    const auto generated = kernel::generate(kernel::distribution::hammersley, 8, 4, kernel::scale_law::none);
    CHECK(std::memcmp(direct.data(), generated.data(), direct.size() * sizeof(vec4)) == 0);
    // The kernel of count N is not a prefix of a longer one (the factor depends on N).
    CHECK(kernel::crytek(8, 1)[7].x != kernel::crytek(16, 1)[7].x);
}

TEST_CASE("kernel count outside 1..256 is rejected with the valid range", "[kernel]")
{
    for (auto kind : all_distributions) {
        for (int count : {0, 257, -1, 100000}) {
            try {
                (void)kernel::generate(kind, count, 0);
                FAIL("count " << count << " was accepted");
            } catch (const aogen::error& e) {
                const std::string message = e.what();
                CHECK(message.find("kernel count") != std::string::npos);
                CHECK(message.find(std::to_string(count)) != std::string::npos);
                CHECK(message.find("1..256") != std::string::npos);
            }
        }
    }
    CHECK_THROWS_AS(kernel::crytek(0, 0), aogen::error);
    CHECK_NOTHROW(kernel::crytek(1, 0));
    CHECK_NOTHROW(kernel::crytek(256, 0));
}

TEST_CASE("kernel names round-trip, unknown names list the valid ones", "[kernel]")
{
    for (auto kind : all_distributions) CHECK(kernel::distribution_from_name(kernel::to_name(kind)) == kind);
    CHECK(kernel::to_name(kernel::distribution::crytek) == "crytek");
    CHECK(kernel::to_name(kernel::distribution::cosine) == "cosine");
    CHECK(kernel::to_name(kernel::distribution::hammersley) == "hammersley");
    CHECK(kernel::scale_law_from_name("crytek") == kernel::scale_law::crytek);
    CHECK(kernel::scale_law_from_name("none") == kernel::scale_law::none);
    CHECK(kernel::to_name(kernel::scale_law::none) == "none");

    CHECK_THROWS_WITH(kernel::distribution_from_name("Crytek"),
                      "kernel distribution: 'Crytek' is not a known name (valid: crytek, cosine, hammersley)");
    CHECK_THROWS_WITH(kernel::scale_law_from_name(""),
                      "kernel scale law: '' is not a known name (valid: crytek, none)");
    CHECK_THROWS_WITH(kernel::generate(static_cast<kernel::distribution>(42), 16, 0),
                      "kernel distribution: 42 is not a valid value (valid: crytek, cosine, hammersley)");
    CHECK_THROWS_WITH(kernel::generate(kernel::distribution::crytek, 16, 0, static_cast<kernel::scale_law>(5)),
                      "kernel scale law: 5 is not a valid value (valid: crytek, none)");
    CHECK_THROWS_WITH(kernel::to_name(static_cast<kernel::distribution>(-1)),
                      "kernel distribution: -1 is not a valid value (valid: crytek, cosine, hammersley)");
}

TEST_CASE("cosine kernel: directions are cosine-weighted", "[kernel][statistics]")
{
    // For p(ω) = cos θ / π: E[z] = 2/3, Var[z] = 1/2 − 4/9 = 1/18, E[x] = E[y] = 0 with
    // Var = 1/4, and z² = 1 − r² is uniform on [0, 1]. 8 seeds × 256 samples = 2048
    // directions: sd of mean z = sqrt(1/18/2048) = 0.0052, of mean x = 0.011. Bounds: 4 sd.
    const int seeds = 8, count = 256, n = seeds * count;
    double sum_x = 0, sum_y = 0, sum_z = 0;
    int below_half = 0;
    for (uint64_t seed = 1; seed <= static_cast<uint64_t>(seeds); ++seed) {
        for (const vec4& s : kernel::cosine(count, seed)) {
            const double length = length_of(s);
            const double z = s.z / length;
            sum_x += s.x / length;
            sum_y += s.y / length;
            sum_z += z;
            if (z * z < 0.5) ++below_half;
        }
    }
    CHECK(std::fabs(sum_z / n - 2.0 / 3.0) < 0.021);
    CHECK(std::fabs(sum_x / n) < 0.045);
    CHECK(std::fabs(sum_y / n) < 0.045);
    // Binomial(2048, 1/2): sd 22.6; 4 sd.
    CHECK(std::abs(below_half - n / 2) < 91);
}

TEST_CASE("hammersley kernel: low discrepancy shows in its moments", "[kernel][statistics]")
{
    // No randomness to average out: 256 stratified points get E[z] = 2/3 far closer than
    // random directions (whose sd would be 0.015 for one kernel of 256).
    for (uint64_t seed : {0ull, 1ull, 2ull}) {
        double sum_x = 0, sum_y = 0, sum_z = 0;
        for (const vec4& s : kernel::hammersley(256, seed, kernel::scale_law::none)) {
            sum_x += s.x;
            sum_y += s.y;
            sum_z += s.z;
        }
        CHECK(std::fabs(sum_z / 256 - 2.0 / 3.0) < 0.002);
        CHECK(std::fabs(sum_x / 256) < 0.002);
        CHECK(std::fabs(sum_y / 256) < 0.002);
    }
}

} // namespace unity_test_kernel
