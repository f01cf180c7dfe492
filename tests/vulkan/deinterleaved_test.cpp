// The deinterleaved dispatch (-deint, variant.hpp's `deinterleaved`, entry_compute.glsl's
// ao_invocation_pixel): the AO pass's invocations walk the target as 4 × 4 interleaved layers,
// which changes which invocation shades a pixel and nothing else. So the oracle is the twin
// without it — itself held to the truth by accuracy_test.cpp — bit for bit, over the whole
// chain, at sizes the layers do and do not divide; and every pixel is written exactly once:
// run over a target cleared to 0 and to 1, a pixel no invocation wrote would keep the clear.
#include "harness.hpp"

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_deinterleaved_test {

using namespace aogen;
using namespace aogen_test;

TEST_CASE("vulkan: a -deint variant's chain equals its twin's bit for bit, every pixel written")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const char* bases[] = {"gtao-2x3-full-noblur-gbufworld-std-persp-cs", "gtao-2x2-half-denoise-gbufview-rev-persp-cs",
                           "vbao-2x3-half-noblur-recon-std-persp-cs", "ssao-s16-half-bilateral-gbufworld-std-persp-cs",
                           "ssao-s16-full-noblur-gbufworld-std-persp-cs-wg16x8"};
    // 64 × 40: the layers divide it; 61 × 37 and 203 × 117: they do not (the last column and
    // row of layers are short), and at half resolution the target is odd again.
    for (auto [W, H] : {std::pair<int, int>{64, 40}, std::pair<int, int>{61, 37}, std::pair<int, int>{203, 117}})
        for (const char* base : bases) {
            const variant twin = variant_from_name(base);
            variant deint = twin;
            deint.deinterleaved = true;
            INFO(to_name(deint) << " at " << W << "x" << H);
            const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f, twin.depth);
            vulkan::gbuffer g = crease(W, H, 0.6f, proj); // floor, wall, their crease, background beside the wall
            if (twin.depth != depth_convention::standard)
                for (float& d : g.depth)
                    if (d == 1.0f) d = 0.0f; // the reversed conventions clear to 0
            const vulkan::chain_result a = chain_under_test(*ctx, twin).run(g, settings_for(proj));
            const vulkan::chain deint_chain = chain_under_test(*ctx, deint);
            for (float clear : {0.0f, 1.0f}) {
                const vulkan::chain_result b = deint_chain.run(g, settings_for(proj), {clear});
                REQUIRE(b.ao.size() == a.ao.size());
                size_t differ = 0, open = 0, occluded = 0;
                for (size_t i = 0; i < a.ao.size(); ++i) differ += a.ao[i] != b.ao[i], open += a.ao[i] == 1.0f, occluded += a.ao[i] < 0.98f;
                INFO("clear " << clear);
                CHECK(differ == 0);
                CHECK(occluded > 0); // the crease is in view: the comparison covers occluded pixels
                CHECK(open > 0);
            }
        }
    require_clean(*ctx);
}

} // namespace unity_deinterleaved_test
