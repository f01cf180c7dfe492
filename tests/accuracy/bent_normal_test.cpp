// Bent normals against the truth: a -bn variant's bent normal (gtao.glsl's THE BENT NORMAL,
// in view space, turned to world space as the report turns it) against the cosine-weighted
// mean of the unoccluded directions that the Embree reference traces (aogen_truth's
// estimate::bent_normal), at 160 x 90 on ten built-in scenes: the eight analytic ones and
// two meshes. For gtao-3x3-half-denoise-bn (the goal) and VBAO's High preset,
// vbao-3x3-half-bilateral-bn, at default parameters:
//   - a mean angular error of at most 10 degrees over the ten scenes (the bar), and
//     below the surface normal's own (2.5 degrees: the truth leans little on open ground, so
//     the bar alone would pass the normal it read);
//   - it is a bent normal and not the surface normal: on the pixels whose true bent normal
//     leans 10 degrees or more from the surface normal (corners, creases, under objects),
//     the variant's error is at most half the surface normal's. A shader that wrote the
//     normal it read, or leaned it the wrong way, fails this (tests/mutants/mutants.json).
#include "accuracy/truth_scenes.hpp"

#include <aogen_report/metrics.hpp>
#include <aogen_report/scene_bench.hpp>

#include <iostream>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_bent_normal_test {

using namespace aogen;
using namespace aogen_test;

namespace {

const char* const scenes_with_normals[] = {"crease", "groove", "wall", "sphere_on_plane", "room", "stairs", "plank", "far_floor", "engine", "teapots"};

// `v`'s bent normals on `t` (frame 0, the report's default settings), in world space, 3 floats
// a pixel at full resolution.
std::vector<float> world_bent_normals(vulkan::context& ctx, const variant& v, const truth_scene& t)
{
    const vulkan::chain_result r = chain_under_test(ctx, v).run(gbuffer_for(v, t), aogen_report::default_settings(v, t.scene));
    REQUIRE(r.width == width);
    REQUIRE(r.height == height);
    REQUIRE(r.bent_normal.size() == 3 * r.ao.size());
    return aogen_report::scene_bench::view_to_world(r.bent_normal, aogen_report::for_variant(t.scene, v).camera.world_to_view());
}

// The surface normals the reference was traced with (world space, facing the camera), 3 floats a pixel.
std::vector<float> surface_normals(const truth_scene& t)
{
    scenes::gbuffer_options world;
    world.use_scene_normals = false;
    world.normals = scenes::normal_space::world;
    const scenes::gbuffer g = scenes::render_gbuffer(t.scene, *t.tracer, world);
    std::vector<float> n(3 * size_t(g.width) * g.height);
    for (size_t i = 0; i < n.size() / 3; ++i)
        for (int c = 0; c < 3; ++c) n[3 * i + c] = g.normals[4 * i + c];
    return n;
}

// The two checks of the header for `name`, printing each scene's numbers.
void check_bent_normals(const char* name)
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const variant v = variant_from_name(name);
    double sum_mean = 0, sum_plain = 0, bent_error = 0, normal_error = 0;
    size_t bent_pixels = 0;
    for (const char* scene : scenes_with_normals) {
        const truth_scene& t = truth_of(scene);
        const std::vector<float> bent = world_bent_normals(*ctx, v, t), surface = surface_normals(t);
        const aogen_report::bent_normal_metrics m = aogen_report::compare_bent_normals(bent, t.truth.bent_normal, t.truth.valid);
        const aogen_report::bent_normal_metrics plain = aogen_report::compare_bent_normals(surface, t.truth.bent_normal, t.truth.valid);
        REQUIRE(m.pixels > 0);
        CHECK(m.missing == 0); // every pixel with geometry has a bent normal
        // Where the truth leans from the surface normal by 10 degrees or more.
        double scene_bent = 0, scene_normal = 0;
        size_t leaning = 0;
        for (size_t i = 0; i < t.truth.valid.size(); ++i) {
            if (!t.truth.valid[i]) continue;
            const float* truth = &t.truth.bent_normal[3 * i];
            const double lean = aogen_report::angle_degrees(&surface[3 * i], truth);
            if (!(lean >= 10.0)) continue;
            scene_bent += aogen_report::angle_degrees(&bent[3 * i], truth), scene_normal += lean, ++leaning;
        }
        std::cout << name << " bent normals on " << scene << ": mean " << m.mean_degrees << " deg (p90 " << m.p90_degrees
                  << "; the surface normal " << plain.mean_degrees << "); " << leaning << " pixels lean >= 10 deg: there "
                  << (leaning ? scene_bent / leaning : 0.0) << " deg, the surface normal " << (leaning ? scene_normal / leaning : 0.0) << " deg\n";
        sum_mean += m.mean_degrees, sum_plain += plain.mean_degrees;
        bent_error += scene_bent, normal_error += scene_normal, bent_pixels += leaning;
    }
    const double scenes = double(std::size(scenes_with_normals)), mean = sum_mean / scenes;
    std::cout << name << " bent normals over the ten scenes: mean " << mean << " deg, the surface normal's " << sum_plain / scenes
              << " deg; where the truth leans >= 10 deg: " << bent_error / double(bent_pixels) << " deg against the surface normal's "
              << normal_error / double(bent_pixels) << " over " << bent_pixels << " pixels\n";
    INFO("mean over the scenes: " << mean << " deg; where the truth leans: bent " << bent_error / double(bent_pixels) << " deg, surface normal "
                                  << normal_error / double(bent_pixels) << " deg over " << bent_pixels << " pixels");
    CHECK(mean <= 10.0);
    CHECK(mean < sum_plain / scenes);
    REQUIRE(bent_pixels > 1000); // the scenes have corners enough for the second check to mean something
    CHECK(bent_error <= 0.5 * normal_error);
}

} // namespace

TEST_CASE("accuracy: bent normals: gtao-3x3-half-denoise-bn is within 10 degrees of the truth on ten scenes and leans where the truth leans")
{
    check_bent_normals("gtao-3x3-half-denoise-gbufworld-std-persp-cs-bn");
}

TEST_CASE("accuracy: bent normals: vbao-3x3-half-bilateral-bn is within 10 degrees of the truth on ten scenes and leans where the truth leans")
{
    check_bent_normals("vbao-3x3-half-bilateral-gbufworld-std-persp-cs-bn");
}

} // namespace unity_bent_normal_test
