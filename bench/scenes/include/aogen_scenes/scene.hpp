// aogen_scenes/scene.hpp — what a benchmark scene is: geometry, camera, AO radius and what
// the renderer has; read from JSON or taken from the built-ins.
//
// WHAT
//   scene                        analytic primitives (planes, boxes, spheres, quads) in world
//                                space, a camera, the AO radius R and the renderer's inputs.
//   camera::world_to_view()      look-at from eye/target/up (right-handed, looking down −z).
//   camera::projection()         aogen::perspective()/orthographic() for the camera's depth
//                                convention (aogen/math.hpp).
//   builtin_scene(name)          DESIGN.md's closed-form configurations and a few more;
//                                builtin_scene_names() lists them.
//   read_scene(text, source)     parses the JSON format below; `source` (a file name) starts
//                                every error message. load_scene(path) reads a file.
//
// JSON FORMAT (every key optional unless marked; unknown keys are errors)
//   {
//     "name": "my scene",
//     "geometry": [                                              (required, ≥ 1 entry)
//       {"type": "plane",  "point": [x,y,z], "normal": [x,y,z], "half_extent": 1e4},
//       {"type": "box",    "min": [x,y,z], "max": [x,y,z]},       (axis-aligned, min < max)
//       {"type": "sphere", "centre": [x,y,z], "radius": r},       (r > 0)
//       {"type": "quad",   "corner": [x,y,z], "e1": [x,y,z], "e2": [x,y,z]}
//     ],                       ("mesh" is rejected: "meshes: not supported yet")
//     "camera": {
//       "projection": "perspective" | "orthographic",            (default perspective)
//       "tan_half_fov_y": 0.57735,                               (perspective; > 0)
//       "left": -1, "right": 1, "bottom": -1, "top": 1,          (orthographic, view units)
//       "near": 0.1, "far": 100,                                 (near > 0 for perspective)
//       "depth": "standard" | "reversed" | "reversed_infinite",  (default standard)
//       "width": 160, "height": 90,                              (1..16384)
//       "eye": [x,y,z], "target": [x,y,z], "up": [x,y,z]
//     },
//     "ao_radius": 1.0,                                           (world units, > 0)
//     "renderer": {"normals": "world" | "view" | "none", "point_cloud": false}
//   }
//   Errors name the file and the field, e.g.
//     scene.json.camera.depth: "reverse" is not a depth convention (valid: standard, reversed, reversed_infinite)
#pragma once

#include <aogen/error.hpp>
#include <aogen/math.hpp>
#include <aogen_truth/tracer.hpp>
#include <generator/json_input.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace aogen::scenes {

using dvec3 = truth::vec3; // world space in double: scenes may sit far from the origin

struct plane { dvec3 point, normal{0, 0, 1}; double half_extent = 1e4; };
struct box { dvec3 lo, hi; };
struct sphere { dvec3 centre; double radius = 1; };
struct quad { dvec3 corner, e1, e2; };

enum class projection_kind { perspective, orthographic };
enum class normal_space { world, view, none };

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
    bool point_cloud = false;
};

struct scene {
    std::string name;
    std::vector<plane> planes;
    std::vector<box> boxes;
    std::vector<sphere> spheres;
    std::vector<quad> quads;
    aogen::scenes::camera camera;
    double ao_radius = 1.0;
    renderer_inputs renderer;

    // Adds the geometry to a tracer scene (and commits it). Geometry ids follow the order
    // planes, boxes, spheres, quads.
    void build(truth::scene& t) const
    {
        for (const plane& p : planes) t.add_plane(p.point, p.normal, p.half_extent);
        for (const box& b : boxes) t.add_box(b.lo, b.hi);
        for (const sphere& s : spheres) t.add_sphere(s.centre, s.radius);
        for (const quad& q : quads) t.add_quad(q.corner, q.e1, q.e2);
        t.commit();
    }
};

// --- validation --------------------------------------------------------------------

inline void validate(const scene& s, const std::string& where)
{
    const camera& c = s.camera;
    if (s.planes.empty() && s.boxes.empty() && s.spheres.empty() && s.quads.empty())
        fail(where + ": geometry", "is empty", "valid: at least one plane, box, sphere or quad");
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
    dvec3 sb, ub, bb;
    c.basis(sb, ub, bb);
    if (!std::isfinite(sb.x + sb.y + sb.z + ub.x + ub.y + ub.z))
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
}

// --- JSON ---------------------------------------------------------------------------

namespace detail {

inline dvec3 read_vec3(const cli::json_reader& r, const char* key)
{
    const cli::json_reader a = r.array(key);
    if (a.size() != 3) fail(a.path(), "has " + std::to_string(a.size()) + " entries", "valid: [x, y, z]");
    return {a.at(0).as_number(), a.at(1).as_number(), a.at(2).as_number()};
}

template <class E>
E read_enum(const cli::json_reader& r, const char* key, std::initializer_list<std::pair<const char*, E>> values, const char* what)
{
    const cli::json_reader f = r.field(key);
    const std::string v = f.as_string();
    std::string valid;
    for (const auto& [name, e] : values) {
        if (v == name) return e;
        valid += (valid.empty() ? "" : ", ") + std::string(name);
    }
    fail(f.path(), "\"" + v + "\" is not " + what, "valid: " + valid);
}

} // namespace detail

// Parses a scene from JSON text; `source` names it in every message (a file name).
inline scene read_scene(const std::string& text, const std::string& source)
{
    const nlohmann::json doc = cli::json_reader::parse(text, source);
    const cli::json_reader root(doc, source);
    root.only_keys({"name", "geometry", "camera", "ao_radius", "renderer"});
    scene s;
    if (root.has("name")) s.name = root.string("name");

    const cli::json_reader geo = root.array("geometry");
    for (size_t i = 0; i < geo.size(); ++i) {
        const cli::json_reader g = geo.at(i);
        g.require_object();
        const std::string type = g.string("type");
        if (type == "plane") {
            g.only_keys({"type", "point", "normal", "half_extent"});
            plane p{detail::read_vec3(g, "point"), detail::read_vec3(g, "normal")};
            if (g.has("half_extent")) p.half_extent = g.number("half_extent");
            s.planes.push_back(p);
        } else if (type == "box") {
            g.only_keys({"type", "min", "max"});
            s.boxes.push_back({detail::read_vec3(g, "min"), detail::read_vec3(g, "max")});
        } else if (type == "sphere") {
            g.only_keys({"type", "centre", "radius"});
            s.spheres.push_back({detail::read_vec3(g, "centre"), g.number("radius")});
        } else if (type == "quad") {
            g.only_keys({"type", "corner", "e1", "e2"});
            s.quads.push_back({detail::read_vec3(g, "corner"), detail::read_vec3(g, "e1"), detail::read_vec3(g, "e2")});
        } else if (type == "mesh") {
            fail(g.path() + ".type", "\"mesh\": meshes: not supported yet", "valid: plane, box, sphere, quad");
        } else {
            fail(g.path() + ".type", "\"" + type + "\" is not a geometry type", "valid: plane, box, sphere, quad");
        }
    }

    if (root.has("camera")) {
        const cli::json_reader c = root.field("camera");
        c.only_keys({"projection", "tan_half_fov_y", "left", "right", "bottom", "top", "near", "far", "depth", "width",
                     "height", "eye", "target", "up"});
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
    }
    if (root.has("ao_radius")) s.ao_radius = root.number("ao_radius");
    if (root.has("renderer")) {
        const cli::json_reader r = root.field("renderer");
        r.only_keys({"normals", "point_cloud"});
        if (r.has("normals"))
            s.renderer.normals = detail::read_enum<normal_space>(
                r, "normals", {{"world", normal_space::world}, {"view", normal_space::view}, {"none", normal_space::none}},
                "a normal space");
        if (r.has("point_cloud")) s.renderer.point_cloud = r.boolean("point_cloud");
    }
    validate(s, source);
    return s;
}

inline scene load_scene(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot be read", "valid: a readable scene JSON file");
    std::ostringstream text;
    text << in.rdbuf();
    return read_scene(text.str(), path);
}

// --- built-in scenes ----------------------------------------------------------------
// World z is up; the floor is z = 0. Default resolution 160×90, 60° vertical field of view.

inline std::vector<std::string> builtin_scene_names()
{
    return {"crease", "groove", "wall", "sphere_on_plane", "room", "stairs", "plank"};
}

inline scene builtin_scene(const std::string& name)
{
    scene s;
    s.name = name;
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
    } else if (name == "stairs") { // five steps of rise 0.2 and run 0.4 climbing along +y
        s.planes = {floor};
        for (int i = 0; i < 5; ++i) s.boxes.push_back({{-1.5, 0.4 * i, 0}, {1.5, 2.0, 0.2 * (i + 1)}});
        c.eye = {3.5, -3, 2.5}, c.target = {0, 1, 0.4};
    } else if (name == "plank") { // a 2 cm plank 5 cm above the floor
        s.planes = {floor};
        s.boxes = {{{-1.5, -0.2, 0.05}, {1.5, 0.2, 0.07}}};
        c.eye = {2.5, -2.5, 1.5}, c.target = {0, 0, 0.05};
    } else {
        std::string valid;
        for (const std::string& n : builtin_scene_names()) valid += (valid.empty() ? "" : ", ") + n;
        fail("built-in scene", "\"" + name + "\" is not known", "valid: " + valid);
    }
    validate(s, "built-in scene " + name);
    return s;
}

} // namespace aogen::scenes
