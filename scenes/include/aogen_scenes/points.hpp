// aogen_scenes/points.hpp — point clouds drawn as splats, as seed 004's point-cloud viewer
// draws them: every point a small square billboard facing the camera, depth written, no
// normals.
//
// WHAT
//   points                      world-space positions and splat_size, the side of every
//                               splat's square in world units.
//   splat_mesh(p, right, up)    the splats as triangles, the geometry both the G-buffer and the
//                               ground truth see: per point c the square c ± ½·size·right
//                               ± ½·size·up (two triangles, vertices 4i..4i+3). With the
//                               camera's right/up (camera::basis) every splat lies in a plane
//                               of constant view depth, like the viewer's billboards, whose
//                               fragments all carry the depth of the point.
//   sample_quad / sample_box / sample_sphere
//                               about density·area points uniformly on a parallelogram, on the
//                               five faces of a box other than its bottom (z = lo.z: it stands
//                               on something), on a sphere; deterministic (pcg32).
//
// USAGE
//     aogen::scenes::points p;
//     p.splat_size = 0.05;
//     auto rng = aogen::random::seeded(0, aogen::scenes::points_stream);
//     aogen::scenes::sample_sphere(p, rng, {0, 0, 1}, 1.0, 400.0);   // ~5000 points
//     camera.basis(right, up, back);
//     const aogen::scenes::mesh splats = aogen::scenes::splat_mesh(p, right, up);
//     tracer.add_triangles(splats.vertices, splats.triangles);     // scene::build does this
//
// WHY
//   * The splats are real geometry in the tracer, not points: the ground truth then measures
//     what the renderer draws (gaps between splats included), so screen-space AO on a point
//     cloud is compared with the AO of the same surfaces.
//   * Counts are rounded density × area, and sampling uses aogen's PCG32 and cos_sin_turns:
//     the same points on every platform.
#pragma once

#include "mesh.hpp"

#include <aogen/random.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace aogen::scenes {

struct points {
    std::vector<dvec3> positions;
    double splat_size = 0.05; // side of each square splat, world units
};

// The point sampling stream ("points01"), beside random.hpp's kernel and noise streams.
inline constexpr uint64_t points_stream = 0x706f696e74733031ull;

inline mesh splat_mesh(const points& p, dvec3 right, dvec3 up)
{
    const double h = 0.5 * p.splat_size;
    const dvec3 r = h * right, u = h * up;
    mesh m;
    m.vertices.reserve(4 * p.positions.size());
    m.triangles.reserve(2 * p.positions.size());
    for (const dvec3& c : p.positions) {
        const auto first = uint32_t(m.vertices.size());
        m.vertices.insert(m.vertices.end(), {c - r - u, c + r - u, c + r + u, c - r + u});
        m.triangles.push_back({first, first + 1, first + 2});
        m.triangles.push_back({first, first + 2, first + 3});
    }
    return m;
}

namespace detail {
inline double length(dvec3 v) { return std::sqrt(truth::dot(v, v)); }
inline long count_for(double area, double density) { return std::lround(area * density); }
} // namespace detail

// Uniform on corner + u·e1 + v·e2, u, v in [0, 1).
inline void sample_quad(points& p, random::pcg32& rng, dvec3 corner, dvec3 e1, dvec3 e2, double density)
{
    const long n = detail::count_for(detail::length(truth::cross(e1, e2)), density);
    for (long i = 0; i < n; ++i) {
        const double u = rng.next_float(), v = rng.next_float(); // sequenced: u before v
        p.positions.push_back(corner + u * e1 + v * e2);
    }
}

// Uniform on the top and the four sides of [lo, hi], each face with its share of the points.
inline void sample_box(points& p, random::pcg32& rng, const box& b, double density)
{
    const dvec3 d = b.hi - b.lo, x{d.x, 0, 0}, y{0, d.y, 0}, z{0, 0, d.z};
    sample_quad(p, rng, b.lo + z, x, y, density); // top
    sample_quad(p, rng, b.lo, x, z, density);     // y = lo.y
    sample_quad(p, rng, b.lo + y, x, z, density); // y = hi.y
    sample_quad(p, rng, b.lo, y, z, density);     // x = lo.x
    sample_quad(p, rng, b.lo + x, y, z, density); // x = hi.x
}

// Uniform on the sphere (Archimedes: z uniform in [−1, 1], angle uniform).
inline void sample_sphere(points& p, random::pcg32& rng, dvec3 centre, double radius, double density)
{
    const long n = detail::count_for(4 * 3.14159265358979323846 * radius * radius, density);
    for (long i = 0; i < n; ++i) {
        const double z = 1 - 2.0 * rng.next_float();
        const random::cos_sin cs = random::cos_sin_turns(rng.next_float());
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        p.positions.push_back(centre + radius * dvec3{r * cs.c, r * cs.s, z});
    }
}

} // namespace aogen::scenes
