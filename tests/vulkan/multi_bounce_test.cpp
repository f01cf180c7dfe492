// Multi-bounce (a -mb variant: variant::multi_bounce, common/core.glsl's ao_multi_bounce):
// the chain's last pass turns the visibility v it writes into the GTAO paper's fit of the
// multi-bounce visibility (Jimenez et al. 2016, eq. 10), written out here from the paper:
//     a = 2.0404 rho - 0.3324, b = -4.7951 rho + 0.6417, c = 2.7552 rho + 0.6903,
//     out = max(v, ((v a + b) v + c) v).
// The oracle is the twin without -mb, whose output is v itself rounded to 8 bits: every
// pixel of the -mb chain must be the fit of it, within what the two roundings allow — a step
// of the output, and the fit's change over a step of its input: Vulkan lets a device round a
// float to 8-bit UNORM to either neighbour (NVIDIA's H100 is 0.01/255 past half a step on a
// few pixels; lavapipe rounds to nearest). Whichever pass
// is last — the AO pass, a blur, the upsample; compute or fragment — and for albedos 0 to 1.
// Background stays exactly 1. The check can fail: the fit with the albedo read as 1 - rho
// is outside its bounds.
#include "harness.hpp"

using namespace aogen;
using namespace aogen_test;

namespace {

// The paper's fit, in double.
double paper_fit(double v, double rho)
{
    const double a = 2.0404 * rho - 0.3324, b = -4.7951 * rho + 0.6417, c = 2.7552 * rho + 0.6903;
    return std::clamp(std::max(v, ((v * a + b) * v + c) * v), 0.0, 1.0);
}

// How many pixels of `with_mb` lie outside the fit of `twin` at albedo `rho`.
size_t outside_the_fit(const std::vector<float>& twin, const std::vector<float>& with_mb, double rho, double* worst = nullptr)
{
    const double step = 1.0 / 255.0;
    size_t outside = 0;
    for (size_t i = 0; i < twin.size(); ++i) {
        const double v = twin[i], expected = paper_fit(v, rho);
        const double input_slack = std::max(std::fabs(paper_fit(std::min(v + step, 1.0), rho) - expected),
                                            std::fabs(paper_fit(std::max(v - step, 0.0), rho) - expected));
        const double off = std::fabs(with_mb[i] - expected) - (step + input_slack + 1e-6);
        if (worst) *worst = std::max(*worst, off);
        outside += off > 0;
    }
    return outside;
}

} // namespace

TEST_CASE("vulkan: a -mb variant's last pass writes the paper's multi-bounce fit of its twin's AO")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, 0.6f, proj); // floor, wall, their crease, background
    for (const char* name : {"gtao-2x3-full-noblur-gbufworld-std-persp-cs",            // last: the AO pass
                             "ssao-s16-half-bilateral-gbufworld-std-persp-cs",         // the upsample
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs-nearest",   // the denoise
                             "vbao-2x3-full-box-gbufworld-std-persp-fs",               // the box blur, fragment
                             "sao-s16-full-bilateral-gbufworld-std-persp-cs"}) {       // the bilateral's second pass
        const variant twin = variant_from_name(name);
        variant with_mb = twin;
        with_mb.multi_bounce = true;
        const vulkan::chain twin_chain = chain_under_test(*ctx, twin), mb_chain = chain_under_test(*ctx, with_mb);
        vulkan::chain_settings s = settings_for(proj);
        const std::vector<float> v = twin_chain.run(g, s).ao;
        size_t occluded = 0, background = 0;
        for (size_t i = 0; i < v.size(); ++i) occluded += v[i] < 0.9f;
        REQUIRE(occluded > v.size() / 40); // the crease is in view: the fit is checked where it bends
        for (float rho : {0.0f, 0.25f, 0.5f, 0.8f, 1.0f}) {
            INFO(to_name(with_mb) << " at albedo " << rho);
            s.finalize.albedo = rho;
            const std::vector<float> out = mb_chain.run(g, s).ao;
            REQUIRE(out.size() == v.size());
            double worst = -1;
            CHECK(outside_the_fit(v, out, rho, &worst) == 0);
            INFO("farthest outside its bound by " << worst * 255 << "/255");
            CHECK(worst <= 0);
            // Brighter as rho grows (at rho 0 the same); what reads open (1) in the twin, exactly 1.
            double sum_v = 0, sum_out = 0;
            for (size_t i = 0; i < v.size(); ++i) {
                sum_v += v[i], sum_out += out[i];
                if (v[i] == 1.0f) background += out[i] != 1.0f;
            }
            CHECK(background == 0);
            if (rho > 0.2f) CHECK(sum_out > sum_v + 0.01 * occluded);
            // The bounds can fail: the fit with the albedo read backwards lies outside them.
            if (rho != 0.5f) {
                std::vector<float> backwards(v.size());
                for (size_t i = 0; i < v.size(); ++i) backwards[i] = float(paper_fit(v[i], 1.0 - rho));
                CHECK(outside_the_fit(v, backwards, rho) > occluded / 4);
            }
        }
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: an albedo outside 0 to 1 is refused by name before any pass runs")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const variant v = variant_from_name("gtao-2x3-full-noblur-gbufworld-std-persp-cs-mb");
    const mat4 proj = perspective(0.6f, 1.5f, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(48, 32, 0.6f, proj);
    const vulkan::chain c = chain_under_test(*ctx, v);
    for (float rho : {-0.25f, 1.5f, std::nanf("")}) {
        vulkan::chain_settings s = settings_for(proj);
        s.finalize.albedo = rho;
        CHECK_THROWS_WITH(c.run(g, s), Catch::Contains("finalize.albedo") && Catch::Contains("valid: 0..1"));
    }
}
