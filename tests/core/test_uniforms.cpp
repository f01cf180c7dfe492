// The passes' uniform blocks: seed 004's SsaoUniform must be exactly the 144 bytes its
// WGSL declares, and every pass block's bytes must hold the values at the offsets the
// layout rules give — checked here against offsets worked out by hand from the rules,
// and against a byte image assembled independently of the writer.
#include <aogen/kernel.hpp>
#include <aogen/presets.hpp>
#include <aogen/uniforms.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_uniforms {

using namespace aogen;
using layout::rules;

namespace {

float float_at(const std::vector<uint8_t>& bytes, size_t offset)
{
    REQUIRE(offset + 4 <= bytes.size());
    float f;
    std::memcpy(&f, bytes.data() + offset, 4);
    return f;
}

void put_float(std::vector<uint8_t>& bytes, size_t offset, float f) { std::memcpy(bytes.data() + offset, &f, 4); }

// perspective(tan 1, aspect 1, near 1, far 3): columns (1,0,0,0) (0,1,0,0) (0,0,−1.5,−1)
// (0,0,−1.5,0); its inverse, worked out by hand: (1,0,0,0) (0,1,0,0) (0,0,0,−2/3) (0,0,−1,1).
const float simple_proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.5f, -1, 0, 0, -1.5f, 0};
const float simple_inv_proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, static_cast<float>(-2.0 / 3.0), 0, 0, -1, 1};

} // namespace

TEST_CASE("perspective and inverse match the hand-worked matrices", "[uniforms]")
{
    const mat4 p = perspective(1.0f, 1.0f, 1.0f, 3.0f);
    const mat4 inv = inverse(p);
    for (int i = 0; i < 16; ++i) {
        CHECK(p[i / 4][i % 4] == simple_proj[i]);
        CHECK(inv[i / 4][i % 4] == simple_inv_proj[i]);
    }
}

TEST_CASE("seed 004's SsaoUniform is 144 bytes with the seed's offsets under every uniform rule set", "[uniforms]")
{
    for (rules r : {rules::std140, rules::std430, rules::wgsl_uniform, rules::hlsl_cbuffer, rules::msl, rules::scalar}) {
        INFO(layout::to_name(r));
        const layout::struct_layout l = layout::compute(uniforms::pointcloud_block(), r);
        CHECK(l.size == 144);
        CHECK(layout::find(l, "inv_proj")->offset == 0);
        CHECK(layout::find(l, "proj")->offset == 64);
        CHECK(layout::find(l, "radius")->offset == 128);
        CHECK(layout::find(l, "bias")->offset == 132);
        CHECK(layout::find(l, "_pad")->offset == 136);
    }
}

TEST_CASE("seed 004's SsaoUniform bytes equal an independently assembled image", "[uniforms]")
{
    ssao_params p = presets::pointcloud_viewer_ssao().settings.ssao;
    p.radius = 0.75f;
    p.bias = 0.03125f;
    mat4 proj;
    std::memcpy(&proj, simple_proj, sizeof proj);
    std::vector<uint8_t> expected(144, 0);
    for (int i = 0; i < 16; ++i) put_float(expected, 4 * i, simple_inv_proj[i]);
    for (int i = 0; i < 16; ++i) put_float(expected, 64 + 4 * i, simple_proj[i]);
    put_float(expected, 128, 0.75f);
    put_float(expected, 132, 0.03125f);
    for (rules r : {rules::std140, rules::wgsl_uniform, rules::hlsl_cbuffer}) {
        INFO(layout::to_name(r));
        CHECK(uniforms::pack_pointcloud(p, proj, r) == expected);
    }
}

TEST_CASE("Taos SSAO block: sizes and offsets worked out from each rule set", "[uniforms]")
{
    // 3 mat4 (192 bytes), vec2 at 192, 200 and 208, the albedo at 216, five floats at
    // 220..236, then vec4[16] at 240 under every rule set (scalar rules too: 240 is where it ends).
    struct expectation { rules r; uint32_t kernel_offset, size; };
    for (expectation e : {expectation{rules::std140, 240, 496}, {rules::std430, 240, 496}, {rules::scalar, 240, 496},
                          {rules::wgsl_uniform, 240, 496}, {rules::hlsl_cbuffer, 240, 496}, {rules::msl, 240, 496}}) {
        INFO(layout::to_name(e.r));
        const layout::struct_layout l = layout::compute(uniforms::ssao_block(16), e.r);
        CHECK(l.size == e.size);
        CHECK(layout::find(l, "kernel")->offset == e.kernel_offset);
        CHECK(layout::find(l, "intensity")->offset == 236);
    }
}

TEST_CASE("Taos SSAO bytes hold the preset, the camera and the kernel", "[uniforms]")
{
    const preset taos = presets::taos_ssao();
    const std::vector<vec4> kernel = kernel::crytek(taos.variant.samples, 1);
    mat4 proj;
    std::memcpy(&proj, simple_proj, sizeof proj);
    const uniforms::camera cam{mat4{}, proj};
    const std::vector<uint8_t> bytes = uniforms::pack_ssao(taos.settings.ssao, cam, kernel, {960, 540}, rules::std140);
    REQUIRE(bytes.size() == 496);
    CHECK(float_at(bytes, 0) == 1.0f);                 // proj[0][0]
    CHECK(float_at(bytes, 64 + 4 * 11) == simple_inv_proj[11]);
    CHECK(float_at(bytes, 128) == 1.0f);               // world_to_view = identity
    CHECK(float_at(bytes, 192) == 240.0f);             // noise_scale = 960 / 4
    CHECK(float_at(bytes, 196) == 135.0f);             // 540 / 4
    CHECK(float_at(bytes, 200) == 1.0f / 960.0f);      // texel_size
    CHECK(float_at(bytes, 208) == 1.0f);               // frame_rotation: the still frame (1, 0)
    CHECK(float_at(bytes, 212) == 0.0f);
    CHECK(float_at(bytes, 216) == 0.5f);               // albedo: finalize_params' default
    CHECK(float_at(bytes, 220) == 0.5f);               // radius
    CHECK(float_at(bytes, 224) == 0.025f);             // bias
    CHECK(float_at(bytes, 228) == 1.0f);               // strength
    for (int i = 0; i < 16; ++i) {
        CHECK(float_at(bytes, 240 + 16 * i) == kernel[i].x);
        CHECK(float_at(bytes, 240 + 16 * i + 8) == kernel[i].z);
    }
}

TEST_CASE("Taos GTAO block: sizes per rule set and the seed's numbers", "[uniforms]")
{
    // 220 bytes of camera members, then six floats (the five settings and frame_step): 244
    // bytes, which std140 and a cbuffer round up to 256; scalar keeps 244.
    CHECK(layout::compute(uniforms::gtao_block(), rules::std140).size == 256);
    CHECK(layout::compute(uniforms::gtao_block(), rules::scalar).size == 244);
    CHECK(layout::compute(uniforms::gtao_block(), rules::hlsl_cbuffer).size == 256);
    const std::vector<uint8_t> bytes =
        uniforms::pack_gtao(presets::taos_gtao().settings.gtao, {mat4{}, perspective(1, 1, 1, 3)}, {960, 540}, rules::std140);
    CHECK(float_at(bytes, 220) == 1.0f);  // radius (seed 001)
    CHECK(float_at(bytes, 224) == 0.1f);  // thickness bias
    CHECK(float_at(bytes, 228) == 2.0f);  // strength exponent
    CHECK(float_at(bytes, 232) == 0.0f);  // falloff range: seed 001's hard cut-off
    CHECK(float_at(bytes, 236) == 0.0f);  // thin-occluder compensation: none
    CHECK(float_at(bytes, 240) == 0.0f);  // frame_step: a still frame's steps
    gtao_params g = presets::taos_gtao().settings.gtao;
    g.falloff_range = 0.625f, g.thin_occluder = 1.5f;
    const std::vector<uint8_t> tuned = uniforms::pack_gtao(g, {mat4{}, perspective(1, 1, 1, 3)}, {960, 540}, rules::std140);
    CHECK(float_at(tuned, 232) == 0.625f);
    CHECK(float_at(tuned, 236) == 1.5f);
}

TEST_CASE("VBAO block: GTAO's camera, then radius, thickness in world units, strength, frame_step", "[uniforms]")
{
    const layout::struct_layout l = layout::compute(uniforms::vbao_block(), rules::std140);
    CHECK(l.size == 240);
    CHECK(l.name == "VbaoUniforms");
    CHECK(layout::compute(uniforms::vbao_block(), rules::scalar).size == 236);
    vbao_params p;
    p.radius = 2.0f, p.thickness = 0.25f, p.strength = 1.5f;
    const std::vector<uint8_t> bytes = uniforms::pack_vbao(p, {mat4{}, perspective(1, 1, 1, 3)}, {960, 540}, rules::std140);
    REQUIRE(bytes.size() == 240);
    CHECK(float_at(bytes, 192) == 240.0f); // noise_scale: a 4×4 tile
    CHECK(float_at(bytes, 208) == 1.0f);   // frame_rotation: the still frame
    CHECK(float_at(bytes, 220) == 2.0f);   // radius
    CHECK(float_at(bytes, 224) == 0.5f);   // thickness: 0.25 of the radius, in world units
    CHECK(float_at(bytes, 228) == 1.5f);   // strength
    CHECK(float_at(bytes, 232) == 0.0f);   // frame_step: a still frame's steps
    for (size_t pad = 236; pad < 240; ++pad) CHECK(bytes[pad] == 0);
    p.thickness = -1;
    CHECK_THROWS_WITH(uniforms::pack_vbao(p, {mat4{}, perspective(1, 1, 1, 3)}, {960, 540}, rules::std140), Catch::Contains("vbao.thickness"));
}

TEST_CASE("SAO block: GTAO's camera, then radius, bias, intensity, contrast and the spiral", "[uniforms]")
{
    const layout::struct_layout l = layout::compute(uniforms::sao_block(4), rules::std140);
    CHECK(l.size == 240 + 4 * 16);
    CHECK(l.name == "SaoUniforms");
    sao_params p;
    p.radius = 2.0f, p.bias = 0.125f, p.intensity = 1.5f, p.contrast = 0.75f;
    const std::vector<uint8_t> bytes = uniforms::pack_sao(p, {mat4{}, perspective(1, 1, 1, 3)}, 4, {960, 540}, rules::std140);
    REQUIRE(bytes.size() == 304);
    CHECK(float_at(bytes, 192) == 240.0f); // noise_scale: a 4×4 tile
    CHECK(float_at(bytes, 208) == 1.0f);   // frame_rotation: the still frame
    CHECK(float_at(bytes, 220) == 2.0f);   // radius
    CHECK(float_at(bytes, 224) == 0.125f); // bias, a share of the radius
    CHECK(float_at(bytes, 228) == 1.5f);   // intensity
    CHECK(float_at(bytes, 232) == 0.75f);  // contrast
    const std::vector<vec4> spiral = spiral::taps(4);
    for (size_t i = 0; i < 4; ++i) {
        CHECK(float_at(bytes, 240 + 16 * i) == spiral[i].x);
        CHECK(float_at(bytes, 240 + 16 * i + 4) == spiral[i].y);
        CHECK(float_at(bytes, 240 + 16 * i + 8) == spiral[i].z);
    }
    p.contrast = 0;
    CHECK_THROWS_WITH(uniforms::pack_sao(p, {mat4{}, perspective(1, 1, 1, 3)}, 4, {960, 540}, rules::std140), Catch::Contains("sao.contrast"));
    CHECK_THROWS_WITH(uniforms::pack_sao(sao_params{}, {mat4{}, perspective(1, 1, 1, 3)}, 257, {960, 540}, rules::std140),
                      Catch::Contains("sao block taps: 257 is out of range"));
}

TEST_CASE("Packing sizes the SSAO block by its kernel and rejects kernels out of range and invalid params", "[uniforms]")
{
    const ssao_params ssao = presets::taos_ssao().settings.ssao;
    const uniforms::camera cam{mat4{}, perspective(1, 1, 1, 3)};
    // The kernel is the variant's samples: its size is the block's N.
    CHECK(uniforms::pack_ssao(ssao, cam, kernel::crytek(8, 1), {960, 540}, rules::std140).size() == 240 + 8 * 16);
    CHECK(uniforms::pack_ssao(ssao, cam, kernel::crytek(256, 1), {960, 540}, rules::std140).size() == 240 + 256 * 16);
    CHECK_THROWS_WITH(uniforms::pack_ssao(ssao, cam, std::vector<vec4>(257), {960, 540}, rules::std140),
                      Catch::Contains("ssao kernel: 257 samples given") && Catch::Contains("valid: 1..256"));
    CHECK_THROWS_WITH(uniforms::pack_ssao(ssao, cam, {}, {960, 540}, rules::std140), Catch::Contains("ssao kernel: 0 samples given"));
    ssao_params bad = ssao;
    bad.radius = -1;
    CHECK_THROWS_WITH(uniforms::pack_ssao(bad, cam, kernel::crytek(16, 1), {960, 540}, rules::std140),
                      Catch::Contains("ssao.radius"));
    CHECK_THROWS_AS(uniforms::pack_ssao(ssao, cam, kernel::crytek(16, 1), {0, 540}, rules::std140), aogen::error);
}

TEST_CASE("uniforms: the history block: members at std140's offsets, the camera's move exact when it stood still, each motion convention's scale", "[uniforms]")
{
    // std140 by hand: three mat4 (64 bytes each), a vec2 at 192, then six 4-byte scalars; 224.
    const layout::struct_layout block = layout::compute(uniforms::history_block(), rules::std140);
    CHECK(block.size == 224);
    const mat4 proj = perspective(0.6f, 1.5f, 0.1f, 100.0f);
    mat4 here;
    here.columns[3] = {-2.0f, -0.5f, 0.25f, 1.0f}; // a camera at (2, 0.5, -0.25)
    history_params p;
    p.clamp = history_clamp::range;
    p.range = 0.125f;
    uniforms::history_frame f{{here, proj}, {here, proj}, {1920, 1080}, false};
    std::vector<uint8_t> still = uniforms::pack_history(p, f, block);
    REQUIRE(still.size() == 224);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(float_at(still, 64 + 16 * c + 4 * r) == (c == r ? 1.0f : 0.0f)); // the identity, to the bit
    CHECK(float_at(still, 128 + 0) == proj[0][0]);
    CHECK(float_at(still, 192) == -0.5f); // NDC, current minus previous, y up: previous uv = uv - 0.5 (x, -y)
    CHECK(float_at(still, 196) == 0.5f);
    CHECK(float_at(still, 200) == 0.1f); // the default blend
    int32_t kind;
    std::memcpy(&kind, still.data() + 204, 4);
    CHECK(kind == 1);
    CHECK(float_at(still, 208) == 0.125f);
    CHECK(float_at(still, 212) == Approx(std::log2(1.05)).epsilon(1e-6));
    CHECK(float_at(still, 216) == 0.0f);
    CHECK(float_at(still, 220) == finalize_params{}.albedo);
    // The camera moved to (2, 0.5, -0.25) from the origin: this view's point x is x + (2, 0.5, -0.25) in the previous view.
    f.previous = {mat4{}, proj};
    f.reset = true;
    const std::vector<uint8_t> moved = uniforms::pack_history(p, f, block);
    CHECK(float_at(moved, 64 + 48) == 2.0f);
    CHECK(float_at(moved, 64 + 52) == 0.5f);
    CHECK(float_at(moved, 64 + 56) == -0.25f);
    CHECK(float_at(moved, 216) == 1.0f);
    // The conventions, by hand: previous uv = uv + scale * vector, uv's y down.
    CHECK(uniforms::motion_scale({motion_units::uv, motion_direction::current_to_previous, motion_y::down}, {1920, 1080}).x == 1.0f);
    CHECK(uniforms::motion_scale({motion_units::uv, motion_direction::current_to_previous, motion_y::down}, {1920, 1080}).y == 1.0f);
    CHECK(uniforms::motion_scale({motion_units::uv, motion_direction::previous_to_current, motion_y::up}, {1920, 1080}).y == 1.0f);
    CHECK(uniforms::motion_scale({motion_units::pixels, motion_direction::previous_to_current, motion_y::down}, {1920, 1080}).x == -1.0f / 1920);
    CHECK(uniforms::motion_scale({motion_units::pixels, motion_direction::previous_to_current, motion_y::down}, {1920, 1080}).y == -1.0f / 1080);
    // Bad settings, by name.
    history_params bad;
    bad.blend = 0.0f;
    CHECK_THROWS_WITH(uniforms::pack_history(bad, f, block), Catch::Contains("history.blend: 0 is out of range") && Catch::Contains("valid:"));
    bad = {};
    bad.depth_tolerance = 0.0f;
    CHECK_THROWS_WITH(uniforms::pack_history(bad, f, block), Catch::Contains("history.depth_tolerance"));
    bad = {};
    bad.clamp = static_cast<history_clamp>(9);
    CHECK_THROWS_WITH(uniforms::pack_history(bad, f, block), Catch::Contains("history.clamp") && Catch::Contains("none, range, min_max, variance"));
    bad = {};
    bad.motion.units = static_cast<motion_units>(5);
    CHECK_THROWS_WITH(uniforms::pack_history(bad, f, block), Catch::Contains("history.motion.units") && Catch::Contains("uv, ndc, pixels"));
}

} // namespace unity_test_uniforms
