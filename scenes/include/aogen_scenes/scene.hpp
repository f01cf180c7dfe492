// aogen_scenes/scene.hpp — what a benchmark scene is: geometry, camera, AO radius and what
// the renderer has; read from JSON or taken from the built-ins.
//
// WHAT
//   scene                        analytic primitives (planes, boxes, spheres, quads), triangle
//                                meshes (mesh.hpp) and point clouds drawn as splats
//                                (points.hpp) in world space, a camera, the AO radius R and
//                                the renderer's inputs; and its motion over frames: a camera
//                                path (camera_path) and spheres and boxes that move
//                                (geometry_motion).
//   make_tracer(scene)           the scene's tracer (truth::scene), built: its origin is the
//                                camera's eye, so Embree's float coordinates are camera-relative
//                                (aogen_truth/tracer.hpp, HOW) and stay precise however far the
//                                scene is from the world's zero. Make every tracer for a scene
//                                here.
//   scene::build(tracer)         adds everything to a truth::scene; geometry ids in the order
//                                planes, boxes, spheres, quads, meshes, point sets. Splats face
//                                the camera of that moment: build again after moving it.
//   camera::world_to_view()      look-at from eye/target/up (right-handed, looking down −z).
//   camera::projection()         aogen::perspective()/orthographic() for the camera's depth
//                                convention (aogen/math.hpp).
//   frame_count(scene)           how many frames the scene has: 1 without a camera path,
//                                path.frames with one.
//   at_frame(scene, f)           the scene at frame f: the camera on its path and every moving
//                                sphere and box translated by f × its translate_per_frame; a
//                                still scene (no path, no motion) whose source names the frame.
//                                Frame 0 is the scene as given.
//   camera_at(camera, path, f)   the camera alone at frame f of a path starting at `camera`.
//   builtin_scene(name)          the closed forms of docs/design.md § Ground truth and a few more (crease,
//                                groove, wall, sphere_on_plane, room, stairs, plank, far_floor,
//                                rolling_sphere),
//                                meshes from assimp-testmodels (engine, teapots, terrain; atat,
//                                dwarf, spider close and _far on a floor) and seed 004's point
//                                cloud (point_cloud); builtin_scene_names().
//   read_scene(text, source)     parses the JSON format below; `source` (a file name) starts
//                                every error message, and relative mesh paths are resolved
//                                against its directory. load_scene(path) reads a file.
//
// JSON FORMAT (every key optional unless marked; unknown keys are errors)
//   {
//     "name": "my scene",                           (required: printable, 1..100 characters)
//     "geometry": [                                              (required, ≥ 1 entry)
//       {"type": "plane",  "point": [x,y,z], "normal": [x,y,z], "half_extent": 1e4},
//                                                                 (normal not zero; half_extent > 0)
//       {"type": "box",    "min": [x,y,z], "max": [x,y,z],        (axis-aligned, min < max)
//                          "motion": {...}},                      (below)
//       {"type": "sphere", "centre": [x,y,z], "radius": r,        (r > 0)
//                          "motion": {"translate_per_frame": [x,y,z]}},
//                                  (required in motion: at frame f the sphere or box is moved
//                                   by f × translate_per_frame; only spheres and boxes move,
//                                   and only in a scene with a camera path, which gives the frames)
//       {"type": "quad",   "corner": [x,y,z], "e1": [x,y,z], "e2": [x,y,z]},
//                                                                 (e1, e2 not parallel)
//       {"type": "mesh",   "file": "model.glb",                   (required; relative to the
//                          "scale": 1, "rotate_x_degrees": 0,      scene file's directory)
//                          "translate": [0, 0, 0]},               world = translate + R_x·(scale·v)
//       {"type": "points", "positions": [[x,y,z], ...],           (required, ≥ 1 point)
//                          "splat_size": 0.05}                    (side of each splat, > 0)
//     ],
//     "camera": {
//       "projection": "perspective" | "orthographic",            (default perspective)
//       "tan_half_fov_y": 0.57735,                               (perspective; > 0)
//       "left": -1, "right": 1, "bottom": -1, "top": 1,          (orthographic, view units)
//       "near": 0.1, "far": 100,                                 (near > 0 for perspective)
//       "depth": "standard" | "reversed" | "reversed_infinite",  (default standard)
//       "width": 160, "height": 90,                              (1..16384)
//       "eye": [x,y,z], "target": [x,y,z], "up": [x,y,z],
//       "path": {"frames": F,                                    (required: 2..10000)
//                and exactly one of
//                "keyframes": [{"eye": [x,y,z], "target": [x,y,z]}, ...],
//                                  (2..F keyframes, both keys required; evenly spaced in frames:
//                                   keyframe k at frame k·(F − 1)/(K − 1), eye and target linear
//                                   between them; keyframe 0 is frame 0's camera, so the camera
//                                   itself gives no eye or target)
//                "orbit": {"degrees": a},  (−3600..3600: the eye turns about the axis `up`
//                                   through the target, a degrees by the last frame, right-handed:
//                                   counter-clockwise seen from above; distance kept)
//                "dolly": {"distance": d}, (eye and target move d along the view direction)
//                "strafe": {"distance": d}}(eye and target move d along the camera's right)
//                                  (d: ±1e15, world units by the last frame; each of these moves
//                                   by f/(F − 1) of it at frame f; frame 0 is the camera above.
//                                   A still camera over F frames: "strafe": {"distance": 0})
//     },
//     "ao_radius": 1.0,                                           (world units, > 0)
//     "renderer": {"normals": "world" | "view" | "none", "point_cloud": false,
//                  "normals_facing": "camera" | "as_stored",  (default camera; as_stored keeps a
//                                       surface's own normal, so back faces point away)
//                  "depth_buffer": "d32_sfloat" | "d24_unorm" | "d16_unorm"}  (default d32_sfloat)
//   }
//   Every coordinate and length is a finite number of magnitude at most 1e15 (max_coordinate):
//   beyond that, float geometry in the tracer and the GPU cannot tell points apart.
//   Meshes are read by load_mesh (mesh.hpp): any format assimp reads, and Terragen .ter.
//   Points become camera-facing square splats when the scene is built (points.hpp), so they
//   follow the camera; a point-cloud renderer has no normals ("normals": "none").
//   Errors name the file and the field, e.g.
//     scene.json.camera.depth: "reverse" is not a depth convention (valid: standard, reversed, reversed_infinite)
//     scene.json.camera.path.frames: 1 is out of range (valid: an integer 2..10000)
#pragma once

#include "mesh.hpp"
#include "points.hpp"

#include <aogen/error.hpp>
#include <aogen/math.hpp>
#include <aogen_truth/tracer.hpp>
#include <aogen_tools/files.hpp>
#include <aogen_tools/json_reader.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace aogen::scenes {

struct plane { dvec3 point, normal{0, 0, 1}; double half_extent = 1e4; };
struct sphere { dvec3 centre; double radius = 1; };
struct quad { dvec3 corner, e1, e2; };

enum class projection_kind { perspective, orthographic };
enum class normal_space { world, view, none };
enum class depth_format { d32_sfloat, d24_unorm, d16_unorm }; // the renderer's depth buffer

struct camera {
    projection_kind projection = projection_kind::perspective;
    float tan_half_fov_y = 0.57735027f; // tan(30°): 60° vertical field of view
    float left = -1, right = 1, bottom = -1, top = 1; // orthographic
    float near = 0.1f, far = 100.0f;
    depth_convention depth = depth_convention::standard;
    int width = 160, height = 90;
    dvec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};

    float aspect() const { return float(width) / float(height); }

    // The view basis: right (s), up (u) and backward (b = −forward), world space.
    void basis(dvec3& s, dvec3& u, dvec3& b) const
    {
        const dvec3 f = truth::normalize(target - eye);
        s = truth::normalize(truth::cross(f, up));
        u = truth::cross(s, f);
        b = -1.0 * f;
    }

    mat4 world_to_view() const
    {
        dvec3 s, u, b;
        basis(s, u, b);
        mat4 m;
        const dvec3 rows[3] = {s, u, b};
        for (int r = 0; r < 3; ++r) {
            m[0][r] = float(rows[r].x), m[1][r] = float(rows[r].y), m[2][r] = float(rows[r].z);
            m[3][r] = float(-truth::dot(rows[r], eye));
        }
        return m;
    }

    mat4 projection_matrix() const
    {
        return projection == projection_kind::perspective ? perspective(tan_half_fov_y, aspect(), near, far, depth)
                                                          : orthographic(left, right, bottom, top, near, far, depth);
    }

    // The depth a cleared buffer holds: 1 for standard, 0 for the reversed conventions.
    float background_depth() const { return depth == depth_convention::standard ? 1.0f : 0.0f; }
};

struct renderer_inputs {
    normal_space normals = normal_space::world;
    bool normals_face_camera = true; // false: normals as stored, a back face's pointing away from the camera
    bool point_cloud = false;
    depth_format depth_buffer = depth_format::d32_sfloat; // the G-buffer's depth is stored as this
};

// --- motion over frames -------------------------------------------------------------
// A scene without a path has one frame; with one, path.frames. Frame 0 is always the scene
// as given (at_frame below).

inline constexpr int max_frames = 10000;
inline constexpr double max_orbit_degrees = 3600; // ten turns

enum class path_kind { none, keyframes, orbit, dolly, strafe };

struct camera_keyframe { dvec3 eye, target; };

// How the camera moves from frame 0 (the scene's camera) to frame `frames` − 1.
struct camera_path {
    path_kind kind = path_kind::none;       // none: a still scene of one frame
    int frames = 1;                         // 2..max_frames with a path
    std::vector<camera_keyframe> keyframes; // keyframes: 2..frames, the first the camera's eye and target
    double amount = 0;                      // by the last frame: orbit, degrees; dolly, strafe, world units
};

enum class moving_kind { box, sphere };

// A box or a sphere that moves: at frame f translated by f × translate_per_frame.
struct geometry_motion {
    moving_kind kind = moving_kind::sphere;
    size_t index = 0; // into scene::boxes or scene::spheres
    dvec3 translate_per_frame;
};

struct scene {
    std::string name;
    std::string source;             // where it came from, for messages: its file, or "built-in scene 'crease'"
    std::vector<plane> planes;
    std::vector<box> boxes;
    std::vector<sphere> spheres;
    std::vector<quad> quads;
    std::vector<mesh> meshes;       // world space
    std::vector<points> point_sets; // drawn as splats facing `camera`
    aogen::scenes::camera camera;
    double ao_radius = 1.0;
    renderer_inputs renderer;
    camera_path path;                     // the camera over the frames (JSON camera.path)
    std::vector<geometry_motion> motions; // the spheres and boxes that move (JSON "motion")

    // Adds the geometry to a tracer scene (and commits it). Geometry ids follow the order
    // planes, boxes, spheres, quads, meshes, point sets (one id per mesh and per point set).
    void build(truth::scene& t) const
    {
        for (const plane& p : planes) t.add_plane(p.point, p.normal, p.half_extent);
        for (const box& b : boxes) t.add_box(b.lo, b.hi);
        for (const sphere& s : spheres) t.add_sphere(s.centre, s.radius);
        for (const quad& q : quads) t.add_quad(q.corner, q.e1, q.e2);
        for (const mesh& m : meshes) t.add_triangles(m.vertices, m.triangles);
        dvec3 right, up, back;
        camera.basis(right, up, back);
        for (const points& p : point_sets) {
            const mesh splats = splat_mesh(p, right, up);
            t.add_triangles(splats.vertices, splats.triangles);
        }
        t.commit();
    }

    bool has_geometry() const
    {
        return !(planes.empty() && boxes.empty() && spheres.empty() && quads.empty() && meshes.empty() &&
                 point_sets.empty());
    }
};

// The tracer for `s`, built and committed, with its origin at the camera's eye: the points
// the G-buffer finds and the reference traces from are within the camera's distances of it.
// A unique_ptr because a tracer owns Embree handles and cannot move.
// A tracer with its origin at `origin`: for rays that start far from the eye (a telephoto
// view's geometry kilometres away), an origin among them keeps their float coordinates
// small (aogen_report/reference.hpp).
inline std::unique_ptr<truth::scene> make_tracer_at(const scene& s, dvec3 origin)
{
    auto tracer = std::make_unique<truth::scene>(origin);
    s.build(*tracer);
    return tracer;
}

inline std::unique_ptr<truth::scene> make_tracer(const scene& s)
{
    return make_tracer_at(s, s.camera.eye);
}

// --- frames -------------------------------------------------------------------------

inline int frame_count(const scene& s) { return s.path.kind == path_kind::none ? 1 : s.path.frames; }

namespace detail {

// (1 − w)·a + w·b: exactly a at w = 0 and exactly b at w = 1.
inline dvec3 mix(dvec3 a, dvec3 b, double w) { return (1 - w) * a + w * b; }

// v turned by `degrees` about the unit axis k, right-handed (Rodrigues' formula).
inline dvec3 rotate(dvec3 v, dvec3 k, double degrees)
{
    const random::cos_sin cs = random::cos_sin_turns(degrees / 360);
    return cs.c * v + cs.s * truth::cross(k, v) + ((1 - cs.c) * truth::dot(k, v)) * k;
}

// The camera of frame f of a keyframe path: keyframe k at frame k·(F − 1)/(K − 1).
inline camera keyframe_camera(camera c, const camera_path& p, int f)
{
    const size_t last = p.keyframes.size() - 1;
    const double u = double(size_t(f) * last) / (p.frames - 1); // exact at every keyframe
    const size_t i = std::min(size_t(u), last - 1);
    c.eye = mix(p.keyframes[i].eye, p.keyframes[i + 1].eye, u - double(i));
    c.target = mix(p.keyframes[i].target, p.keyframes[i + 1].target, u - double(i));
    return c;
}

} // namespace detail

// The camera at frame f (0..p.frames − 1) of path `p` whose frame 0 is `c`.
inline camera camera_at(camera c, const camera_path& p, int f)
{
    if (p.kind == path_kind::none || f == 0) return c;
    if (p.kind == path_kind::keyframes) return detail::keyframe_camera(c, p, f);
    const double share = (double(f) / (p.frames - 1)) * p.amount; // of the orbit's degrees or the distance
    dvec3 right, up, back;
    c.basis(right, up, back);
    if (p.kind == path_kind::orbit) {
        c.eye = c.target + detail::rotate(c.eye - c.target, truth::normalize(c.up), share);
        return c;
    }
    const dvec3 move = share * (p.kind == path_kind::dolly ? -1.0 * back : right);
    c.eye = c.eye + move, c.target = c.target + move;
    return c;
}

// `s` at frame f (0..frame_count(s) − 1): the camera placed on its path and every moving
// sphere and box moved by f × its translate_per_frame. A still scene (no path, no motion):
// frame 0 of a scene with one frame is `s` itself.
inline scene at_frame(const scene& s, int f)
{
    const int frames = frame_count(s);
    if (f < 0 || f >= frames)
        fail(s.source + ": frame", std::to_string(f) + " is out of range",
             "valid: 0.." + std::to_string(frames - 1) + ": the scene has " + std::to_string(frames) + (frames == 1 ? " frame" : " frames"));
    if (frames == 1) return s;
    scene out = s;
    out.source = s.source + " at frame " + std::to_string(f);
    out.camera = camera_at(s.camera, s.path, f);
    for (const geometry_motion& m : s.motions) {
        const dvec3 d = double(f) * m.translate_per_frame;
        if (m.kind == moving_kind::sphere) {
            out.spheres[m.index].centre = out.spheres[m.index].centre + d;
        } else {
            box& b = out.boxes[m.index];
            b.lo = b.lo + d, b.hi = b.hi + d;
        }
    }
    out.path = {};
    out.motions.clear();
    return out;
}

// --- validation --------------------------------------------------------------------

// The largest coordinate or length a scene file may give (see JSON FORMAT).
inline constexpr double max_coordinate = 1e15;

namespace detail {

// Whether eye, target and up give a view basis (eye != target, up not along the view).
inline bool has_view(const camera& c)
{
    dvec3 s, u, b;
    c.basis(s, u, b);
    return std::isfinite(s.x + s.y + s.z + u.x + u.y + u.z);
}

inline bool same(dvec3 a, dvec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// `what` (a moving sphere's or box's motion) needs frames, which only a camera path gives.
inline void require_frames_for_motion(const std::string& what, const scene& s)
{
    if (frame_count(s) == 1)
        fail(what, "moves, but the scene has one frame: there is no camera.path",
             "valid: a camera.path, which gives the frames; \"strafe\": {\"distance\": 0} keeps the camera still");
}

inline void validate_path(const scene& s, const std::string& where)
{
    const camera_path& p = s.path;
    if (p.kind == path_kind::none) return;
    const std::string what = where + ": camera.path";
    require_range(what + ".frames", p.frames, 2, max_frames);
    if (p.kind == path_kind::keyframes) {
        require_range(what + ".keyframes count", int(p.keyframes.size()), 2, p.frames);
        if (!same(p.keyframes[0].eye, s.camera.eye) || !same(p.keyframes[0].target, s.camera.target))
            fail(what + ".keyframes[0]", "is not the camera's eye and target", "valid: keyframe 0 is frame 0's camera");
    } else if (p.kind == path_kind::orbit) {
        require_finite_range(what + ".orbit.degrees", p.amount, -max_orbit_degrees, max_orbit_degrees);
    } else {
        require_finite_range(what + (p.kind == path_kind::dolly ? ".dolly" : ".strafe") + ".distance", p.amount, -max_coordinate, max_coordinate);
    }
    for (int f = 1; f < p.frames; ++f)
        if (!has_view(camera_at(s.camera, p, f)))
            fail(what, "frame " + std::to_string(f) + "'s eye, target and up do not define a view (eye == target, or up parallel to the view)",
                 "valid: a path whose eye stays off its target and off the up axis through it");
}

inline void validate_motions(const scene& s, const std::string& where)
{
    for (size_t i = 0; i < s.motions.size(); ++i) {
        const geometry_motion& m = s.motions[i];
        const bool sphere = m.kind == moving_kind::sphere;
        const std::string what = where + ": " + (sphere ? "sphere " : "box ") + std::to_string(m.index) + " motion";
        const size_t count = sphere ? s.spheres.size() : s.boxes.size();
        if (m.index >= count)
            fail(what, std::string("names a ") + (sphere ? "sphere" : "box") + " the scene does not have",
                 "valid: index < " + std::to_string(count));
        for (size_t j = 0; j < i; ++j)
            if (s.motions[j].kind == m.kind && s.motions[j].index == m.index) fail(what, "is given twice", "valid: one motion per sphere or box");
        for (double c : {m.translate_per_frame.x, m.translate_per_frame.y, m.translate_per_frame.z})
            require_finite_range(what + ".translate_per_frame", c, -max_coordinate, max_coordinate);
        require_frames_for_motion(what, s);
    }
}

} // namespace detail

inline void validate(const scene& s, const std::string& where)
{
    const camera& c = s.camera;
    if (!s.has_geometry())
        fail(where + ": geometry", "is empty", "valid: at least one plane, box, sphere, quad, mesh or point set");
    require_range(where + ": camera.width", c.width, 1, 16384);
    require_range(where + ": camera.height", c.height, 1, 16384);
    if (c.projection == projection_kind::perspective) {
        require_finite_range(where + ": camera.tan_half_fov_y", c.tan_half_fov_y, 1e-6, 1e6);
        if (!(c.near > 0)) fail(where + ": camera.near", format_number(c.near) + " is not > 0", "valid: > 0 for a perspective camera");
    } else {
        if (!(c.near >= 0)) fail(where + ": camera.near", format_number(c.near) + " is negative", "valid: >= 0");
        if (!(c.right != c.left) || !(c.top != c.bottom))
            fail(where + ": camera.left/right/bottom/top", "describe an empty window", "valid: left != right, bottom != top");
    }
    if (!(c.far > c.near) || !std::isfinite(c.far))
        fail(where + ": camera.far", format_number(c.far) + " is not a finite value > near", "valid: near < far < inf");
    if (!detail::has_view(c))
        fail(where + ": camera.eye/target/up", "do not define a view (eye == target, or up parallel to the view)",
             "valid: eye != target, up not parallel to target − eye");
    if (!(s.ao_radius > 0) || !std::isfinite(s.ao_radius))
        fail(where + ": ao_radius", format_number(s.ao_radius) + " is not a positive number", "valid: > 0");
    for (size_t i = 0; i < s.spheres.size(); ++i)
        if (!(s.spheres[i].radius > 0))
            fail(where + ": sphere " + std::to_string(i) + " radius", format_number(s.spheres[i].radius) + " is not > 0", "valid: > 0");
    for (size_t i = 0; i < s.boxes.size(); ++i) {
        const box& b = s.boxes[i];
        if (!(b.lo.x < b.hi.x && b.lo.y < b.hi.y && b.lo.z < b.hi.z))
            fail(where + ": box " + std::to_string(i), "min is not below max on every axis", "valid: min < max componentwise");
    }
    for (size_t i = 0; i < s.point_sets.size(); ++i) {
        const points& p = s.point_sets[i];
        const std::string what = where + ": point set " + std::to_string(i);
        if (p.positions.empty()) fail(what + " positions", "are empty", "valid: at least one [x, y, z]");
        if (!(p.splat_size > 0) || !std::isfinite(p.splat_size))
            fail(what + " splat_size", format_number(p.splat_size) + " is not a positive number", "valid: > 0");
    }
    detail::validate_path(s, where);
    detail::validate_motions(s, where);
}

// --- JSON ---------------------------------------------------------------------------

namespace detail {

// An [x, y, z] value, each component within ±max_coordinate. json_reader cannot ask
// whether an array element is an array, so nlohmann's type_error (indexing an object)
// stands for "not an array".
inline dvec3 as_vec3(const tools::json_reader& a)
{
    if (a.size() != 3) fail(a.path(), "has " + std::to_string(a.size()) + " entries", "valid: [x, y, z]");
    dvec3 v;
    try {
        v = {a.at(0).as_number(), a.at(1).as_number(), a.at(2).as_number()};
    } catch (const nlohmann::json::type_error&) {
        fail(a.path(), "is not an array", "valid: [x, y, z]");
    }
    for (double c : {v.x, v.y, v.z}) require_finite_range(a.path(), c, -max_coordinate, max_coordinate);
    return v;
}

inline dvec3 read_vec3(const tools::json_reader& r, const char* key) { return as_vec3(r.array(key)); }

// A length within (0, max_coordinate].
inline double read_length(const tools::json_reader& g, const char* key)
{
    const double x = g.number(key);
    require_finite_above(g.path() + "." + key, x, 0, max_coordinate);
    return x;
}

// A direction that is not zero (nor so small its square underflows).
inline dvec3 read_direction(const tools::json_reader& g, const char* key)
{
    const dvec3 d = read_vec3(g, key);
    if (!(truth::dot(d, d) > 1e-200)) fail(g.path() + "." + key, "is the zero vector", "valid: a non-zero direction");
    return d;
}

// Two edge vectors spanning a parallelogram: neither zero, not parallel.
inline void require_spanning(const tools::json_reader& g, const dvec3& e1, const dvec3& e2)
{
    const dvec3 n = truth::cross(e1, e2);
    const double scale = std::sqrt(truth::dot(e1, e1) * truth::dot(e2, e2));
    if (!(std::sqrt(truth::dot(n, n)) > 1e-9 * scale) || !(scale > 0))
        fail(g.path(), "e1 and e2 are parallel or zero: the quad has no area", "valid: two edges that are not parallel");
}

// A mesh file named in `source` (a scene file): relative paths start at its directory.
inline std::string resolve_path(const std::string& file, const std::string& source)
{
    const std::filesystem::path f(file);
    return f.is_absolute() ? file : (std::filesystem::path(source).parent_path() / f).string();
}

// {"type": "mesh", "file", "scale", "rotate_x_degrees", "translate"}: loaded here.
inline mesh read_mesh(const tools::json_reader& g, const std::string& source)
{
    g.only_keys({"type", "file", "scale", "rotate_x_degrees", "translate"});
    mesh_placement at;
    if (g.has("scale")) {
        at.scale = g.number("scale");
        require_finite_above(g.path() + ".scale", at.scale, 0, 1e30);
    }
    if (g.has("rotate_x_degrees")) {
        at.rotate_x_degrees = g.number("rotate_x_degrees");
        require_finite_range(g.path() + ".rotate_x_degrees", at.rotate_x_degrees, -360, 360);
    }
    if (g.has("translate")) at.translate = read_vec3(g, "translate");
    return load_mesh(resolve_path(g.string("file"), source), at, g.path() + ".file");
}

// {"type": "points", "positions": [[x, y, z], ...], "splat_size"}.
inline points read_points(const tools::json_reader& g)
{
    g.only_keys({"type", "positions", "splat_size"});
    points p;
    const tools::json_reader positions = g.array("positions");
    for (size_t i = 0; i < positions.size(); ++i) p.positions.push_back(as_vec3(positions.at(i)));
    if (g.has("splat_size")) {
        p.splat_size = g.number("splat_size");
        require_finite_above(g.path() + ".splat_size", p.splat_size, 0, 1e30);
    }
    return p;
}

// {"motion": {"translate_per_frame": [x, y, z]}} of a sphere or box.
inline dvec3 read_motion(const tools::json_reader& g)
{
    const tools::json_reader m = g.field("motion");
    m.only_keys({"translate_per_frame"});
    return read_vec3(m, "translate_per_frame");
}

// Planes, quads, meshes and points stand still: a "motion" on one is refused by name.
inline void refuse_motion(const tools::json_reader& g, const std::string& type)
{
    if (g.has("motion") && (type == "plane" || type == "quad" || type == "mesh" || type == "points"))
        fail(g.path() + ".motion", "is for spheres and boxes, not a " + type,
             "valid: motion on a sphere or a box; planes, quads, meshes and points stand still");
}

// camera.path's keyframes: 2..frames of them, each {"eye", "target"}.
inline std::vector<camera_keyframe> read_keyframes(const tools::json_reader& p, int frames)
{
    const tools::json_reader k = p.array("keyframes");
    if (k.size() < 2 || k.size() > size_t(frames))
        fail(k.path(), "has " + std::to_string(k.size()) + (k.size() == 1 ? " keyframe" : " keyframes"),
             "valid: 2.." + std::to_string(frames) + " keyframes, at most one per frame");
    std::vector<camera_keyframe> out;
    for (size_t i = 0; i < k.size(); ++i) {
        const tools::json_reader f = k.at(i);
        f.only_keys({"eye", "target"});
        out.push_back({read_vec3(f, "eye"), read_vec3(f, "target")});
    }
    return out;
}

// {"degrees": a} of an orbit, {"distance": d} of a dolly or strafe.
inline double read_path_amount(const tools::json_reader& p, const char* kind)
{
    const tools::json_reader k = p.field(kind);
    const bool orbit = std::string(kind) == "orbit";
    const char* key = orbit ? "degrees" : "distance";
    k.only_keys({key});
    const double limit = orbit ? max_orbit_degrees : max_coordinate;
    const double x = k.number(key);
    require_finite_range(k.path() + "." + key, x, -limit, limit);
    return x;
}

// camera.path: "frames" and exactly one of keyframes, orbit, dolly, strafe.
inline camera_path read_path(const tools::json_reader& c)
{
    const tools::json_reader p = c.field("path");
    p.only_keys({"frames", "keyframes", "orbit", "dolly", "strafe"});
    camera_path out;
    out.frames = int(p.unsigned_integer("frames", 2, max_frames));
    const std::pair<const char*, path_kind> kinds[] = {
        {"keyframes", path_kind::keyframes}, {"orbit", path_kind::orbit}, {"dolly", path_kind::dolly}, {"strafe", path_kind::strafe}};
    std::string given;
    for (const auto& [key, kind] : kinds)
        if (p.has(key)) {
            if (!given.empty())
                fail(p.path(), "has both " + given + " and " + key, "valid: exactly one of keyframes, orbit, dolly, strafe");
            given = key, out.kind = kind;
        }
    if (given.empty()) fail(p.path(), "has no kind of path", "valid: exactly one of keyframes, orbit, dolly, strafe");
    if (out.kind == path_kind::keyframes) out.keyframes = read_keyframes(p, out.frames);
    else out.amount = read_path_amount(p, given.c_str());
    return out;
}

template <class E>
E read_enum(const tools::json_reader& r, const char* key, std::initializer_list<std::pair<const char*, E>> values, const char* what)
{
    const tools::json_reader f = r.field(key);
    const std::string v = f.as_string();
    std::string valid;
    for (const auto& [name, e] : values) {
        if (v == name) return e;
        valid += (valid.empty() ? "" : ", ") + std::string(name);
    }
    fail(f.path(), quote(v) + " is not " + what, "valid: " + valid);
}

} // namespace detail

// Parses a scene from JSON text; `source` names it in every message (a file name).
// Parses a scene from a JSON object (a file's root, or a value inside another document
// such as a stability case); `source` names the file it came from, for mesh paths and messages.
inline scene read_scene(const tools::json_reader& root, const std::string& source)
{
    root.only_keys({"name", "geometry", "camera", "ao_radius", "renderer"});
    scene s;
    s.source = root.path();

    std::string first_motion; // the first geometry entry's motion, if any: it needs a camera path
    const tools::json_reader geo = root.array("geometry");
    for (size_t i = 0; i < geo.size(); ++i) {
        const tools::json_reader g = geo.at(i);
        g.require_object();
        const std::string type = g.string("type");
        detail::refuse_motion(g, type);
        if (type == "plane") {
            g.only_keys({"type", "point", "normal", "half_extent"});
            plane p{detail::read_vec3(g, "point"), detail::read_direction(g, "normal")};
            if (g.has("half_extent")) p.half_extent = detail::read_length(g, "half_extent");
            s.planes.push_back(p);
        } else if (type == "box") {
            g.only_keys({"type", "min", "max", "motion"});
            const box b{detail::read_vec3(g, "min"), detail::read_vec3(g, "max")};
            if (!(b.lo.x < b.hi.x && b.lo.y < b.hi.y && b.lo.z < b.hi.z))
                fail(g.path(), "min is not below max on every axis", "valid: min < max componentwise");
            if (g.has("motion")) s.motions.push_back({moving_kind::box, s.boxes.size(), detail::read_motion(g)});
            s.boxes.push_back(b);
        } else if (type == "sphere") {
            g.only_keys({"type", "centre", "radius", "motion"});
            s.spheres.push_back({detail::read_vec3(g, "centre"), detail::read_length(g, "radius")});
            if (g.has("motion")) s.motions.push_back({moving_kind::sphere, s.spheres.size() - 1, detail::read_motion(g)});
        } else if (type == "quad") {
            g.only_keys({"type", "corner", "e1", "e2"});
            const quad q{detail::read_vec3(g, "corner"), detail::read_vec3(g, "e1"), detail::read_vec3(g, "e2")};
            detail::require_spanning(g, q.e1, q.e2);
            s.quads.push_back(q);
        } else if (type == "mesh") {
            s.meshes.push_back(detail::read_mesh(g, source));
        } else if (type == "points") {
            s.point_sets.push_back(detail::read_points(g));
        } else {
            fail(g.path() + ".type", quote(type) + " is not a geometry type", "valid: plane, box, sphere, quad, mesh, points");
        }
        if (g.has("motion") && first_motion.empty()) first_motion = g.path() + ".motion";
    }

    if (root.has("camera")) {
        const tools::json_reader c = root.field("camera");
        c.only_keys({"projection", "tan_half_fov_y", "left", "right", "bottom", "top", "near", "far", "depth", "width",
                     "height", "eye", "target", "up", "path"});
        camera& cam = s.camera;
        if (c.has("projection"))
            cam.projection = detail::read_enum<projection_kind>(
                c, "projection", {{"perspective", projection_kind::perspective}, {"orthographic", projection_kind::orthographic}},
                "a projection");
        const bool persp = cam.projection == projection_kind::perspective;
        for (const char* k : {"left", "right", "bottom", "top"})
            if (persp && c.has(k)) fail(c.path() + "." + k, "is for orthographic cameras", "valid: tan_half_fov_y for a perspective camera");
        if (!persp && c.has("tan_half_fov_y"))
            fail(c.path() + ".tan_half_fov_y", "is for perspective cameras", "valid: left, right, bottom, top for an orthographic camera");
        auto num = [&](const char* k, float& out) {
            if (c.has(k)) out = float(c.number(k));
        };
        num("tan_half_fov_y", cam.tan_half_fov_y);
        num("left", cam.left), num("right", cam.right), num("bottom", cam.bottom), num("top", cam.top);
        num("near", cam.near), num("far", cam.far);
        if (c.has("depth"))
            cam.depth = detail::read_enum<depth_convention>(c, "depth",
                                                            {{"standard", depth_convention::standard},
                                                             {"reversed", depth_convention::reversed},
                                                             {"reversed_infinite", depth_convention::reversed_infinite}},
                                                            "a depth convention");
        if (c.has("width")) cam.width = int(c.unsigned_integer("width", 1, 16384));
        if (c.has("height")) cam.height = int(c.unsigned_integer("height", 1, 16384));
        if (c.has("eye")) cam.eye = detail::read_vec3(c, "eye");
        if (c.has("target")) cam.target = detail::read_vec3(c, "target");
        if (c.has("up")) cam.up = detail::read_vec3(c, "up");
        if (c.has("path")) s.path = detail::read_path(c);
        if (s.path.kind == path_kind::keyframes) {
            for (const char* k : {"eye", "target"})
                if (c.has(k))
                    fail(c.path() + "." + k, "is given by camera.path.keyframes[0] in a path of keyframes",
                         "valid: leave eye and target out with keyframes; orbit, dolly and strafe start from them");
            cam.eye = s.path.keyframes[0].eye, cam.target = s.path.keyframes[0].target;
        }
    }
    if (!first_motion.empty()) detail::require_frames_for_motion(first_motion, s);
    if (root.has("ao_radius")) s.ao_radius = detail::read_length(root, "ao_radius");
    if (root.has("renderer")) {
        const tools::json_reader r = root.field("renderer");
        r.only_keys({"normals", "normals_facing", "point_cloud", "depth_buffer"});
        if (r.has("normals"))
            s.renderer.normals = detail::read_enum<normal_space>(
                r, "normals", {{"world", normal_space::world}, {"view", normal_space::view}, {"none", normal_space::none}},
                "a normal space");
        if (r.has("normals_facing"))
            s.renderer.normals_face_camera =
                detail::read_enum<bool>(r, "normals_facing", {{"camera", true}, {"as_stored", false}}, "a normal orientation");
        if (r.has("point_cloud")) s.renderer.point_cloud = r.boolean("point_cloud");
        if (r.has("depth_buffer"))
            s.renderer.depth_buffer = detail::read_enum<depth_format>(r, "depth_buffer",
                                                                      {{"d32_sfloat", depth_format::d32_sfloat},
                                                                       {"d24_unorm", depth_format::d24_unorm},
                                                                       {"d16_unorm", depth_format::d16_unorm}},
                                                                      "a depth buffer format");
    }
    validate(s, root.path());
    // Checked last, so that a file's other mistakes are named first. The report's tables,
    // progress and strip file are named by it: present, not empty, printable.
    s.name = root.string("name");
    if (s.name.empty() || printable(s.name) != s.name || s.name.size() > 100)
        fail(root.path() + ".name", s.name.empty() ? "is empty" : quote(s.name) + " is not a printable name of at most 100 characters",
             "valid: a name for the scene, e.g. \"box on a floor\"");
    return s;
}

// Parses a scene from JSON text; `source` (a file name) starts every error message.
inline scene read_scene(const std::string& text, const std::string& source)
{
    const nlohmann::json doc = tools::json_reader::parse(text, source);
    return read_scene(tools::json_reader(doc, source), source);
}

inline scene load_scene(const std::string& path) { return read_scene(tools::read_file(path), path); }

// --- built-in scenes ----------------------------------------------------------------
// World z is up; the floor is z = 0. Default resolution 160×90, 60° vertical field of view.
// The analytic scenes come first, then the meshes of assimp-testmodels (engine, teapots,
// terrain: builtin_scene says to install the package when a model is missing), then the
// point cloud. Frames: room strafes, stairs orbits, engine dollies and rolling_sphere's
// sphere rolls while its camera strafes, 16 frames each; the rest are still (one frame).
// Frame 0 of each is the scene as it was before paths existed.

inline std::vector<std::string> builtin_scene_names()
{
    return {"crease", "groove", "wall", "sphere_on_plane", "room", "stairs", "plank", "far_floor", "rolling_sphere",
            "engine", "teapots", "terrain", "atat", "atat_far", "dwarf", "dwarf_far", "spider", "spider_far", "point_cloud"};
}

namespace detail {

// Where Debian's assimp-testmodels installs the models.
inline const std::string testmodels_dir = "/usr/share/assimp/models/";

// A built-in scene's model from assimp-testmodels, placed by `p`, then centred on the z axis
// with its lowest point at z = 0 (on the floor).
inline mesh builtin_model(const std::string& scene_name, const std::string& relative_path, const mesh_placement& p)
{
    const std::string path = testmodels_dir + relative_path;
    const std::string subject = "built-in scene " + scene_name;
    if (!std::ifstream(path))
        fail(subject, "needs " + path + ", which is missing", "install assimp-testmodels (apt-get install assimp-testmodels)");
    mesh m = load_mesh(path, p, subject);
    const box b = bounds(m);
    translate(m, {-0.5 * (b.lo.x + b.hi.x), -0.5 * (b.lo.y + b.hi.y), -b.lo.z});
    return m;
}

// Frames `vertices` (a mesh's, or points) from `azimuth_degrees` around z (0: from −y, 90:
// from +x) and `elevation_degrees` above the horizon: the nearest distance d at which every
// vertex projects within ±fill in NDC x and y (per vertex, view offsets (x, y, z) from the
// target: d ≥ z + |x|/(fill·tan·aspect) and d ≥ z + |y|/(fill·tan)); fill > 1 crops. Three
// rounds move the target so that the projected extent is centred. Vertices, not the bounding
// box: a box's corners lie far outside an oblique view of a rounded model. near = d/50;
// far = d·far_factor, which must reach the farthest visible geometry (a floor seen from 35°
// elevation: ~7·d at the top of the image).
inline void frame(camera& c, const std::vector<dvec3>& vertices, double azimuth_degrees, double elevation_degrees, double fill,
                  double far_factor)
{
    const box b = bounds(vertices);
    const random::cos_sin az = random::cos_sin_turns(azimuth_degrees / 360), el = random::cos_sin_turns(elevation_degrees / 360);
    const dvec3 back{el.c * az.s, -el.c * az.c, el.s}; // from the target towards the eye
    c.target = 0.5 * (b.lo + b.hi);
    c.eye = c.target + back;
    c.up = {0, 0, 1};
    dvec3 right, up, b_;
    c.basis(right, up, b_);
    const double tx = c.tan_half_fov_y * c.aspect(), ty = c.tan_half_fov_y;
    double d = 0;
    for (int round = 0; round < 4; ++round) {
        d = 0;
        for (const dvec3& v : vertices) {
            const dvec3 o = v - c.target;
            const double z = truth::dot(o, back);
            d = std::max({d, z + std::abs(truth::dot(o, right)) / (fill * tx), z + std::abs(truth::dot(o, up)) / (fill * ty)});
        }
        if (round == 3) break;
        double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300; // NDC extent at distance d
        for (const dvec3& v : vertices) {
            const dvec3 o = v - c.target;
            const double depth = d - truth::dot(o, back);
            const double x = truth::dot(o, right) / (depth * tx), y = truth::dot(o, up) / (depth * ty);
            lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
        }
        c.target = c.target + (0.5 * (lo_x + hi_x) * tx * d) * right + (0.5 * (lo_y + hi_y) * ty * d) * up;
    }
    c.eye = c.target + d * back;
    c.near = float(d / 50), c.far = float(d * far_factor);
}

// A model scene: the mesh (on a floor plane z = 0 when `floor`), framed from 35° elevation,
// with ao_radius = radius_fraction × the mesh's bounding-box diagonal.
inline void set_model(scene& s, mesh m, bool floor, double azimuth_degrees, double fill, double radius_fraction)
{
    const box b = bounds(m);
    const dvec3 diagonal = b.hi - b.lo;
    if (floor) s.planes = {{{0, 0, 0}, {0, 0, 1}}};
    frame(s.camera, m.vertices, azimuth_degrees, 35, fill, floor ? 10 : 3);
    s.meshes = {std::move(m)};
    s.ao_radius = radius_fraction * std::sqrt(truth::dot(diagonal, diagonal));
}

// Seed 004's point cloud: a 4 m × 3.5 m floor, a 1 m box and a sphere of radius 0.6 sampled
// at 400 points/m² (~8 000 points), drawn as 8 cm splats (2 to 4 pixels at 160×90), which
// cover ~90% of the surfaces (1 − e^(−400·0.08²)) and leave gaps as real point clouds do.
inline void set_point_cloud(scene& s)
{
    constexpr double density = 400;
    const box b{{-1.2, -0.4, 0}, {-0.2, 0.6, 1}};
    points p;
    p.splat_size = 0.08;
    auto rng = random::seeded(0, points_stream);
    sample_quad(p, rng, {-2, -1.5, 0}, {4, 0, 0}, {0, 3.5, 0}, density);
    const auto under_box = [&](dvec3 q) { return q.x > b.lo.x && q.x < b.hi.x && q.y > b.lo.y && q.y < b.hi.y; };
    p.positions.erase(std::remove_if(p.positions.begin(), p.positions.end(), under_box), p.positions.end());
    sample_box(p, rng, b, density);
    sample_sphere(p, rng, {0.9, 0.2, 0.6}, 0.6, density);
    frame(s.camera, p.positions, 30, 35, 0.95, 10);
    s.point_sets = {std::move(p)};
    s.renderer.normals = normal_space::none; // the viewer has depth only
    s.renderer.point_cloud = true;
    s.ao_radius = 0.5;
}

} // namespace detail

inline scene builtin_scene(const std::string& name)
{
    scene s;
    s.name = name;
    s.source = "built-in scene " + quote(name);
    camera& c = s.camera;
    c.up = {0, 0, 1};
    const plane floor{{0, 0, 0}, {0, 0, 1}};
    if (name == "crease") { // floor + wall x = 0 at 90°: AO → 0.5 along the crease
        s.planes = {floor, {{0, 0, 0}, {1, 0, 0}}};
        c.eye = {5, -5, 3.5}, c.target = {1, 0, 0.5};
    } else if (name == "groove") { // 90° V groove along y, apex on the y axis
        const double h = std::sqrt(0.5);
        s.planes = {{{0, 0, 0}, {h, 0, h}}, {{0, 0, 0}, {-h, 0, h}}};
        c.eye = {0, -6, 5}, c.target = {0, 0, 0.5};
    } else if (name == "wall") { // a thin wall of height H = 1 standing on the floor
        s.planes = {floor};
        s.boxes = {{{-0.02, -1000, 0}, {0, 1000, 1}}};
        c.eye = {5, -4, 3}, c.target = {1, 0, 0.3};
    } else if (name == "sphere_on_plane") { // unit sphere resting on the floor at the origin
        s.planes = {floor};
        s.spheres = {{{0, 0, 1}, 1}};
        c.eye = {4, -5, 3.5}, c.target = {0, 0, 0.7};
    } else if (name == "room") { // floor, three walls (quads) and a few boxes, seen from inside
        s.planes = {floor};
        s.quads = {{{-5, 5, 0}, {10, 0, 0}, {0, 0, 3}},   // back wall y = 5
                   {{-5, -5, 0}, {0, 10, 0}, {0, 0, 3}},  // left wall x = −5
                   {{5, -5, 0}, {0, 10, 0}, {0, 0, 3}}};  // right wall x = 5
        s.boxes = {{{-4.5, 3, 0}, {-2.5, 4.5, 1}}, {{1, 1, 0}, {2, 2, 2}}, {{-1, -1, 0}, {0.5, 0, 0.5}}};
        s.spheres = {{{3, 3.5, 0.6}, 0.6}};
        c.eye = {0, -7, 2.5}, c.target = {0, 1.5, 0.8};
        s.path = {path_kind::strafe, 16, {}, 1.0}; // 1 m to the right (+x) over 16 frames
    } else if (name == "stairs") { // five steps of rise 0.2 and run 0.4 climbing along +y
        s.planes = {floor};
        for (int i = 0; i < 5; ++i) s.boxes.push_back({{-1.5, 0.4 * i, 0}, {1.5, 2.0, 0.2 * (i + 1)}});
        c.eye = {3.5, -3, 2.5}, c.target = {0, 1, 0.4};
        s.path = {path_kind::orbit, 16, {}, 20.0}; // 20° about the vertical through the target over 16 frames
    } else if (name == "plank") { // a 2 cm plank 5 cm above the floor
        s.planes = {floor};
        s.boxes = {{{-1.5, -0.2, 0.05}, {1.5, 0.2, 0.07}}};
        c.eye = {2.5, -2.5, 1.5}, c.target = {0, 0, 0.05};
    } else if (name == "far_floor") { // a floor to the horizon from eye height: the truth is 1 everywhere,
                                      // so anything darker is false occlusion (distant floors banded grey)
        s.planes = {{{0, 0, 0}, {0, 0, 1}, 2000}}; // 2 km: within what an R = 1 reference traces reliably
        c.eye = {0, 0, 1.6}, c.target = {0, 40, 0.8};
        c.far = 5000;
    } else if (name == "rolling_sphere") { // crease's floor and wall x = 0 and sphere_on_plane's unit sphere,
                                           // 0.5 from the wall (half R), rolling along it (+y, left to right
                                           // on screen) 0.2 a frame from y = −1.5 to 1.5 over 16 frames while
                                           // the camera strafes 0.5 the same way
        s.planes = {floor, {{0, 0, 0}, {1, 0, 0}}};
        s.spheres = {{{1.5, -1.5, 1}, 1}};
        s.motions = {{moving_kind::sphere, 0, {0, 0.2, 0}}};
        c.eye = {6, -2, 3}, c.target = {1, 0, 0.8};
        s.path = {path_kind::strafe, 16, {}, 0.5};
    } else if (name == "engine") { // glTF 2CylinderEngine: y-up millimetres → z-up metres (0.74 m long)
        detail::set_model(s, detail::builtin_model(name, "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", {0.001, 90, {}}),
                          true, 30, 0.9, 0.06);
        const dvec3 view = c.target - c.eye; // dollies in by a fifth of the distance to the target over 16 frames
        s.path = {path_kind::dolly, 16, {}, 0.2 * std::sqrt(truth::dot(view, view))};
    } else if (name == "teapots") { // Collada teapots, y-up → z-up (1.3 units across)
        detail::set_model(s, detail::builtin_model(name, "Collada/teapots.DAE", {1, 90, {}}), true, 30, 0.9, 0.08);
    } else if (name == "terrain") { // Terragen height field, metres → km (10 km square, 1.4 km relief, z up),
                                    // seen from −y and cropped (fill 1.3): no floor, sky at the top
        detail::set_model(s, detail::builtin_model(name, "TER/RealisticTerrain_Large.ter", {0.001, 0, {}}), false, 0, 1.3, 0.06);
    } else if (name == "atat" || name == "atat_far") { // Quick3D AT-AT walker, y-up → z-up: thin legs (thickness)
        detail::set_model(s, detail::builtin_model(name, "Q3D/E-AT-AT.q3o", {1, 0, {}}), true, 30, name == "atat" ? 0.9 : 0.3, 0.06);
    } else if (name == "dwarf" || name == "dwarf_far") { // Caligari dwarf, y-up → z-up
        detail::set_model(s, detail::builtin_model(name, "COB/dwarf.cob", {1, 0, {}}), true, 30, name == "dwarf" ? 0.9 : 0.3, 0.06);
    } else if (name == "spider" || name == "spider_far") { // OBJ spider, y-up → z-up: thin legs over the floor
        detail::set_model(s, detail::builtin_model(name, "OBJ/spider.obj", {1, 90, {}}), true, 30, name == "spider" ? 0.9 : 0.3, 0.06);
    } else if (name == "point_cloud") {
        detail::set_point_cloud(s);
    } else {
        std::string valid;
        for (const std::string& n : builtin_scene_names()) valid += (valid.empty() ? "" : ", ") + n;
        fail("built-in scene", quote(name) + " is not known", "valid: " + valid);
    }
    validate(s, "built-in scene " + name);
    return s;
}

} // namespace aogen::scenes
