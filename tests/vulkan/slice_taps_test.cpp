// Far slice taps (common/slices.glsl's ao_slice_tap_surface, aogen::slice_taps): from 16
// pixels on, a GTAO or VBAO tap reads the texel under it at the texel's centre — a true
// surface point up to 0.71 pixels off the slice's line — instead of the plane's depth under
// the tap. The claim that makes it safe is that on an open plane the horizon such a point
// raises moves the slice integral by second order only, below 1/255. Held here on planes
// tilted up to 85° and seen through radii of 15-60 pixels, where most taps are far ones
// (measured: every pixel clear of the plane's cut edge exactly 1; VBAO's open plane stays
// exactly 1 everywhere: vbao_test.cpp). Whether far taps still find occluders
// is the truth's to say (accuracy_test.cpp, and the report at 1080p).
#include "harness.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_slice_taps_test {

using namespace aogen;
using namespace aogen_test;

namespace {

// Per pixel, the Chebyshev distance in pixels to the nearest background pixel of `g` (a
// large value where there is none): the two-pass distance transform.
std::vector<int> chebyshev_to_background(const vulkan::gbuffer& g)
{
    const int W = g.width, H = g.height, none = 1 << 20;
    std::vector<int> d(g.depth.size());
    for (size_t i = 0; i < d.size(); ++i) d[i] = g.depth[i] >= 1.0f ? 0 : none;
    auto relax = [&](int x, int y, int dx, int dy) {
        const int u = x + dx, v = y + dy;
        if (u >= 0 && v >= 0 && u < W && v < H) d[pixel(W, x, y)] = std::min(d[pixel(W, x, y)], d[pixel(W, u, v)] + 1);
    };
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) relax(x, y, -1, 0), relax(x, y, -1, -1), relax(x, y, 0, -1), relax(x, y, 1, -1);
    for (int y = H - 1; y >= 0; --y)
        for (int x = W - 1; x >= 0; --x) relax(x, y, 1, 0), relax(x, y, 1, 1), relax(x, y, 0, 1), relax(x, y, -1, 1);
    return d;
}

} // namespace

TEST_CASE("vulkan: gtao's far taps keep an open plane open at any tilt (within 1/255)")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 256, H = 160;
    const float tan_half_fov_y = 0.7f;
    const mat4 proj = perspective(tan_half_fov_y, float(W) / H, 0.1f, 100.0f);
    for (float tilt_degrees : {0.0f, 35.0f, 70.0f, 85.0f}) {
        const vulkan::gbuffer g = tilted_plane(W, H, tan_half_fov_y, proj, tilt_degrees);
        // Taps at the plane's cut edge (background beside it) read a silhouette's texel centre
        // at any distance, as they always have: only pixels whose radius (capped at H / 2 = 80
        // pixels) stays clear of it are held to 1/255.
        const std::vector<int> far = chebyshev_to_background(g);
        for (const char* name : {"gtao-4x4-full-noblur-gbufworld-std-persp-cs", "gtao-3x3-full-noblur-gbufworld-std-persp-fs"}) {
            vulkan::chain_settings s = settings_for(proj);
            s.gtao.radius = 1.5f; // about 57 pixels at the plane's centre: three of four steps are far taps
            const vulkan::chain_result r = chain_under_test(*ctx, variant_from_name(name)).run(g, s);
            INFO(name << ", tilt " << tilt_degrees);
            size_t below_one = 0, plane = 0;
            for (size_t i = 0; i < r.ao.size(); ++i) {
                if (g.depth[i] >= 1.0f || far[i] <= 80) continue; // within the capped radius of the plane's cut edge
                ++plane, below_one += r.ao[i] < 1.0f;
                INFO("pixel " << i % W << ", " << i / W);
                REQUIRE(r.ao[i] >= 1.0f - 1.0f / 255);
            }
            std::cout << name << ", open plane tilted " << tilt_degrees << " degrees: " << below_one << " of " << plane
                      << " pixels clear of its edge below 1\n";
            CHECK(plane >= 1000); // measured: 1305 pixels at 85 degrees, 40960 (all) at 0
        }
    }
    require_clean(*ctx);
}

} // namespace unity_slice_taps_test
