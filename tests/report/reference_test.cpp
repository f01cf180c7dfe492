// The report's reference image against a closed form at every pixel: with an unbounded
// radius, every point of a 90° crease has AO (1 − cos 90°)/2 = 1/2 (DESIGN.md), wherever
// it is (the other plane covers the same share of the hemisphere at any distance). The
// built-in groove is the same configuration turned 45° — its walls are tilted planes, the
// case where a tracer that occludes itself (float precision of large triangles) fails.
#include <aogen_report/reference.hpp>

#include <catch2/catch.hpp>

#include <cmath>

namespace {

void check_every_pixel(const std::string& name, double expected)
{
    aogen::scenes::scene s = aogen::scenes::builtin_scene(name);
    s.camera.width = 48, s.camera.height = 27;
    aogen::truth::scene t;
    s.build(t);
    aogen::scenes::gbuffer_options world;
    world.use_scene_normals = false;
    world.normals = aogen::scenes::normal_space::world;
    const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(s, t, world);
    const aogen_report::reference r = aogen_report::trace_reference(t, g, std::numeric_limits<double>::infinity(), 32, 2);
    int pixels = 0;
    double sum = 0;
    for (size_t i = 0; i < r.ao.size(); ++i) {
        if (!r.valid[i]) {
            CHECK(std::isnan(r.ao[i]));
            continue;
        }
        INFO(name << " pixel " << i);
        CHECK(std::fabs(r.ao[i] - expected) <= 5 * r.standard_error[i] + 0.004);
        sum += r.ao[i], ++pixels;
    }
    REQUIRE(pixels > 48 * 27 / 2);
    CHECK(sum / pixels == Approx(expected).margin(0.002));
    CHECK(r.noise_rms > 0);
    CHECK(r.noise_rms < 0.005);
    CHECK(r.rays_per_pixel == 1024);
}

} // namespace

TEST_CASE("reference: every pixel of the crease is 1/2 with an unbounded radius")
{
    check_every_pixel("crease", 0.5);
}

TEST_CASE("reference: every pixel of the groove's tilted walls is 1/2 with an unbounded radius")
{
    check_every_pixel("groove", 0.5);
}

TEST_CASE("reference: the same image for any number of threads")
{
    aogen::scenes::scene s = aogen::scenes::builtin_scene("room");
    s.camera.width = 32, s.camera.height = 18;
    aogen::truth::scene t;
    s.build(t);
    aogen::scenes::gbuffer_options world;
    world.use_scene_normals = false;
    const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(s, t, world);
    const aogen_report::reference one = aogen_report::trace_reference(t, g, 1.0, 32, 1);
    const aogen_report::reference three = aogen_report::trace_reference(t, g, 1.0, 32, 3);
    for (size_t i = 0; i < one.ao.size(); ++i)
        if (one.valid[i]) CHECK(one.ao[i] == three.ao[i]);
    CHECK(one.noise_rms == three.noise_rms);
}
