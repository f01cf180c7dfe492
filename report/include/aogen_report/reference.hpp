// aogen_report/reference.hpp — the ground-truth AO image of a scene: Embree-traced AO at
// every pixel's surface point, with its Monte-Carlo standard error.
//
//     const auto t = aogen::scenes::make_tracer(s);   // camera-relative: origin at the eye
//     aogen::scenes::gbuffer g = render_gbuffer(s, *t, world_normals);
//     aogen_report::reference r = aogen_report::trace_reference(*t, g, s.ao_radius, 64);
//     r.ao[i], r.standard_error[i], r.valid[i];   r.noise_rms;
//
// AO(p) = (1/π)∫ V_R(p, ω) cos θ dω over the hemisphere of the pixel's world-space
// normal (g must hold world normals), with grid × grid stratified cosine-distributed rays
// (aogen::truth::scene::ao). Pixel i's rays use seed i, whichever thread traces it,
// so the image is the same for any thread count. noise_rms is the root mean
// square of the per-pixel standard errors: how much the truth's own noise adds to a
// variant's RMSE (in quadrature), to be read against the errors the report shows. A hit
// too far from the camera for a reference at `radius` (truth::reliable_extent) is not
// traced: `valid` leaves it out of every score and `untrusted` counts it; `hit` still says
// a surface is there.
#pragma once

#include <aogen/parallel.hpp>
#include <aogen_scenes/gbuffer.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

namespace aogen_report {

struct reference {
    int width = 0, height = 0;
    std::vector<float> ao;             // NaN on background and where it cannot be trusted
    std::vector<float> standard_error; // 0 there
    std::vector<float> bent_normal;    // 3 per pixel, world space, unit: the true bent normal (tracer.hpp); NaN where ao is
    std::vector<uint8_t> valid;        // 1 where a surface was hit and its reference can be trusted: the pixels scored
    std::vector<uint8_t> hit;          // 1 where a surface was hit (0: background, which a shader must leave at 1)
    size_t untrusted = 0;              // hits left out: farther from the camera than truth::reliable_extent(radius)
    double noise_rms = 0;              // √(mean standard_error²) over valid pixels
    int rays_per_pixel = 0;
};

namespace detail {
// noise_rms over the valid pixels.
inline void finish(reference& r)
{
    double squares = 0, pixels = 0;
    for (size_t i = 0; i < r.valid.size(); ++i)
        if (r.valid[i]) squares += double(r.standard_error[i]) * r.standard_error[i], pixels += 1;
    r.noise_rms = pixels > 0 ? std::sqrt(squares / pixels) : 0;
}
} // namespace detail

inline reference trace_reference(const aogen::truth::scene& t, const aogen::scenes::gbuffer& g, double radius, int grid,
                                 unsigned threads = std::thread::hardware_concurrency())
{
    if (g.normals_space != aogen::scenes::normal_space::world)
        aogen::fail("reference", "a G-buffer without world-space normals", "valid: render_gbuffer with normals = world");
    const size_t n = size_t(g.width) * g.height;
    reference r;
    r.width = g.width, r.height = g.height;
    r.ao.assign(n, std::nanf(""));
    r.standard_error.assign(n, 0.0f);
    r.bent_normal.assign(3 * n, std::nanf(""));
    r.hit = g.hit;
    r.valid = g.hit;
    r.rays_per_pixel = grid * grid;
    // A hit farther from the tracer's origin (the eye) than the extent at which float
    // geometry can place rays of length `radius` has no reference to trust: left out.
    const double reliable = aogen::truth::reliable_extent(radius);
    const aogen::truth::vec3 origin = t.origin();
    for (size_t i = 0; i < n; ++i) {
        if (!g.hit[i]) continue;
        const double extent = std::max({std::abs(g.position[3 * i] - origin.x), std::abs(g.position[3 * i + 1] - origin.y),
                                        std::abs(g.position[3 * i + 2] - origin.z)});
        if (extent > reliable) r.valid[i] = 0, ++r.untrusted;
    }
    aogen::parallel_for(
        n,
        [&](size_t i) {
            if (!r.valid[i]) return;
            aogen::truth::options o;
            o.radius = radius;
            o.grid = grid;
            o.seed = i;
            const aogen::truth::vec3 p{g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]};
            const aogen::truth::vec3 normal{g.normals[4 * i], g.normals[4 * i + 1], g.normals[4 * i + 2]};
            const aogen::truth::estimate e = t.ao(p, normal, o);
            r.ao[i] = float(e.value);
            r.standard_error[i] = float(e.standard_error);
            r.bent_normal[3 * i] = float(e.bent_normal.x), r.bent_normal[3 * i + 1] = float(e.bent_normal.y), r.bent_normal[3 * i + 2] = float(e.bent_normal.z);
        },
        threads);

    detail::finish(r);
    return r;
}

// The reference of scene `s` (G-buffer `g`, world normals), traced from `eye_tracer` (origin
// at the eye: scenes::make_tracer) where that can be trusted, and the hits too far from
// the eye for it from a second tracer whose origin is the centre of their bounding box —
// a telephoto view of geometry kilometres away is scored whole. What neither can trust
// stays left out (`untrusted`).
inline reference trace_reference(const aogen::scenes::scene& s, const aogen::truth::scene& eye_tracer, const aogen::scenes::gbuffer& g, int grid,
                                 unsigned threads = std::thread::hardware_concurrency())
{
    reference r = trace_reference(eye_tracer, g, s.ao_radius, grid, threads);
    if (r.untrusted == 0) return r;
    aogen::scenes::gbuffer rest = g; // only the hits left out
    aogen::truth::vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (size_t i = 0; i < rest.hit.size(); ++i) {
        rest.hit[i] = rest.hit[i] && !r.valid[i];
        if (!rest.hit[i]) continue;
        const double* p = &g.position[3 * i];
        lo = {std::min(lo.x, p[0]), std::min(lo.y, p[1]), std::min(lo.z, p[2])};
        hi = {std::max(hi.x, p[0]), std::max(hi.y, p[1]), std::max(hi.z, p[2])};
    }
    const std::unique_ptr<aogen::truth::scene> centred =
        aogen::scenes::make_tracer_at(s, {0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)});
    const reference second = trace_reference(*centred, rest, s.ao_radius, grid, threads);
    for (size_t i = 0; i < r.valid.size(); ++i)
        if (second.valid[i]) {
            r.ao[i] = second.ao[i], r.standard_error[i] = second.standard_error[i], r.valid[i] = 1, --r.untrusted;
            std::copy_n(&second.bent_normal[3 * i], 3, &r.bent_normal[3 * i]);
        }
    detail::finish(r);
    return r;
}

} // namespace aogen_report
