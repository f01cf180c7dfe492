// aogen::scenes in motion: camera paths, moving spheres and boxes, scenes at a frame and the
// G-buffer's motion vectors, each against a closed form worked out here in double.
#include "scene_tests.hpp"

#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_motion_test {

namespace {

dvec3 add(dvec3 a, dvec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
dvec3 sub(dvec3 a, dvec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
dvec3 scaled(double s, dvec3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot3(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(dvec3 a) { return std::sqrt(dot3(a, a)); }
dvec3 unit(dvec3 a) { return scaled(1 / length(a), a); }
dvec3 cross3(dvec3 a, dvec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Whether a and b agree within `tolerance` (absolute) on every axis.
bool near(dvec3 a, dvec3 b, double tolerance)
{
    return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

// A pinhole camera written out here: a look-at basis and the perspective divide.
struct pinhole {
    dvec3 eye, right, up, forward;
    double tan_y, aspect;

    pinhole(dvec3 eye_, dvec3 target, dvec3 up_hint, double tan_half_fov_y, double aspect_)
        : eye(eye_), tan_y(tan_half_fov_y), aspect(aspect_)
    {
        forward = unit(sub(target, eye));
        right = unit(cross3(forward, up_hint));
        up = cross3(right, forward);
    }

    // World point → NDC (x right, y up).
    std::pair<double, double> ndc(dvec3 p) const
    {
        const dvec3 o = sub(p, eye);
        const double depth = dot3(o, forward);
        return {dot3(o, right) / (depth * tan_y * aspect), dot3(o, up) / (depth * tan_y)};
    }

    // The ray's direction through an NDC point.
    dvec3 through(double x, double y) const
    {
        return add(forward, add(scaled(x * tan_y * aspect, right), scaled(y * tan_y, up)));
    }
};

pinhole pinhole_of(const scenes::camera& c, dvec3 eye, dvec3 target)
{
    return pinhole(eye, target, c.up, c.tan_half_fov_y, double(c.width) / c.height);
}

// A scene file with `geometry` and a perspective camera looking from (6, −5, 3) at (0, 0, 0.5),
// z up, and `path` (a JSON object, or empty for none).
std::string scene_json(const std::string& geometry, const std::string& path, const std::string& camera_extra = "")
{
    return R"({"name": "moving", "geometry": [)" + geometry + R"(], "camera": {"width": 64, "height": 36, )" + camera_extra +
           R"("eye": [6, -5, 3], "target": [0, 0, 0.5], "up": [0, 0, 1])" + (path.empty() ? "" : R"(, "path": )" + path) + "}}";
}

const std::string floor_json = R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]})";

// A floor seen along a path of keyframes: the keyframes place the camera.
std::string keyframes_json(const std::string& keyframes, int frames)
{
    return R"({"name": "keyframed", "geometry": [)" + floor_json + R"(], "camera": {"up": [0, 0, 1], "path": {"frames": )" +
           std::to_string(frames) + R"(, "keyframes": )" + keyframes + "}}}";
}

// The error message at_frame(s, f) gives, "(no error)" when there is none.
std::string frame_error(const scene& s, int f)
{
    return aogen_test::error_of([&] { at_frame(s, f); });
}

size_t hits_of(const gbuffer& g)
{
    size_t n = 0;
    for (uint8_t h : g.hit) n += h;
    return n;
}

} // namespace

TEST_CASE("a path's frame 0 is the scene's camera, and its last frame the closed form of its kind", "[scenes][motion]")
{
    const dvec3 eye{6, -5, 3}, target{0, 0, 0.5}, up{0, 0, 1};
    const dvec3 forward = unit(sub(target, eye)), right = unit(cross3(forward, up));
    SECTION("orbit: the eye turned a degrees about the vertical through the target")
    {
        const scene s = read_scene(scene_json(floor_json, R"({"frames": 9, "orbit": {"degrees": 72}})"), "orbit.json");
        REQUIRE(frame_count(s) == 9);
        CHECK(near(at_frame(s, 0).camera.eye, eye, 0));
        for (int f : {1, 4, 8}) {
            const double a = 72.0 * f / 8 * 3.14159265358979323846 / 180;
            const dvec3 v = sub(eye, target); // turned about z through the target, counter-clockwise from above
            const dvec3 want{target.x + v.x * std::cos(a) - v.y * std::sin(a), target.y + v.x * std::sin(a) + v.y * std::cos(a), eye.z};
            const scenes::camera c = at_frame(s, f).camera;
            INFO("frame " << f);
            CHECK(near(c.eye, want, 1e-12));
            CHECK(near(c.target, target, 0));
            CHECK(length(sub(c.eye, c.target)) == Approx(length(sub(eye, target))).epsilon(1e-14));
        }
    }
    SECTION("dolly: eye and target moved d along the view")
    {
        const scene s = read_scene(scene_json(floor_json, R"({"frames": 5, "dolly": {"distance": 2}})"), "dolly.json");
        CHECK(near(at_frame(s, 0).camera.eye, eye, 0));
        for (int f : {1, 4}) {
            const scenes::camera c = at_frame(s, f).camera;
            CHECK(near(c.eye, add(eye, scaled(2.0 * f / 4, forward)), 1e-12));
            CHECK(near(c.target, add(target, scaled(2.0 * f / 4, forward)), 1e-12));
        }
    }
    SECTION("strafe: eye and target moved d along the camera's right")
    {
        const scene s = read_scene(scene_json(floor_json, R"({"frames": 3, "strafe": {"distance": -1.5}})"), "strafe.json");
        CHECK(near(at_frame(s, 0).camera.target, target, 0));
        const scenes::camera last = at_frame(s, 2).camera;
        CHECK(near(last.eye, add(eye, scaled(-1.5, right)), 1e-12));
        CHECK(near(last.target, add(target, scaled(-1.5, right)), 1e-12));
        CHECK(near(at_frame(s, 1).camera.eye, add(eye, scaled(-0.75, right)), 1e-12));
    }
    SECTION("keyframes: evenly spaced in frames, eye and target linear between them")
    {
        const scene s = read_scene(keyframes_json(R"([{"eye": [6, -5, 3], "target": [0, 0, 0.5]}, {"eye": [0, -6, 3], "target": [0, 0, 0]},
                                                       {"eye": [-6, -3, 6], "target": [3, 0, 0]}])", 7),
                                   "keyframes.json");
        REQUIRE(frame_count(s) == 7);
        const dvec3 eyes[] = {{6, -5, 3}, {0, -6, 3}, {-6, -3, 6}}, targets[] = {{0, 0, 0.5}, {0, 0, 0}, {3, 0, 0}};
        CHECK(near(s.camera.eye, eyes[0], 0)); // the camera itself is keyframe 0
        for (int f = 0; f < 7; ++f) {
            const int k = std::min(f / 3, 1); // keyframes at frames 0, 3, 6
            const double w = (f - 3.0 * k) / 3;
            const scenes::camera c = at_frame(s, f).camera;
            INFO("frame " << f);
            CHECK(near(c.eye, add(scaled(1 - w, eyes[k]), scaled(w, eyes[k + 1])), 1e-12));
            CHECK(near(c.target, add(scaled(1 - w, targets[k]), scaled(w, targets[k + 1])), 1e-12));
        }
        CHECK(near(at_frame(s, 3).camera.eye, eyes[1], 0)); // exactly on the keyframes
        CHECK(near(at_frame(s, 6).camera.target, targets[2], 0));
    }
}

TEST_CASE("a scene at frame f moves its spheres and boxes by f times their translation", "[scenes][motion]")
{
    const scene s = read_scene(scene_json(floor_json + R"(,
        {"type": "box", "min": [-1, -1, 0], "max": [0, 0, 1], "motion": {"translate_per_frame": [0.5, 0, 0]}},
        {"type": "box", "min": [2, 2, 0], "max": [3, 3, 1]},
        {"type": "sphere", "centre": [1, 1, 1], "radius": 0.5, "motion": {"translate_per_frame": [0, -0.25, 0.125]}})",
                                          R"({"frames": 4, "strafe": {"distance": 0}})"),
                               "moving.json");
    REQUIRE(s.motions.size() == 2);
    const scene f3 = at_frame(s, 3);
    CHECK(near(f3.boxes[0].lo, {0.5, -1, 0}, 0));
    CHECK(near(f3.boxes[0].hi, {1.5, 0, 1}, 0));
    CHECK(near(f3.boxes[1].lo, {2, 2, 0}, 0)); // still
    CHECK(near(f3.spheres[0].centre, {1, 0.25, 1.375}, 0));
    CHECK(f3.spheres[0].radius == 0.5);
    CHECK(near(f3.camera.eye, s.camera.eye, 0)); // a still camera: strafe by 0
    // A scene at a frame is a still scene that says which frame it is.
    CHECK(frame_count(f3) == 1);
    CHECK(f3.motions.empty());
    CHECK(f3.source == "moving.json at frame 3");
    CHECK(near(at_frame(s, 0).spheres[0].centre, s.spheres[0].centre, 0));
    CHECK_THAT(frame_error(s, 4), Catch::Contains("moving.json: frame") && Catch::Contains("4 is out of range") &&
                                      Catch::Contains("valid: 0..3: the scene has 4 frames"));
    CHECK_THAT(frame_error(s, -1), Catch::Contains("-1 is out of range"));
}

TEST_CASE("a scene without a path has one frame: frame 0 is the scene itself", "[scenes][motion]")
{
    const scene s = builtin_scene("crease");
    CHECK(frame_count(s) == 1);
    const scene f0 = at_frame(s, 0);
    CHECK(f0.source == s.source);
    CHECK(near(f0.camera.eye, s.camera.eye, 0));
    CHECK_THAT(frame_error(s, 1), Catch::Contains("built-in scene 'crease': frame") && Catch::Contains("1 is out of range") &&
                                      Catch::Contains("the scene has 1 frame"));
}

TEST_CASE("under a strafe every pixel of a still scene moves as its hit point projects by both cameras", "[scenes][motion][gbuffer]")
{
    // room: a still scene whose camera strafes 1 m right (+x) over 16 frames.
    const scene s = builtin_scene("room");
    REQUIRE(s.path.kind == path_kind::strafe);
    const int frames = frame_count(s);
    const scenes::camera& c0 = s.camera;
    const dvec3 right = unit(cross3(unit(sub(c0.target, c0.eye)), c0.up));
    for (int f : {1, 7, frames - 1}) {
        const gbuffer g = render_frame(s, f);
        REQUIRE(g.motion.size() == size_t(g.width) * g.height * 2);
        const auto at = [&](int frame) {
            const dvec3 move = scaled(1.0 * frame / (frames - 1), right);
            return pinhole_of(c0, add(c0.eye, move), add(c0.target, move));
        };
        const pinhole now = at(f), before = at(f - 1);
        // The GPU's way too: aogen's float matrices of both cameras.
        const scene sf = at_frame(s, f), sp = at_frame(s, f - 1);
        const mat4 now_m = sf.camera.projection_matrix() * sf.camera.world_to_view();
        const mat4 before_m = sp.camera.projection_matrix() * sp.camera.world_to_view();
        const auto clip_ndc = [](const mat4& m, dvec3 p) {
            const vec4 q = m * vec4{float(p.x), float(p.y), float(p.z), 1.0f};
            return std::pair<double, double>{q.x / q.w, q.y / q.w};
        };
        double worst = 0, worst_matrix = 0, largest = 0;
        size_t hits = 0;
        for (size_t i = 0; i < g.hit.size(); ++i) {
            if (!g.hit[i]) continue;
            ++hits;
            const dvec3 p{g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]};
            const auto [x1, y1] = now.ndc(p);
            const auto [x0, y0] = before.ndc(p);
            worst = std::max({worst, std::abs(g.motion[2 * i] - (x1 - x0)), std::abs(g.motion[2 * i + 1] - (y1 - y0))});
            largest = std::max(largest, std::abs(x1 - x0));
            const auto [mx1, my1] = clip_ndc(now_m, p);
            const auto [mx0, my0] = clip_ndc(before_m, p);
            worst_matrix = std::max({worst_matrix, std::abs(g.motion[2 * i] - (mx1 - mx0)), std::abs(g.motion[2 * i + 1] - (my1 - my0))});
        }
        INFO("frame " << f << ": " << hits << " hits, worst " << worst << ", with float matrices " << worst_matrix << ", largest |mv.x| " << largest);
        CHECK(hits > g.hit.size() / 2); // walls, boxes and the floor below the sky
        CHECK(worst < 1e-7);
        CHECK(worst_matrix < 2e-5);
        CHECK(largest > 0.005); // the camera did move: more than a pixel's width (2/160 = 0.0125) at the near end
    }
}

TEST_CASE("an orthographic strafe moves every pixel by the same closed-form vector", "[scenes][motion][gbuffer]")
{
    // A strafe of d over F − 1 frames moves view x by −d/(F − 1) a frame: ndc x by −2·d/((F − 1)(right − left)).
    const scene s = read_scene(scene_json(floor_json + R"(, {"type": "sphere", "centre": [0, 0, 1], "radius": 1})",
                                          R"({"frames": 5, "strafe": {"distance": 2}})",
                                          R"("projection": "orthographic", "left": -4, "right": 4, "bottom": -2.25, "top": 2.25, "near": 0, )"),
                               "ortho.json");
    const gbuffer g = render_frame(s, 2);
    const float want = float(-2.0 * (2.0 / 4) / 8);
    size_t hits = 0;
    for (size_t i = 0; i < g.hit.size(); ++i) {
        if (!g.hit[i]) continue;
        ++hits;
        REQUIRE(g.motion[2 * i] == Approx(want).margin(1e-7));
        REQUIRE(g.motion[2 * i + 1] == Approx(0).margin(1e-7));
    }
    CHECK(hits > 0);
}

TEST_CASE("rolling_sphere: the sphere carries its translation's motion, the floor the camera's only", "[scenes][motion][gbuffer]")
{
    const scene s = builtin_scene("rolling_sphere");
    REQUIRE(s.motions.size() == 1);
    const dvec3 step = s.motions[0].translate_per_frame;
    const int frames = frame_count(s);
    CHECK(frames == 16);
    const scenes::camera& c0 = s.camera;
    const dvec3 right = unit(cross3(unit(sub(c0.target, c0.eye)), c0.up));
    const int floor_id = 0, wall_id = 1, sphere_id = 2; // build order: planes, then spheres
    for (int f : {1, 8, frames - 1}) {
        const gbuffer g = render_frame(s, f);
        const auto at = [&](int frame) {
            const dvec3 move = scaled(s.path.amount * frame / (frames - 1), right);
            return pinhole_of(c0, add(c0.eye, move), add(c0.target, move));
        };
        const pinhole now = at(f), before = at(f - 1);
        double worst = 0, sphere_apart = 0;
        size_t sphere = 0, still = 0;
        for (size_t i = 0; i < g.hit.size(); ++i) {
            if (!g.hit[i]) continue;
            const dvec3 p{g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]};
            const bool moving = g.geometry[i] == sphere_id;
            const dvec3 was = moving ? sub(p, step) : p; // where the point stood a frame ago
            const auto [x1, y1] = now.ndc(p);
            const auto [x0, y0] = before.ndc(was);
            worst = std::max({worst, std::abs(g.motion[2 * i] - (x1 - x0)), std::abs(g.motion[2 * i + 1] - (y1 - y0))});
            if (moving) {
                ++sphere;
                const auto [sx0, sy0] = before.ndc(p); // had the sphere stood still
                sphere_apart = std::max(sphere_apart, std::hypot(g.motion[2 * i] - (x1 - sx0), g.motion[2 * i + 1] - (y1 - sy0)));
            } else {
                still += g.geometry[i] == floor_id || g.geometry[i] == wall_id;
            }
        }
        INFO("frame " << f << ": sphere pixels " << sphere << ", floor and wall " << still << ", worst " << worst);
        CHECK(sphere > 300);
        CHECK(still > 3000);
        CHECK(worst < 1e-7);
        CHECK(sphere_apart > 0.01); // the sphere's own motion shows: more than a pixel (2/160)
    }
}

TEST_CASE("motion vectors are 0 on the background and everywhere at frame 0", "[scenes][motion][gbuffer]")
{
    const scene s = read_scene(scene_json(R"({"type": "sphere", "centre": [0, 0, 0.5], "radius": 1, "motion": {"translate_per_frame": [0.1, 0.2, 0]}})",
                                          R"({"frames": 3, "orbit": {"degrees": 10}})"),
                               "sphere.json");
    const gbuffer first = render_frame(s, 0);
    REQUIRE(first.motion.size() == size_t(64) * 36 * 2);
    for (float m : first.motion) REQUIRE(m == 0.0f);
    const gbuffer g = render_frame(s, 2);
    size_t background = 0, moving = 0;
    for (size_t i = 0; i < g.hit.size(); ++i) {
        if (g.hit[i]) {
            moving += g.motion[2 * i] != 0.0f || g.motion[2 * i + 1] != 0.0f;
            continue;
        }
        ++background;
        REQUIRE(g.motion[2 * i] == 0.0f);
        REQUIRE(g.motion[2 * i + 1] == 0.0f);
    }
    CHECK(background > 0);
    CHECK(moving > 0);
    // Without motion asked for, there is none.
    CHECK(render_gbuffer(at_frame(s, 2)).motion.empty());
}

TEST_CASE("ndc minus the motion vector lands, seen by the previous camera, on the same world point", "[scenes][motion][gbuffer]")
{
    const scene s = builtin_scene("rolling_sphere");
    const int f = 5;
    const gbuffer g = render_frame(s, f);
    const scene before = at_frame(s, f - 1);
    const pinhole then = pinhole_of(before.camera, before.camera.eye, before.camera.target);
    const dvec3 step = s.motions[0].translate_per_frame;
    double worst = 0;
    size_t checked = 0;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const size_t i = size_t(y) * g.width + x;
            if (!g.hit[i]) continue;
            const double ndc_x = 2.0 * (x + 0.5) / g.width - 1, ndc_y = 1 - 2.0 * (y + 0.5) / g.height;
            const double px = ndc_x - g.motion[2 * i], py = ndc_y - g.motion[2 * i + 1];
            dvec3 was{g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]};
            if (g.geometry[i] == 2) was = sub(was, step);
            // The previous camera's ray through (px, py) passes through `was`: its distance from the ray.
            const dvec3 d = unit(then.through(px, py)), o = sub(was, then.eye);
            const double off = length(sub(o, scaled(dot3(o, d), d)));
            worst = std::max(worst, off / length(o));
            ++checked;
        }
    INFO(checked << " pixels, worst distance from the ray / distance from the eye " << worst);
    CHECK(checked > 1000);
    CHECK(worst < 1e-7); // float motion vectors: ~2e-9 of the view
}

TEST_CASE("to_gbuffer copies the motion vectors into a G-buffer type that has them", "[scenes][motion]")
{
    struct with_motion {
        int width = 0, height = 0;
        std::vector<float> depth, normals, albedo, motion;
    };
    struct without_motion {
        int width = 0, height = 0;
        std::vector<float> depth, normals;
    };
    const gbuffer g = render_frame(builtin_scene("room"), 3);
    const with_motion a = to_gbuffer<with_motion>(g);
    CHECK(a.width == 160);
    CHECK(a.depth == g.depth);
    CHECK(a.motion == g.motion);
    CHECK(a.motion.size() == size_t(160) * 90 * 2);
    CHECK(a.albedo.empty());
    const without_motion b = to_gbuffer<without_motion>(g);
    CHECK(b.normals == g.normals);
}

TEST_CASE("built-in paths: modest frame counts, and frame 0 is the scene as it was", "[scenes][motion][builtin]")
{
    size_t with_path = 0;
    for (const std::string& name : builtin_scene_names()) {
        INFO(name);
        scene s;
        if (!builtin_or_skip(name, s)) continue;
        const int frames = frame_count(s);
        if (frames == 1) continue;
        ++with_path;
        CHECK(frames >= 8);
        CHECK(frames <= 32);
        const scene f0 = at_frame(s, 0);
        CHECK(near(f0.camera.eye, s.camera.eye, 0));
        CHECK(near(f0.camera.target, s.camera.target, 0));
        for (int f : {frames / 2, frames - 1}) CHECK(hits_of(render_gbuffer(at_frame(s, f))) > size_t(160) * 90 / 2);
    }
    CHECK(with_path >= 3);
    // Frame 0 of the scenes with new paths: their cameras as they were before paths existed.
    const scene room = builtin_scene("room"), stairs = builtin_scene("stairs");
    CHECK(near(room.camera.eye, {0, -7, 2.5}, 0));
    CHECK(near(room.camera.target, {0, 1.5, 0.8}, 0));
    CHECK(near(stairs.camera.eye, {3.5, -3, 2.5}, 0));
    CHECK(near(stairs.camera.target, {0, 1, 0.4}, 0));
    CHECK(stairs.path.kind == path_kind::orbit);
}

TEST_CASE("rolling_sphere: a unit sphere on the floor beside the wall, in view on every frame", "[scenes][motion][builtin]")
{
    const scene s = builtin_scene("rolling_sphere");
    REQUIRE(s.spheres.size() == 1);
    REQUIRE(s.planes.size() == 2);
    CHECK(s.ao_radius == 1.0);
    for (int f = 0; f < frame_count(s); ++f) {
        const scene at = at_frame(s, f);
        const dvec3 c = at.spheres[0].centre;
        CHECK(c.z == at.spheres[0].radius); // touching the floor z = 0
        CHECK(c.x - at.spheres[0].radius == 0.5); // 0.5 from the wall x = 0
        const gbuffer g = render_gbuffer(at);
        size_t sphere = 0;
        for (int id : g.geometry) sphere += id == 2;
        INFO("frame " << f);
        CHECK(sphere > 300);
    }
}

TEST_CASE("JSON path and motion errors name the field and what is valid", "[scenes][motion][json]")
{
    const auto path_error = [](const std::string& path) { return message_of(scene_json(floor_json, path)); };
    CHECK_THAT(path_error(R"({"frames": 1, "dolly": {"distance": 1}})"),
               Catch::Contains("scene.json.camera.path.frames: 1 is out of range") && Catch::Contains("2..10000"));
    CHECK_THAT(path_error(R"({"frames": 10001, "dolly": {"distance": 1}})"),
               Catch::Contains("scene.json.camera.path.frames") && Catch::Contains("2..10000"));
    CHECK_THAT(path_error(R"({"frames": 2.5, "dolly": {"distance": 1}})"),
               Catch::Contains("scene.json.camera.path.frames") && Catch::Contains("not an integer"));
    CHECK_THAT(path_error(R"({"dolly": {"distance": 1}})"), Catch::Contains("scene.json.camera.path.frames") && Catch::Contains("is missing"));
    CHECK_THAT(path_error(R"({"frames": 4, "spiral": {"turns": 1}})"),
               Catch::Contains("scene.json.camera.path.spiral") && Catch::Contains("not a known key") &&
                   Catch::Contains("keyframes, orbit, dolly, strafe"));
    CHECK_THAT(path_error(R"({"frames": 4, "orbit": {"degrees": 10}, "dolly": {"distance": 1}})"),
               Catch::Contains("scene.json.camera.path: has both orbit and dolly") && Catch::Contains("exactly one of keyframes, orbit, dolly, strafe"));
    CHECK_THAT(path_error(R"({"frames": 4})"), Catch::Contains("scene.json.camera.path: has no kind of path") && Catch::Contains("exactly one of"));
    CHECK_THAT(path_error(R"({"frames": 4, "orbit": {"degrees": 4000}})"),
               Catch::Contains("scene.json.camera.path.orbit.degrees: 4000 is out of range") && Catch::Contains("-3600..3600"));
    CHECK_THAT(path_error(R"({"frames": 4, "orbit": {"radius": 2}})"),
               Catch::Contains("scene.json.camera.path.orbit.radius") && Catch::Contains("valid: degrees"));
    CHECK_THAT(path_error(R"({"frames": 4, "dolly": {"distance": 2e15}})"),
               Catch::Contains("scene.json.camera.path.dolly.distance") && Catch::Contains("out of range") && Catch::Contains("1e+15"));
    CHECK_THAT(path_error(R"({"frames": 4, "strafe": {"distance": "far"}})"),
               Catch::Contains("scene.json.camera.path.strafe.distance") && Catch::Contains("not a number"));
    CHECK_THAT(path_error(R"({"frames": 4, "keyframes": [{"eye": [1, 2, 3], "target": [0, 0, 0]}]})"),
               Catch::Contains("scene.json.camera.path.keyframes: has 1 keyframe") && Catch::Contains("valid: 2..4 keyframes"));
    CHECK_THAT(path_error(R"({"frames": 2, "keyframes": [{"eye": [1, 2, 3], "target": [0, 0, 0]}, {"eye": [1, 2, 4], "target": [0, 0, 0]},
                                                          {"eye": [1, 2, 5], "target": [0, 0, 0]}]})"),
               Catch::Contains("scene.json.camera.path.keyframes: has 3 keyframes") && Catch::Contains("valid: 2..2 keyframes"));
    CHECK_THAT(path_error(R"({"frames": 4, "keyframes": [{"eye": [1, 2, 3], "target": [0, 0, 0]}, {"eye": [1, 2, 4]}]})"),
               Catch::Contains("scene.json.camera.path.keyframes[1].target") && Catch::Contains("is missing"));
    CHECK_THAT(path_error(R"({"frames": 4, "keyframes": [{"eye": [1, 2, 3], "target": [0, 0, 0], "up": [0, 0, 1]}, {"eye": [1, 2, 4], "target": [0, 0, 0]}]})"),
               Catch::Contains("scene.json.camera.path.keyframes[0].up") && Catch::Contains("valid: eye, target"));
    // A path of keyframes places the camera: eye and target beside it are refused.
    CHECK_THAT(message_of(scene_json(floor_json, R"({"frames": 4, "keyframes": [{"eye": [1, 2, 3], "target": [0, 0, 0]}, {"eye": [1, 2, 4], "target": [0, 0, 0]}]})")),
               Catch::Contains("scene.json.camera.eye") && Catch::Contains("keyframes[0]"));
    // Keyframes whose eye passes through the target leave a frame with no view.
    const std::string crossing = keyframes_json(R"([{"eye": [0, 5, 5], "target": [0, -5, -5]}, {"eye": [0, -5, -5], "target": [0, 5, 5]}])", 3);
    CHECK_THAT(message_of(crossing), Catch::Contains("scene.json: camera.path") && Catch::Contains("frame 1's eye, target and up do not define a view"));
}

TEST_CASE("JSON motion errors: only spheres and boxes move, and only along a path", "[scenes][motion][json]")
{
    const std::string path = R"({"frames": 4, "strafe": {"distance": 1}})";
    CHECK_THAT(message_of(scene_json(R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "motion": {"translate_per_frame": [1, 0, 0]}})", path)),
               Catch::Contains("scene.json.geometry[0].motion: is for spheres and boxes, not a plane") &&
                   Catch::Contains("valid: motion on a sphere or a box"));
    CHECK_THAT(message_of(scene_json(floor_json + R"(, {"type": "quad", "corner": [0, 0, 0], "e1": [1, 0, 0], "e2": [0, 1, 0], "motion": {}})", path)),
               Catch::Contains("scene.json.geometry[1].motion: is for spheres and boxes, not a quad"));
    CHECK_THAT(message_of(scene_json(floor_json + R"(, {"type": "sphere", "centre": [0, 0, 1], "radius": 1, "motion": {"translate_per_frame": [1, 0, 0]}})", "")),
               Catch::Contains("scene.json.geometry[1].motion: moves, but the scene has one frame") && Catch::Contains("camera.path"));
    CHECK_THAT(message_of(scene_json(floor_json + R"(, {"type": "sphere", "centre": [0, 0, 1], "radius": 1, "motion": {}})", path)),
               Catch::Contains("scene.json.geometry[1].motion.translate_per_frame") && Catch::Contains("is missing"));
    CHECK_THAT(message_of(scene_json(floor_json + R"(, {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "motion": {"translate_per_frame": [1, 0]}})", path)),
               Catch::Contains("scene.json.geometry[1].motion.translate_per_frame") && Catch::Contains("[x, y, z]"));
    CHECK_THAT(message_of(scene_json(floor_json + R"(, {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "motion": {"rotate": [1, 0, 0]}})", path)),
               Catch::Contains("scene.json.geometry[1].motion.rotate") && Catch::Contains("valid: translate_per_frame"));
    // A scene put together in code is checked by validate().
    scene s = builtin_scene("rolling_sphere");
    s.motions.push_back({moving_kind::sphere, 0, {1, 0, 0}});
    CHECK_THROWS_WITH(validate(s, "code"), Catch::Contains("code: sphere 0 motion") && Catch::Contains("given twice"));
    s.motions = {{moving_kind::box, 0, {1, 0, 0}}};
    CHECK_THROWS_WITH(validate(s, "code"), Catch::Contains("code: box 0 motion") && Catch::Contains("valid: index < 0"));
    s = builtin_scene("rolling_sphere");
    s.path.frames = 1;
    CHECK_THROWS_WITH(validate(s, "code"), Catch::Contains("code: camera.path.frames: 1 is out of range") && Catch::Contains("2..10000"));
}

} // namespace unity_motion_test
