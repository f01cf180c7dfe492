// aogen_truth/tracer.hpp — the ray-traced ground truth: AO(p) with Embree 3.
//
// WHAT
//   aogen::truth::scene     an Embree scene built from analytic primitives: quads (a large
//                           quad stands in for an infinite plane), boxes (12 triangles) and
//                           spheres (Embree's analytic RTC_GEOMETRY_TYPE_SPHERE_POINT, exact
//                           up to float rounding, no tessellation error).
//   scene(origin)           the tracer's frame. Everything given to the tracer and returned by
//                           it is world space in double; Embree, which works in float, sees
//                           world − origin. Make it at the camera's eye, as
//                           aogen::scenes::make_tracer does (HOW: camera-relative float).
//   scene::intersect(o, d)  the first hit along a ray; its t, position and normal are
//                           recomputed in double on the primitive Embree found.
//   scene::ao(p, n, opts)   AO(p) = (1/π) ∫ V_R(p, ω) (n·ω) dω over the hemisphere of n:
//                           binary visibility of geometry within world radius R, cosine-
//                           weighted, no falloff (docs/design.md § Ground truth);
//                           with the bent normal, the same rays' mean unoccluded direction.
//   surface_offset(q, R)    how far ao() lifts its rays' origin off the surface by default.
//   reliable_extent(R)      how far from the origin a point may be for that lift to be reliable.
//
// USAGE
//     aogen::truth::scene s({3e6 + 4, -5, 3});   // origin: the eye of a camera looking on
//     s.add_plane({3e6, 0, 0}, {0, 0, 1});       // floor z = 0 around x = 3·10⁶, 2·10⁴ wide
//     s.add_sphere({3e6, 0, 1}, 1.0);            // resting on it
//     s.commit();
//     aogen::truth::estimate e = s.ao({3e6 + 1, 0, 0}, {0, 0, 1});   // R unbounded
//     // e.value ≈ 0.6464, e.standard_error ≈ 0.002, e.binomial_bound ≈ 0.0075
//
// HOW
//   * Camera-relative float. Embree 3 holds vertices and rays in float, whose 24-bit mantissa
//     spaces its values 1 apart at 10⁷ and 0.008 apart at 10⁵: a scene that far from the
//     world's zero would lose its detail, and its rays' offsets, to rounding. So every vertex
//     and ray origin has `origin` subtracted in double before it becomes a float, and what the
//     tracer returns has it added back. A relative coordinate c is then off by at most
//     ½ ulp(c) ≤ 2⁻²⁴·|c|: the rounding grows with the distance from the origin, not from the
//     world's zero, and with the origin at the camera's eye it stays at the scale of the
//     distances the camera sees. Directions and t do not depend on the origin.
//   * Primary hits refined. Embree computes t in float from the ray origin, so a hit t away
//     lies off the surface by up to ~2⁻²³·t (measured: 8·10⁻⁵ below a floor seen from 5 km).
//     intersect() takes only which primitive was hit from Embree and recomputes t in double
//     against that primitive's stored float geometry — the plane of its triangle, or its
//     sphere — so its position lies on the very surface the AO rays see, at any distance.
//     The offset below therefore has no term for how far away a point was found, and a
//     G-buffer seen from far off does not occlude itself whatever the tracer's origin.
//     What refining cannot undo: a ray that meets a crease between two meshes within float
//     rounding may slip past one mesh's edge onto the other behind it (Embree is watertight
//     only along edges a mesh shares), and its point, inside geometry, reads AO 0 — seen from
//     5 km, one pixel of 48×27 at the foot of the built-in wall, 5·10⁻⁶ behind its face.
//   * Rays: a jittered grid of grid×grid strata (default 64×64 = 4096 rays; at 32×32 the
//     collapsed-pair standard error reaches ~0.006 at AO ≈ 0.65, above 0.005) on the unit
//     square, mapped to cosine-distributed directions by Malley's method (uniform point on
//     the unit disk by the polar map r = √u, φ = 2πv, lifted to the hemisphere). Each ray has
//     weight 1/N, so the estimate is the visible fraction.
//   * Deterministic: the jitter comes from aogen::random::pcg32 seeded with
//     seeded(opts.seed, truth_rays_stream); the angle from cos_sin_turns. The same point,
//     normal and options give the same rays every call, whatever was traced before.
//   * Visibility: rtcOccluded1 from o = p + ε·n with tnear = 0 and tfar = R (infinity by
//     default). The origin is lifted off the surface (rather than tnear = ε) so that a point
//     lying on two surfaces at once — the apex of a groove — is still occluded by both.
//     ε = surface_offset(p − origin, R) must clear float rounding yet stay far below R:
//       - what can put o on the wrong side of a surface through p is that surface's vertices
//         rounded to float (a point from intersect() lies exactly on its own surface, but not
//         on a second one through it, like the groove's apex, and a point worked out on the
//         exact geometry lies on neither) and o itself rounded to float: ½ ulp per
//         coordinate each, √3·½ ulp(M) each along n, √3·2⁻²³·M together, where M is the
//         largest |coordinate| of p − origin;
//       - ε = 4·2⁻²³·max(M, 1) is more than twice that. The floor of 1 (world unit) keeps
//         ε ≥ 4.8·10⁻⁷ at the origin itself, where the geometry around p is rounded at its own
//         size, not p's: add_plane's innermost squares have half-side 1;
//       - capped at 10⁻³·R: lifting p by ε shifts what it sees of an occluder by about ε, so
//         AO moves by about ε/R for geometry R away — under a ceiling at h < R, (h/R)² moves
//         by 2εh/R² ≤ 2ε/R = 0.002 at the cap, within the 0.005 the tests hold the truth to.
//         The cap binds only past M ≈ 2100·R and falls below the worst-case rounding only
//         past M ≈ 4800·R; a point that far from the origin cannot be lifted reliably in float
//         and shows it (self-occlusion, AO → 0) instead of looking past its occluders (AO →
//         1, what an offset growing with |p| without a cap does 10⁷ from the origin).
//     options::epsilon ≥ 0 replaces ε.
//   * Error: `standard_error` is the stratified estimator's standard error, estimated by
//     collapsing adjacent strata in pairs: Var ≈ (1/N²) Σ_pairs (y_a − y_b)² (conservative
//     in expectation). `binomial_bound` = √(a(1−a)/N) is the plain Monte-Carlo figure, an
//     upper bound for stratified sampling; it is reported too.
#pragma once

#include <aogen/random.hpp>
#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace aogen::truth {

struct vec3 {
    double x = 0, y = 0, z = 0;
};
inline vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator*(double s, vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vec3 cross(vec3 a, vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline vec3 normalize(vec3 a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

// A right-handed orthonormal frame (t, b, n) around the unit vector n.
struct tangent_frame {
    vec3 t, b, n;
};
inline tangent_frame frame_around(vec3 n)
{
    const vec3 helper = std::abs(n.x) < 0.9 ? vec3{1, 0, 0} : vec3{0, 1, 0};
    const vec3 t = normalize(cross(helper, n));
    return {t, cross(n, t), n};
}

// The jitter stream of the tracer ("truth001"), beside random.hpp's kernel/noise streams.
inline constexpr uint64_t truth_rays_stream = 0x7472757468303031ull;

struct options {
    double radius = std::numeric_limits<double>::infinity();  // R, world units
    int grid = 64;               // grid×grid stratified rays (≥ 2, even: strata are paired)
    uint64_t seed = 0;
    double epsilon = -1;         // origin lift along n; < 0: surface_offset(p − origin, R)
};

struct estimate {
    double value = 1;            // AO in [0, 1], 1 = unoccluded
    double standard_error = 0;   // stratified, collapsed-strata estimate
    double binomial_bound = 0;   // √(a(1−a)/N), an upper bound for stratified sampling
    int rays = 0;
    // The bent normal: the cosine-weighted mean of the unoccluded directions,
    // ∫ V_R(p, ω) ω (n·ω) dω normalised — the direction light arrives from on average. The
    // rays are cosine-distributed, so it is the plain mean of the rays that escape. Unit
    // length; n itself when every ray is occluded (no direction to prefer).
    vec3 bent_normal{0, 0, 1};
};

// The default lift of ao()'s ray origin off the surface at `relative_point` (p − the tracer's
// origin) for AO radius R: 4·2⁻²³·max(1, largest |coordinate|), at most 10⁻³·R (HOW).
inline double surface_offset(vec3 relative_point, double radius)
{
    constexpr double float_ulp_of_one = std::numeric_limits<float>::epsilon(); // 2⁻²³
    const double largest =
        std::max({1.0, std::abs(relative_point.x), std::abs(relative_point.y), std::abs(relative_point.z)});
    return std::min(4 * float_ulp_of_one * largest, 1e-3 * radius);
}

// The farthest a point may lie from the tracer's origin (its largest |coordinate|) for
// ao() at radius R to lift its rays reliably: where the capped offset 10⁻³·R still clears
// the worst float rounding √3·2⁻²³·M (HOW, above): M ≤ 10⁻³·R·2²³/√3 ≈ 4843·R. Past it the
// reference is not to be trusted; callers refuse the radius (the report does, naming it).
inline double reliable_extent(double radius)
{
    return 1e-3 * radius / (std::sqrt(3.0) * std::numeric_limits<float>::epsilon());
}

class scene {
public:
    // `origin` is subtracted from all geometry and rays before Embree sees them: put it where
    // the camera is. It is fixed for the tracer's life, so geometry and rays always share it.
    explicit scene(vec3 origin = {}) : origin_(origin), device_(rtcNewDevice(nullptr))
    {
        if (!device_) throw std::runtime_error("aogen::truth: rtcNewDevice failed");
        scene_ = rtcNewScene(device_);
        rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    }
    ~scene()
    {
        if (scene_) rtcReleaseScene(scene_);
        if (device_) rtcReleaseDevice(device_);
    }
    scene(const scene&) = delete;
    scene& operator=(const scene&) = delete;

    vec3 origin() const { return origin_; }

    // Triangles, counter-clockwise or not: occlusion is two-sided.
    void add_triangles(const std::vector<vec3>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles)
    {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), vertices.size()));
        for (size_t i = 0; i < vertices.size(); ++i) store_relative(vertices[i], v + 3 * i);
        auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), triangles.size()));
        for (size_t i = 0; i < triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) idx[3 * i + k] = triangles[i][k];
        attach(g, {v, idx});
    }

    // The parallelogram corner, corner + e1, corner + e1 + e2, corner + e2.
    void add_quad(vec3 corner, vec3 e1, vec3 e2)
    {
        add_triangles({corner, corner + e1, corner + e1 + e2, corner + e2}, {{{0, 1, 2}}, {{0, 2, 3}}});
    }

    // A square of side 2·half_extent centred on `point`, perpendicular to `normal`:
    // "infinite" for points within a few units of the centre (10⁴ by default). It is made
    // of nested square rings of half-side 1, 4, 16, … because Embree intersects in float
    // relative to a triangle's vertices: one pair of 10⁴-sized triangles puts a tilted
    // plane's surface ~10⁻³ off near its centre, far more than the rays' origin offset,
    // and every point there would occlude itself. Near the centre the triangles are small.
    void add_plane(vec3 point, vec3 normal, double half_extent = 1e4)
    {
        const tangent_frame f = frame_around(normalize(normal));
        std::vector<vec3> v;
        std::vector<std::array<uint32_t, 3>> triangles;
        const auto add_square = [&](double s) { // corners counter-clockwise about n
            for (const auto& c : {std::array<double, 2>{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) v.push_back(point + (s * c[0]) * f.t + (s * c[1]) * f.b);
        };
        double s = std::min(1.0, half_extent);
        add_square(s);
        triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
        while (s < half_extent) {
            s = std::min(4 * s, half_extent);
            const auto inner = uint32_t(v.size() - 4), outer = uint32_t(v.size());
            add_square(s);
            for (uint32_t k = 0; k < 4; ++k) {
                const uint32_t k1 = (k + 1) % 4;
                triangles.push_back({{inner + k, outer + k, outer + k1}});
                triangles.push_back({{inner + k, outer + k1, inner + k1}});
            }
        }
        add_triangles(v, triangles);
    }

    // An axis-aligned box, 12 triangles.
    void add_box(vec3 lo, vec3 hi)
    {
        std::vector<vec3> v;
        for (int i = 0; i < 8; ++i) v.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
        add_triangles(v, {{{0, 2, 3}}, {{0, 3, 1}}, {{4, 5, 7}}, {{4, 7, 6}},   // z = lo, hi
                          {{0, 1, 5}}, {{0, 5, 4}}, {{2, 6, 7}}, {{2, 7, 3}},   // y = lo, hi
                          {{0, 4, 6}}, {{0, 6, 2}}, {{1, 3, 7}}, {{1, 7, 5}}}); // x = lo, hi
    }

    // An analytic sphere (Embree's sphere point primitive).
    void add_sphere(vec3 centre, double radius)
    {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        store_relative(centre, v);
        v[3] = float(radius);
        attach(g, {v, nullptr});
    }

    // Builds the BVH; call once after the last add_*.
    void commit()
    {
        rtcCommitScene(scene_);
        committed_ = true;
    }

    // True when the segment o + t·d, t in [tnear, tfar], hits any geometry.
    bool occluded(vec3 o, vec3 d, double tnear, double tfar) const
    {
        return occluded_relative(o - origin_, d, tnear, tfar);
    }

    // The first hit of o + t·d for t in [tnear, tfar] (d need not be unit length: t is in
    // units of d). t, `position` = o + t·d and `normal` are worked out in double on the hit
    // primitive (HOW: primary hits refined). `normal` is unnormalised, oriented as the
    // primitive's winding, (v1 − v0) × (v2 − v0) as Embree's, and outward for spheres.
    // `geometry` is the index in add_* order.
    struct hit {
        bool found = false;
        double t = 0;
        vec3 position;
        vec3 normal;
        unsigned geometry = 0;
    };
    hit intersect(vec3 o, vec3 d, double tnear, double tfar) const
    {
        if (!committed_) throw std::logic_error("aogen::truth: intersect() before commit()");
        const vec3 relative_origin = o - origin_;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray = float_ray(relative_origin, d, tnear, tfar);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        hit h;
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
        const surface_point s = refine(rh.hit, relative_origin, d, rh.ray.tfar);
        h.found = true;
        h.t = s.t;
        h.position = o + s.t * d;
        h.normal = s.normal;
        h.geometry = rh.hit.geomID;
        return h;
    }

    // AO at surface point p with normal n (normalised here).
    estimate ao(vec3 p, vec3 normal, const options& opts = {}) const
    {
        if (!committed_) throw std::logic_error("aogen::truth: ao() before commit()");
        if (opts.grid < 2 || opts.grid % 2 != 0) throw std::invalid_argument("aogen::truth: grid must be even and >= 2");
        const tangent_frame f = frame_around(normalize(normal));
        const vec3 relative_point = p - origin_;
        const double eps = opts.epsilon >= 0 ? opts.epsilon : surface_offset(relative_point, opts.radius);
        const vec3 o = relative_point + eps * f.n;

        auto rng = random::seeded(opts.seed, truth_rays_stream);
        const int m = opts.grid;
        const int count = m * m;
        int visible = 0;
        vec3 escaped{0, 0, 0}; // Σ of the unoccluded directions
        double pair_sq = 0;  // Σ over stratum pairs (y_a − y_b)²
        for (int i = 0; i < m; ++i) {
            int previous = 0;
            for (int j = 0; j < m; ++j) {
                const double u = (i + double(rng.next_float())) / m;  // r² on the disk
                const double v = (j + double(rng.next_float())) / m;  // turns
                const double r = std::sqrt(u);
                const random::cos_sin cs = random::cos_sin_turns(v);
                const double z = std::sqrt(std::max(0.0, 1 - u));
                const vec3 d = (r * cs.c) * f.t + (r * cs.s) * f.b + z * f.n;
                const int y = occluded_relative(o, d, 0.0, opts.radius) ? 0 : 1;
                visible += y;
                if (y) escaped = escaped + d;
                if (j % 2 == 1) pair_sq += double((y - previous) * (y - previous));
                previous = y;
            }
        }
        estimate e;
        e.rays = count;
        e.value = double(visible) / count;
        e.standard_error = std::sqrt(pair_sq) / count;
        e.binomial_bound = std::sqrt(e.value * (1 - e.value) / count);
        e.bent_normal = visible > 0 ? normalize(escaped) : f.n;
        return e;
    }

private:
    // A geometry's float data as Embree holds it (its own buffers, alive as long as the
    // scene), kept to refine hits: a triangle mesh's xyz vertices and index triples, or a
    // sphere's centre and radius (xyzr) with no triangles.
    struct stored_geometry {
        const float* vertices = nullptr;
        const uint32_t* triangles = nullptr;
    };
    struct surface_point {
        double t = 0;
        vec3 normal;
    };

    // Writes world point w, made relative to the origin in double, as three floats.
    void store_relative(vec3 w, float* out) const
    {
        const vec3 r = w - origin_;
        out[0] = float(r.x), out[1] = float(r.y), out[2] = float(r.z);
    }

    // Geometry ids are the add_* order, which indexes geometries_.
    void attach(RTCGeometry g, stored_geometry stored)
    {
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene_, g, unsigned(geometries_.size()));
        rtcReleaseGeometry(g);
        geometries_.push_back(stored);
        committed_ = false;
    }

    // A ray as Embree takes it: the camera-relative origin and the direction in float;
    // tfar = infinity stays infinity.
    static RTCRay float_ray(vec3 relative_origin, vec3 d, double tnear, double tfar)
    {
        RTCRay ray{};
        ray.org_x = float(relative_origin.x);
        ray.org_y = float(relative_origin.y);
        ray.org_z = float(relative_origin.z);
        ray.dir_x = float(d.x);
        ray.dir_y = float(d.y);
        ray.dir_z = float(d.z);
        ray.tnear = float(tnear);
        ray.tfar = float(tfar);
        ray.mask = 0xffffffffu;
        ray.time = 0;
        return ray;
    }

    bool occluded_relative(vec3 relative_origin, vec3 d, double tnear, double tfar) const
    {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray = float_ray(relative_origin, d, tnear, tfar);
        rtcOccluded1(scene_, &context, &ray);
        return ray.tfar == -std::numeric_limits<float>::infinity();
    }

    // The hit Embree found along relative_origin + t·d, redone in double on its primitive.
    surface_point refine(const RTCHit& h, vec3 relative_origin, vec3 d, double embree_t) const
    {
        const stored_geometry& g = geometries_[h.geomID];
        return g.triangles ? on_triangle_plane(g, h.primID, relative_origin, d, embree_t)
                           : on_sphere(g, relative_origin, d, embree_t);
    }

    static vec3 stored_vertex(const stored_geometry& g, uint32_t i)
    {
        return {g.vertices[3 * i], g.vertices[3 * i + 1], g.vertices[3 * i + 2]};
    }

    // Where o + t·d meets the plane of triangle `primitive`. Only a ray lying in that plane
    // has no such point; it keeps Embree's t.
    static surface_point on_triangle_plane(const stored_geometry& g, unsigned primitive, vec3 o, vec3 d, double embree_t)
    {
        const uint32_t* corner = g.triangles + 3 * size_t(primitive);
        const vec3 v0 = stored_vertex(g, corner[0]), v1 = stored_vertex(g, corner[1]), v2 = stored_vertex(g, corner[2]);
        const vec3 n = cross(v1 - v0, v2 - v0);
        const double approach = dot(d, n);
        return {approach != 0 ? dot(v0 - o, n) / approach : embree_t, n};
    }

    // The root of a·t² + 2·half_b·t + c = 0, i.e. |o + t·d − centre|² = r², nearest Embree's t
    // (the near one unless the ray starts inside or tnear cut it off). Seen from afar,
    // half_b² and a·c are nearly equal (6·10¹⁴ each from 5 km) and their difference loses
    // digits even in double, so the discriminant is a·r² − |d × oc|² (Lagrange's identity:
    // a·|oc|² − half_b² = |d × oc|²), and the roots are the cancellation-free q/a and c/q. A
    // ray that grazes the sphere in float but misses it in double keeps Embree's t.
    static surface_point on_sphere(const stored_geometry& g, vec3 o, vec3 d, double embree_t)
    {
        const vec3 centre{g.vertices[0], g.vertices[1], g.vertices[2]};
        const double radius = g.vertices[3];
        const vec3 oc = o - centre, off_axis = cross(d, oc);
        const double a = dot(d, d), half_b = dot(oc, d), c = dot(oc, oc) - radius * radius;
        const double discriminant = a * radius * radius - dot(off_axis, off_axis);
        double t = embree_t;
        if (discriminant >= 0) {
            const double q = -(half_b + std::copysign(std::sqrt(discriminant), half_b));
            if (q != 0) {
                const double t1 = q / a, t2 = c / q;
                t = std::abs(t1 - embree_t) <= std::abs(t2 - embree_t) ? t1 : t2;
            }
        }
        return {t, (o + t * d) - centre};
    }

    vec3 origin_;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<stored_geometry> geometries_; // by geometry id
    bool committed_ = false;
};

} // namespace aogen::truth
