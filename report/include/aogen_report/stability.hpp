// aogen_report/stability.hpp — the stability suite's cases: stiff and extreme inputs, each
// with a benign twin and a criterion.
//
// WHAT
//   A stability case is a scene at an extreme (a 175° field of view, geometry 10⁷ from the
//   origin, a NaN in the depth buffer, ...) and its benign twin — the same content at an
//   ordinary setting — so that a variant's error on the case can be read against the error
//   the same variant makes anyway. suite.hpp runs every variant on every case and judges it:
//     always   no NaN or Inf computed in any pass (raw diagnostics, before the guard), no
//              raw value outside [0, 1] by more than criterion.max_excess, background
//              pixels exactly 1, the output finite and in [0, 1];
//     error    RMSE against the ray-traced reference at most
//              criterion.error_ratio × the twin's RMSE + criterion.error_slack;
//     depth    with criterion.compare_depth, the AO in standard, reversed and reversed-
//              infinite depth the same: per-pixel difference at most depth_max, mean at
//              most depth_mean;
//     faults   with faults planted (the twin: the same scene without them), every output
//              pixel farther than criterion.fault_reach from each fault within
//              twin_pixel_max of the twin's, pixel by pixel;
//     scales   with criterion.compare_scales, the scene scaled by each of scale_factors()
//              (every length and the AO radius × 10⁻⁶ … 10⁶) gives the same AO as the scene,
//              every output pixel within scale_max.
//   The error criterion is skipped where criterion.compare_error is false: a case whose
//   twin is the scene itself (depth_conventions, scale_invariance) would compare its RMSE
//   with itself.
//   A case may also plant faults in the G-buffer the variant reads (faults: a NaN depth or a
//   zero normal at chosen pixels, which must give AO 1 there and change nothing else) and
//   fix the noise tile to one rotation (noise_rotation: parallel or anti-parallel to a
//   surface's normal).
//
//   builtin_case_names() lists the 31 built-in cases (docs/design.md § Extreme cases, and fields
//   of view from 0.1° to 175°, extreme aspect ratios, 1×1 and 8×8 images, D16/D24 depth,
//   tiny and huge radii, geometry cut by the near plane, sub-millimetre geometry, the
//   same scene at thirteen scales);
//   builtin_case(name) makes one. read_case reads a case file (JSON, below), so users add
//   their own.
//
// JSON (a case file; unknown keys are errors)
//   {"name": "my case", "about": "what it stresses",
//    "scene": {...scene JSON (scene.hpp)...}, "twin": {...scene JSON...},   (both required)
//    "criterion": {"error_ratio": 1.5, "error_slack": 0.03, "max_excess": 1e-5,
//                  "compare_depth": false, "depth_max": 0.0118, "depth_mean": 0.002,
//                  "compare_error": true, "fault_reach": 12, "twin_pixel_max": 0.0039,
//                  "compare_scales": false, "scale_max": 0.0039},
//    "faults": [{"kind": "nan_depth" | "zero_normal", "at": [u, v]}],        (u, v in [0, 1])
//    "noise_rotation": [x, y],
//    "twin_window": [x, y]}           (the scene's image is the twin's from pixel (x, y) on)
#pragma once

#include "scene_bench.hpp"
#include "settings.hpp"

#include <aogen_scenes/scene.hpp>
#include <aogen_tools/json_reader.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace aogen_report {

struct stability_criterion {
    double error_ratio = 1.5;        // RMSE <= error_ratio · twin RMSE + error_slack
    double error_slack = 0.03;
    double max_excess = 1e-5;        // raw values beyond [0, 1] by more than this fail (rounding does not)
    bool compare_depth = false;      // run standard, reversed and reversed-infinite depth and compare
    double depth_max = 3.0 / 255.0;  // per pixel, against standard depth
    double depth_mean = 0.5 / 255.0;
    bool compare_error = true;       // judge the RMSE against the twin's; off where the twin is the scene itself
    // With faults: every output pixel farther than fault_reach full-resolution pixels from
    // each fault within twin_pixel_max of the unfaulted twin's — "nothing else changed".
    double fault_reach = 0;
    double twin_pixel_max = 1.0 / 255.0;
    // Scale invariance: the scene × each of scale_factors(), every output pixel within
    // scale_max of the scene's own — AO is a ratio of lengths, so nothing may change.
    bool compare_scales = false;
    double scale_max = 1.0 / 255.0;
};

// The factors compare_scales multiplies a scene by: the powers of ten from 10⁻⁶ to 10⁶
// other than 1 (a 2 µm box and a 2000 km one, with their radii).
inline std::vector<double> scale_factors()
{
    std::vector<double> k;
    for (int e = -6; e <= 6; ++e)
        if (e != 0) k.push_back(std::pow(10.0, e));
    return k;
}

// A case's faults are planted in the G-buffer a variant reads, not in the reference's
// (gbuffer_fault: scene_bench.hpp).
struct stability_case {
    std::string name, about;
    aogen::scenes::scene scene, twin;
    stability_criterion criterion;
    std::vector<gbuffer_fault> faults;
    std::optional<aogen::vec2> noise_rotation; // every pixel's noise rotation, when set
    // When set, the scene's image is the window of the twin's image at this pixel offset (same
    // pixels, less screen around them), and the twin is scored in that window only: the twin
    // sees the same surfaces, so the comparison isolates what the missing screen costs.
    std::optional<std::array<int, 2>> twin_window;
    std::string source;                        // its file, or "built-in case 'name'"
};

namespace detail {

using aogen::scenes::dvec3;

// The scenes the built-in cases vary: a unit box on a floor, and a floor meeting a wall.
inline aogen::scenes::scene box_on_floor(const std::string& name)
{
    aogen::scenes::scene s;
    s.name = name;
    s.planes = {{{0, 0, 0}, {0, 0, 1}}};
    s.boxes = {{{-0.5, -0.5, 0}, {0.5, 0.5, 1}}};
    s.camera.up = {0, 0, 1};
    s.camera.eye = {2.5, -3.5, 2.2}, s.camera.target = {0, 0, 0.4};
    s.camera.width = 64, s.camera.height = 36;
    s.ao_radius = 0.5;
    return s;
}

inline aogen::scenes::scene floor_and_wall(const std::string& name)
{
    aogen::scenes::scene s = box_on_floor(name);
    s.boxes.clear();
    s.planes = {{{0, 0, 0}, {0, 0, 1}}, {{0, 0, 0}, {1, 0, 0}}};
    s.camera.eye = {4, -4, 2.5}, s.camera.target = {0.8, 0, 0.4};
    return s;
}

// Every length of `s` (geometry, camera, radius) times k, and everything moved by `offset`.
inline aogen::scenes::scene scaled(aogen::scenes::scene s, double k, dvec3 offset = {})
{
    const auto at = [&](dvec3 p) { return offset + k * p; };
    for (auto& p : s.planes) p.point = at(p.point), p.half_extent *= k;
    for (auto& b : s.boxes) b.lo = at(b.lo), b.hi = at(b.hi);
    for (auto& sp : s.spheres) sp.centre = at(sp.centre), sp.radius *= k;
    for (auto& q : s.quads) q.corner = at(q.corner), q.e1 = k * q.e1, q.e2 = k * q.e2;
    s.camera.eye = at(s.camera.eye), s.camera.target = at(s.camera.target);
    s.camera.near = float(s.camera.near * k), s.camera.far = float(s.camera.far * k);
    s.camera.left = float(s.camera.left * k), s.camera.right = float(s.camera.right * k);
    s.camera.bottom = float(s.camera.bottom * k), s.camera.top = float(s.camera.top * k);
    s.ao_radius *= k;
    return s;
}

// A telephoto camera: moved back along its view ray so that a field of view of
// `tan_half_fov_y` frames what the 60° view framed, near and far set around the scene as a
// renderer would (a near plane left at 0.1 from 3 km away leaves standard depth no
// precision at all: that is a setup error, not an extreme).
inline void telephoto(aogen::scenes::camera& c, double tan_half_fov_y)
{
    const dvec3 back = c.eye - c.target;
    const double d = std::sqrt(aogen::truth::dot(back, back));
    const double k = 0.57735026918962576 / tan_half_fov_y; // tan 30° over the new one
    c.eye = c.target + k * back;
    c.tan_half_fov_y = float(tan_half_fov_y);
    c.near = float(0.5 * k * d);
    c.far = float(4 * k * d);
}

inline stability_case make(const std::string& name, const std::string& about, aogen::scenes::scene scene, aogen::scenes::scene twin)
{
    stability_case c;
    c.name = name, c.about = about;
    scene.name = name, twin.name = name + " (twin)";
    scene.source = "built-in case " + aogen::quote(name), twin.source = scene.source + " twin";
    c.scene = std::move(scene), c.twin = std::move(twin);
    c.source = c.scene.source;
    return c;
}

inline double tan_half_degrees(double full_fov_degrees) { return std::tan(full_fov_degrees * 0.5 * 3.14159265358979323846 / 180.0); }

// One maker per case, or per family of cases that differ in a value, by section.

// ---------------------------------------------------------------------------------
// The view: grazing and edge-on surfaces, the noise against the normal, the screen's border, normals facing away
// ---------------------------------------------------------------------------------

inline stability_case grazing_floor(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s.camera.eye = {0, -12, 0.06}, s.camera.target = {0, 0, 0.3};
    return make(name, "the floor seen at a grazing angle from just above it", s, t);
}

// wall_edge_on, noise_parallel, noise_antiparallel
inline stability_case edge_on_wall(const std::string& name)
{
    aogen::scenes::scene s = floor_and_wall(name), t = s;
    // The wall x = 0 seen along it, nearly edge-on: its normal (1, 0, 0) lies in the view plane.
    s.camera.eye = {0.05, -6, 0.6}, s.camera.target = {0.05, 0, 0.4};
    if (name == "wall_edge_on") {
        t.camera.eye = {3, -4, 2}, t.camera.target = {0.5, 0, 0.4};
        return make(name, "a wall seen edge-on: its normal perpendicular to the view", s, t);
    }
    stability_case c = make(name, std::string("the noise vector ") + (name == "noise_parallel" ? "parallel" : "anti-parallel") +
                                      " to the wall's view-space normal (1, 0, 0)", s, s);
    c.noise_rotation = aogen::vec2{name == "noise_parallel" ? 1.0f : -1.0f, 0.0f};
    return c;
}

inline stability_case object_at_border(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // No floor: a box cut by the screen's left edge, cleared depth all around it. The camera
    // turns 35 degrees right from in front of the box rather than moving right, so no side
    // face shows edge-on (a face one texel wide seen edge-on is the horizon model's limit,
    // not the border's: wall_edge_on has it).
    s.planes.clear(), t.planes.clear();
    s.camera.eye = {0.3, -3.5, 0.5}, s.camera.target = {0.3 + 3.5 * std::tan(35 * 3.14159265358979 / 180), 0, 0.5};
    t.camera.eye = {0, -3.5, 0.5}, t.camera.target = {0, 0, 0.5};
    return make(name, "an object against cleared depth at the screen's border", s, t);
}

inline stability_case normals_away(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // The floor seen from below through a transparent world: its stored normal, +z, faces away.
    s.boxes.clear(), t.boxes.clear();
    s.camera.eye = {0, -3, -2}, s.camera.target = {0, 0, 0};
    s.renderer.normals_face_camera = false;
    t.camera = s.camera;
    return make(name, "G-buffer normals that face away from the camera", s, t);
}

// ---------------------------------------------------------------------------------
// Depth: conventions, precision, near and far planes, quantised buffers
// ---------------------------------------------------------------------------------

inline stability_case depth_conventions(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // Judged by the per-pixel comparison of the three conventions only: the twin is the
    // scene itself, so an error criterion would compare a number with itself.
    stability_case c = make(name, "standard, reversed and reversed-infinite depth give the same AO, pixel by pixel", s, t);
    c.criterion.compare_depth = true;
    c.criterion.compare_error = false;
    return c;
}

inline stability_case near_far_km(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s = detail::scaled(box, 50, {0, 600, 0});
    s.camera.eye = {0, -400, 120}, s.camera.target = {0, 600, 20};
    s.camera.near = 0.01f, s.camera.far = 1e5f;
    t = s, t.camera.near = 50, t.camera.far = 5000;
    return make(name, "near 0.01 and far 1e5 with the geometry 1 km away", s, t);
}

inline stability_case depth_past_fp16(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // The box scene × 2000 seen through a telephoto lens from 8 × as far (about 78 000
    // units: every view depth past 65504, the largest half float), framed as the 60°
    // view frames it, so the box covers as much of the screen as in the twin: the same
    // picture at × 20, whose depths a half holds.
    s = detail::scaled(box, 2000, {0, 0, 0});
    detail::telephoto(s.camera, 0.57735026918962576 / 8);
    t = detail::scaled(box, 20, {0, 0, 0});
    detail::telephoto(t.camera, 0.57735026918962576 / 8);
    return make(name, "view depths past 65504, the largest half float, the box as large as in its twin", s, t);
}

inline stability_case ortho_near0_offcentre(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s.camera.projection = aogen::scenes::projection_kind::orthographic;
    s.camera.left = -0.5f, s.camera.right = 2.5f, s.camera.bottom = -0.6f, s.camera.top = 1.1f, s.camera.near = 0.0f;
    // The twin sees the same region through a centred frustum with near 0.1: the camera
    // moved by the frustum's centre (1, 0.25) along its right and up vectors, so the two
    // differ in nothing but the projection (a centred twin of the old camera saw other
    // parts of the scene, and its error was no bound on this one's).
    t = s, t.camera.left = -1.5f, t.camera.right = 1.5f, t.camera.bottom = -0.85f, t.camera.top = 0.85f, t.camera.near = 0.1f;
    aogen::scenes::dvec3 right, up, back;
    s.camera.basis(right, up, back);
    const aogen::scenes::dvec3 shift = 1.0 * right + 0.25 * up;
    t.camera.eye = s.camera.eye + shift, t.camera.target = s.camera.target + shift;
    stability_case c = make(name, "an orthographic camera with near 0 and an off-centre frustum", s, t);
    // The same pixels of the same surfaces: the error may differ by rounding only (every
    // default variant within 4.2e-5 of its twin on lavapipe).
    c.criterion.error_ratio = 1.02, c.criterion.error_slack = 0.002;
    return c;
}

inline stability_case blur_weights_underflow(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // Geometry just past a near plane close to it: raw depth changes steeply between
    // neighbours (Δd ≈ near·Δz/z²), so the seed's exp(-|Δ raw depth| · 1000) weights all
    // underflow. The twin: the same view with near 0.01, where they do not.
    s.camera.eye = {1.0, -1.4, 0.9}, s.camera.target = {0, 0, 0.4}, s.camera.near = 0.6f;
    t = s, t.camera.near = 0.01f;
    return make(name, "a bilateral blur whose depth weights all underflow", s, t);
}

inline stability_case near_plane_cut(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // Low over the floor, looking down at it: the near plane cuts the floor in front of
    // the camera (an open surface, so the cut shows more floor, not an object's inside).
    s.camera.eye = {0.6, -2.2, 0.35}, s.camera.target = {0, 0, 0.2}, s.camera.near = 0.45f;
    t = s, t.camera.near = 0.05f;
    return make(name, "geometry cut by the near plane", s, t);
}

// depth_d16, depth_d24
inline stability_case quantised_depth(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s.renderer.depth_buffer = name == "depth_d16" ? aogen::scenes::depth_format::d16_unorm : aogen::scenes::depth_format::d24_unorm;
    return make(name, std::string("depth quantised as a ") + (name == "depth_d16" ? "D16" : "D24") + " UNORM buffer stores it", s, t);
}

// ---------------------------------------------------------------------------------
// The AO radius: sub-pixel, past the screen, at the ends of its range
// ---------------------------------------------------------------------------------

inline stability_case radius_0p1px(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s.ao_radius = 0.016; // 0.5 H cot(30°) R / d ≈ 0.1 px at the box (d ≈ 4.9)
    return make(name, "an AO radius that projects to about 0.1 pixel", s, t);
}

// radius_past_screen, radius_huge
inline stability_case radius_past_screen(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s.ao_radius = name == "radius_huge" ? ao_radius_range().hi : 20;
    // The twin: the largest radius that still fits the screen (half its height at the
    // box's depth is 2.8). A hemisphere past the screen can see no more than that one, so
    // it must do as well as it — not send its samples off screen and read too light.
    t.ao_radius = 2.8;
    stability_case c =
        make(name, name == "radius_huge" ? "the largest AO radius the settings take (" + aogen::format_number(s.ao_radius) + ")" : "an AO radius far past the whole screen", s, t);
    // Slack 0.03 (measured, BENCHMARKS.md: RMSE − 1.25 × twin at most 0.014 past the
    // screen and 0.023 at the largest radius, vbao-9x3-half-bilateral): GTAO's tuned radius (0.78 R, params.hpp) keeps the twin's horizon
    // search inside the screen, where the capped one reaches its edge, and what lies
    // past the screen's edge no filter recovers: the depth-aware upsample lowered the
    // twins' error (gtao-2x3-half-bilateral 0.038 -> 0.032) more than the case's
    // (0.0625 -> 0.0613), which got better too.
    c.criterion.error_ratio = 1.25, c.criterion.error_slack = 0.03;
    return c;
}

inline stability_case radius_tiny(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // The box alone (a floor reaching the horizon would be too far for so short a
    // reference ray: the report refuses radii below ~1/4800 of the farthest visible
    // point), with a radius of 0.2 % of it: a hundredth of a pixel.
    s.planes.clear(), t.planes.clear();
    s.ao_radius = 2e-3;
    return make(name, "a tiny AO radius: 0.2 % of the box, a hundredth of a pixel", s, t);
}

// ---------------------------------------------------------------------------------
// Scale and position: far from the origin, micrometres, every power of ten
// ---------------------------------------------------------------------------------

inline stability_case far_from_origin(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s = detail::scaled(box, 1, {1e7, -1e7, 1e7});
    return make(name, "scene and camera 1e7 from the origin", s, t);
}

inline stability_case sub_millimetre(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // 2 µm: an AO radius of 1e-6, which every blurred variant once refused (the linear
    // blur's sharpness, 10 / R, left its range).
    s = detail::scaled(box, 2e-6);
    return make(name, "the scene 500 000 times smaller: a 2 µm box, AO radius 1e-6", s, t);
}

inline stability_case scale_invariance(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // The box on its floor at 10⁻⁶ … 10⁶ of its size, the camera, its near and far planes
    // and the AO radius scaled with it: every quantity the shaders compare is a ratio of
    // two lengths, so the AO must not change beyond rounding. An absolute epsilon in a
    // shader (a `max(d, 1e-4)`, a fixed bias) shows here first, at one end of the range.
    stability_case c = make(name, "the scene and its AO radius scaled by 10⁻⁶ … 10⁶: the same AO, pixel by pixel", s, t);
    c.criterion.compare_scales = true;
    c.criterion.compare_error = false;
    return c;
}

// ---------------------------------------------------------------------------------
// The image: odd sizes, lenses from 0.1° to 175°, strips, a single pixel
// ---------------------------------------------------------------------------------

inline stability_case odd_size_half(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    s.camera.width = 101, s.camera.height = 61;
    t.camera.width = 100, t.camera.height = 60;
    return make(name, "an odd size (101×61) at half resolution", s, t);
}

inline stability_case fov_0p1(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    detail::telephoto(s.camera, detail::tan_half_degrees(0.1));
    return make(name, "a 0.1° vertical field of view from 2.8 km", s, t);
}

// fov_120, fov_175
inline stability_case wide_lens(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // The same camera with a wider lens: the scene shrinks to the middle, the open floor
    // fills the rest — where GTAO made it darker than it is.
    const double fov = name == "fov_120" ? 120 : 175;
    s.camera.tan_half_fov_y = float(detail::tan_half_degrees(fov));
    return make(name, "a " + aogen::format_number(fov) + "° vertical field of view", s, t);
}

// aspect_wide, aspect_tall
inline stability_case aspect_strip(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    // A letterbox strip 8 pixels across of a square 60° view, and the square view itself
    // as the twin, scored on the strip's pixels: the same surfaces, with the screen
    // around them cut away. (The same lens at 256×8 would be a 174° view, fov_175's case.)
    t.camera.width = t.camera.height = 256;
    if (name == "aspect_wide") {
        s.camera.width = 256, s.camera.height = 8;
        s.camera.tan_half_fov_y = float(t.camera.tan_half_fov_y * 8 / 256);
    } else {
        s.camera.width = 8, s.camera.height = 256;
    }
    stability_case c = make(name, "an extreme aspect ratio (" + std::to_string(s.camera.width) + "×" + std::to_string(s.camera.height) +
                                      "): a strip of a square view", s, t);
    c.twin_window = name == "aspect_wide" ? std::array<int, 2>{0, 124} : std::array<int, 2>{124, 0};
    // A strip 8 pixels across (4 at half resolution) cannot show occluders beside it
    // that the twin's screen shows; the error that costs is information, not precision
    // (with GTAO's tuned defaults the twin's RMSE fell 4x, the strip's cannot). Measured
    // on lavapipe, 2026-12-02 (BENCHMARKS.md): RMSE − 1.5 × twin at most 0.049 for the
    // tall strip (vbao-3x3-half-bilateral), 0.0054 for the wide one: slack 0.06 and 0.02.
    // SAO (2026-12-05) loses most of its spiral off a strip 4 texels wide and divides what is
    // left by the taps it kept, its nearest, which weigh most: 0.070 for the tall strip
    // (sao-s32-half-denoise): slack 0.08.
    c.criterion.error_slack = name == "aspect_tall" ? 0.08 : 0.02;
    return c;
}

// image_1x1, image_8x8
inline stability_case tiny_image(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    const int n = name == "image_1x1" ? 1 : 8;
    s.camera.width = s.camera.height = n;
    s.camera.target = {0, 0, 0.8}; // the one pixel sees the box
    stability_case c = make(name, "an image of " + std::to_string(n) + "×" + std::to_string(n) + " pixels", s, t);
    // 4×4 AO pixels at half resolution show little of what the 64×36 twin shows (as
    // aspect_*). Measured (BENCHMARKS.md): RMSE − 1.5 × twin at most 0.053 at 8×8
    // (vbao-3x3-full-bilateral), below 0 at 1×1: slack 0.06 and the default 0.03.
    if (n == 8) c.criterion.error_slack = 0.06;
    return c;
}

// ---------------------------------------------------------------------------------
// Faults planted in the G-buffer
// ---------------------------------------------------------------------------------

// nan_depth_texel, zero_normal
inline stability_case planted_faults(const std::string& name)
{
    const aogen::scenes::scene box = box_on_floor(name);
    aogen::scenes::scene s = box, t = box;
    stability_case c = make(name, name == "zero_normal" ? "zero normals in the G-buffer: AO 1 there, nothing else changed"
                                                        : "NaN depth texels: AO 1 there, nothing else changed", s, t);
    const auto k = name == "zero_normal" ? gbuffer_fault::kind::zero_normal : gbuffer_fault::kind::nan_depth;
    c.faults = {{k, 0.5, 0.55}, {k, 0.3, 0.8}, {k, 0.7, 0.3}};
    // "Nothing else changed", pixel by pixel: beyond the widest filter's footprint (the
    // 7-tap bilateral at half resolution, ±3 target pixels = ±6 full-resolution pixels,
    // and the upsample's 2 × 2 candidates) every pixel within 1/255 of the twin's. On
    // lavapipe (2026-12-02) the farthest pixel that changed at all lay 4.0 px from its
    // fault (the bilateral blurs mixing the fault's AO 1 into their neighbours). SAO reads
    // farther: its disc (2.69 R) spans 8.6 px at the box, and a tap whose four texels include
    // a NaN one reads it as an edge beside background -- its farthest change beyond 1/255
    // lay 9.5 px from its fault (sao-s16-half-bilateral, 2026-12-05): reach 10.
    c.criterion.fault_reach = 10;
    return c;
}

// The built-in cases, in the order the suite runs them: each name and what makes it.
struct builtin_case_maker {
    const char* name;
    stability_case (*make)(const std::string& name);
};
inline constexpr builtin_case_maker builtin_cases[] = {
    {"grazing_floor", grazing_floor},
    {"wall_edge_on", edge_on_wall},
    {"noise_parallel", edge_on_wall},
    {"noise_antiparallel", edge_on_wall},
    {"object_at_border", object_at_border},
    {"depth_conventions", depth_conventions},
    {"near_far_km", near_far_km},
    {"depth_past_fp16", depth_past_fp16},
    {"radius_0p1px", radius_0p1px},
    {"radius_past_screen", radius_past_screen},
    {"ortho_near0_offcentre", ortho_near0_offcentre},
    {"far_from_origin", far_from_origin},
    {"blur_weights_underflow", blur_weights_underflow},
    {"odd_size_half", odd_size_half},
    {"nan_depth_texel", planted_faults},
    {"zero_normal", planted_faults},
    {"normals_away", normals_away},
    {"fov_0p1", fov_0p1},
    {"fov_120", wide_lens},
    {"fov_175", wide_lens},
    {"aspect_wide", aspect_strip},
    {"aspect_tall", aspect_strip},
    {"image_1x1", tiny_image},
    {"image_8x8", tiny_image},
    {"depth_d16", quantised_depth},
    {"depth_d24", quantised_depth},
    {"radius_tiny", radius_tiny},
    {"radius_huge", radius_past_screen},
    {"near_plane_cut", near_plane_cut},
    {"sub_millimetre", sub_millimetre},
    {"scale_invariance", scale_invariance},
};

} // namespace detail

inline std::vector<std::string> builtin_case_names()
{
    std::vector<std::string> names;
    for (const detail::builtin_case_maker& c : detail::builtin_cases) names.push_back(c.name);
    return names;
}

inline stability_case builtin_case(const std::string& name)
{
    for (const detail::builtin_case_maker& c : detail::builtin_cases)
        if (name == c.name) return c.make(name);
    std::string valid;
    for (const std::string& n : builtin_case_names()) valid += (valid.empty() ? "" : ", ") + n;
    aogen::fail("built-in stability case", aogen::quote(name) + " is not known", "valid: " + valid);
}

// A case from JSON text (the format above); `source` (its file) starts every message.
inline stability_case read_case(const std::string& text, const std::string& source)
{
    const nlohmann::json doc = aogen::tools::json_reader::parse(text, source);
    const aogen::tools::json_reader root(doc, source);
    root.only_keys({"name", "about", "scene", "twin", "criterion", "faults", "noise_rotation", "twin_window"});
    stability_case c;
    c.name = root.string("name");
    if (c.name.empty() || aogen::printable(c.name) != c.name)
        aogen::fail(root.path() + ".name", "is not a printable name", "valid: a name for the case");
    if (root.has("about")) c.about = root.string("about");
    c.scene = aogen::scenes::read_scene(root.field("scene"), source);
    c.twin = aogen::scenes::read_scene(root.field("twin"), source);
    c.source = source;
    if (root.has("criterion")) {
        const aogen::tools::json_reader k = root.field("criterion");
        k.only_keys({"error_ratio", "error_slack", "max_excess", "compare_depth", "depth_max", "depth_mean", "compare_error", "fault_reach",
                     "twin_pixel_max", "compare_scales", "scale_max"});
        stability_criterion& cr = c.criterion;
        const auto number = [&](const char* key, double& out, double lo, double hi) {
            if (!k.has(key)) return;
            out = k.number(key);
            aogen::require_finite_range(k.path() + "." + key, out, lo, hi);
        };
        number("error_ratio", cr.error_ratio, 0, 1e6);
        number("error_slack", cr.error_slack, 0, 1);
        number("max_excess", cr.max_excess, 0, 1e30);
        number("depth_max", cr.depth_max, 0, 1);
        number("depth_mean", cr.depth_mean, 0, 1);
        number("fault_reach", cr.fault_reach, 0, 1e6);
        number("twin_pixel_max", cr.twin_pixel_max, 0, 1);
        number("scale_max", cr.scale_max, 0, 1);
        if (k.has("compare_depth")) cr.compare_depth = k.boolean("compare_depth");
        if (k.has("compare_scales")) cr.compare_scales = k.boolean("compare_scales");
        if (k.has("compare_error")) cr.compare_error = k.boolean("compare_error");
    }
    if (root.has("faults")) {
        const aogen::tools::json_reader list = root.array("faults");
        for (size_t i = 0; i < list.size(); ++i) {
            const aogen::tools::json_reader f = list.at(i);
            f.only_keys({"kind", "at"});
            gbuffer_fault g;
            const std::string kind = f.string("kind");
            if (kind == "nan_depth") g.what = gbuffer_fault::kind::nan_depth;
            else if (kind == "zero_normal") g.what = gbuffer_fault::kind::zero_normal;
            else aogen::fail(f.path() + ".kind", aogen::quote(kind) + " is not a fault", "valid: nan_depth, zero_normal");
            const aogen::tools::json_reader at = f.array("at");
            if (at.size() != 2) aogen::fail(at.path(), "has " + std::to_string(at.size()) + " entries", "valid: [u, v]");
            g.u = at.at(0).as_number(), g.v = at.at(1).as_number();
            aogen::require_finite_range(at.path(), g.u, 0, 1);
            aogen::require_finite_range(at.path(), g.v, 0, 1);
            c.faults.push_back(g);
        }
    }
    if (root.has("noise_rotation")) {
        const aogen::tools::json_reader r = root.array("noise_rotation");
        if (r.size() != 2) aogen::fail(r.path(), "has " + std::to_string(r.size()) + " entries", "valid: [x, y], not both 0");
        const double x = r.at(0).as_number(), y = r.at(1).as_number();
        if (!(x * x + y * y > 1e-12) || !std::isfinite(x * x + y * y))
            aogen::fail(r.path(), "is not a direction", "valid: [x, y], finite, not both 0");
        c.noise_rotation = aogen::vec2{float(x), float(y)};
    }
    if (root.has("twin_window")) {
        const aogen::tools::json_reader w = root.array("twin_window");
        const int free_x = c.twin.camera.width - c.scene.camera.width, free_y = c.twin.camera.height - c.scene.camera.height;
        const std::string valid = "valid: [x, y] with the scene's image inside the twin's: x in 0.." + std::to_string(std::max(0, free_x)) +
                                  ", y in 0.." + std::to_string(std::max(0, free_y));
        if (w.size() != 2 || free_x < 0 || free_y < 0) aogen::fail(w.path(), "does not fit the scene's image into the twin's", valid);
        std::array<int, 2> at{};
        for (size_t i = 0; i < 2; ++i) {
            const double x = w.at(i).as_number();
            if (!(x >= 0 && x <= (i == 0 ? free_x : free_y) && x == std::floor(x)))
                aogen::fail(w.at(i).path(), aogen::format_number(x) + " does not fit the scene's image into the twin's", valid);
            at[i] = int(x);
        }
        c.twin_window = at;
    }
    return c;
}

} // namespace aogen_report
