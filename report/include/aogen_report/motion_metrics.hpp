// aogen_report/motion_metrics.hpp — the figures of the report in motion (motion.hpp), from
// frames already run: how long each pixel's surface point has been in view, and a variant's
// error, ghosting and flicker along a path. No GPU here: the scenes' geometry and tracer only.
//
// WHAT
//   previous_pixel(now, before, tracer, p, id)   where frame f's hit point p (on geometry
//                          id) stood in frame f − 1: the previous frame's pixel it lands on and
//                          where in it, or pixel -1 when it was out of view (off that screen,
//                          or hidden from that eye: a ray cast in frame f − 1's tracer)
//   previous_pixels(now, g, before, tracer)      the same for every pixel of a G-buffer
//   next_ages(ages, from)  each pixel's age -- frames its point has been in view -- after a
//                          frame: its source's age + 1, or 0 where its point was not in view
//   motion_metrics(frames, window)               error, ghosting and flicker of scored frames
//                          (motion_record.hpp; motion.hpp says what each is)
//
// USAGE
//     std::vector<int> ages(n, 0);                                      // frame 0: all new
//     const std::vector<aogen_report::previous_place> from = aogen_report::previous_pixels(now, g, before, *before_tracer);
//     ages = aogen_report::next_ages(ages, from);
//     aogen_report::motion_record r = aogen_report::motion_metrics(scored, 4);
//
// ERRORS
//   aogen::error from compare() (metrics.hpp): a frame whose AO and truth differ in size.
#pragma once

#include "metrics.hpp"
#include "motion_record.hpp"
#include "reference.hpp"

#include <aogen_scenes/gbuffer.hpp>
#include <aogen_scenes/scene.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace aogen_report {

// ---------------------------------------------------------------------------------
// Ages: how long each pixel's surface point has been in view (the truth's)
// ---------------------------------------------------------------------------------

// Where a surface point stood on the previous frame's screen: the pixel it lands on, and
// where in pixels (pixel (x, y)'s centre is (x + 0.5, y + 0.5)); pixel -1 when it was out of view.
struct previous_place {
    long pixel = -1;
    double x = 0, y = 0;
};

// Where frame f's pixel (its hit `position`, on geometry `id`) stood in frame f − 1, or pixel
// -1 when it was out of view -- off that frame's screen, or hidden from its eye by something
// of that frame's scene.
inline previous_place previous_pixel(const aogen::scenes::scene& now, const aogen::scenes::scene& before, const aogen::truth::scene& before_tracer,
                                     aogen::truth::vec3 position, int id)
{
    const aogen::truth::vec3 was = aogen::scenes::position_in(before, now, position, id);
    const std::optional<aogen::scenes::ndc_point> ndc = aogen::scenes::project_ndc(before.camera, was);
    if (!ndc || !(std::fabs(ndc->x) < 1.0 && std::fabs(ndc->y) < 1.0)) return {};
    const int w = before.camera.width, h = before.camera.height;
    const double px = (ndc->x + 1.0) * 0.5 * w, py = (1.0 - ndc->y) * 0.5 * h;
    const int x = std::min(w - 1, int(px)), y = std::min(h - 1, int(py));
    // Hidden: something lies on the view ray's segment from the eye (an orthographic camera's
    // eye plane, straight above the point) to the point, short of the point by more than
    // the lift a point on a surface needs (truth::surface_offset's scale).
    aogen::scenes::dvec3 right, up, back;
    before.camera.basis(right, up, back);
    const aogen::truth::vec3 eye = before.camera.projection == aogen::scenes::projection_kind::orthographic
                                       ? was + (-aogen::truth::dot(was - before.camera.eye, back)) * back
                                       : before.camera.eye;
    if (before_tracer.occluded(eye, was - eye, 0.0, 1.0 - 1e-4)) return {};
    return {long(y) * w + x, px, py};
}

// Each pixel's source in the previous frame (previous_pixel; -1 on background and where the
// point was out of view), for frame `now` of a path whose frame before is `before`.
inline std::vector<previous_place> previous_pixels(const aogen::scenes::scene& now, const aogen::scenes::gbuffer& g, const aogen::scenes::scene& before,
                                                   const aogen::truth::scene& before_tracer)
{
    std::vector<previous_place> from(size_t(g.width) * g.height);
    for (size_t i = 0; i < from.size(); ++i)
        if (g.hit[i])
            from[i] = previous_pixel(now, before, before_tracer, {g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]}, g.geometry[i]);
    return from;
}

// The ages after a frame whose pixels came from `from` (previous_pixels): a pixel whose
// point was in view is one frame older than the pixel it came from, any other 0.
inline std::vector<int> next_ages(const std::vector<int>& ages, const std::vector<previous_place>& from)
{
    std::vector<int> out(from.size(), 0);
    for (size_t i = 0; i < from.size(); ++i)
        if (from[i].pixel >= 0) out[i] = std::min(ages.at(size_t(from[i].pixel)) + 1, 1 << 20);
    return out;
}

// ---------------------------------------------------------------------------------
// The metrics, from frames already read back (screen-sized AO)
// ---------------------------------------------------------------------------------

// One scored frame: the variant's AO at the screen's size, the frame's truth, and where its
// pixels came from and how old their points are.
struct scored_frame {
    std::vector<float> ao;
    const reference* truth = nullptr;
    std::vector<previous_place> from; // previous_pixels of this frame
    std::vector<int> ages;            // after this frame (next_ages)
    std::vector<int> geometry;        // each pixel's geometry id (the G-buffer's), -1 on background
    int width = 0;                    // pixels per row
};

// (AO − truth) of frame `p` where a point stood (`at`, on geometry `id`): bilinear over the
// four pixels about it that are valid, finite and on the same geometry (a pixel of another
// object is not the point's neighbour); NaN when none is.
inline double previous_error(const scored_frame& p, const previous_place& at, int id)
{
    const int w = p.width, h = int(p.ao.size()) / std::max(w, 1);
    const double fx = at.x - 0.5, fy = at.y - 0.5;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    double sum = 0, weight = 0;
    for (int k = 0; k < 4; ++k) {
        const int x = x0 + (k & 1), y = y0 + (k >> 1);
        if (x < 0 || y < 0 || x >= w || y >= h) continue;
        const size_t j = size_t(y) * w + x;
        if (!p.truth->valid[j] || !std::isfinite(p.ao[j]) || p.geometry[j] != id) continue;
        const double wk = ((k & 1) ? fx - x0 : 1.0 - (fx - x0)) * ((k >> 1) ? fy - y0 : 1.0 - (fy - y0));
        sum += wk * (double(p.ao[j]) - p.truth->ao[j]), weight += wk;
    }
    return weight > 1e-6 ? sum / weight : std::nan("");
}

// The metrics of `frames` (consecutive scored frames, the first one's predecessor not
// among them), for a ghost window of `window` frames.
inline motion_record motion_metrics(const std::vector<scored_frame>& frames, int window)
{
    motion_record r;
    double ghost_squares = 0, flicker_squares = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
        const scored_frame& s = frames[f];
        const reference& t = *s.truth;
        r.rmse.push_back(compare(s.ao, t.ao, t.valid).rmse);
        for (size_t i = 0; i < s.ao.size(); ++i) {
            if (!t.valid[i] || !std::isfinite(s.ao[i])) continue;
            const double e = double(s.ao[i]) - t.ao[i];
            if (s.ages[i] < window) ghost_squares += e * e, ++r.ghost_pixels;
            if (f == 0 || s.from[i].pixel < 0) continue;
            const double before = previous_error(frames[f - 1], s.from[i], s.geometry[i]);
            if (!std::isfinite(before)) continue;
            const double d = e - before;
            flicker_squares += d * d, ++r.flicker_pixels;
        }
    }
    double sum = 0;
    for (double x : r.rmse) sum += x;
    r.error = r.rmse.empty() ? 0 : sum / double(r.rmse.size());
    r.ghosting = r.ghost_pixels ? std::sqrt(ghost_squares / double(r.ghost_pixels)) : 0;
    r.flicker = r.flicker_pixels ? std::sqrt(flicker_squares / double(r.flicker_pixels)) : 0;
    return r;
}

} // namespace aogen_report
