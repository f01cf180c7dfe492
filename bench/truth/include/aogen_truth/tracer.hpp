// aogen_truth/tracer.hpp — the ray-traced ground truth: AO(p) with Embree 3.
//
// WHAT
//   aogen::truth::scene     an Embree scene built from analytic primitives: quads (a large
//                           quad stands in for an infinite plane), boxes (12 triangles) and
//                           spheres (Embree's analytic RTC_GEOMETRY_TYPE_SPHERE_POINT, exact
//                           up to float rounding, no tessellation error).
//   scene::ao(p, n, opts)   AO(p) = (1/π) ∫ V_R(p, ω) (n·ω) dω over the hemisphere of n:
//                           binary visibility of geometry within world radius R, cosine-
//                           weighted, no falloff (DESIGN.md, "Ground truth and oracles").
//
// USAGE
//     aogen::truth::scene s;
//     s.add_plane({0, 0, 0}, {0, 0, 1});          // floor z = 0, a 2·10⁴-wide quad
//     s.add_sphere({0, 0, 1}, 1.0);               // resting on it
//     s.commit();
//     aogen::truth::estimate e = s.ao({1, 0, 0}, {0, 0, 1});   // R unbounded
//     // e.value ≈ 0.6464, e.standard_error ≈ 0.002, e.binomial_bound ≈ 0.0075
//
// HOW
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
//     lying on two surfaces at once — the apex of a groove — is still occluded by both. ε defaults to
//     1e-5·(1 + max|p_i|), about 100 float ulps of the point's coordinates.
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

// The jitter stream of the tracer ("truth001"), beside random.hpp's kernel/noise streams.
inline constexpr uint64_t truth_rays_stream = 0x7472757468303031ull;

struct options {
    double radius = std::numeric_limits<double>::infinity();  // R, world units
    int grid = 64;               // grid×grid stratified rays (≥ 2, even: strata are paired)
    uint64_t seed = 0;
    double epsilon = -1;         // origin lift along n; < 0: 1e-5·(1 + max|p_i|)
};

struct estimate {
    double value = 1;            // AO in [0, 1], 1 = unoccluded
    double standard_error = 0;   // stratified, collapsed-strata estimate
    double binomial_bound = 0;   // √(a(1−a)/N), an upper bound for stratified sampling
    int rays = 0;
};

class scene {
public:
    scene() : device_(rtcNewDevice(nullptr))
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

    // Triangles, counter-clockwise or not: occlusion is two-sided.
    void add_triangles(const std::vector<vec3>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles)
    {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), vertices.size()));
        for (size_t i = 0; i < vertices.size(); ++i) {
            v[3 * i] = float(vertices[i].x);
            v[3 * i + 1] = float(vertices[i].y);
            v[3 * i + 2] = float(vertices[i].z);
        }
        auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), triangles.size()));
        for (size_t i = 0; i < triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) idx[3 * i + k] = triangles[i][k];
        attach(g);
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
        const vec3 n = normalize(normal);
        const vec3 helper = std::abs(n.x) < 0.9 ? vec3{1, 0, 0} : vec3{0, 1, 0};
        const vec3 t = normalize(cross(helper, n));
        const vec3 b = cross(n, t);
        std::vector<vec3> v;
        std::vector<std::array<uint32_t, 3>> triangles;
        const auto add_square = [&](double s) { // corners counter-clockwise about n
            for (const auto& c : {std::array<double, 2>{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) v.push_back(point + (s * c[0]) * t + (s * c[1]) * b);
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
        v[0] = float(centre.x);
        v[1] = float(centre.y);
        v[2] = float(centre.z);
        v[3] = float(radius);
        attach(g);
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
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{};
        ray.org_x = float(o.x);
        ray.org_y = float(o.y);
        ray.org_z = float(o.z);
        ray.dir_x = float(d.x);
        ray.dir_y = float(d.y);
        ray.dir_z = float(d.z);
        ray.tnear = float(tnear);
        ray.tfar = float(tfar);  // infinity stays infinity
        ray.mask = 0xffffffffu;
        ray.time = 0;
        rtcOccluded1(scene_, &context, &ray);
        return ray.tfar == -std::numeric_limits<float>::infinity();
    }

    // The first hit of o + t·d for t in [tnear, tfar] (d need not be unit length: t is in
    // units of d). `normal` is Embree's geometric normal, unnormalised, oriented as the
    // primitive's winding (outward for spheres). `geometry` is the index in add_* order.
    struct hit {
        bool found = false;
        double t = 0;
        vec3 normal;
        unsigned geometry = 0;
    };
    hit intersect(vec3 o, vec3 d, double tnear, double tfar) const
    {
        if (!committed_) throw std::logic_error("aogen::truth: intersect() before commit()");
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = float(o.x);
        rh.ray.org_y = float(o.y);
        rh.ray.org_z = float(o.z);
        rh.ray.dir_x = float(d.x);
        rh.ray.dir_y = float(d.y);
        rh.ray.dir_z = float(d.z);
        rh.ray.tnear = float(tnear);
        rh.ray.tfar = float(tfar);
        rh.ray.mask = 0xffffffffu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        hit h;
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
        h.found = true;
        h.t = rh.ray.tfar;
        h.normal = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
        h.geometry = rh.hit.geomID;
        return h;
    }

    // AO at surface point p with normal n (normalised here).
    estimate ao(vec3 p, vec3 normal, const options& opts = {}) const
    {
        if (!committed_) throw std::logic_error("aogen::truth: ao() before commit()");
        if (opts.grid < 2 || opts.grid % 2 != 0) throw std::invalid_argument("aogen::truth: grid must be even and >= 2");
        const vec3 n = normalize(normal);
        const vec3 helper = std::abs(n.x) < 0.9 ? vec3{1, 0, 0} : vec3{0, 1, 0};
        const vec3 t = normalize(cross(helper, n));
        const vec3 b = cross(n, t);
        const double eps = opts.epsilon >= 0
                               ? opts.epsilon
                               : 1e-5 * (1 + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
        const vec3 o = p + eps * n;

        auto rng = random::seeded(opts.seed, truth_rays_stream);
        const int m = opts.grid;
        const int count = m * m;
        int visible = 0;
        double pair_sq = 0;  // Σ over stratum pairs (y_a − y_b)²
        for (int i = 0; i < m; ++i) {
            int previous = 0;
            for (int j = 0; j < m; ++j) {
                const double u = (i + double(rng.next_float())) / m;  // r² on the disk
                const double v = (j + double(rng.next_float())) / m;  // turns
                const double r = std::sqrt(u);
                const random::cos_sin cs = random::cos_sin_turns(v);
                const double z = std::sqrt(std::max(0.0, 1 - u));
                const vec3 d = (r * cs.c) * t + (r * cs.s) * b + z * n;
                const int y = occluded(o, d, 0.0, opts.radius) ? 0 : 1;
                visible += y;
                if (j % 2 == 1) pair_sq += double((y - previous) * (y - previous));
                previous = y;
            }
        }
        estimate e;
        e.rays = count;
        e.value = double(visible) / count;
        e.standard_error = std::sqrt(pair_sq) / count;
        e.binomial_bound = std::sqrt(e.value * (1 - e.value) / count);
        return e;
    }

private:
    void attach(RTCGeometry g)
    {
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        committed_ = false;
    }

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    bool committed_ = false;
};

} // namespace aogen::truth
