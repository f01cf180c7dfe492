// aogen::scenes: scene JSON, built-in scenes, and the ray-cast G-buffer's depth and normals.
#include "scene_tests.hpp"

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_scenes {

namespace {

// A plane z_view = −distance facing a camera at `eye` (the origin unless told) that looks
// down −z.
scene facing_plane(double distance, depth_convention d, dvec3 eye = {})
{
    scene s;
    s.planes = {{eye + dvec3{0, 0, -distance}, {0, 0, 1}}};
    s.camera.eye = eye, s.camera.target = eye + dvec3{0, 0, -1}, s.camera.up = {0, 1, 0};
    s.camera.depth = d;
    s.camera.width = 32, s.camera.height = 18;
    return s;
}

const depth_convention all_conventions[] = {depth_convention::standard, depth_convention::reversed,
                                            depth_convention::reversed_infinite};

} // namespace

TEST_CASE("depth of a facing plane equals the projection formula for each convention", "[scenes][gbuffer]")
{
    // At the world's zero, and 10⁷ from it, where float world coordinates are 1 apart: the
    // tracer works relative to the camera's eye (make_tracer).
    const double from_zero = GENERATE(0.0, 1e7);
    const dvec3 eye = from_zero * truth::normalize({1, -std::sqrt(2.0), std::sqrt(3.0)});
    INFO("camera " << from_zero << " from the world's zero");
    for (depth_convention d : all_conventions)
        for (double z : {0.5, 5.0, 37.25}) {
            const scene s = facing_plane(z, d, eye);
            const gbuffer g = render_gbuffer(s);
            const float want = expected_depth(d, s.camera.near, s.camera.far, float(z));
            int64_t worst = 0;
            for (size_t i = 0; i < g.depth.size(); ++i) {
                REQUIRE(g.hit[i] == 1);
                worst = std::max(worst, ulps(g.depth[i], want));
            }
            INFO("convention " << int(d) << ", z " << z << ", want " << want << ", worst " << worst << " ulps");
            CHECK(worst <= 4);
        }
}

TEST_CASE("view z reconstructed from depth with inverse(proj) is the plane distance", "[scenes][gbuffer]")
{
    for (depth_convention d : all_conventions)
        for (double z : {0.5, 5.0}) {
            const scene s = facing_plane(z, d);
            const gbuffer g = render_gbuffer(s);
            const mat4 inv = inverse(s.camera.projection_matrix());
            for (int y = 0; y < g.height; ++y)
                for (int x = 0; x < g.width; ++x) {
                    const float ndc_x = 2.0f * (x + 0.5f) / g.width - 1.0f, ndc_y = 1.0f - 2.0f * (y + 0.5f) / g.height;
                    const vec4 v = inv * vec4{ndc_x, ndc_y, g.depth[size_t(y) * g.width + x], 1.0f};
                    const double zv = double(v.z) / v.w;
                    INFO("convention " << int(d) << ", z " << z << ", pixel " << x << "," << y);
                    REQUIRE(std::abs(zv + z) <= 1e-5 * z);
                }
        }
}

TEST_CASE("background pixels carry exactly the convention's far value", "[scenes][gbuffer]")
{
    for (depth_convention d : all_conventions) {
        scene s;
        s.spheres = {{{0, 0, 0}, 0.5}};
        s.camera.eye = {0, 0, 5}, s.camera.target = {0, 0, 0}, s.camera.up = {0, 1, 0};
        s.camera.depth = d;
        const gbuffer g = render_gbuffer(s);
        const float far_value = d == depth_convention::standard ? 1.0f : 0.0f;
        int background = 0, geometry = 0;
        for (size_t i = 0; i < g.depth.size(); ++i) {
            if (g.hit[i]) {
                ++geometry;
                CHECK(g.depth[i] != far_value);
                continue;
            }
            ++background;
            REQUIRE(g.depth[i] == far_value);
            REQUIRE(g.normals[4 * i + 3] == 0.0f);
            REQUIRE(std::isnan(g.position[3 * i]));
        }
        CHECK(background > 0);
        CHECK(geometry > 0);
    }
}

TEST_CASE("normals of the sphere point away from its centre", "[scenes][gbuffer]")
{
    const scene s = builtin_scene("sphere_on_plane");
    const gbuffer g = render_gbuffer(s);
    const dvec3 c = s.spheres[0].centre;
    const int sphere_id = int(s.planes.size() + s.boxes.size()); // build order: planes, boxes, spheres
    int count = 0;
    for (size_t i = 0; i < g.depth.size(); ++i) {
        if (g.geometry[i] != sphere_id) continue;
        ++count;
        const dvec3 p{g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]};
        const dvec3 radial = truth::normalize(p - c);
        const dvec3 n{g.normals[4 * i], g.normals[4 * i + 1], g.normals[4 * i + 2]};
        REQUIRE(std::abs(truth::dot(n, n) - 1) < 1e-5);
        REQUIRE(truth::dot(n, radial) > 0.9999);
        REQUIRE(std::abs(std::sqrt(truth::dot(p - c, p - c)) - s.spheres[0].radius) < 1e-4);
    }
    CHECK(count > 100);
}

TEST_CASE("view-space normals are the world normals in the camera basis", "[scenes][gbuffer]")
{
    scene s = facing_plane(3.0, depth_convention::standard);
    s.camera.eye = {1, 2, 3}, s.camera.target = {1, 2, -1}; // still looks down −z, plane z = −3
    s.planes[0].point = {0, 0, 0};
    gbuffer_options o;
    o.use_scene_normals = false;
    o.normals = normal_space::view;
    const gbuffer g = render_gbuffer(s, o);
    for (size_t i = 0; i < g.depth.size(); ++i) {
        REQUIRE(g.hit[i] == 1);
        CHECK(g.normals[4 * i + 2] == Approx(1.0f));
    }
}

TEST_CASE("every built-in scene instantiates and has geometry on screen", "[scenes][builtin]")
{
    for (const std::string& name : builtin_scene_names()) {
        INFO(name);
        scene s;
        if (!builtin_or_skip(name, s)) continue;
        CHECK(s.name == name);
        CHECK(s.camera.width == 160);
        CHECK(s.camera.height == 90);
        const gbuffer g = render_gbuffer(s);
        REQUIRE(g.depth.size() == size_t(160) * 90);
        REQUIRE(g.normals.size() == (s.renderer.normals == normal_space::none ? 0 : size_t(160) * 90 * 4));
        size_t hits = 0;
        for (uint8_t h : g.hit) hits += h;
        CHECK(hits > 0);
        for (size_t i = 0; i < g.depth.size(); ++i)
            if (g.hit[i]) {
                REQUIRE(g.depth[i] >= 0.0f);
                REQUIRE(g.depth[i] <= 1.0f);
            }
    }
}

TEST_CASE("an unknown built-in scene name lists the valid names", "[scenes][builtin]")
{
    CHECK_THROWS_WITH(builtin_scene("sphere"), Catch::Contains("sphere_on_plane") && Catch::Contains("plank") &&
                                                   Catch::Contains("'sphere'"));
}

TEST_CASE("a JSON scene parses into the description", "[scenes][json]")
{
    const scene s = read_scene(R"({
        "name": "test",
        "geometry": [
            {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]},
            {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]},
            {"type": "sphere", "centre": [3, 0, 1], "radius": 1},
            {"type": "quad", "corner": [0, 5, 0], "e1": [1, 0, 0], "e2": [0, 0, 1]}
        ],
        "camera": {"projection": "orthographic", "left": -4, "right": 4, "bottom": -2, "top": 2,
                   "near": 0, "far": 50, "depth": "reversed", "width": 64, "height": 32,
                   "eye": [0, -10, 5], "target": [0, 0, 0], "up": [0, 0, 1]},
        "ao_radius": 0.5,
        "renderer": {"normals": "view", "point_cloud": true}
    })",
                               "scene.json");
    CHECK(s.name == "test");
    CHECK(s.planes.size() == 1);
    CHECK(s.boxes.size() == 1);
    CHECK(s.spheres.size() == 1);
    CHECK(s.quads.size() == 1);
    CHECK(s.camera.projection == projection_kind::orthographic);
    CHECK(s.camera.depth == depth_convention::reversed);
    CHECK(s.camera.width == 64);
    CHECK(s.ao_radius == 0.5);
    CHECK(s.renderer.normals == normal_space::view);
    CHECK(s.renderer.point_cloud);
    const gbuffer g = render_gbuffer(s);
    size_t hits = 0;
    for (uint8_t h : g.hit) hits += h;
    CHECK(hits > 0);
}

TEST_CASE("JSON scene errors name the file and the field", "[scenes][json]")
{
    const std::string geo = R"("geometry": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}])";
    std::string m = message_of("{" + geo + R"(, "camera": {"fov": 60}})");
    CHECK_THAT(m, Catch::Contains("scene.json.camera.fov") && Catch::Contains("not a known key") &&
                      Catch::Contains("tan_half_fov_y"));
    m = message_of("{" + geo + R"(, "camera": {"depth": "reverse"}})");
    CHECK_THAT(m, Catch::Contains("scene.json.camera.depth") && Catch::Contains("reversed_infinite"));
    m = message_of("{" + geo + R"(, "camera": {"width": 0}})");
    CHECK_THAT(m, Catch::Contains("scene.json.camera.width") && Catch::Contains("1..16384"));
    m = message_of("{" + geo + R"(, "colour": 1})");
    CHECK_THAT(m, Catch::Contains("scene.json.colour") && Catch::Contains("not a known key"));
    m = message_of(R"({"geometry": [{"type": "sphere", "centre": [0, 0], "radius": 1}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].centre") && Catch::Contains("[x, y, z]"));
    m = message_of(R"({"geometry": [{"type": "sphere", "centre": [0, 0, 0], "radius": "big"}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].radius") && Catch::Contains("not a number"));
    m = message_of(R"({"geometry": [{"type": "cone"}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].type") && Catch::Contains("plane, box, sphere, quad, mesh, points"));
    m = message_of(R"({"geometry": []})");
    CHECK_THAT(m, Catch::Contains("scene.json: geometry") && Catch::Contains("is empty"));
    m = message_of("{not json");
    CHECK_THAT(m, Catch::Contains("scene.json") && Catch::Contains("not valid JSON"));
    // The name comes last: required, not empty, printable.
    m = message_of("{" + geo + "}");
    CHECK_THAT(m, Catch::Contains("scene.json.name") && Catch::Contains("is missing"));
    m = message_of("{" + geo + R"(, "name": "a\u001b[31m"})");
    CHECK_THAT(m, Catch::Contains("scene.json.name") && Catch::Contains("\\x1b") && !Catch::Contains("\x1b"));
    m = message_of("{" + geo + R"(, "name": ""})");
    CHECK_THAT(m, Catch::Contains("scene.json.name") && Catch::Contains("is empty"));
    // Geometry that cannot be traced is refused where it is read.
    m = message_of(R"({"geometry": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0]}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].normal") && Catch::Contains("zero vector"));
    m = message_of(R"({"geometry": [{"type": "quad", "corner": [0, 0, 0], "e1": [1, 0, 0], "e2": [2, 0, 0]}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0]") && Catch::Contains("parallel"));
    m = message_of(R"({"geometry": [{"type": "box", "min": [-1e308, -1e308, -1e308], "max": [1e308, 1e308, 1e308]}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].min") && Catch::Contains("1e+15"));
    m = message_of(R"({"geometry": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "half_extent": -1}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].half_extent") && Catch::Contains("out of range"));
}

TEST_CASE("normals_facing as_stored keeps a surface's own normal, the default faces the camera", "[scenes][json]")
{
    // The floor z = 0, normal +z, seen from below: its stored normal points away from the camera.
    const std::string json = R"({"name": "floor from below", "geometry": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}],
        "camera": {"eye": [0, -1, -3], "target": [0, 0, 0], "up": [0, 0, 1], "width": 8, "height": 8}, "renderer": {"normals_facing": "as_stored"}})";
    const scene stored = read_scene(json, "below.json");
    CHECK(!stored.renderer.normals_face_camera);
    gbuffer_options o;
    o.face_camera = false;
    const gbuffer as_stored = render_gbuffer(stored, o);
    const gbuffer facing = render_gbuffer(stored); // the reference's G-buffer: always facing
    size_t hits = 0;
    for (size_t i = 0; i < as_stored.hit.size(); ++i) {
        if (!as_stored.hit[i]) continue;
        ++hits;
        CHECK(as_stored.normals[4 * i + 2] == Approx(1.0f));
        CHECK(facing.normals[4 * i + 2] == Approx(-1.0f));
    }
    CHECK(hits > 0);
    CHECK_THAT(message_of(R"({"name": "x", "geometry": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}],
        "renderer": {"normals_facing": "outward"}})"), Catch::Contains("renderer.normals_facing") && Catch::Contains("as_stored"));
}

} // namespace unity_scenes
