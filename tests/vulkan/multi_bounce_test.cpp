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
//   -mbg reads each pixel's albedo from the G-buffer instead: the same bounds hold with the
// albedo's luminance at the screen pixel each output pixel stands for (the harness's test
// albedo changes from pixel to pixel and channel to channel, so another pixel or one channel
// is caught); a grey G-buffer of rho gives -mb's output at rho.
#include "harness.hpp"

#include <array>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_multi_bounce_test {

using namespace aogen;
using namespace aogen_test;

namespace {

// The paper's fit, in double.
double paper_fit(double v, double rho)
{
    const double a = 2.0404 * rho - 0.3324, b = -4.7951 * rho + 0.6417, c = 2.7552 * rho + 0.6903;
    return std::clamp(std::max(v, ((v * a + b) * v + c) * v), 0.0, 1.0);
}

// How many pixels of `with_mb` lie outside the fit of `twin` at each pixel's albedo rho[i].
size_t outside_the_fit(const std::vector<float>& twin, const std::vector<float>& with_mb, const std::vector<double>& rho, double* worst = nullptr)
{
    const double step = 1.0 / 255.0;
    size_t outside = 0;
    for (size_t i = 0; i < twin.size(); ++i) {
        const double v = twin[i], expected = paper_fit(v, rho[i]);
        const double input_slack = std::max(std::fabs(paper_fit(std::min(v + step, 1.0), rho[i]) - expected),
                                            std::fabs(paper_fit(std::max(v - step, 0.0), rho[i]) - expected));
        const double off = std::fabs(with_mb[i] - expected) - (step + input_slack + 1e-6);
        if (worst) *worst = std::max(*worst, off);
        outside += off > 0;
    }
    return outside;
}

// The same at one albedo for every pixel.
size_t outside_the_fit(const std::vector<float>& twin, const std::vector<float>& with_mb, double rho, double* worst = nullptr)
{
    return outside_the_fit(twin, with_mb, std::vector<double>(twin.size(), rho), worst);
}

// The albedo weighed per channel (`weights` for R, G, B) at each of a w × h output's pixels,
// pixel p standing for screen pixel scale·p, clamped to the screen.
std::vector<double> albedo_at_outputs(const vulkan::gbuffer& g, int w, int h, int scale, const std::array<double, 3>& weights)
{
    std::vector<double> rho;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = static_cast<size_t>(std::min(scale * y, g.height - 1)) * g.width + std::min(scale * x, g.width - 1);
            rho.push_back(weights[0] * g.albedo[4 * i] + weights[1] * g.albedo[4 * i + 1] + weights[2] * g.albedo[4 * i + 2]);
        }
    return rho;
}

// The albedo a -mbg chain must apply: the luminance (Rec. 709) of the G-buffer's albedo at
// the screen pixel each output pixel stands for -- itself, or at half resolution without the
// upsample (output_scale 2) the pixel 2p.
constexpr std::array<double, 3> rec709_luminance{0.2126, 0.7152, 0.0722};
constexpr std::array<double, 3> red_only{1.0, 0.0, 0.0};

// The fit of `twin` at each pixel's `rho`, as a chain would write it.
std::vector<float> fit_of(const std::vector<float>& twin, const std::vector<double>& rho)
{
    std::vector<float> out(twin.size());
    for (size_t i = 0; i < twin.size(); ++i) out[i] = float(paper_fit(twin[i], rho[i]));
    return out;
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
        with_mb.multi_bounce = multi_bounce_mode::uniform_albedo;
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

TEST_CASE("vulkan: a -mbg variant's last pass writes the fit at each pixel's albedo from the G-buffer")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    constexpr int W = 96, H = 64;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, 0.6f, proj); // with the harness's test albedo
    REQUIRE(g.albedo.size() == size_t(W) * H * 4);
    const vulkan::chain_settings s = settings_for(proj);
    for (const char* name : {"gtao-2x3-full-noblur-gbufworld-std-persp-cs",               // last: the AO pass
                             "ssao-s16-half-bilateral-gbufworld-std-persp-cs",            // the upsample (screen pixels)
                             "vbao-2x2-half-noblur-gbufworld-std-persp-cs-nearest",       // a half-resolution AO pass: pixel 2p
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs-nearest",      // the denoise at half resolution
                             "gtao-2x3-half-box-gbufworld-std-persp-fs-nearest"}) {       // the box blur, fragment, half resolution
        const variant twin = variant_from_name(name);
        variant with_mbg = twin, with_mb = twin;
        with_mbg.multi_bounce = multi_bounce_mode::gbuffer_albedo;
        with_mb.multi_bounce = multi_bounce_mode::uniform_albedo;
        INFO(to_name(with_mbg));
        const vulkan::chain_result v = chain_under_test(*ctx, twin).run(g, s);
        const vulkan::chain mbg_chain = chain_under_test(*ctx, with_mbg);
        const vulkan::chain_result out = mbg_chain.run(g, s);
        REQUIRE(out.ao.size() == v.ao.size());
        size_t occluded = 0;
        for (float x : v.ao) occluded += x < 0.9f;
        REQUIRE(occluded > v.ao.size() / 40);
        const int scale = output_scale(twin);
        const std::vector<double> rho = albedo_at_outputs(g, v.width, v.height, scale, rec709_luminance);
        double worst = -1;
        CHECK(outside_the_fit(v.ao, out.ao, rho, &worst) == 0);
        INFO("farthest outside its bound by " << worst * 255 << "/255");
        CHECK(worst <= 0);
        // The bounds can fail: the red channel alone, and at half resolution the albedo at the
        // output pixel's own coordinates (not its screen pixel's), lie outside them.
        CHECK(outside_the_fit(v.ao, fit_of(v.ao, albedo_at_outputs(g, v.width, v.height, scale, red_only)), rho) > occluded / 4);
        if (scale == 2)
            CHECK(outside_the_fit(v.ao, fit_of(v.ao, albedo_at_outputs(g, v.width, v.height, 1, rec709_luminance)), rho) > occluded / 4);
        // A grey G-buffer of rho is -mb at rho, within the step the float luminance may round.
        for (float grey : {0.3f, 0.9f}) {
            vulkan::chain_settings at = s;
            at.finalize.albedo = grey;
            const std::vector<float> mb = chain_under_test(*ctx, with_mb).run(g, at).ao;
            const std::vector<float> mbg = mbg_chain.run(with_uniform_albedo(g, grey), s).ao;
            size_t identical = 0, farther = 0;
            for (size_t i = 0; i < mb.size(); ++i) identical += mb[i] == mbg[i], farther += std::fabs(mb[i] - mbg[i]) > 1.5f / 255.0f;
            CHECK(farther == 0);
            CHECK(identical >= mb.size() * 99 / 100);
        }
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: a -mbg chain bound to a G-buffer without albedo is refused by name")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const mat4 proj = perspective(0.6f, 1.5f, 0.1f, 100.0f);
    vulkan::gbuffer g = crease(48, 32, 0.6f, proj);
    g.albedo.clear();
    const vulkan::chain c = chain_under_test(*ctx, variant_from_name("gtao-2x3-full-noblur-gbufworld-std-persp-cs-mbg"));
    CHECK_THROWS_WITH(c.run(g, settings_for(proj)), Catch::Contains("reads the albedo G-buffer (-mbg), and the G-buffer has none"));
    g.albedo.assign(7, 0.5f);
    CHECK_THROWS_WITH(c.run(g, settings_for(proj)), Catch::Contains("albedo of 7 values (valid: width × height × 4, or none)"));
}

} // namespace unity_multi_bounce_test
