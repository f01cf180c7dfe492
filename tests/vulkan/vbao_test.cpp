// VBAO on the Vulkan harness (lavapipe in CI), validation layer on: the contract every
// technique keeps (a facing plane unoccluded, background exactly 1, every value finite),
// an open plane exactly 1 at any tilt, to its silhouette and the screen's edges (its own
// samples lie on its tangent plane and must mark no sector: a sector is 1/64 of a pixel's
// visibility with two slices, so there is no rounding slack to hide in), and what the bitmask is for: with a small thickness the floor around a
// thin floating plate is less occluded than GTAO makes it, and closer to the truth, which
// the test integrates itself (cosine-weighted rays from each floor point against the plate,
// within the AO radius).
#include "harness.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_vbao_test {

using namespace aogen;
using namespace aogen_test;

namespace {

variant vbao_variant(int slices, int steps, bool half, pipeline_stage stage)
{
    variant v;
    v.tech = technique::vbao;
    v.slices = slices, v.steps = steps;
    v.half_resolution = half;
    v.blur = blur_mode::none;
    v.stage = stage;
    return v;
}

// A camera at `eye` looking at `target`, world z up: its view basis (right, up, forward).
struct view_basis {
    vec3 eye, right, up, forward;
};
view_basis look_at(vec3 eye, vec3 target)
{
    const vec3 f = (target - eye) * (1.0f / length(target - eye));
    const vec3 r0 = cross(f, vec3{0, 0, 1});
    const vec3 r = r0 * (1.0f / length(r0));
    return {eye, r, cross(r, f), f};
}
vec3 to_view(const view_basis& b, vec3 w) { return {dot(w, b.right), dot(w, b.up), -dot(w, b.forward)}; }

// The world ray through pixel (x, y)'s centre, and the view-space point at parameter t of it.
struct pixel_ray {
    vec3 view_dir, world_dir;
};
pixel_ray ray_of(const view_basis& b, int w, int h, int x, int y, float tan_half_fov_y)
{
    const float aspect = float(w) / float(h);
    const vec3 d{(2.0f * (x + 0.5f) / w - 1.0f) * aspect * tan_half_fov_y, (1.0f - 2.0f * (y + 0.5f) / h) * tan_half_fov_y, -1.0f};
    return {d, b.right * d.x + b.up * d.y + b.forward * 1.0f};
}

// The floor z = 0 and an infinitely thin plate z = plate_z over |x| < plate_x, |y| < plate_y.
constexpr float plate_z = 0.3f, plate_x = 2.0f, plate_y = 0.2f;
bool on_plate(vec3 p) { return std::fabs(p.x) < plate_x && std::fabs(p.y) < plate_y; }

// AO of floor point p (normal +z) against the plate within radius R: Malley's method on a
// grid of the unit disk, each direction's ray tested against the plate's plane.
double plate_truth(vec3 p, double R)
{
    const int n = 96;
    int hit = 0, total = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = (i + 0.5) / n * 2 - 1, v = (j + 0.5) / n * 2 - 1;
            if (u * u + v * v >= 1) continue;
            ++total;
            const double z = std::sqrt(1 - u * u - v * v);
            const double t = (plate_z - p.z) / z; // the direction is unit: t is the distance
            if (t > R) continue;
            if (on_plate({float(p.x + t * u), float(p.y + t * v), plate_z})) ++hit;
        }
    return 1.0 - double(hit) / total;
}

} // namespace

TEST_CASE("vulkan: vbao, a plane facing the camera is unoccluded, background is exactly 1")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    check_facing_plane(*ctx, vbao_variant(2, 3, false, pipeline_stage::compute));
    check_facing_plane(*ctx, vbao_variant(3, 3, true, pipeline_stage::compute));
    check_facing_plane(*ctx, vbao_variant(1, 2, false, pipeline_stage::fragment));
}

TEST_CASE("vulkan: vbao, an open plane is exactly 1 at any tilt, whatever the thickness")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 96, H = 64;
    const float tan_half_fov_y = 0.7f;
    const mat4 proj = perspective(tan_half_fov_y, float(W) / H, 0.1f, 100.0f);
    for (float tilt_degrees : {0.0f, 35.0f, 70.0f, 85.0f}) {
        const vulkan::gbuffer g = tilted_plane(W, H, tan_half_fov_y, proj, tilt_degrees);
        for (float thickness : {0.01f, 0.5f, 100.0f}) {
            const variant v = vbao_variant(4, 4, false, pipeline_stage::compute);
            vulkan::chain_settings s = settings_for(proj);
            s.vbao.radius = 1.5f, s.vbao.thickness = thickness;
            const vulkan::chain_result r = chain_under_test(*ctx, v).run(g, s);
            INFO("tilt " << tilt_degrees << " thickness " << thickness);
            for (size_t i = 0; i < r.ao.size(); ++i) {
                INFO("pixel " << i % W << ", " << i / W << (g.depth[i] < 1.0f ? " (plane)" : " (background)"));
                REQUIRE(r.ao[i] == 1.0f);
            }
        }
    }
    require_clean(*ctx);
}

TEST_CASE("vulkan: vbao with a small thickness occludes less than gtao around a thin plate, and nearer the truth")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 160, H = 120;
    const float tan_half_fov_y = 0.45f;
    const mat4 proj = perspective(tan_half_fov_y, float(W) / H, 0.1f, 100.0f);
    // From 1.2 above the floor, 3 in front of the plate: the floor under and behind the plate
    // is seen through the gap, just below the plate on screen -- where a horizon taken from
    // the plate shadows it as if a wall stood there.
    const view_basis cam = look_at({0, -3, 1.2f}, {0, 0.3f, 0});
    vulkan::gbuffer g = cleared(W, H);
    std::vector<double> truth(size_t(W) * H, -1.0); // -1: not scored
    const double R = 1.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const pixel_ray ray = ray_of(cam, W, H, x, y, tan_half_fov_y);
            float t = 1e30f;
            bool plate = false;
            if (ray.world_dir.z < 0.0f) {
                const float tp = (plate_z - cam.eye.z) / ray.world_dir.z;
                if (on_plate(cam.eye + ray.world_dir * tp)) t = tp, plate = true;
                else t = -cam.eye.z / ray.world_dir.z;
            }
            if (t > 90.0f) continue;
            const size_t i = pixel(W, x, y);
            g.depth[i] = depth_of(proj, ray.view_dir * t);
            set_normal(g, i, to_view(cam, {0, 0, 1}));
            const vec3 p = cam.eye + ray.world_dir * t;
            // Scored: floor points within R of the plate's middle section, not near its ends.
            if (!plate && std::fabs(p.x) < 1.0f && p.y > -plate_y && p.y < plate_y + 0.6f) truth[i] = plate_truth(p, R);
        }
    auto run = [&](technique tech, float thickness) {
        variant v = vbao_variant(8, 8, false, pipeline_stage::compute);
        v.tech = tech;
        vulkan::chain_settings s = settings_for(proj);
        s.gtao.radius = gtao_params::radius_per_ao_radius * float(R);
        s.vbao.radius = vbao_params::radius_per_ao_radius * float(R);
        s.vbao.thickness = thickness;
        s.vbao.strength = s.gtao.strength = 1.0f;
        return chain_under_test(*ctx, v).run(g, s).ao;
    };
    struct score {
        double mean_ao = 0, mean_truth = 0, mae = 0;
        int n = 0;
    };
    auto score_of = [&](const std::vector<float>& ao) {
        score s;
        for (size_t i = 0; i < ao.size(); ++i) {
            if (truth[i] < 0) continue;
            REQUIRE(std::isfinite(ao[i]));
            s.mean_ao += ao[i], s.mean_truth += truth[i], s.mae += std::fabs(ao[i] - truth[i]), ++s.n;
        }
        REQUIRE(s.n > 200);
        s.mean_ao /= s.n, s.mean_truth /= s.n, s.mae /= s.n;
        return s;
    };
    const score gtao = score_of(run(technique::gtao, 0.5f));
    // 0.3 of the radius (0.23 at R = 1): the plate itself has no thickness, but 8 samples per
    // side lie 0.1 apart, and each sample's wedge must reach its neighbour's for the plate to
    // read as one piece (at 0.05 the plate reads as a comb of thin wedges, too light: 0.94).
    const score thin = score_of(run(technique::vbao, 0.3f));
    const score deep = score_of(run(technique::vbao, 100.0f)); // every sample infinitely deep: horizons
    INFO("scored pixels " << thin.n << ", truth mean " << thin.mean_truth);
    INFO("gtao mean " << gtao.mean_ao << " MAE " << gtao.mae);
    INFO("vbao thin mean " << thin.mean_ao << " MAE " << thin.mae);
    INFO("vbao deep mean " << deep.mean_ao << " MAE " << deep.mae);
    CHECK(thin.mean_ao > gtao.mean_ao + 0.2); // less occlusion behind the thin plate (truth 0.67, GTAO 0.26)
    CHECK(thin.mae < 0.5 * gtao.mae);         // and nearer the truth (0.11 against 0.44)
    CHECK(thin.mae < deep.mae);                // the thickness is what does it
    CHECK(std::fabs(deep.mean_ao - gtao.mean_ao) < 0.1); // infinitely deep samples: about GTAO's horizons
    require_clean(*ctx);
}

} // namespace unity_vbao_test
