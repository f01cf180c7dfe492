// The depth MIP chain (aogen/depth_mips.hpp, templates/prefilter.glsl): the prefilter's atlas
// against a CPU reduction of the same depth buffer (prefilter.glsl's "ONE TEXEL FROM FOUR"),
// level by level, at sizes that are and are not multiples of its 16 × 16 blocks, in standard
// and reversed depth; and the sizes and places of the levels against the picture in
// depth_mips.hpp. Whether the AO pass reads the chain right is accuracy_test.cpp's: mip
// variants against the truth.
#include "harness.hpp"

#include <aogen/depth_mips.hpp>

#include <cmath>
#include <tuple>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_depth_mips_test {

using namespace aogen;
using namespace aogen_test;

namespace {

bool background(float d, depth_convention c) { return !std::isfinite(d) || (c == depth_convention::standard ? d >= 1.0f : d <= 0.0f); }

// One texel from four, as prefilter.glsl's header says, in float; `borderline` is set when
// the plane test is within rounding of its threshold (a GPU may fuse its multiply-add there),
// and `other` is then what the other decision gives.
float reduce(float d00, float d10, float d01, float d11, depth_convention c, bool& borderline, float& other)
{
    const float d[4] = {d00, d10, d01, d11};
    bool all = true, any = false;
    for (float x : d) all = all && background(x, c), any = any || background(x, c);
    borderline = false;
    if (all) return c == depth_convention::standard ? 1.0f : 0.0f;
    float nearest = 0;
    bool first = true;
    for (float x : d)
        if (!background(x, c)) nearest = first ? x : (c == depth_convention::standard ? std::min(nearest, x) : std::max(nearest, x)), first = false;
    if (any) return nearest;
    const float spread = std::fabs(d10 - d00) + std::fabs(d01 - d00) + std::fabs(d11 - d00);
    const float planarity = std::fabs(d00 + d11 - d10 - d01);
    const float threshold = 0.25f * spread + 2.5e-7f * std::fabs(d00);
    const float mean = 0.25f * ((d00 + d10) + (d01 + d11));
    borderline = std::fabs(planarity - threshold) <= 1e-6f * threshold + 1e-30f;
    other = planarity > threshold ? mean : nearest;
    return planarity > threshold ? nearest : mean;
}

struct level {
    int w = 0, h = 0;
    std::vector<float> d;
    std::vector<bool> borderline;
    std::vector<float> other;
    float at(int x, int y) const { return d[size_t(std::min(y, h - 1)) * w + std::min(x, w - 1)]; }
};

// Levels 0 .. levels - 1 of `depth` (w × h) on the CPU.
std::vector<level> chain_on_cpu(const std::vector<float>& depth, int w, int h, int levels, depth_convention c)
{
    std::vector<level> out(1);
    out[0] = {w, h, depth, {}, {}};
    for (int l = 1; l < levels; ++l) {
        const level& below = out.back();
        level next;
        std::tie(next.w, next.h) = depth_mips::level_size(w, h, l);
        for (int y = 0; y < next.h; ++y)
            for (int x = 0; x < next.w; ++x) {
                bool borderline;
                float other = 0;
                next.d.push_back(reduce(below.at(2 * x, 2 * y), below.at(2 * x + 1, 2 * y), below.at(2 * x, 2 * y + 1), below.at(2 * x + 1, 2 * y + 1), c,
                                        borderline, other));
                next.borderline.push_back(borderline);
                next.other.push_back(other);
            }
        out.push_back(std::move(next));
    }
    return out;
}

} // namespace

TEST_CASE("depth mips: the levels' sizes and places in the atlas are depth_mips.hpp's picture")
{
    CHECK(depth_mips::level_size(1920, 1080, 1) == std::pair<int, int>{960, 540});
    CHECK(depth_mips::level_size(1920, 1080, 4) == std::pair<int, int>{120, 68}); // 1080 / 16 = 67.5, rounded up
    CHECK(depth_mips::level_size(1, 1, 4) == std::pair<int, int>{1, 1});
    CHECK(depth_mips::level_origin(1920, 1080, 1) == std::pair<int, int>{0, 0});
    CHECK(depth_mips::level_origin(1920, 1080, 2) == std::pair<int, int>{960, 0});
    CHECK(depth_mips::level_origin(1920, 1080, 3) == std::pair<int, int>{960, 270});
    CHECK(depth_mips::level_origin(1920, 1080, 4) == std::pair<int, int>{960, 405});
    CHECK(depth_mips::atlas_size(1920, 1080, 5) == std::pair<int, int>{1440, 540});
    CHECK(depth_mips::atlas_size(1920, 1080, 2) == std::pair<int, int>{960, 540});
    CHECK(depth_mips::atlas_size(1920, 1080, 1) == std::pair<int, int>{0, 0});
    // Where the column of levels 2.. is taller than level 1 (a screen 3 pixels tall).
    CHECK(depth_mips::atlas_size(64, 3, 5) == std::pair<int, int>{48, 3});
    // Which level a tap reads: texels about a tenth of its distance apart.
    CHECK(depth_mips::level_for(0.0f, 5) == 0);
    CHECK(depth_mips::level_for(19.0f, 5) == 0);
    CHECK(depth_mips::level_for(20.0f, 5) == 1);
    CHECK(depth_mips::level_for(80.0f, 5) == 3);
    CHECK(depth_mips::level_for(1e6f, 5) == 4);
    CHECK(depth_mips::level_for(1e6f, 3) == 2);
}

TEST_CASE("vulkan: the prefilter's depth MIP atlas is prefilter.glsl's reduction of the depth buffer, every level")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    for (depth_convention c : {depth_convention::standard, depth_convention::reversed})
        for (auto [W, H] : {std::pair<int, int>{64, 40}, std::pair<int, int>{61, 37}, std::pair<int, int>{5, 3}})
            for (int levels : {2, 5}) {
                const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f, c);
                vulkan::gbuffer g = crease(W, H, 0.6f, proj); // floor, wall, their crease, background beside the wall
                if (c != depth_convention::standard)
                    for (float& d : g.depth)
                        if (d == 1.0f) d = 0.0f; // the reversed conventions clear to 0
                variant v;
                v.tech = technique::gtao, v.half_resolution = false, v.blur = blur_mode::none, v.depth = c, v.depth_mips = levels;
                INFO(to_name(v) << " at " << W << "x" << H);
                const vulkan::chain ch = chain_under_test(*ctx, v);
                const vulkan::gpu_gbuffer uploaded(*ctx, g);
                const std::unique_ptr<vulkan::bound_chain> b = ch.bind(uploaded, settings_for(proj));
                const vulkan::chain_result r = b->run_once(-7.0f); // a value no texel of the chain holds
                REQUIRE(r.passes.front() == "prefilter");
                const std::vector<float> atlas = b->read_output(0);
                const int atlas_w = b->output_size(0).first;
                const std::vector<level> cpu = chain_on_cpu(g.depth, W, H, levels, c);
                size_t means = 0, picks = 0; // texels that are their children's mean, or one of them
                for (int l = 1; l < levels; ++l) {
                    const auto [ox, oy] = depth_mips::level_origin(W, H, l);
                    const level& e = cpu[l];
                    for (int y = 0; y < e.h; ++y)
                        for (int x = 0; x < e.w; ++x) {
                            const size_t i = size_t(y) * e.w + x;
                            const float gpu = atlas[size_t(oy + y) * atlas_w + ox + x];
                            INFO("level " << l << " texel " << x << ", " << y << ": gpu " << gpu << ", cpu " << e.d[i]);
                            REQUIRE((gpu == e.d[i] || (e.borderline[i] && gpu == e.other[i])));
                            const level& b = cpu[l - 1];
                            const bool child = gpu == b.at(2 * x, 2 * y) || gpu == b.at(2 * x + 1, 2 * y) || gpu == b.at(2 * x, 2 * y + 1) ||
                                               gpu == b.at(2 * x + 1, 2 * y + 1);
                            if (!background(gpu, c)) ++(child ? picks : means);
                        }
                }
                if (W > 8) {
                    CHECK(means > 0); // both rules were exercised
                    CHECK(picks > 0);
                }
            }
    require_clean(*ctx);
}

TEST_CASE("vulkan: a -mipN variant reads its far taps from the chain: its twin's AO but at silhouettes, and open planes stay open")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    // 640 × 360: the AO radius spans 50-150 pixels on the crease, so the far taps read levels 1-3.
    const int W = 640, H = 360;
    for (depth_convention c : {depth_convention::standard, depth_convention::reversed})
        for (const char* base : {"gtao-2x3-full-noblur-gbufworld", "vbao-2x3-full-noblur-gbufworld", "ssao-s16-full-noblur-gbufworld"}) {
            const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f, c);
            vulkan::gbuffer g = crease(W, H, 0.6f, proj);
            if (c != depth_convention::standard)
                for (float& d : g.depth)
                    if (d == 1.0f) d = 0.0f;
            const std::string suffix = std::string(c == depth_convention::standard ? "-std" : "-rev") + "-persp-cs";
            const variant twin = variant_from_name(base + suffix), mip = variant_from_name(base + suffix + "-mip5");
            INFO(to_name(mip));
            const vulkan::chain_result a = chain_under_test(*ctx, twin).run(g, settings_for(proj));
            const vulkan::chain_result b = chain_under_test(*ctx, mip).run(g, settings_for(proj));
            REQUIRE(a.ao.size() == b.ao.size());
            double sum = 0;
            size_t differ = 0, open = 0, open_kept = 0;
            for (size_t i = 0; i < a.ao.size(); ++i) {
                const double d = std::fabs(double(a.ao[i]) - b.ao[i]);
                sum += d, differ += d > 0;
                if (a.ao[i] == 1.0f) ++open, open_kept += b.ao[i] >= 1.0f - 1.0f / 255;
            }
            const double mean = sum / a.ao.size();
            std::cout << to_name(mip) << ": mean |mip - twin| " << mean * 255 << "/255, " << differ << " of " << a.ao.size()
                      << " pixels differ; open " << open << ", kept " << open_kept << "\n";
            // Over a plane a coarse level gives the plane's depth under the tap as level 0 does
            // (depth_mips.hpp), so the two agree bit for bit but where far taps meet a silhouette:
            // few pixels differ, and little. Where they do, the chain was read.
            CHECK(differ > 0);
            CHECK(mean <= 1.0 / 255);
            CHECK(open_kept >= open - open / 200); // measured: 0.24 % of the open pixels lose 1/255 or more beside silhouettes (GTAO)
        }
    require_clean(*ctx);
}

} // namespace unity_depth_mips_test
