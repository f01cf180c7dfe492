// The denoise blurs (5 x 5 and 3 x 3) and the depth-aware upsample, each against a CPU
// implementation of its formula (blur_denoise.glsl's, blur_denoise3.glsl's and upsample.glsl's headers) applied to the GPU's own input:
// the AO of the same variant without the pass (blur none / upsample nearest), whose AO pass
// compiles to the same shader, so both sides filter the same 8-bit values.
#include "harness.hpp"

#include <aogen/params.hpp>

#include <cmath>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_denoise_upsample_test {

using namespace aogen;
using namespace aogen_test;

namespace {

// View-space z of every screen pixel of `g` (common/depth.glsl's ao_view_z, in double);
// NaN on background.
std::vector<double> view_z(const vulkan::gbuffer& g, const mat4& proj)
{
    const mat4 inv = inverse(proj);
    std::vector<double> z(g.depth.size(), std::nan(""));
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const float d = g.depth[pixel(g.width, x, y)];
            if (!(d < 1.0f)) continue;
            const float u = (x + 0.5f) / g.width, v = (y + 0.5f) / g.height;
            const vec4 p = inv * vec4{u * 2 - 1, 1 - v * 2, d, 1};
            z[pixel(g.width, x, y)] = double(p.z) / double(p.w);
        }
    return z;
}

// The crease at 64 x 40: open floor and wall, the occluded corner, and silhouettes where the
// wall's sides stand in front of the floor and against background.
struct scene {
    static constexpr int W = 64, H = 40;
    mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    vulkan::gbuffer g = crease(W, H, 0.6f, proj);
    std::vector<double> z = view_z(g, proj);
    float sharpness = blur_params{}.linear_sharpness;
};

// blur_denoise.glsl on the CPU: `in` is the target (tw × th), a target pixel's depth is its
// full pixel's. A tap weighs W[|dx|] W[|dy|] times the product of the edge weights
// exp(-|Δz| · sharpness) on its path from the centre: along the centre's row to the tap's
// column, then along that column; a pixel that is no tap (off the target, background) cuts
// the path.
std::vector<double> denoise_on_cpu(const scene& s, const variant& v, const std::vector<float>& in, int tw, int th)
{
    // The weights of offsets 0, ±1, ±2, written here rather than read from params.hpp (the
    // constants the shader is generated from), so that a change there shows: offsets 4 apart
    // share a phase of the 4 × 4 noise tile, and (1/2, 1, 1, 1, 1/2) gives each phase the same
    // weight (blur_denoise.glsl's header).
    const double W[] = {1.0, 1.0, 0.5};
    const int R = 2;
    const int k = v.half_resolution ? 2 : 1;
    auto z_at = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= tw || y >= th) return std::nan("");
        return s.z[pixel(s.W, std::min(x * k, s.W - 1), std::min(y * k, s.H - 1))];
    };
    auto edge = [&](int ax, int ay, int bx, int by) {
        const double za = z_at(ax, ay), zb = z_at(bx, by);
        return std::isnan(za) || std::isnan(zb) ? 0.0 : std::exp(-std::fabs(za - zb) * s.sharpness);
    };
    // The product of the edges from (x, y0) to (x, y0 + dy) along a column, or along a row.
    auto column_path = [&](int x, int y0, int dy) {
        double e = 1;
        for (int step = dy > 0 ? 1 : -1, y = y0; y != y0 + dy; y += step) e *= edge(x, y, x, y + step);
        return e;
    };
    auto row_path = [&](int x0, int y, int dx) {
        double e = 1;
        for (int step = dx > 0 ? 1 : -1, x = x0; x != x0 + dx; x += step) e *= edge(x, y, x + step, y);
        return e;
    };
    std::vector<double> out(in.size());
    for (int y = 0; y < th; ++y)
        for (int x = 0; x < tw; ++x) {
            if (std::isnan(z_at(x, y))) {
                out[pixel(tw, x, y)] = 1.0;
                continue;
            }
            double sum = 0, weight = 0;
            for (int dy = -R; dy <= R; ++dy)
                for (int dx = -R; dx <= R; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (std::isnan(z_at(qx, qy))) continue;
                    const double w = W[std::abs(dx)] * W[std::abs(dy)] * row_path(x, y, dx) * column_path(qx, y, dy);
                    sum += w * in[pixel(tw, qx, qy)], weight += w;
                }
            out[pixel(tw, x, y)] = sum / weight;
        }
    return out;
}

// blur_denoise3.glsl on the CPU, with the edges of common/edges.glsl: `in` is the target
// (tw × th), a target pixel's depth is its full pixel's. An edge between neighbours is
// exp(-16 |Δz| / min |z|), stored in 8 bits; a side tap weighs 1/2 times its edge, a diagonal
// 1/4 times the mean of its two paths' products (row then column, column then row).
std::vector<double> denoise3_on_cpu(const scene& s, const variant& v, const std::vector<float>& in, int tw, int th)
{
    // Written here rather than read from params.hpp (the shader's source), so a change shows.
    const double W[] = {1.0, 0.5}, sharpness = 16.0;
    const int k = v.half_resolution ? 2 : 1;
    auto z_at = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= tw || y >= th) return std::nan("");
        return std::fabs(s.z[pixel(s.W, std::min(x * k, s.W - 1), std::min(y * k, s.H - 1))]);
    };
    auto edge = [&](int ax, int ay, int bx, int by) { // what the AO pass stores: 8-bit unorm
        const double za = z_at(ax, ay), zb = z_at(bx, by);
        if (std::isnan(za) || std::isnan(zb)) return 0.0;
        return std::round(std::exp(-sharpness * std::fabs(za - zb) / std::min(za, zb)) * 255.0) / 255.0;
    };
    std::vector<double> out(in.size());
    for (int y = 0; y < th; ++y)
        for (int x = 0; x < tw; ++x) {
            double sum = in[pixel(tw, x, y)], weight = 1;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if (dx == 0 && dy == 0) continue;
                    const int qx = x + dx, qy = y + dy;
                    const double e = dy == 0   ? edge(x, y, qx, y)
                                     : dx == 0 ? edge(x, y, x, qy)
                                               : 0.5 * (edge(x, y, qx, y) * edge(qx, y, qx, qy) + edge(x, y, x, qy) * edge(x, qy, qx, qy));
                    const double w = W[std::abs(dx)] * W[std::abs(dy)] * e;
                    if (w > 0) sum += w * in[pixel(tw, qx, qy)], weight += w;
                }
            out[pixel(tw, x, y)] = sum / weight; // background: no edges, its own 1
        }
    return out;
}

// upsample.glsl on the CPU: `in` is the half-resolution target (tw × th).
std::vector<double> upsample_on_cpu(const scene& s, const std::vector<float>& in, int tw, int th)
{
    std::vector<double> out(size_t(s.W) * s.H);
    for (int y = 0; y < s.H; ++y)
        for (int x = 0; x < s.W; ++x) {
            const double z = s.z[pixel(s.W, x, y)];
            if (std::isnan(z)) {
                out[pixel(s.W, x, y)] = 1.0;
                continue;
            }
            const int qx0 = std::min(x / 2, tw - 1), qy0 = std::min(y / 2, th - 1);
            const double fx = (x - 2 * qx0) * 0.5, fy = (y - 2 * qy0) * 0.5;
            double sum = 0, weight = 0, nearest = in[pixel(tw, qx0, qy0)], nearest_dz = -1;
            for (int j = 0; j <= 1; ++j)
                for (int i = 0; i <= 1; ++i) {
                    const int qx = qx0 + i, qy = qy0 + j;
                    if (qx >= tw || qy >= th) continue;
                    const double qz = s.z[pixel(s.W, std::min(2 * qx, s.W - 1), std::min(2 * qy, s.H - 1))];
                    if (std::isnan(qz)) continue;
                    const double dz = std::fabs(qz - z), ao = in[pixel(tw, qx, qy)];
                    if (nearest_dz < 0 || dz < nearest_dz) nearest_dz = dz, nearest = ao;
                    const double w = (i ? fx : 1 - fx) * (j ? fy : 1 - fy) * std::exp(-dz * s.sharpness);
                    if (w > 0) sum += w * ao, weight += w;
                }
            out[pixel(s.W, x, y)] = weight > 0 ? sum / weight : nearest;
        }
    return out;
}

// |gpu - cpu| <= 1/255 + rounding everywhere; returns how many pixels the pass moved from
// `before` by more than 1/255 (so a pass that did nothing cannot pass as its formula).
size_t require_equal(const std::vector<float>& gpu, const std::vector<double>& cpu, const std::vector<float>& before, int w)
{
    REQUIRE(gpu.size() == cpu.size());
    size_t moved = 0;
    for (size_t i = 0; i < gpu.size(); ++i) {
        INFO("pixel " << i % w << ", " << i / w << ": gpu " << gpu[i] << ", cpu " << cpu[i]);
        REQUIRE(std::fabs(gpu[i] - cpu[i]) <= 1.0 / 255 + 1e-4);
        if (!before.empty() && std::fabs(cpu[i] - before[i]) > 1.0 / 255) ++moved;
    }
    return moved;
}

// A variant whose last pass is its blur: `blur` at `half` resolution (no upsample: the
// blur's own output), in tiles that are not square (8 x 4) and that the 64x40 screen is not
// a multiple of at half resolution.
variant filter_variant(technique t, pipeline_stage stage, bool half, blur_mode blur)
{
    variant v;
    v.tech = t, v.stage = stage, v.half_resolution = half;
    v.upsample = upsample_mode::nearest;
    v.blur = blur;
    v.workgroup_x = 8, v.workgroup_y = 4;
    return v;
}

using filter_on_cpu = std::vector<double> (*)(const scene&, const variant&, const std::vector<float>&, int, int);

// `v`'s chain (AO pass, then `pass`) equals `cpu` applied to the AO of its twin without a blur
// (whose AO pass computes the same AO), and moves enough pixels that a pass doing nothing fails.
void require_filter_of_raw(vulkan::context& ctx, const scene& s, const variant& v, const char* pass, filter_on_cpu cpu)
{
    variant raw = v;
    raw.blur = blur_mode::none;
    INFO(to_name(v));
    const vulkan::chain_result in = chain_under_test(ctx, raw).run(s.g, settings_for(s.proj));
    const vulkan::chain_result out = chain_under_test(ctx, v).run(s.g, settings_for(s.proj));
    REQUIRE(out.passes == std::vector<std::string>{"ao", pass});
    REQUIRE(out.width == in.width);
    const size_t moved = require_equal(out.ao, cpu(s, v, in.ao, in.width, in.height), in.ao, in.width);
    CHECK(moved > in.ao.size() / 20); // the noise pattern is there to remove
}

} // namespace

TEST_CASE("vulkan: the denoise pass is blur_denoise.glsl's 5x5 edge-aware filter of the AO pass's output (edges along a row, then a column)")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const scene s;
    for (pipeline_stage stage : {pipeline_stage::compute, pipeline_stage::fragment})
        for (technique t : {technique::ssao, technique::gtao})
            for (bool half : {false, true}) require_filter_of_raw(*ctx, s, filter_variant(t, stage, half, blur_mode::denoise), "blur_denoise", denoise_on_cpu);
    require_clean(*ctx);
}

TEST_CASE("vulkan: the 3x3 denoise is blur_denoise3.glsl's filter of the AO pass's output, with the edges the AO pass wrote (common/edges.glsl)")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const scene s;
    for (technique t : {technique::ssao, technique::gtao})
        for (bool half : {false, true})
            require_filter_of_raw(*ctx, s, filter_variant(t, pipeline_stage::compute, half, blur_mode::denoise3), "blur_denoise3", denoise3_on_cpu);
    require_clean(*ctx);
}

TEST_CASE("vulkan: the depth-aware upsample is upsample.glsl's joint bilateral upsample of the half-resolution target")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const scene s;
    for (pipeline_stage stage : {pipeline_stage::compute, pipeline_stage::fragment})
        for (blur_mode blur : {blur_mode::none, blur_mode::bilateral}) {
            variant v;
            v.tech = technique::gtao, v.stage = stage, v.blur = blur;
            variant nearest = v;
            nearest.upsample = upsample_mode::nearest;
            INFO(to_name(v));
            const vulkan::chain_result target = chain_under_test(*ctx, nearest).run(s.g, settings_for(s.proj));
            const vulkan::chain_result out = chain_under_test(*ctx, v).run(s.g, settings_for(s.proj));
            REQUIRE(out.passes.back() == "upsample");
            REQUIRE(out.width == s.W);
            REQUIRE(out.height == s.H);
            // What nearest upsampling shows: target pixel (x / 2, y / 2).
            std::vector<float> blocky(out.ao.size());
            for (int y = 0; y < s.H; ++y)
                for (int x = 0; x < s.W; ++x) blocky[pixel(s.W, x, y)] = target.ao[pixel(target.width, x / 2, y / 2)];
            const size_t moved = require_equal(out.ao, upsample_on_cpu(s, target.ao, target.width, target.height), blocky, s.W);
            CHECK(moved > 0);
            // Screen pixels a target texel stands for keep its value exactly.
            for (int y = 0; y < s.H; y += 2)
                for (int x = 0; x < s.W; x += 2) REQUIRE(out.ao[pixel(s.W, x, y)] == blocky[pixel(s.W, x, y)]);
        }
    require_clean(*ctx);
}

} // namespace unity_denoise_upsample_test
