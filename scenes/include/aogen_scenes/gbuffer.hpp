// aogen_scenes/gbuffer.hpp — a scene's G-buffer, ray-cast with Embree.
//
// WHAT
//   render_gbuffer(scene, opts)  one primary ray per pixel through the pixel centre; per pixel
//                                the raw depth a GPU would write, the normal and the world-
//                                space hit position (for the ground truth).
//   visible_geometry(scene, t)   how many pixels see geometry, and how far out it lies;
//   require_scoreable(scene, t)  refuses a scene that shows nothing, or one too large for the
//                                reference at its AO radius
//   render_frame(scene, f)       frame f of a scene in motion (at_frame, scene.hpp), with its
//                                motion vectors from frame f − 1 (gbuffer_options::previous).
//   project_ndc(camera, p)       where a world point lands on a camera's screen, in NDC.
//   to_gbuffer<G>(g)             G's width, height, depth, normals, and motion when G has
//                                one: aogen::vulkan::gbuffer (this header does not include
//                                Vulkan).
//   stored_depth(d, format)      the value a shader reads back after the GPU stored d in a
//                                depth buffer of that format.
//
// USAGE (a scene in motion, scene.hpp's camera.path and "motion")
//   for (int f = 0; f < frame_count(s); ++f) {
//       const gbuffer g = render_frame(s, f);          // g.motion: frame f − 1 → f, 0 at f = 0
//       const auto in = to_gbuffer<aogen::vulkan::gbuffer>(g); // in.motion for a -histmv variant
//   }
//   or, with a tracer of your own: o.previous = &before (at_frame(s, f − 1)) and
//   render_gbuffer(at_frame(s, f), tracer, o).
//
// ERRORS
//   render_frame: a frame outside 0..frame_count(s) − 1, naming the scene and its frame
//   count. render_gbuffer: a `previous` with other geometry than the scene's.
//
// CONVENTIONS
//   * Rows are top row first; pixel (x, y) has uv = ((x + ½)/W, (y + ½)/H) and
//     ndc = (2·uv.x − 1, 1 − 2·uv.y) (math.hpp: uv.y = 0.5 − 0.5·ndc.y).
//   * Depth is float32 clip-space math with aogen's projection matrix: from the hit's view-
//     space position v (x, y from the ray, z = −t with the ray's view-space direction having
//     z = −1, so t is the view distance), clip = P·(v, 1) in float and depth = clip.z/clip.w.
//     Geometry nearer than `near` is clipped (ray tnear = near); beyond `far` too, except for
//     reversed_infinite. Background: 1 for standard, 0 for reversed and reversed_infinite.
//   * Depth buffer format (scene.renderer.depth_buffer): d32_sfloat keeps the float; for
//     d24_unorm and d16_unorm (n bits) depth is quantised as the GPU stores it and read back:
//     k = round-to-nearest(d·(2ⁿ − 1)) (ties up), then float(k)/float(2ⁿ − 1). 0 and 1 — the
//     background — stay exact. `position` keeps the exact hit (the ground truth's point).
//   * normals: RGBA32F, xyz unit length facing the camera (two-sided surfaces are flipped
//     towards the ray; with face_camera false and the scene's renderer "normals_facing":
//     "as_stored", a surface keeps its own orientation: a plane its given normal, a back
//     face pointing away), w = 1 on geometry; (0, 0, 0, 0) on background. World space by
//     default, view space with normal_space::view; empty with normal_space::none.
//   * position: world-space hit, xyz doubles per pixel (NaN on background); hit: 1/0;
//     geometry: the hit's geometry id (scene::build order), or −1. The hit's t, position and
//     normal are truth::scene::intersect's, recomputed in double on the primitive hit: Embree's
//     float t puts a point seen from t away up to ~2⁻²³·t off its surface (8·10⁻⁵ from 5 km),
//     which the reference's ray offset would otherwise have to grow with t to clear; the
//     refined point lies on the surface its rays start from.
//   * motion (gbuffer_options::motion, or previous set; else empty): RG32F, width × height × 2,
//     the motion from frame f − 1 (o.previous, at_frame(s, f − 1)) to this frame f, in NDC
//     units, current minus previous, y up: mv = ndc − ndc_previous, with ndc the pixel
//     centre's (above) and ndc_previous where the pixel's hit point stood at frame f − 1 — p
//     minus its geometry's translation from frame f − 1 to f (a moving sphere's or box's;
//     all else stands still) — projected, in double, by frame f − 1's camera (its view and
//     projection). So ndc_previous = ndc − mv, and in uv (y down) uv_previous = uv −
//     (mv.x/2, −mv.y/2). A still camera over still geometry writes 0. Background: 0. Frame 0
//     (previous null): 0 everywhere. A point behind frame f − 1's perspective eye (w ≤ 0)
//     had no place on screen: its mv is behind_previous_camera, (−4, −4), which puts
//     ndc_previous (ndc + 4) off screen, where a history pass finds nothing to reuse.
#pragma once

#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace aogen::scenes {

struct gbuffer {
    int width = 0, height = 0;
    std::vector<float> depth;     // width × height raw depth values
    std::vector<float> normals;   // width × height × 4 (xyz, w = 1 on geometry)
    normal_space normals_space = normal_space::world;
    std::vector<double> position; // width × height × 3, world space, NaN on background
    std::vector<uint8_t> hit;     // width × height, 1 where a ray hit geometry
    std::vector<int> geometry;    // width × height, geometry id or −1
    std::vector<float> motion;    // width × height × 2, NDC, current − previous, y up; empty unless asked for
};

namespace detail {

template <class G, class = void>
struct has_motion : std::false_type {};
template <class G>
struct has_motion<G, std::void_t<decltype(std::declval<G&>().motion)>> : std::true_type {};

} // namespace detail

// Converts to a type with members width, height, depth and normals, such as
// aogen::vulkan::gbuffer, copying the motion vectors too when it has a member `motion`;
// its other members (an albedo) are left as G{} has them.
template <class G>
G to_gbuffer(const gbuffer& g)
{
    G out{};
    out.width = g.width, out.height = g.height, out.depth = g.depth, out.normals = g.normals;
    if constexpr (detail::has_motion<G>::value) out.motion = g.motion;
    return out;
}

// Vulkan's float → UNORM conversion, then UNORM → float, as the shader sees it. d·(2ⁿ − 1) is
// exact in double (24 × 24 bits), so the rounding is the only one before the division.
inline float stored_depth(float d, depth_format format)
{
    if (format == depth_format::d32_sfloat) return d;
    const double steps = format == depth_format::d24_unorm ? 16777215.0 : 65535.0;
    const double k = std::floor(std::min(1.0, std::max(0.0, double(d))) * steps + 0.5);
    return float(k) / float(steps); // k/(2ⁿ − 1) rounded to float: what a conforming GPU returns
}

struct gbuffer_options {
    bool use_scene_normals = true;                 // take the space from scene.renderer.normals
    normal_space normals = normal_space::world;    // used when use_scene_normals is false
    bool face_camera = true;                       // flip normals toward the ray (the reference's need);
                                                   // false follows scene.renderer.normals_face_camera
    bool motion = false;                           // write gbuffer::motion (all 0 without `previous`)
    const scene* previous = nullptr;               // the scene at frame f − 1 (at_frame), the rendered one
                                                   // at frame f: motion vectors from it (implies motion)
};

// A point in normalised device coordinates: x right, y up, the screen's edges at ±1.
struct ndc_point {
    double x = 0, y = 0;
};

// The motion vector of a point that stood behind frame f − 1's eye (CONVENTIONS).
inline constexpr ndc_point behind_previous_camera{-4, -4};

// Pixel (x, y)'s centre in NDC (CONVENTIONS).
inline ndc_point pixel_ndc(const camera& c, int x, int y)
{
    return {2.0 * (x + 0.5) / c.width - 1.0, 1.0 - 2.0 * (y + 0.5) / c.height};
}

// Where world point p lands on camera c's screen, in double: its view-space position
// projected (perspective: divided by its distance along the view, w = −z). None for a
// point on or behind a perspective camera's eye plane (w ≤ 0).
inline std::optional<ndc_point> project_ndc(const camera& c, dvec3 p)
{
    dvec3 right, up, back;
    c.basis(right, up, back);
    const dvec3 o = p - c.eye;
    const double x = truth::dot(o, right), y = truth::dot(o, up), w = -truth::dot(o, back);
    if (c.projection == projection_kind::orthographic)
        return ndc_point{2 * (x - c.left) / (double(c.right) - c.left) - 1, 2 * (y - c.bottom) / (double(c.top) - c.bottom) - 1};
    if (!(w > 0)) return std::nullopt;
    const double tan_y = c.tan_half_fov_y, tan_x = tan_y * (double(c.width) / c.height);
    return ndc_point{x / (w * tan_x), y / (w * tan_y)};
}

// The camera ray through pixel (x, y)'s centre: world origin and direction, and the same
// in view space (dir_v.z = −1, so the hit's t is its view distance).
struct primary_ray {
    dvec3 org, dir, org_v, dir_v;
};

// The primary rays of a camera, pixel by pixel, as render_gbuffer casts them.
class primary_rays {
public:
    explicit primary_rays(const camera& c) : c_(c), aspect_(double(c.width) / c.height)
    {
        c.basis(right_, up_, back_);
        const bool infinite = c.projection == projection_kind::perspective && c.depth == depth_convention::reversed_infinite;
        tfar_ = infinite ? std::numeric_limits<double>::infinity() : double(c.far);
    }

    double tnear() const { return c_.near; } // geometry nearer than near is clipped
    double tfar() const { return tfar_; }    // and beyond far, but for reversed_infinite

    primary_ray at(int x, int y) const
    {
        const auto [ndc_x, ndc_y] = pixel_ndc(c_, x, y);
        primary_ray r;
        if (c_.projection == projection_kind::perspective) {
            r.dir_v = {ndc_x * aspect_ * c_.tan_half_fov_y, ndc_y * c_.tan_half_fov_y, -1};
        } else {
            r.dir_v = {0, 0, -1};
            r.org_v = {c_.left + (ndc_x + 1) * 0.5 * (double(c_.right) - c_.left), c_.bottom + (ndc_y + 1) * 0.5 * (double(c_.top) - c_.bottom), 0};
        }
        r.org = c_.eye + world(r.org_v);
        r.dir = world(r.dir_v);
        return r;
    }

    // A view-space vector in world space, and back.
    dvec3 world(dvec3 v) const { return v.x * right_ + v.y * up_ + v.z * back_; }
    dvec3 view(dvec3 w) const { return {truth::dot(w, right_), truth::dot(w, up_), truth::dot(w, back_)}; }

private:
    const camera& c_;
    double aspect_;
    dvec3 right_, up_, back_;
    double tfar_;
};

namespace detail {

// Where geometry `id` (scene::build order) stands: a box's lower corner, a sphere's centre,
// the origin for everything else (which never moves).
inline dvec3 placement(const scene& s, int id)
{
    const size_t i = size_t(id), boxes = s.planes.size(), spheres = boxes + s.boxes.size();
    if (i >= boxes && i < spheres) return s.boxes[i - boxes].lo;
    if (i >= spheres && i < spheres + s.spheres.size()) return s.spheres[i - spheres].centre;
    return {};
}

// `previous` must be the same scene at another frame: the same geometry, id for id.
inline void require_same_geometry(const scene& s, const scene& previous)
{
    if (s.planes.size() != previous.planes.size() || s.boxes.size() != previous.boxes.size() ||
        s.spheres.size() != previous.spheres.size() || s.quads.size() != previous.quads.size() ||
        s.meshes.size() != previous.meshes.size() || s.point_sets.size() != previous.point_sets.size())
        fail(s.source + ": gbuffer_options.previous", previous.source + " has other geometry",
             "valid: the same scene at frame f − 1, at_frame(s, f − 1)");
}

} // namespace detail

// Where point p of geometry `id` (scene::build order) in scene `s` stood in `previous`, the
// same scene at another frame: p moved back by that geometry's translation between the two
// (static geometry: p itself). The motion vectors and the report in motion's ages read it.
inline dvec3 position_in(const scene& previous, const scene& s, dvec3 p, int id)
{
    return p - (detail::placement(s, id) - detail::placement(previous, id));
}

namespace detail {

// Pixel i's motion vector from `previous` (CONVENTIONS): its hit point p on geometry `id`,
// moved back by that geometry's translation since `previous`, seen by previous's camera.
inline void write_motion(gbuffer& g, size_t i, ndc_point now, dvec3 p, int id, const scene& s, const scene& previous)
{
    const dvec3 was = position_in(previous, s, p, id);
    const std::optional<ndc_point> then = project_ndc(previous.camera, was);
    const ndc_point mv = then ? ndc_point{now.x - then->x, now.y - then->y} : behind_previous_camera;
    g.motion[2 * i] = float(mv.x), g.motion[2 * i + 1] = float(mv.y);
}

} // namespace detail

// Ray-casts the G-buffer of `s` into an already built tracer `t` (make_tracer(s)).
inline gbuffer render_gbuffer(const scene& s, const truth::scene& t, const gbuffer_options& o = {})
{
    const camera& c = s.camera;
    const int W = c.width, H = c.height;
    gbuffer g;
    g.width = W, g.height = H;
    g.normals_space = o.use_scene_normals ? s.renderer.normals : o.normals;
    const size_t n = size_t(W) * H;
    g.depth.assign(n, c.background_depth());
    if (g.normals_space != normal_space::none) g.normals.assign(n * 4, 0.0f);
    g.position.assign(n * 3, std::numeric_limits<double>::quiet_NaN());
    g.hit.assign(n, 0);
    g.geometry.assign(n, -1);
    if (o.motion || o.previous) g.motion.assign(n * 2, 0.0f);
    if (o.previous) detail::require_same_geometry(s, *o.previous);

    const primary_rays rays(c);
    const mat4 proj = c.projection_matrix();
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const primary_ray r = rays.at(x, y);
            const truth::scene::hit h = t.intersect(r.org, r.dir, rays.tnear(), rays.tfar());
            if (!h.found) continue;
            const size_t i = size_t(y) * W + x;
            const dvec3 v = r.org_v + h.t * r.dir_v; // view-space hit, z = −t
            const vec4 clip = proj * vec4{float(v.x), float(v.y), float(v.z), 1.0f};
            g.depth[i] = stored_depth(clip.z / clip.w, s.renderer.depth_buffer);
            g.position[3 * i] = h.position.x, g.position[3 * i + 1] = h.position.y, g.position[3 * i + 2] = h.position.z;
            g.hit[i] = 1;
            g.geometry[i] = int(h.geometry);
            if (o.previous) detail::write_motion(g, i, pixel_ndc(c, x, y), h.position, int(h.geometry), s, *o.previous);
            if (g.normals_space != normal_space::none) {
                dvec3 nw = truth::normalize(h.normal);
                const bool flip = o.face_camera || s.renderer.normals_face_camera;
                if (flip && truth::dot(nw, r.dir) > 0) nw = -1.0 * nw;
                const dvec3 nn = g.normals_space == normal_space::world ? nw : rays.view(nw);
                g.normals[4 * i] = float(nn.x), g.normals[4 * i + 1] = float(nn.y), g.normals[4 * i + 2] = float(nn.z);
                g.normals[4 * i + 3] = 1.0f;
            }
        }
    return g;
}

// What `s`'s camera sees of tracer `t`: how many pixels hit geometry, the nearest and the
// largest |coordinate| of a hit relative to the tracer's origin (what the reference's
// precision depends on, truth::reliable_extent), and how many hits lie within the extent
// whose reference can be trusted at the scene's AO radius. A scene that shows nothing has
// no error to score, and one whose every hit lies too far for its radius no reference to
// trust: the report refuses both before it traces anything. Hits beyond the reliable
// extent are left out of the score (aogen_report/reference.hpp), and counted.
struct visibility {
    size_t pixels = 0;
    size_t trusted_pixels = 0;
    double extent = 0;
    double nearest = 0;
};

// The largest |coordinate| of p - origin.
inline double extent_from(dvec3 p, dvec3 origin)
{
    const dvec3 q = p - origin;
    return std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)});
}

inline visibility visible_geometry(const scene& s, const truth::scene& t)
{
    const primary_rays rays(s.camera);
    const double reliable = truth::reliable_extent(s.ao_radius);
    visibility v;
    v.nearest = std::numeric_limits<double>::infinity();
    std::vector<dvec3> far; // hits too far from the eye: aogen_report/reference.hpp traces them from their bounding box's centre
    for (int y = 0; y < s.camera.height; ++y)
        for (int x = 0; x < s.camera.width; ++x) {
            const primary_ray r = rays.at(x, y);
            const truth::scene::hit h = t.intersect(r.org, r.dir, rays.tnear(), rays.tfar());
            if (!h.found) continue;
            ++v.pixels;
            const double extent = extent_from(h.position, t.origin());
            v.extent = std::max(v.extent, extent);
            v.nearest = std::min(v.nearest, extent);
            if (extent <= reliable) ++v.trusted_pixels;
            else far.push_back(h.position);
        }
    if (far.empty()) return v;
    dvec3 lo = far.front(), hi = far.front();
    for (const dvec3& p : far) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const dvec3 centre = 0.5 * (lo + hi);
    for (const dvec3& p : far) v.trusted_pixels += extent_from(p, centre) <= reliable;
    return v;
}

// aogen::error naming `s.source` unless its camera sees some of its geometry, some of it
// near enough for the reference to be traced reliably at the scene's AO radius (the rest
// is left out of the score, not refused).
inline void require_scoreable(const scene& s, const truth::scene& t)
{
    const visibility v = visible_geometry(s, t);
    if (v.pixels == 0) fail(s.source, "shows no geometry: no pixel's ray hits anything between near and far", "valid: geometry in front of the camera");
    if (v.trusted_pixels == 0)
        fail(s.source + ": ao_radius", format_number(s.ao_radius) + " is too small for a reliable reference anywhere in view (the nearest geometry is " +
                                           format_number(v.nearest) + " from the camera)",
             "valid: ao_radius >= " + format_number(v.nearest / truth::reliable_extent(1.0)));
}

// Builds the scene's tracer and ray-casts the G-buffer.
inline gbuffer render_gbuffer(const scene& s, const gbuffer_options& o = {})
{
    return render_gbuffer(s, *make_tracer(s), o);
}

// Frame f of `s` (at_frame), its tracer built, with motion vectors from frame f − 1 (all 0
// at frame 0). `o.motion` and `o.previous` are set here.
inline gbuffer render_frame(const scene& s, int f, gbuffer_options o = {})
{
    const scene now = at_frame(s, f);
    const std::optional<scene> before = f > 0 ? std::optional<scene>(at_frame(s, f - 1)) : std::nullopt;
    o.motion = true;
    o.previous = before ? &*before : nullptr;
    return render_gbuffer(now, *make_tracer(now), o);
}

} // namespace aogen::scenes
