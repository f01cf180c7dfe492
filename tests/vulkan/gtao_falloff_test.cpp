// GTAO's falloff and thin-occluder settings (gtao.glsl's ao_gtao_horizon_cos), on the crease:
// each only ever takes occlusion away (a sample's horizon moves toward the hemisphere's
// edge, never past its own), does so where the corner's occluders are, grows with the
// setting, and leaves open surfaces and background exactly as they were.
#include "harness.hpp"

#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_gtao_falloff_test {

using namespace aogen;
using namespace aogen_test;

namespace {

struct crease_run {
    static constexpr int W = 64, H = 40;
    mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    vulkan::gbuffer g = crease(W, H, 0.6f, proj);

    std::vector<float> ao(const vulkan::chain& c, float falloff_range, float thin_occluder) const
    {
        vulkan::chain_settings s = settings_for(proj);
        s.gtao.falloff_range = falloff_range, s.gtao.thin_occluder = thin_occluder;
        return c.run(g, s).ao;
    }
};

// Every pixel of `more` at least `less` (1/255 for rounding); how many are above it by more.
size_t count_lighter(const std::vector<float>& more, const std::vector<float>& less)
{
    REQUIRE(more.size() == less.size());
    size_t lighter = 0;
    for (size_t i = 0; i < more.size(); ++i) {
        INFO("pixel " << i << ": " << more[i] << " vs " << less[i]);
        REQUIRE(more[i] >= less[i] - 1.0f / 255);
        lighter += more[i] > less[i] + 1.0f / 255;
    }
    return lighter;
}

} // namespace

TEST_CASE("vulkan: gtao's falloff and thin-occluder compensation only remove occlusion, more as they grow")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const crease_run c;
    for (pipeline_stage stage : {pipeline_stage::compute, pipeline_stage::fragment}) {
        const variant v = variant_from_name(std::string("gtao-4x4-full-noblur-gbufworld-std-persp-") + (stage == pipeline_stage::compute ? "cs" : "fs"));
        INFO(to_name(v));
        const vulkan::chain chain = chain_under_test(*ctx, v);
        const std::vector<float> hard = c.ao(chain, 0, 0);
        // The corner is occluded under the hard cut-off: there is something to fade.
        REQUIRE(*std::min_element(hard.begin(), hard.end()) < 0.9f);
        const std::vector<float> half = c.ao(chain, 0.5f, 0), full = c.ao(chain, 1.0f, 0);
        CHECK(count_lighter(half, hard) > 0);
        CHECK(count_lighter(full, half) > 0);
        const std::vector<float> thin = c.ao(chain, 0, 2.0f), thinner = c.ao(chain, 0, 8.0f);
        CHECK(count_lighter(thin, hard) > 0);
        CHECK(count_lighter(thinner, thin) > 0);
        // Open floor, open wall and background: 1 under every setting.
        for (size_t i = 0; i < hard.size(); ++i)
            if (hard[i] == 1.0f) {
                REQUIRE(full[i] == 1.0f);
                REQUIRE(thinner[i] == 1.0f);
            }
    }
    require_clean(*ctx);
}

} // namespace unity_gtao_falloff_test
