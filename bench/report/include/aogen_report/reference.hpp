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
// (aogen::truth::scene::ao). Pixel i's rays use seed i, and pixels are split over threads
// by index, so the image is the same for any thread count. noise_rms is the root mean
// square of the per-pixel standard errors: how much the truth's own noise adds to a
// variant's RMSE (in quadrature), to be read against the errors the report shows.
#pragma once

#include <aogen_scenes/gbuffer.hpp>

#include <cmath>
#include <thread>
#include <vector>

namespace aogen_report {

struct reference {
    int width = 0, height = 0;
    std::vector<float> ao;             // NaN on background
    std::vector<float> standard_error; // 0 on background
    std::vector<uint8_t> valid;        // 1 where a surface was hit
    double noise_rms = 0;              // √(mean standard_error²) over valid pixels
    int rays_per_pixel = 0;
};

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
    r.valid = g.hit;
    r.rays_per_pixel = grid * grid;
    const auto trace = [&](size_t first, size_t stride) {
        for (size_t i = first; i < n; i += stride) {
            if (!g.hit[i]) continue;
            aogen::truth::options o;
            o.radius = radius;
            o.grid = grid;
            o.seed = i;
            const aogen::truth::vec3 p{g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]};
            const aogen::truth::vec3 normal{g.normals[4 * i], g.normals[4 * i + 1], g.normals[4 * i + 2]};
            const aogen::truth::estimate e = t.ao(p, normal, o);
            r.ao[i] = float(e.value);
            r.standard_error[i] = float(e.standard_error);
        }
    };
    std::vector<std::thread> workers;
    const unsigned count = std::max(1u, threads);
    for (unsigned k = 1; k < count; ++k) workers.emplace_back(trace, k, count);
    trace(0, count);
    for (std::thread& w : workers) w.join();

    double squares = 0, pixels = 0;
    for (size_t i = 0; i < n; ++i)
        if (r.valid[i]) squares += double(r.standard_error[i]) * r.standard_error[i], pixels += 1;
    r.noise_rms = pixels > 0 ? std::sqrt(squares / pixels) : 0;
    return r;
}

} // namespace aogen_report
