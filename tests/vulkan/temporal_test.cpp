// The frame index on the GPU (aogen/temporal.hpp, common/noise.glsl, common/slices.glsl):
// frame f's uniforms turn every pixel's noise texel by temporal::frame_rotation(v, f) and,
// in GTAO and VBAO, move each slice's inner steps by temporal::step_offset(f), and change
// nothing else. So the oracle of frame f is frame 0 run with every texel of the noise tile
// turned by that rotation on the host and the step offset written into its block: the same
// directions, reached the other way. They agree but for the last bit of a texel (the host
// rounds the turned texel, the shader its product), which moves a pixel's 8-bit output by at
// most a step, and rarely; a shader that ignores the rotation, or turns the other way,
// disagrees at most pixels.
//   Where the steps go has an exact oracle of its own: a step offset of a whole step moves a
// two-step march's inner step onto the pixel itself, which never counts, so the march is
// the one-step march at the same radius, bit for bit; and a one-step march has no inner
// step, so no offset moves it.
// The accuracy of the frames' mean against the truth is accuracy/temporal_test.cpp's.
#include "harness.hpp"

#include <cstring>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_temporal_test {

using namespace aogen;
using namespace aogen_test;

namespace {

// The noise tile of `in` (RGBA32F texels) with every texel's xy turned by `turn`.
chain_inputs with_noise_turned(chain_inputs in, vec2 turn)
{
    for (size_t at = 0; at + 16 <= in.noise.size(); at += 16) {
        float t[2];
        std::memcpy(t, in.noise.data() + at, sizeof t);
        const double x = double(t[0]) * turn.x - double(t[1]) * turn.y, y = double(t[0]) * turn.y + double(t[1]) * turn.x;
        t[0] = float(x), t[1] = float(y);
        std::memcpy(in.noise.data() + at, t, sizeof t);
    }
    return in;
}

// `in` with its AO pass's block's frame_step (GTAO's and VBAO's) set to `offset`.
chain_inputs with_steps_moved(chain_inputs in, const variant& v, float offset)
{
    if (!has_slices(v.tech)) return in;
    const layout::block_desc block = codegen::uniform_block(v, pass_kind::ao);
    for (const layout::member_layout& m : layout::compute(block, layout::rules::std140).members)
        if (m.name == "frame_step") {
            std::memcpy(in.uniforms[0].data() + m.offset, &offset, sizeof offset);
            return in;
        }
    FAIL("no frame_step in " << block.root.name);
    return in;
}

} // namespace

TEST_CASE("vulkan: frame f of a chain equals frame 0 with its noise tile turned by frame f's rotation and its steps moved by frame f's offset")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease(W, H, 0.6f, proj); // floor, wall, their crease, background
    const vulkan::gpu_gbuffer g(*ctx, host);
    for (const char* name : {"gtao-2x3-full-noblur-gbufworld-std-persp-cs", "vbao-2x3-full-noblur-gbufworld-std-persp-cs",
                             "ssao-s16-full-noblur-gbufworld-std-persp-cs", "sao-s16-full-noblur-gbufworld-std-persp-cs",
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs", "ssao-s16-full-noblur-gbufworld-std-persp-fs"}) {
        const variant v = variant_from_name(name);
        const vulkan::chain c = chain_under_test(*ctx, v);
        const vulkan::chain_settings still = settings_for(proj);
        const vulkan::chain_result frame0 = vulkan::bound_chain(*ctx, c.passes(), g, c.plan().inputs(still, W, H)).run_once();
        for (uint32_t f : {1u, 3u, 6u}) {
            INFO(name << ", frame " << f);
            vulkan::chain_settings s = still;
            s.frame = f;
            const vulkan::chain_result moved = vulkan::bound_chain(*ctx, c.passes(), g, c.plan().inputs(s, W, H)).run_once();
            const chain_inputs turned_tile = with_steps_moved(with_noise_turned(c.plan().inputs(still, W, H), temporal::frame_rotation(v, f)), v,
                                                              temporal::step_offset(still.frame_sequence, f));
            const vulkan::chain_result turned = vulkan::bound_chain(*ctx, c.passes(), g, turned_tile).run_once();
            REQUIRE(moved.ao.size() == turned.ao.size());
            size_t differ = 0, moved_from_frame0 = 0;
            float largest = 0;
            for (size_t i = 0; i < moved.ao.size(); ++i) {
                const float d = std::fabs(moved.ao[i] - turned.ao[i]);
                differ += d > 0, largest = std::max(largest, d);
                moved_from_frame0 += moved.ao[i] != frame0.ao[i];
            }
            INFO(differ << " of " << moved.ao.size() << " pixels differ from the turned tile's, by at most " << largest * 255 << "/255; "
                        << moved_from_frame0 << " differ from frame 0");
            CHECK(differ * 100 <= moved.ao.size()); // at most 1 %
            CHECK(largest <= 1.5f / 255);
            CHECK(moved_from_frame0 * 10 >= moved.ao.size() / 4); // the frame did move the noise where there is occlusion
        }
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: a step offset of a whole step makes a two-step march the one-step march and moves no one-step march")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer host = crease(W, H, 0.6f, proj);
    const vulkan::gpu_gbuffer g(*ctx, host);
    const vulkan::chain_settings still = settings_for(proj);
    for (const char* technique : {"gtao", "vbao"}) {
        const variant two = variant_from_name(std::string(technique) + "-2x2-full-noblur-gbufworld-std-persp-cs");
        const variant one = variant_from_name(std::string(technique) + "-2x1-full-noblur-gbufworld-std-persp-cs");
        INFO(technique);
        auto run = [&](const variant& v, float offset) {
            const vulkan::chain c = chain_under_test(*ctx, v);
            return vulkan::bound_chain(*ctx, c.passes(), g, with_steps_moved(c.plan().inputs(still, W, H), v, offset)).run_once().ao;
        };
        const std::vector<float> one_still = run(one, 0.0f), two_still = run(two, 0.0f);
        // The inner step on the pixel itself: the one-step march, to the bit.
        const std::vector<float> two_whole = run(two, 1.0f);
        REQUIRE(two_whole.size() == one_still.size());
        size_t differ = 0, two_differs = 0;
        for (size_t i = 0; i < two_whole.size(); ++i) differ += two_whole[i] != one_still[i], two_differs += two_still[i] != one_still[i];
        INFO(differ << " of " << two_whole.size() << " pixels differ from the one-step march; at frame 0, " << two_differs);
        CHECK(differ == 0);
        CHECK(two_differs * 20 >= two_whole.size()); // the inner step does find occlusion the outer one misses, at frame 0
        // Half a step: the inner step moves (to a quarter of the radius), the outer one does not.
        const std::vector<float> two_half = run(two, 0.5f);
        size_t moved = 0;
        for (size_t i = 0; i < two_half.size(); ++i) moved += two_half[i] != two_still[i];
        CHECK(moved * 20 >= two_half.size());
        CHECK(run(one, 0.5f) == one_still);
        CHECK(run(one, 0.999f) == one_still);
    }
    require_clean(*ctx);
}

} // namespace unity_temporal_test
