// Bent normals (a -bn variant: variant::bent_normals; gtao.glsl's THE BENT NORMAL, carried
// through every pass as common/core.glsl's ao_value, stored as aogen/bent_normals.hpp says) on
// the harness's crease: the floor y = -0.6 meeting the wall z = -3, seen down -z, so view space
// is world space and the normals are known exactly.
//
//   - the AO of a -bn chain is its twin's bit for bit, whichever passes carry the normal: the
//     normal rides beside the AO and never feeds back into it;
//   - every pixel with a surface has a unit bent normal in the hemisphere of its surface
//     normal; background has none (the zero vector) and AO exactly 1;
//   - it leans away from the occluder: on the floor by the wall toward +z (out of the wall),
//     on the wall by the floor toward +y (up, out of the floor) -- the direction of the open
//     sky in a 90-degree corner -- and, on open floor far from the wall, it stays within a few
//     degrees of the floor's normal.
// The truth's bent normal is checked in tests/accuracy/bent_normal_test.cpp.
#include "harness.hpp"

#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_bent_normal_test {

using namespace aogen;
using namespace aogen_test;

namespace {

constexpr int W = 96, H = 64;

// The chains: the AO pass last; the denoise and the upsample; the denoise left at half
// resolution; the box; the bilateral's two passes and the upsample; 16-bit arithmetic;
// deinterleaved dispatch; a depth MIP chain; VBAO through the bilateral and the upsample, and
// with 16-bit arithmetic.
const char* const chains[] = {"gtao-2x3-full-noblur-gbufworld-std-persp-cs-bn",
                              "gtao-2x2-half-denoise-gbufworld-std-persp-cs-bn",
                              "gtao-2x2-half-denoise-gbufworld-std-persp-cs-nearest-bn",
                              "gtao-3x3-full-box-gbufworld-std-persp-cs-bn",
                              "gtao-2x3-half-bilateral-gbufworld-std-persp-cs-bn",
                              "gtao-3x3-full-denoise-gbufview-std-persp-cs-fp16-bn",
                              "gtao-3x3-full-noblur-recon-std-persp-cs-deint-bn",
                              "gtao-3x3-full-noblur-gbufworld-std-persp-cs-mip4-bn",
                              "vbao-3x3-half-bilateral-gbufworld-std-persp-cs-bn",
                              "vbao-2x3-full-noblur-gbufview-std-persp-cs-fp16-bn"};

float length3(const float* n) { return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]); }

} // namespace

TEST_CASE("vulkan: a -bn chain writes its twin's AO bit for bit and a unit bent normal on every surface pixel and none on background")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, 0.6f, proj);
    for (const char* name : chains) {
        INFO(name);
        const variant v = variant_from_name(name);
        variant twin = v;
        twin.bent_normals = false;
        const vulkan::chain_result r = chain_under_test(*ctx, v).run(g, settings_for(proj));
        const vulkan::chain_result t = chain_under_test(*ctx, twin).run(g, settings_for(proj));
        CHECK(r.ao == t.ao);
        CHECK(t.bent_normal.empty());
        REQUIRE(r.bent_normal.size() == 3 * r.ao.size());
        size_t background = 0, surface = 0, not_unit = 0, below = 0, open_background = 0;
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x) {
                const size_t i = pixel(r.width, x, y);
                // The screen pixel the output pixel stands for: itself, or 2p at half resolution.
                const size_t full = r.width == W ? pixel(W, x, y) : full_pixel_of(v, W, H, x, y);
                const float* n = &r.bent_normal[3 * i];
                if (g.depth[full] >= 1.0f) {
                    ++background;
                    open_background += r.ao[i] == 1.0f && length3(n) == 0.0f;
                    continue;
                }
                ++surface;
                not_unit += std::fabs(length3(n) - 1.0f) > 0.01f;
                const float* s = &g.normals[4 * full];
                below += n[0] * s[0] + n[1] * s[1] + n[2] * s[2] <= 0.0f;
            }
        REQUIRE(background > 0);
        REQUIRE(surface > r.ao.size() / 2);
        CHECK(open_background == background);
        CHECK(not_unit == 0);
        CHECK(below == 0);
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: a bent normal leans out of the crease away from the occluder and follows the normal on open floor")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, 0.6f, proj);
    for (const char* name : {"gtao-3x3-full-noblur-gbufworld-std-persp-cs-bn", "gtao-2x2-half-denoise-gbufworld-std-persp-cs-bn",
                             "vbao-3x3-full-noblur-gbufworld-std-persp-cs-bn"}) {
        INFO(name);
        const variant v = variant_from_name(name);
        const vulkan::chain_result r = chain_under_test(*ctx, v).run(g, settings_for(proj));
        REQUIRE(r.width == W);
        double floor_z = 0, wall_y = 0, open_angle = 0, worst_open = 0;
        size_t floor_near = 0, wall_near = 0, open = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const size_t i = pixel(W, x, y);
                if (g.depth[i] >= 1.0f) continue;
                const float* n = &r.bent_normal[3 * i];
                const bool floor = g.normals[4 * i + 1] > 0.5f;
                if (r.ao[i] < 0.8f) { // in the corner's shadow
                    if (floor) floor_z += n[2], ++floor_near;
                    else wall_y += n[1], ++wall_near;
                } else if (floor && r.ao[i] == 1.0f) { // open floor: the bent normal is the floor's, (0, 1, 0)
                    const double angle = std::acos(std::clamp(double(n[1]), -1.0, 1.0)) * 180.0 / 3.14159265358979;
                    open_angle += angle, worst_open = std::max(worst_open, angle), ++open;
                }
            }
        REQUIRE(floor_near > 20);
        REQUIRE(wall_near > 20);
        REQUIRE(open > 100);
        INFO("floor by the wall: mean z " << floor_z / floor_near << "; wall by the floor: mean y " << wall_y / wall_near
                                          << "; open floor: mean angle " << open_angle / open << " deg, worst " << worst_open);
        // In a 90-degree corner the open sky's cosine-weighted mean leans well out of it.
        CHECK(floor_z / floor_near > 0.15);
        CHECK(wall_y / wall_near > 0.15);
        CHECK(open_angle / open < 5.0);
    }
    require_clean(*ctx);
}

} // namespace unity_bent_normal_test
