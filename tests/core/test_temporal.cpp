// aogen/temporal.hpp: the frame index's turns of the noise and moves of the slice steps,
// against their definitions — the base-2 radical inverse written out by hand, the
// stratification that makes turns and steps a (0, 2)-sequence, a whole slice period, exact
// (1, 0) and 0 at frame 0 — and the uniform members they reach.
#include <aogen/chain_inputs.hpp>
#include <aogen/layout.hpp>
#include <aogen/plan.hpp>
#include <aogen/temporal.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_temporal {

using namespace aogen;

namespace {

float float_at(const std::vector<uint8_t>& bytes, size_t offset)
{
    float f;
    std::memcpy(&f, bytes.data() + offset, sizeof f);
    return f;
}

uint32_t bits_of(float f)
{
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

size_t offset_of(const layout::block_desc& block, const std::string& member)
{
    for (const layout::member_layout& m : layout::compute(block, layout::rules::std140).members)
        if (m.name == member) return m.offset;
    FAIL("no member " << member);
    return 0;
}

} // namespace

TEST_CASE("temporal: frame 0 is the still frame (1 and 0) to the bit for every variant and sequence", "[temporal]")
{
    for (const char* name : {"gtao-2x3-half-bilateral-gbufworld-std-persp-cs", "vbao-7x3-full-noblur-recon-std-persp-cs",
                             "ssao-s16-half-bilateral-gbufworld-std-persp-cs", "sao-s16-half-denoise-gbufworld-std-persp-cs"})
        for (temporal::sequence s : {temporal::sequence::van_der_corput, temporal::sequence::golden_ratio, temporal::sequence::white}) {
            INFO(name << ", " << temporal::to_name(s));
            const vec2 r = temporal::frame_rotation(variant_from_name(name), 0, s);
            CHECK(bits_of(r.x) == bits_of(1.0f));
            CHECK(bits_of(r.y) == bits_of(0.0f));
            CHECK(bits_of(uniforms::still_frame.x) == bits_of(1.0f));
            CHECK(bits_of(uniforms::still_frame.y) == bits_of(0.0f));
        }
}

TEST_CASE("temporal: van der Corput's offsets are the base-2 radical inverse stratified at every power of two", "[temporal]")
{
    // Written out: frame 1 = 0.1b, 2 = 0.01b, 3 = 0.11b, 4 = 0.001b, 5 = 0.101b, 6 = 0.011b, 7 = 0.111b.
    const double expected[8] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
    for (uint32_t f = 0; f < 8; ++f) CHECK(temporal::offset_turns(temporal::sequence::van_der_corput, f) == expected[f]);
    CHECK(temporal::offset_turns(temporal::sequence::van_der_corput, 0x80000000u) == 0x1p-32);
    CHECK(temporal::offset_turns(temporal::sequence::van_der_corput, 0xffffffffu) == 1.0 - 0x1p-32);
    // The first 2^k frames are the 2^k offsets j / 2^k, each once.
    for (int k = 0; k <= 10; ++k) {
        const uint32_t n = 1u << k;
        std::set<double> seen;
        for (uint32_t f = 0; f < n; ++f) {
            const double o = temporal::offset_turns(temporal::sequence::van_der_corput, f);
            REQUIRE(o * n == std::floor(o * n));
            seen.insert(o);
        }
        CHECK(seen.size() == n);
    }
}

TEST_CASE("temporal: the golden ratio and white sequences stay below 1 and repeat bit for bit", "[temporal]")
{
    for (temporal::sequence s : {temporal::sequence::golden_ratio, temporal::sequence::white}) {
        std::set<double> seen;
        for (uint32_t f = 0; f < 1000; ++f) {
            const double o = temporal::offset_turns(s, f);
            REQUIRE(o >= 0.0);
            REQUIRE(o < 1.0);
            REQUIRE(o == temporal::offset_turns(s, f));
            seen.insert(o);
        }
        CHECK(seen.size() == 1000);
    }
    // fract(f (sqrt(5) - 1) / 2) to the 32-bit fraction's precision.
    for (uint32_t f : {1u, 2u, 10u, 12345u})
        CHECK(std::fabs(temporal::offset_turns(temporal::sequence::golden_ratio, f) - std::fmod(f * 0.6180339887498949, 1.0)) < 1e-5);
}

TEST_CASE("temporal: every sequence's step offset is 0 at frame 0 and in 0..1 after", "[temporal]")
{
    for (temporal::sequence s : {temporal::sequence::van_der_corput, temporal::sequence::golden_ratio, temporal::sequence::white}) {
        INFO(temporal::to_name(s));
        CHECK(bits_of(temporal::step_offset(s, 0)) == bits_of(0.0f));
        std::set<float> seen;
        for (uint32_t f : {1u, 2u, 3u, 1000u, 0x00ffffffu, 0x7fffffffu, 0xfffffffeu, 0xffffffffu}) {
            const float o = temporal::step_offset(s, f);
            CHECK(o >= 0.0f);
            CHECK(o < 1.0f);
            CHECK(bits_of(o) == bits_of(temporal::step_offset(s, f)));
            seen.insert(o);
        }
        CHECK(seen.size() >= 6); // they move
    }
    // fract(f / rho^2), rho the plastic number (rho^3 = rho + 1), to the float's 24 bits.
    const double rho = 1.324717957244746025960908854;
    REQUIRE(std::fabs(rho * rho * rho - rho - 1) < 1e-12);
    for (uint32_t f : {1u, 2u, 10u, 12345u})
        CHECK(std::fabs(temporal::step_offset(temporal::sequence::golden_ratio, f) - std::fmod(f / (rho * rho), 1.0)) < 1e-5);
}

TEST_CASE("temporal: van der Corput's turns and step offsets stratify every 2^a x 2^b grid together", "[temporal]")
{
    // Sobol's second dimension written out: 0, 0.1b, 0.11b, 0.01b, 0.101b, 0.001b, 0.011b, 0.111b.
    const float expected[8] = {0, 0.5f, 0.75f, 0.25f, 0.625f, 0.125f, 0.375f, 0.875f};
    for (uint32_t f = 0; f < 8; ++f) CHECK(temporal::step_offset(temporal::sequence::van_der_corput, f) == expected[f]);
    // The definition of a (0, k, 2)-net in base 2: the first 2^k frames' pairs (turn, step)
    // put exactly one frame in each box of the 2^a x 2^(k-a) grid over [0, 1)^2, every a.
    for (int k = 0; k <= 10; ++k) {
        const uint32_t n = 1u << k;
        for (int a = 0; a <= k; ++a) {
            std::set<std::pair<uint32_t, uint32_t>> boxes;
            for (uint32_t f = 0; f < n; ++f) {
                const double turn = temporal::offset_turns(temporal::sequence::van_der_corput, f);
                const double step = temporal::step_offset(temporal::sequence::van_der_corput, f);
                boxes.insert({uint32_t(std::floor(turn * double(1u << a))), uint32_t(std::floor(step * double(1u << (k - a))))});
            }
            INFO("first " << n << " frames, a " << (1u << a) << " x " << (1u << (k - a)) << " grid");
            CHECK(boxes.size() == n);
        }
    }
}

TEST_CASE("temporal: a frame turns slices within their period and SSAO's kernel within a whole turn", "[temporal]")
{
    // GTAO's and VBAO's S slices lie s pi / S apart: turning them by pi / S is no turn at all.
    CHECK(temporal::period_turns(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs")) == 0.25);
    CHECK(temporal::period_turns(variant_from_name("vbao-4x3-half-bilateral-gbufworld-std-persp-cs")) == 0.125);
    CHECK(temporal::period_turns(variant_from_name("gtao-1x3-half-bilateral-gbufworld-std-persp-cs")) == 0.5);
    CHECK(temporal::period_turns(variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-cs")) == 1.0);
    CHECK(temporal::period_turns(variant_from_name("sao-s16-half-bilateral-gbufworld-std-persp-cs")) == 1.0);
    // Frame 1 is half a period: 45 degrees for two slices, half a turn for SSAO.
    const vec2 gtao = temporal::frame_rotation(variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs"), 1);
    CHECK(gtao.x == Approx(std::sqrt(0.5)).margin(1e-7));
    CHECK(gtao.y == Approx(std::sqrt(0.5)).margin(1e-7));
    const vec2 ssao = temporal::frame_rotation(variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-cs"), 1);
    CHECK(ssao.x == -1.0f);
    CHECK(ssao.y == 0.0f);
    // Every frame's rotation is a unit vector.
    for (uint32_t f = 0; f < 64; ++f) {
        const vec2 r = temporal::frame_rotation(variant_from_name("gtao-3x3-half-denoise-gbufworld-std-persp-cs"), f);
        CHECK(std::fabs(std::hypot(r.x, r.y) - 1.0) < 1e-7);
    }
}

TEST_CASE("temporal: chain_settings' frame reaches the AO pass's frame_rotation and frame_step and no other block", "[temporal]")
{
    for (const char* name : {"gtao-2x3-half-bilateral-gbufworld-std-persp-cs", "vbao-2x3-half-denoise-gbufworld-std-persp-cs",
                             "ssao-s16-half-bilateral-gbufworld-std-persp-cs"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        const layout::block_desc block = codegen::uniform_block(v, pass_kind::ao);
        chain_settings s;
        s.camera = {mat4{}, perspective(1, 1, 1, 3)};
        const chain_inputs still = codegen::make_plan(v).inputs(s, 80, 45);
        s.frame = 5;
        const chain_inputs moved = codegen::make_plan(v).inputs(s, 80, 45);
        const size_t at = offset_of(block, "frame_rotation");
        const vec2 expected = temporal::frame_rotation(v, 5);
        CHECK(float_at(still.uniforms[0], at) == 1.0f);
        CHECK(float_at(still.uniforms[0], at + 4) == 0.0f);
        CHECK(float_at(moved.uniforms[0], at) == expected.x);
        CHECK(float_at(moved.uniforms[0], at + 4) == expected.y);
        // The slice techniques' step offset: 0 at frame 0, frame 5's after (SSAO has none).
        size_t expected_changes = 8;
        if (has_slices(v.tech)) {
            const size_t step_at = offset_of(block, "frame_step");
            CHECK(float_at(still.uniforms[0], step_at) == 0.0f);
            CHECK(float_at(moved.uniforms[0], step_at) == temporal::step_offset(temporal::sequence::van_der_corput, 5));
            expected_changes += 4;
        }
        // Only those bytes changed; the blur passes' blocks and the tile are the same.
        REQUIRE(still.uniforms.size() == moved.uniforms.size());
        size_t changed = 0;
        for (size_t i = 0; i < still.uniforms[0].size(); ++i) changed += still.uniforms[0][i] != moved.uniforms[0][i];
        CHECK(changed > 0);
        CHECK(changed <= expected_changes);
        for (size_t p = 1; p < still.uniforms.size(); ++p) CHECK(still.uniforms[p] == moved.uniforms[p]);
        CHECK(still.noise == moved.noise);
    }
}

TEST_CASE("temporal: sequence names", "[temporal]")
{
    CHECK(temporal::sequence_from_name("van_der_corput") == temporal::sequence::van_der_corput);
    CHECK(temporal::sequence_from_name("golden-ratio") == temporal::sequence::golden_ratio);
    CHECK(std::string(temporal::to_name(temporal::sequence::white)) == "white");
    CHECK_THROWS_WITH(temporal::sequence_from_name("halton", "--frame-sequence"),
                      Catch::Contains("--frame-sequence") && Catch::Contains("halton") && Catch::Contains("van_der_corput, golden_ratio, white"));
}

TEST_CASE("temporal: a step offset outside 0..1 or not finite is refused by name", "[temporal]")
{
    const uniforms::camera cam{mat4{}, perspective(1, 1, 1, 3)};
    for (float bad : {-0.25f, 1.5f, std::nanf(""), INFINITY}) {
        INFO(bad);
        const uniforms::extras e{uniforms::still_frame, finalize_params{}, bad};
        CHECK_THROWS_WITH(uniforms::pack_gtao(gtao_params{}, cam, {80, 45}, layout::rules::std140, 4, e),
                          Catch::Contains("uniforms frame_step") && Catch::Contains("valid: 0..1"));
        CHECK_THROWS_WITH(uniforms::pack_vbao(vbao_params{}, cam, {80, 45}, layout::rules::std140, 4, e), Catch::Contains("uniforms frame_step"));
    }
    for (float good : {0.0f, 0.5f, 1.0f}) {
        const uniforms::extras e{uniforms::still_frame, finalize_params{}, good};
        CHECK_NOTHROW(uniforms::pack_gtao(gtao_params{}, cam, {80, 45}, layout::rules::std140, 4, e));
    }
}

} // namespace unity_test_temporal
