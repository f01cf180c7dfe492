// aogen::scenes point clouds drawn as splats (depth = the point's projection, checked against
// a brute-force ray/square test) and depth buffers stored as D24/D16 UNORM.
#include "scene_tests.hpp"

#include <limits>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_splats_depth {

namespace {

// The point's view-space position (camera basis, double), as the projection sees it.
dvec3 to_view(const camera& c, dvec3 p)
{
    dvec3 s, u, b;
    c.basis(s, u, b);
    const dvec3 o = p - c.eye;
    return {truth::dot(o, s), truth::dot(o, u), truth::dot(o, b)};
}

float projected_depth(const camera& c, dvec3 view)
{
    const vec4 clip = c.projection_matrix() * vec4{float(view.x), float(view.y), float(view.z), 1.0f};
    return clip.z / clip.w;
}

// What pixel (x, y) sees of the splats, found without Embree: the view ray's intersection
// with each splat's plane (view z constant), inside the square, nearest first. `ambiguous`
// when the ray passes within a hair of some splat's edge (then Embree may decide otherwise).
struct brute_hit {
    bool found = false, ambiguous = false;
    size_t point = 0;
};

brute_hit brute_force(const scene& s, const std::vector<dvec3>& view_points, int x, int y)
{
    const camera& c = s.camera;
    const double h = 0.5 * s.point_sets[0].splat_size;
    const double ndc_x = 2.0 * (x + 0.5) / c.width - 1.0, ndc_y = 1.0 - 2.0 * (y + 0.5) / c.height;
    const double dx = ndc_x * c.aspect() * c.tan_half_fov_y, dy = ndc_y * c.tan_half_fov_y; // per unit view distance
    brute_hit best;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < view_points.size(); ++i) {
        const dvec3 v = view_points[i];
        const double t = -v.z;
        const double margin = h - std::max(std::abs(dx * t - v.x), std::abs(dy * t - v.y));
        if (std::abs(margin) < 1e-6 * h) best.ambiguous = true;
        if (margin >= 0 && t >= c.near && t < nearest) nearest = t, best.found = true, best.point = i;
    }
    return best;
}

const depth_format unorm_formats[] = {depth_format::d24_unorm, depth_format::d16_unorm};

double unorm_steps(depth_format f) { return f == depth_format::d24_unorm ? 16777215.0 : 65535.0; }

} // namespace

TEST_CASE("the point_cloud scene draws depth-only splats at the depth of their points", "[scenes][points]")
{
    const scene s = builtin_scene("point_cloud");
    CHECK(s.renderer.normals == normal_space::none);
    CHECK(s.renderer.point_cloud);
    REQUIRE(s.point_sets.size() == 1);
    CHECK(s.point_sets[0].positions.size() > 5000);
    const gbuffer g = render_gbuffer(s);
    CHECK(g.normals.empty());

    std::vector<dvec3> view_points;
    for (const dvec3& p : s.point_sets[0].positions) view_points.push_back(to_view(s.camera, p));
    size_t hits = 0, checked = 0;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const size_t i = size_t(y) * g.width + x;
            hits += g.hit[i];
            const brute_hit b = brute_force(s, view_points, x, y);
            if (b.ambiguous) continue;
            INFO("pixel " << x << "," << y);
            REQUIRE(bool(g.hit[i]) == b.found);
            if (!b.found) continue;
            ++checked;
            const float want = projected_depth(s.camera, view_points[b.point]);
            INFO("depth " << g.depth[i] << ", the point's " << want);
            REQUIRE(ulps(g.depth[i], want) <= 8);
        }
    const double coverage = double(hits) / g.hit.size();
    CHECK(coverage > 0.2);
    CHECK(checked > hits * 9 / 10); // few pixels sit on an edge
}

TEST_CASE("a JSON point becomes a square splat of its size, facing the camera", "[scenes][points][json]")
{
    const scene s = read_scene(R"({
        "name": "one splat",
        "geometry": [{"type": "points", "positions": [[0, 0, 0]], "splat_size": 0.5}],
        "camera": {"eye": [0, -5, 0], "target": [0, 0, 0], "up": [0, 0, 1]},
        "renderer": {"normals": "none", "point_cloud": true}
    })",
                               "scene.json");
    const gbuffer g = render_gbuffer(s);
    const camera& c = s.camera;
    const float want = expected_depth(depth_convention::standard, c.near, c.far, 5.0f);
    size_t hits = 0, inside = 0;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            // The pixel ray meets the splat's plane (view distance 5) at (5·dx, 5·dy).
            const double dx = (2.0 * (x + 0.5) / c.width - 1.0) * c.aspect() * c.tan_half_fov_y;
            const double dy = (1.0 - 2.0 * (y + 0.5) / c.height) * c.tan_half_fov_y;
            inside += std::abs(5 * dx) < 0.25 && std::abs(5 * dy) < 0.25;
            const size_t i = size_t(y) * g.width + x;
            if (!g.hit[i]) continue;
            ++hits;
            CHECK(ulps(g.depth[i], want) <= 4); // one depth across the splat
        }
    CHECK(inside == 64); // ±0.25 at distance 5 is ±3.9 pixels each way at 160×90
    CHECK(hits == inside);
}

TEST_CASE("JSON point set errors name the field", "[scenes][points][json]")
{
    std::string m = message_of(R"({"geometry": [{"type": "points", "positions": [[0, 0, 0], [1, 2]]}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].positions[1]") && Catch::Contains("[x, y, z]"));
    m = message_of(R"({"geometry": [{"type": "points", "positions": [[0, 0, 0], {"x": 1, "y": 2, "z": 3}]}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].positions[1]") && Catch::Contains("not an array"));
    m = message_of(R"({"geometry": [{"type": "points", "positions": [[0, 0, 0]], "splat_size": 0}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].splat_size") && Catch::Contains("out of range"));
    m = message_of(R"({"geometry": [{"type": "points", "positions": []}]})");
    CHECK_THAT(m, Catch::Contains("point set 0 positions") && Catch::Contains("empty"));
}

TEST_CASE("UNORM depth is the float depth rounded to the nearest of 2^n - 1 steps", "[scenes][depth]")
{
    // Closed form: 0.5·65535 = 32767.5 rounds up; 0.5·16777215 = 8388607.5 rounds up.
    CHECK(stored_depth(0.5f, depth_format::d16_unorm) == 32768.0f / 65535.0f);
    CHECK(stored_depth(0.5f, depth_format::d24_unorm) == 8388608.0f / 16777215.0f);
    CHECK(stored_depth(0.3f, depth_format::d32_sfloat) == 0.3f);
    CHECK(stored_depth(1e-6f, depth_format::d16_unorm) == 0.0f);

    for (depth_format f : unorm_formats)
        for (depth_convention d : {depth_convention::standard, depth_convention::reversed}) {
            scene s = builtin_scene("room"); // depths spread over the range, and no background
            s.camera.depth = d;
            const gbuffer exact = render_gbuffer(s);
            s.renderer.depth_buffer = f;
            const gbuffer q = render_gbuffer(s);
            const double steps = unorm_steps(f);
            for (size_t i = 0; i < q.depth.size(); ++i) {
                const float v = q.depth[i];
                const double k = std::round(double(v) * steps);
                INFO("format " << int(f) << ", convention " << int(d) << ", pixel " << i << ", depth " << v);
                REQUIRE(float(k) / float(steps) == v); // exactly a step, as read back in float
                const double half_ulp = 0.5 * std::nextafter(v, 2.0f) - 0.5 * v;
                REQUIRE(std::abs(double(v) - double(exact.depth[i])) <= 0.5 / steps + half_ulp);
            }
        }
}

TEST_CASE("UNORM depth keeps the background exactly at the convention's far value", "[scenes][depth]")
{
    for (depth_format f : unorm_formats)
        for (depth_convention d : {depth_convention::standard, depth_convention::reversed_infinite}) {
            scene s;
            s.spheres = {{{0, 0, 0}, 0.5}};
            s.camera.eye = {0, 0, 5}, s.camera.target = {0, 0, 0}, s.camera.up = {0, 1, 0};
            s.camera.depth = d;
            s.renderer.depth_buffer = f;
            const gbuffer g = render_gbuffer(s);
            const float far_value = d == depth_convention::standard ? 1.0f : 0.0f;
            size_t background = 0;
            for (size_t i = 0; i < g.depth.size(); ++i)
                if (!g.hit[i]) {
                    ++background;
                    REQUIRE(g.depth[i] == far_value);
                }
            CHECK(background > 0);
        }
}

TEST_CASE("the JSON depth_buffer option reaches the G-buffer", "[scenes][depth][json]")
{
    const scene s = read_scene(R"({
        "name": "plane at 3",
        "geometry": [{"type": "plane", "point": [0, 0, -3], "normal": [0, 0, 1]}],
        "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "up": [0, 1, 0], "width": 8, "height": 8},
        "renderer": {"depth_buffer": "d16_unorm"}
    })",
                               "scene.json");
    REQUIRE(s.renderer.depth_buffer == depth_format::d16_unorm);
    const gbuffer g = render_gbuffer(s);
    scene as_float = s;
    as_float.renderer.depth_buffer = depth_format::d32_sfloat;
    const gbuffer exact = render_gbuffer(as_float);
    CHECK(ulps(exact.depth[0], expected_depth(depth_convention::standard, s.camera.near, s.camera.far, 3.0f)) <= 4);
    for (size_t i = 0; i < g.depth.size(); ++i) CHECK(g.depth[i] == float(std::round(double(exact.depth[i]) * 65535.0)) / 65535.0f);
    const std::string m = message_of(R"({"geometry": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}],
                                         "renderer": {"depth_buffer": "d32"}})");
    CHECK_THAT(m, Catch::Contains("scene.json.renderer.depth_buffer") && Catch::Contains("d32_sfloat, d24_unorm, d16_unorm"));
}

} // namespace unity_splats_depth
