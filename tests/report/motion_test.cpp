// The figures of the report in motion (aogen_report/motion_metrics.hpp) against closed forms:
//   - error, ghosting and flicker of two hand-made frames, worked out by hand;
//   - the truth's ages along an orthographic strafe of exactly one pixel a frame, seeing a
//     plane: the column that entered f' frames ago has age f', the rightmost is new every
//     frame, so after frame f pixel column x has age min(f, W − 1 − x); and with the camera
//     standing still every pixel's age is the frame's index;
//   - a box sliding over the plane uncovers a column a frame: the truth's disocclusion.
#include <aogen_report/motion_metrics.hpp>
#include <aogen_report/page.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_motion_test {

using namespace aogen_report;

namespace {

reference truth_of(std::vector<float> ao, std::vector<uint8_t> valid)
{
    reference r;
    r.width = int(ao.size()), r.height = 1;
    r.ao = std::move(ao);
    r.valid = std::move(valid);
    return r;
}

// An orthographic camera 20 × 12 pixels of 0.1 looking down −z at a plane z = 0 (and `extra`
// geometry), strafing `distance` over `frames` frames.
aogen::scenes::scene strafe(double distance, int frames, const std::string& extra = "")
{
    const std::string json = R"({"name": "strafe", "geometry": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "half_extent": 100})" + extra +
                             R"(], "camera": {"projection": "orthographic", "left": -1, "right": 1, "bottom": -0.6, "top": 0.6, "near": 0.1, "far": 20,
                             "width": 20, "height": 12, "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0],
                             "path": {"frames": )" + std::to_string(frames) + R"(, "strafe": {"distance": )" + std::to_string(distance) + R"(}}},
                             "ao_radius": 0.5})";
    return aogen::scenes::read_scene(json, "strafe.json");
}

// Every frame's ages along `s`'s path.
std::vector<std::vector<int>> ages_along(const aogen::scenes::scene& s)
{
    std::vector<std::vector<int>> out;
    aogen::scenes::scene before;
    std::unique_ptr<aogen::truth::scene> before_tracer;
    for (int f = 0; f < aogen::scenes::frame_count(s); ++f) {
        aogen::scenes::scene now = aogen::scenes::at_frame(s, f);
        std::unique_ptr<aogen::truth::scene> tracer = aogen::scenes::make_tracer(now);
        const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(now, *tracer);
        out.push_back(f == 0 ? std::vector<int>(g.depth.size(), 0) : next_ages(out.back(), previous_pixels(now, g, before, *before_tracer)));
        before = std::move(now), before_tracer = std::move(tracer);
    }
    return out;
}

} // namespace

TEST_CASE("motion: error, ghosting and flicker of two hand-made frames are their closed forms")
{
    // Pixel 2 is background (not valid). Frame 0: errors +0.1, -0.1; frame 1: +0.05, 0.
    const reference t0 = truth_of({0.5f, 0.5f, 1.0f}, {1, 1, 0}), t1 = truth_of({0.5f, 0.5f, 1.0f}, {1, 1, 0});
    // Frame 1's pixel 0 came from pixel 1's centre, pixel 1 from pixel 0's (a row of 3 pixels).
    const std::vector<int> ids{0, 0, -1};
    std::vector<scored_frame> frames{{{0.6f, 0.4f, 1.0f}, &t0, {{}, {}, {}}, {5, 1, 0}, ids, 3},
                                     {{0.55f, 0.5f, 1.0f}, &t1, {{1, 1.5, 0.5}, {0, 0.5, 0.5}, {}}, {6, 0, 0}, ids, 3}};
    const motion_record r = motion_metrics(frames, 4);
    REQUIRE(r.rmse.size() == 2);
    CHECK(r.rmse[0] == Approx(0.1).epsilon(1e-6));
    CHECK(r.rmse[1] == Approx(std::sqrt(0.05 * 0.05 / 2)).epsilon(1e-5));
    CHECK(r.error == Approx((0.1 + std::sqrt(0.05 * 0.05 / 2)) / 2).epsilon(1e-5));
    // Young pixels (age < 4): frame 0's pixel 1 (-0.1) and frame 1's pixel 1 (0).
    CHECK(r.ghost_pixels == 2);
    CHECK(r.ghosting == Approx(std::sqrt(0.01 / 2)).epsilon(1e-5));
    // Frame 1 against frame 0 at one point: 0.05 - (-0.1) and 0 - 0.1.
    CHECK(r.flicker_pixels == 2);
    CHECK(r.flicker == Approx(std::sqrt((0.15 * 0.15 + 0.1 * 0.1) / 2)).epsilon(1e-5));
    // Between two pixel centres the frame before's error is their bilinear mean: frame 1's
    // pixel 0 came from x = 0.75, a quarter of the way from pixel 0's centre to pixel 1's
    // (0.75 * 0.1 + 0.25 * -0.1 = 0.05); pixel 1 from a pixel of another object only: no figure.
    frames[1].from = {{0, 0.75, 0.5}, {0, 0.5, 0.5}, {}};
    frames[1].geometry = {0, 7, -1};
    const motion_record between = motion_metrics(frames, 4);
    CHECK(between.flicker_pixels == 1);
    CHECK(between.flicker == Approx(std::fabs(0.05 - 0.05)).margin(1e-6));
}

TEST_CASE("motion: along a strafe of one pixel a frame, column x is min(f, W - 1 - x) frames old, and standing still every pixel is f")
{
    const std::vector<std::vector<int>> moving = ages_along(strafe(0.1 * 5, 6));
    for (size_t f = 0; f < moving.size(); ++f)
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 20; ++x) {
                INFO("frame " << f << ", pixel (" << x << ", " << y << ")");
                REQUIRE(moving[f][size_t(y) * 20 + x] == std::min(int(f), 19 - x));
            }
    const std::vector<std::vector<int>> still = ages_along(strafe(0.0, 4));
    for (size_t f = 0; f < still.size(); ++f)
        for (int age : still[f]) REQUIRE(age == int(f));
}

TEST_CASE("motion: a box sliding one pixel a frame over the plane uncovers one column a frame, whose age starts again from 0")
{
    // The camera stands still; a box 0.2 wide (two pixel columns) slides +0.1 in x a frame over
    // the plane. Column c's centre is x = -0.95 + 0.1 c; the box covers x in (-0.5 + 0.1 g,
    // -0.3 + 0.1 g) at frame g: columns 5 + g and 6 + g. So at frame f column 4 + f comes out from
    // under it (age 0), column 4 + k came out at frame k (age f - k), the box's top is in view
    // all along (age f), and the columns it has not reached, or never covered, are f old.
    const aogen::scenes::scene s = strafe(0.0, 5, R"(, {"type": "box", "min": [-0.5, -1, 0.5], "max": [-0.3, 1, 1.0],
                                                        "motion": {"translate_per_frame": [0.1, 0, 0]}})");
    const std::vector<std::vector<int>> ages = ages_along(s);
    for (int f = 0; f < int(ages.size()); ++f)
        for (int c = 0; c < 20; ++c) {
            const bool top = c == 5 + f || c == 6 + f;
            const int expected = top ? f : (c >= 4 && c <= 4 + f) ? f - (c - 4) : f;
            for (int y = 0; y < 12; ++y) {
                INFO("frame " << f << ", pixel (" << c << ", " << y << ")");
                REQUIRE(ages[size_t(f)][size_t(y) * 20 + c] == expected);
            }
        }
}

TEST_CASE("report: the plot in motion has a point per variant: its error the mean over its scenes, its time their median, and the front among them")
{
    report_data d;
    d.device = "a device";
    const std::string cheap = "gtao-1x4-half-noblur-gbufworld-std-persp-cs", held = cheap + "-histmv", dear = "gtao-4x4-half-noblur-gbufworld-std-persp-fs";
    const auto record = [](const std::string& v, const std::string& scene, double error, double ms) {
        motion_record r;
        r.variant = v, r.scene = scene, r.error = error, r.ms = ms;
        return r;
    };
    d.motion = {record(cheap, "room", 0.10, 2.0), record(held, "room", 0.05, 2.5), record(dear, "room", 0.05, 8.0),
                record(cheap, "stairs", 0.08, 3.0), record(held, "stairs", 0.03, 3.5), record(dear, "stairs", 0.07, 6.0),
                record(cheap, "engine", 0.12, 1.0), record(held, "engine", 0.07, 1.5), record(dear, "engine", 0.06, NAN)};
    const std::vector<plot_point> p = motion_plot_points(d);
    REQUIRE(p.size() == 3);
    CHECK(p[0].name == cheap);
    CHECK(p[0].error_motion == Approx(0.10));
    CHECK(p[0].ms == 2.0);                     // the median of 2, 3, 1
    CHECK(p[1].error_motion == Approx(0.05));
    CHECK(p[1].ms == 2.5);
    CHECK(p[2].ms == 7.0);                     // the median of the two timed scenes
    CHECK(p[2].stage == "fragment");
    CHECK(p[0].pareto_motion);                 // the fastest
    CHECK(p[1].pareto_motion);                 // the most accurate
    CHECK(p[2].error_motion == Approx(0.06));
    CHECK_FALSE(p[2].pareto_motion);           // less accurate than the history variant, and slower
    const std::string svg = motion_time_svg(p, motion_plot_title(d));
    size_t points = 0;
    for (size_t at = svg.find("class=\"point\""); at != std::string::npos; at = svg.find("class=\"point\"", at + 1)) ++points;
    CHECK(points == 3);
    CHECK(svg.find("data-panel=\"motion\"") != std::string::npos);
    CHECK(svg.find(held + ": 2.500 ms, RMSE 0.0500") != std::string::npos);
}

} // namespace unity_motion_test
