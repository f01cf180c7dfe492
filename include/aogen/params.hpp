// aogen/params.hpp — the settings of each AO pass, their defaults, ranges and presets.
//
// One plain struct per pass (XeGTAO style): every setting an SSAO, GTAO or blur pass
// takes is a field here, with its default, its valid range and its meaning written
// next to it. The ranges are `static constexpr` members beside the fields, so the
// documentation, `validate()` and the command line all read the same numbers.
//
//   ssao_params   hemisphere SSAO (Taos SSAOPass, Unique Engine UeSSAOPass, ssao.wgsl)
//   gtao_params   ground-truth AO, slice/horizon based (Taos GTAOPass)
//   vbao_params   visibility-bitmask AO: GTAO's slices with a 32-sector mask and a thickness
//   blur_params   the denoise pass after either: 7-tap bilateral, 4×4 box, 5×5 edge-aware
//                 denoise, or none; the depth term of the depth-aware upsample
//   presets::     the seeds' configurations, as ssao_preset / gtao_preset bundles
//
// Usage:
//
//     #include <aogen/params.hpp>
//
//     aogen::ssao_preset p = aogen::presets::taos_ssao();   // 16 samples, half res, ...
//     p.ssao.radius = 0.8f;                                  // tune a field
//     p.blur.mode = aogen::blur_mode_from_name("box");       // names <-> enum values
//     aogen::validate(p);  // throws aogen::error, e.g.
//                          // "ssao.radius: nan is not a finite number (valid: > 0 and <= 1e+15)"
//
//     aogen::to_name(p.blur.mode);                  // "box"
//     aogen::ssao_params::radius_range;             // {0, 1e15, lower bound excluded}
//     aogen::to_string(aogen::ssao_params::radius_range);  // "> 0 and <= 1e+15"
//
// Nothing here touches a GPU: these are the numbers that kernel.hpp, noise.hpp,
// layout.hpp and the shader templates consume. Fields are float because that is what
// reaches the shader; validation rejects NaN, infinities and out-of-range values, and
// enum values outside their enumeration (for instance cast from an int read from a
// file). Errors follow error.hpp: "<struct>.<field>: <value> <problem> (valid: <range>)".
//
// Numbers the seeds state are used exactly. Numbers the seeds leave open are marked
// "(ours)" where they are chosen.
#pragma once

#include "error.hpp"
#include "names.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace aogen {

// ---------------------------------------------------------------------------------
// Ranges
// ---------------------------------------------------------------------------------

// An inclusive integer range lo..hi.
struct int_range {
    int lo;
    int hi;
    constexpr bool contains(int v) const { return v >= lo && v <= hi; }
};

// A range of finite floats: [lo, hi], or (lo, hi] when `lo_excluded`.
struct float_range {
    float lo;
    float hi;
    bool lo_excluded;
    bool contains(float v) const
    {
        if (!std::isfinite(v)) return false;
        return (lo_excluded ? v > lo : v >= lo) && v <= hi;
    }
};

// The largest world length a setting may hold (a radius, a bias). Not a limit of taste but
// of float arithmetic: every radius is capped at the screen's extent at the pixel's depth
// before it is used (ssao.glsl's ao_ssao_radius, common/slices.glsl's ao_slice_radius), so
// what must stay finite is the one length that is not capped, VBAO's thickness (up to 100 ×
// its radius, params below), and its square: (100 · 1e15)² = 1e34 < FLT_MAX ≈ 3.4e38.
inline constexpr float max_world_length = 1e15f;

// The words error messages and help text use for a range: "1..256", "> 0 and <= 1e+15".
inline std::string to_string(const int_range& r)
{
    return format_number(r.lo) + ".." + format_number(r.hi);
}
inline std::string to_string(const float_range& r)
{
    if (r.lo_excluded) return "> " + format_number(r.lo) + " and <= " + format_number(r.hi);
    return format_number(r.lo) + ".." + format_number(r.hi);
}

// ---------------------------------------------------------------------------------
// Enumerations and their names
// ---------------------------------------------------------------------------------
//
// Every enum has a table of canonical names (lower case, '_' between words) used by
// to_name(), the *_from_name() readers, the command line and JSON, read through
// names.hpp. The readers also accept '-' for '_' ("gbuffer-world" as DESIGN.md spells
// the axis values).

// How an SSAO pass turns the occlusion sum into its output.
enum class ssao_output {
    // Taos SSAOPass: out = clamp(1 − occlusion/N · strength, 0, 1).
    // ssao.wgsl (seed 004) is this form with strength 1.
    strength,
    // Unique Engine UeSSAOPass: ao = pow(1 − occlusion/N, power), then blended toward 1
    // by intensity: out = clamp(mix(1, ao, intensity), 0, 1). This is our reading of its
    // documentation ("power: the exponent applied to the occlusion factor; higher values
    // make the shadows darker" — ao^power with power > 1 is darker; "intensity: blending
    // factor for the final composition, 0 means no AO, 1 means full AO" — a mix). Its
    // own example uses intensity 1.5, so intensity may exceed 1 (extrapolating past
    // the raw AO); the clamp keeps the output in [0, 1].
    power_intensity,
};
inline constexpr std::array<enum_name<ssao_output>, 2> ssao_output_names{{
    {ssao_output::strength, "strength"},
    {ssao_output::power_intensity, "power_intensity"},
}};

// How much one occluding sample counts, from the view-space depth difference
// Δz = pixel z − scene z at the sample.
enum class ssao_range_check {
    // Taos SSAOPass: vote · (1 − smoothstep(0, radius, |Δz|)) — fades to 0 at |Δz| = radius.
    taos,
    // ssao.wgsl (seed 004): vote · smoothstep(0, 1, radius / |Δz|) — 1 while |Δz| <= radius,
    // then falls off with distance (never exactly 0).
    seed004,
};
inline constexpr std::array<enum_name<ssao_range_check>, 2> ssao_range_check_names{{
    {ssao_range_check::taos, "taos"},
    {ssao_range_check::seed004, "seed004"},
}};

// Where a pass gets its surface normal from (a variant axis; see DESIGN.md).
enum class normal_source {
    gbuffer_world,  // world-space G-buffer normal, rotated into view space (Taos)
    gbuffer_view,   // view-space normal target (Unique Engine's normal pre-pass)
    reconstructed,  // from the depth buffer alone (ssao.wgsl: cross of position derivatives)
};
inline constexpr std::array<enum_name<normal_source>, 3> normal_source_names{{
    {normal_source::gbuffer_world, "gbuffer_world"},
    {normal_source::gbuffer_view, "gbuffer_view"},
    {normal_source::reconstructed, "reconstructed"},
}};

// The denoise pass after SSAO or GTAO.
enum class blur_mode {
    bilateral,  // Taos 'quality': two-pass separable 7-tap Gaussian with a depth term
    box,        // Taos 'performance': single-pass 4×4 unweighted box average
    none,       // raw AO (ssao.wgsl has no blur)
    denoise,    // ours: single-pass 5×5 edge-aware filter (blur_denoise.glsl), one pass
                // instead of the bilateral's two, for XeGTAO's denoiser's cost
};
inline constexpr std::array<enum_name<blur_mode>, 4> blur_mode_names{{
    {blur_mode::bilateral, "bilateral"},
    {blur_mode::box, "box"},
    {blur_mode::none, "none"},
    {blur_mode::denoise, "denoise"},
}};

// How a half-resolution AO target reaches the screen's resolution (full-resolution
// variants have nothing to upsample).
enum class upsample_mode {
    // A joint bilateral upsample pass (upsample.glsl): each screen pixel blends the AO
    // target texels around it by their bilinear weights times a depth term against the
    // pixel's own full-resolution depth, so AO does not bleed across silhouettes the
    // half-resolution target cannot resolve. The chain's output is screen-sized.
    depth_aware,
    // No pass: the chain's output is the half-resolution target, and whoever samples it
    // upsamples (the report reads target pixel x / 2: nearest, as a renderer without an
    // upsample pass would show it).
    nearest,
};
inline constexpr std::array<enum_name<upsample_mode>, 2> upsample_mode_names{{
    {upsample_mode::depth_aware, "depth_aware"},
    {upsample_mode::nearest, "nearest"},
}};

// The depth term of the bilateral blur, which stops AO bleeding across silhouettes.
enum class bilateral_depth {
    // Seed-exact (Taos): weight · exp(−|Δ raw depth| · raw_depth_k), raw depth being the
    // depth-buffer value. Depends on near/far and the depth convention: far from the
    // camera a standard [0,1] buffer's values barely change, so edges hardly stop the
    // blur; close up the differences are large and every depth weight can underflow.
    seed_raw,
    // View-space linear depth: weight · exp(−|Δz_view| · linear_sharpness), Δz in world
    // units. The same edge stop at every distance and for every depth convention.
    linear,
};
inline constexpr std::array<enum_name<bilateral_depth>, 2> bilateral_depth_names{{
    {bilateral_depth::seed_raw, "seed_raw"},
    {bilateral_depth::linear, "linear"},
}};

static_assert(names::distinct(ssao_output_names) && names::distinct(ssao_range_check_names) &&
              names::distinct(normal_source_names) && names::distinct(blur_mode_names) &&
              names::distinct(bilateral_depth_names) && names::distinct(upsample_mode_names));

namespace detail {

inline std::string field(std::string_view prefix, std::string_view name)
{
    std::string s(prefix);
    if (!s.empty()) s += '.';
    s.append(name);
    return s;
}

// A finite float inside `r`, worded like error.hpp's require_finite_* helpers but
// printing the float as a float ("0.1", not "0.10000000149011612").
inline void require_in(std::string_view subject, float value, const float_range& r)
{
    std::string valid = "valid: " + to_string(r);
    if (!std::isfinite(value)) fail(subject, format_number(value) + " is not a finite number", valid);
    if (!r.contains(value)) fail(subject, format_number(value) + " is out of range", valid);
}

inline void require_in(std::string_view subject, int value, const int_range& r)
{
    require_range(subject, value, r.lo, r.hi);
}

} // namespace detail

// Enum -> canonical name. A value outside the enumeration throws aogen::error.
inline const char* to_name(ssao_output v) { return names::name_of(ssao_output_names, v, "ssao_output"); }
inline const char* to_name(ssao_range_check v) { return names::name_of(ssao_range_check_names, v, "ssao_range_check"); }
inline const char* to_name(normal_source v) { return names::name_of(normal_source_names, v, "normal_source"); }
inline const char* to_name(blur_mode v) { return names::name_of(blur_mode_names, v, "blur_mode"); }
inline const char* to_name(bilateral_depth v) { return names::name_of(bilateral_depth_names, v, "bilateral_depth"); }
inline const char* to_name(upsample_mode v) { return names::name_of(upsample_mode_names, v, "upsample_mode"); }

// Name -> enum. An unknown name throws aogen::error listing the valid names; `subject`
// is what the message names (pass the option or JSON path, e.g. "--blur" or "blur.mode").
inline ssao_output ssao_output_from_name(std::string_view name, std::string_view subject = "ssao.output")
{
    return names::value_of(ssao_output_names, name, subject);
}
inline ssao_range_check ssao_range_check_from_name(std::string_view name, std::string_view subject = "ssao.range_check")
{
    return names::value_of(ssao_range_check_names, name, subject);
}
inline normal_source normal_source_from_name(std::string_view name, std::string_view subject = "normals")
{
    return names::value_of(normal_source_names, name, subject);
}
inline blur_mode blur_mode_from_name(std::string_view name, std::string_view subject = "blur.mode")
{
    return names::value_of(blur_mode_names, name, subject);
}
inline bilateral_depth bilateral_depth_from_name(std::string_view name, std::string_view subject = "blur.depth")
{
    return names::value_of(bilateral_depth_names, name, subject);
}
inline upsample_mode upsample_mode_from_name(std::string_view name, std::string_view subject = "upsample")
{
    return names::value_of(upsample_mode_names, name, subject);
}

// ---------------------------------------------------------------------------------
// SSAO
// ---------------------------------------------------------------------------------
//
// Crytek-style view-space hemisphere SSAO (seeds 000, 002, 003, 004): per pixel, N kernel
// samples in the normal-oriented hemisphere (rotated by a tiled noise vector) are
// projected to the screen; a sample is occluded when the scene surface there is closer
// to the camera than the sample by more than `bias`. Each vote is weighted by the range
// check, summed to `occlusion`, and turned into the output by `output`.
struct ssao_params {
    // Kernel samples per pixel, N. Taos: 16, Unique Engine: 32, ssao.wgsl: 64.
    static constexpr int_range samples_range{1, 256};
    int samples = 16;

    // Hemisphere radius in view-space units; also the range check's scale.
    // 0.5 is Unique Engine's default (and ours for Taos SSAO and ssao.wgsl).
    static constexpr float_range radius_range{0.0f, max_world_length, true};
    float radius = 0.5f;

    // Depth-comparison bias in view-space units: occluded when
    // scene_z > sample_z + bias (toward the camera). Avoids self-occlusion ("acne").
    static constexpr float_range bias_range{0.0f, max_world_length, false};
    float bias = 0.025f;

    // Which formula makes the output (see ssao_output). Default: Taos' strength form.
    ssao_output output = ssao_output::strength;

    // output == strength: out = clamp(1 − occlusion/N · strength, 0, 1).
    // 0 = no AO, 1 = the plain average, > 1 darkens (saturates sooner). Not tuned yet:
    // the search's best (3.3 at a radius of 2 R) multiplies every sample's vote, and a
    // single vote flipping at the bias threshold then moves a pixel by 0.2 -- the
    // stability suite's depth_conventions case fails with it (BENCHMARKS.md, 2026-12-01).
    static constexpr float_range strength_range{0.0f, 100.0f, false};
    float strength = 1.0f;

    // output == power_intensity: ao = pow(1 − occlusion/N, power). Must be > 0 (GLSL's
    // pow(0, y) is undefined for y <= 0). Unique Engine default 1.0.
    static constexpr float_range power_range{0.0f, 100.0f, true};
    float power = 1.0f;

    // output == power_intensity: out = clamp(mix(1, ao, intensity), 0, 1).
    // 0 = no AO, 1 = full AO, > 1 extrapolates (Unique Engine's example uses 1.5).
    static constexpr float_range intensity_range{0.0f, 100.0f, false};
    float intensity = 1.0f;

    // How an occluding vote is weighted by its depth difference (see ssao_range_check).
    ssao_range_check range_check = ssao_range_check::taos;

    // Kernel distribution, by name, resolved by kernel.hpp (which lists and checks the
    // distributions it knows). Stored as a name so params.hpp does not depend on
    // kernel.hpp. "crytek" (seed 000): points in the unit hemisphere (z >= 0), scaled by
    // 0.1 + 0.9·(i/N)² so samples cluster near the origin. validate() checks only that it
    // is a well-formed name: 1..32 characters of a-z, 0-9 and '_'.
    static constexpr int_range kernel_name_length_range{1, 32};
    std::string kernel = "crytek";

    // Seed of the kernel's random numbers: any value; the same seed gives the same bytes.
    std::uint32_t kernel_seed = 1;

    // Side of the square noise tile of rotation vectors ((cos θ, sin θ, 0, 1)), in pixels;
    // the tile repeats over the screen. Seeds 000 and 004: 4 (a 4×4 tile).
    static constexpr int_range noise_size_range{1, 64};
    int noise_size = 4;

    // Seed of the noise tile's random numbers: any value.
    std::uint32_t noise_seed = 2;

    // AO at half the input resolution (Taos) instead of full (ssao.wgsl).
    bool half_resolution = true;

    // Where the normal comes from. Taos: world-space G-buffer normal.
    normal_source normals = normal_source::gbuffer_world;

    // ssao.wgsl's point-cloud fallback: pixels whose 8 neighbours all share their depth
    // (billboard interiors) get a depth-cavity test instead of hemisphere sampling.
    // Its constants are in aogen::point_cloud below.
    bool point_cloud_fallback = false;
};

// Constants of ssao.wgsl's point-cloud fallback (seed 004), on raw depth-buffer values
// of a standard [0, 1] depth buffer (templates convert them for other conventions).
namespace point_cloud {
// Raw depth at or above this is background (AO 1).
inline constexpr float background_depth = 0.9999f;
// Two raw depths closer than this count as "the same" (billboard interior test).
inline constexpr float same_depth_tolerance = 0.000005f;
// A ring neighbour shallower than the centre by more than this makes the centre a cavity.
inline constexpr float cavity_threshold = 0.0002f;
// Distance in pixels of the 8 ring neighbours of the cavity test.
inline constexpr int ring_pixels = 3;
} // namespace point_cloud

// ---------------------------------------------------------------------------------
// GTAO
// ---------------------------------------------------------------------------------
//
// Ground Truth AO (Jiménez et al. 2016; Taos GTAOPass, seed 001): for each slice through
// the view direction, march `steps` samples to each side tracking the highest horizon,
// clamp the horizons to the hemisphere around the projected normal, integrate the
// cosine-weighted slice analytically, weight by the projected normal's length; average
// over slices and raise to `strength`. Seed 001 has no falloff setting beyond the hard
// thickness cut-off below, so there is none here.
//
// The defaults of thickness_bias and strength, and radius_per_ao_radius, are tuned: the
// values with the lowest mean RMSE against ray-traced AO over eight GTAO variants of the
// default matrix (1x2 to 8x4, bilateral, box and no blur) on the ten built-in scenes with
// normals, found by `aogen_tune --joint` (a narrowing grid, 375 settings) and checked on six
// mesh scenes the search did not see: 37 % lower error on both than seed 001's values
// (BENCHMARKS.md, 2026-12-01). Seed 001's values stay in presets::taos_gtao().
struct gtao_params {
    // World-space sampling radius. Seed 001 default 1.0. To match ambient occlusion of
    // radius R (a ray-traced reference's, or what an artist means by "AO radius"), search
    // radius_per_ao_radius · R: GTAO's cosine-weighted horizons reach farther than their
    // radius suggests (tuned; XeGTAO scales its radius by a multiplier for the same reason).
    static constexpr float_range radius_range{0.0f, max_world_length, true};
    static constexpr float radius_per_ao_radius = 0.78125f;
    float radius = 1.0f;

    // Thickness bias: a sample farther than radius · (1 + thickness_bias · 10) from the
    // surface does not lower the horizon (no haunting from background geometry).
    // Tuned: 0.075, a cut-off at 1.75 · radius (seed 001: 0.1, at 2 · radius).
    static constexpr float_range thickness_bias_range{0.0f, 100.0f, false};
    float thickness_bias = 0.075f;

    // Falloff (XeGTAO's falloff range): the share of that cut-off distance d_max over which
    // a sample's pull on the horizon fades out. A sample at distance d counts with weight
    // w = clamp((d_max − d) / (falloff_range · d_max), 0, 1): its horizon is moved from the
    // unoccluded one (the hemisphere's edge) toward its own by w, so an occluder entering
    // the radius darkens gradually rather than all at once -- no ring where the cut-off
    // passes through a surface. 0 is the hard cut-off of seed 001; 1 fades from P itself.
    static constexpr float_range falloff_range_range{0.0f, 1.0f, false};
    float falloff_range = 0.0f;

    // Thin-occluder compensation: the part of a sample's offset along the view ray counts
    // (1 + thin_occluder) times in the distance that the cut-off and the falloff measure.
    // A thin object (a leg, a pole, a railing) covers the horizon over a long depth range
    // behind it that the heightfield model reads as solid; measuring depth differences as
    // longer makes samples far in front of or behind P stop counting sooner, so less of
    // that false shadow remains. 0: plain Euclidean distance (seed 001).
    static constexpr float_range thin_occluder_range{0.0f, 10.0f, false};
    float thin_occluder = 0.0f;

    // Exponent applied to the averaged visibility: out = visibility^strength; higher
    // means more contrast. Must be > 0 (pow(0, 0) is undefined). Tuned: 1.109 (seed 001:
    // 2.0, which squares the visibility once too often: the fitted power on every scene
    // was about 0.5).
    static constexpr float_range strength_range{0.0f, 100.0f, true};
    float strength = 1.109375f;

    // Slice directions per pixel (rotated per pixel by noise). DESIGN.md default 2.
    static constexpr int_range slices_range{1, 16};
    int slices = 2;

    // Horizon samples per side of each slice. DESIGN.md default 3.
    static constexpr int_range steps_range{1, 16};
    int steps = 3;

    // AO at half the input resolution.
    bool half_resolution = true;

    // Where the normal comes from (projected onto each slice).
    normal_source normals = normal_source::gbuffer_world;
};

// ---------------------------------------------------------------------------------
// VBAO
// ---------------------------------------------------------------------------------
//
// Visibility-bitmask AO (Therrien, Levesque, Gilet 2023, "Screen Space Indirect Lighting
// with Visibility Bitmask"; templates/vbao.glsl): GTAO's slices and steps, but instead of
// one horizon per side each slice keeps a 32-bit mask of occluded sectors, and every sample
// occludes only the sectors between its front surface and that surface pushed `thickness`
// away from the camera. Objects are thus `thickness` deep instead of infinitely deep, so
// what lies behind a thin occluder (under a plank, behind a pole) is not shadowed as
// GTAO's horizons shadow it. The sectors are cosine-weighted, so with a large thickness it
// converges to GTAO's integral on heightfields.
//
// The defaults of radius_per_ao_radius, thickness and strength are tuned as GTAO's: the values
// with the lowest mean RMSE against ray-traced AO over the five VBAO variants of the default
// matrix (the four quality presets at half resolution and High at full, bilateral blur) on
// the ten built-in scenes with normals, found by `aogen_tune --joint` (a narrowing grid, 375
// settings) and checked on six mesh scenes the search did not see: 31 % lower error on the
// training scenes (0.078 -> 0.054) and 7 % on the unseen ones (0.033 -> 0.031) than the
// first choice (GTAO's multiplier, thickness 0.5, strength 1; BENCHMARKS.md, 2026-12-01).
// VBAO wants a longer radius than GTAO (1.16 R against 0.78 R): with finite thickness, a
// far sample occludes a thin wedge instead of the whole horizon below it.
struct vbao_params {
    // World-space sampling radius, as gtao_params::radius: to match AO of radius R, search
    // radius_per_ao_radius · R.
    static constexpr float_range radius_range{0.0f, max_world_length, true};
    static constexpr float radius_per_ao_radius = 1.15625f; // tuned
    float radius = 1.0f;

    // The constant thickness every depth sample is given, as a fraction of `radius`: a sample
    // occludes the directions from P between its front point and that point moved
    // thickness · radius farther from the camera along its view ray. Relative to the radius
    // rather than in world units because the radius already sets the scale of what the AO
    // sees: the same value works for a scene in micrometres and one in kilometres (the report
    // and the stability suite scale every length with the AO radius), and the tuner searches
    // one dimensionless number, as GTAO's thickness_bias. pack_vbao writes the world length
    // (thickness · radius) into the uniform block. Large values (> ~10) make every sample
    // infinitely deep: GTAO's horizons. 0 is excluded: nothing would occlude.
    static constexpr float_range thickness_range{0.0f, 100.0f, true};
    float thickness = 1.634375f; // tuned

    // Exponent applied to the visibility: out = visibility^strength (> 0, as GTAO's). Tuned.
    static constexpr float_range strength_range{0.0f, 100.0f, true};
    float strength = 1.28125f;

    // Slice directions per pixel and samples per side of each, as GTAO's (variant axes).
    static constexpr int_range slices_range{1, 16};
    int slices = 2;
    static constexpr int_range steps_range{1, 16};
    int steps = 3;

    // AO at half the input resolution.
    bool half_resolution = true;

    // Where the normal comes from (projected onto each slice).
    normal_source normals = normal_source::gbuffer_world;
};

// ---------------------------------------------------------------------------------
// Blur
// ---------------------------------------------------------------------------------
struct blur_params {
    // 7-tap separable Gaussian weights of the bilateral blur (seeds 000/002), centre
    // first, then offsets 1, 2, 3 (the same on each side).
    static constexpr int bilateral_radius = 3;
    static constexpr int bilateral_taps = 2 * bilateral_radius + 1;
    static constexpr std::array<float, bilateral_radius + 1> bilateral_weights{
        0.196f, 0.175f, 0.122f, 0.067f};
    // Their sum over all 7 taps: 0.196 + 2·(0.175 + 0.122 + 0.067) = 0.924. The seed's
    // weights do not sum to 1, and the depth term removes some taps anyway, so the blur
    // divides by the weight sum it actually accumulated.
    static constexpr float bilateral_weight_sum =
        0.196f + 2.0f * (0.175f + 0.122f + 0.067f);

    // Side of the box blur's square, in pixels (Taos 'performance': 4×4, unweighted).
    static constexpr int box_size = 4;

    // The denoise filter's 5 × 5 weights are w(x) · w(y) · depth term, with w over offsets
    // −2..2 = (½, 1, 1, 1, ½) (ours): offsets 4 apart share a phase of the 4 × 4 noise tile,
    // so each phase of the tile gets the same weight (1 of 4) along each axis and the
    // tile's pattern averages out exactly on a plane, as under the 4 × 4 box, but centred
    // on the pixel (the box's window is off by half a pixel). Centre first, then offsets 1, 2.
    static constexpr int denoise_radius = 2;
    static constexpr std::array<float, denoise_radius + 1> denoise_weights{1.0f, 1.0f, 0.5f};

    // Which blur runs (see blur_mode). DESIGN.md default: bilateral.
    blur_mode mode = blur_mode::bilateral;

    // The bilateral blur's depth term (see bilateral_depth). DESIGN.md default: linear;
    // the seeds' form is seed_raw.
    bilateral_depth depth = bilateral_depth::linear;

    // depth == seed_raw: weight · exp(−|Δ raw depth| · raw_depth_k). Seed: 1000.
    // 0 turns the depth term off (a plain Gaussian).
    static constexpr float_range raw_depth_k_range{0.0f, 1e6f, false};
    float raw_depth_k = 1000.0f;

    // depth == linear: weight · exp(−|Δz_view| · linear_sharpness), per world unit. The
    // denoise filter and the depth-aware upsample use the same term.
    // 10 (ours): a step of 0.1 world units gets weight e^-1 ≈ 0.37. 0 turns it off.
    // A sharpness is an inverse length, so a scene in micrometres needs one in the
    // millions: 10 per unit scaled to an AO radius of 1e-6 is 1e7. The range reaches 1e12
    // (a radius of 1e-11); the product with |Δz| can only overflow to +inf, whose weight
    // is 0.
    static constexpr float_range linear_sharpness_range{0.0f, 1e12f, false};
    float linear_sharpness = 10.0f;
};

// ---------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------
//
// Each throws aogen::error on the first field outside its range, naming
// "<prefix>.<field>", the value and the valid range or names.

inline void validate(const ssao_params& p, std::string_view prefix = "ssao")
{
    using detail::field;
    using detail::require_in;
    using P = ssao_params;
    require_in(field(prefix, "samples"), p.samples, P::samples_range);
    require_in(field(prefix, "radius"), p.radius, P::radius_range);
    require_in(field(prefix, "bias"), p.bias, P::bias_range);
    names::require_listed(ssao_output_names, p.output, field(prefix, "output"));
    require_in(field(prefix, "strength"), p.strength, P::strength_range);
    require_in(field(prefix, "power"), p.power, P::power_range);
    require_in(field(prefix, "intensity"), p.intensity, P::intensity_range);
    names::require_listed(ssao_range_check_names, p.range_check, field(prefix, "range_check"));

    const auto& len = P::kernel_name_length_range;
    bool well_formed = p.kernel.size() >= static_cast<std::size_t>(len.lo) &&
                       p.kernel.size() <= static_cast<std::size_t>(len.hi);
    for (char c : p.kernel)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) well_formed = false;
    if (!well_formed)
        fail(field(prefix, "kernel"), quote(p.kernel) + " is not a kernel name",
             "valid: " + to_string(P::kernel_name_length_range) +
                 " characters of a-z, 0-9 and _, e.g. crytek");

    require_in(field(prefix, "noise_size"), p.noise_size, P::noise_size_range);
    names::require_listed(normal_source_names, p.normals, field(prefix, "normals"));
}

inline void validate(const gtao_params& p, std::string_view prefix = "gtao")
{
    using detail::field;
    using detail::require_in;
    using P = gtao_params;
    require_in(field(prefix, "radius"), p.radius, P::radius_range);
    require_in(field(prefix, "thickness_bias"), p.thickness_bias, P::thickness_bias_range);
    require_in(field(prefix, "falloff_range"), p.falloff_range, P::falloff_range_range);
    require_in(field(prefix, "thin_occluder"), p.thin_occluder, P::thin_occluder_range);
    require_in(field(prefix, "strength"), p.strength, P::strength_range);
    require_in(field(prefix, "slices"), p.slices, P::slices_range);
    require_in(field(prefix, "steps"), p.steps, P::steps_range);
    names::require_listed(normal_source_names, p.normals, field(prefix, "normals"));
}

inline void validate(const vbao_params& p, std::string_view prefix = "vbao")
{
    using detail::field;
    using detail::require_in;
    using P = vbao_params;
    require_in(field(prefix, "radius"), p.radius, P::radius_range);
    require_in(field(prefix, "thickness"), p.thickness, P::thickness_range);
    require_in(field(prefix, "strength"), p.strength, P::strength_range);
    require_in(field(prefix, "slices"), p.slices, P::slices_range);
    require_in(field(prefix, "steps"), p.steps, P::steps_range);
    names::require_listed(normal_source_names, p.normals, field(prefix, "normals"));
}

inline void validate(const blur_params& p, std::string_view prefix = "blur")
{
    using detail::field;
    using detail::require_in;
    using P = blur_params;
    names::require_listed(blur_mode_names, p.mode, field(prefix, "mode"));
    names::require_listed(bilateral_depth_names, p.depth, field(prefix, "depth"));
    require_in(field(prefix, "raw_depth_k"), p.raw_depth_k, P::raw_depth_k_range);
    require_in(field(prefix, "linear_sharpness"), p.linear_sharpness, P::linear_sharpness_range);
}

// ---------------------------------------------------------------------------------
// Presets
// ---------------------------------------------------------------------------------

// A pass's settings together with the blur that follows it.
struct ssao_preset {
    const char* name;
    ssao_params ssao;
    blur_params blur;
};
struct gtao_preset {
    const char* name;
    gtao_params gtao;
    blur_params blur;
};

inline void validate(const ssao_preset& p)
{
    validate(p.ssao, "ssao");
    validate(p.blur, "blur");
}
inline void validate(const gtao_preset& p)
{
    validate(p.gtao, "gtao");
    validate(p.blur, "blur");
}

namespace presets {

// The seeds' blur: 'quality' bilateral, 7 taps, depth term exp(−|Δ raw depth| · 1000).
inline blur_params taos_quality_blur()
{
    blur_params b;
    b.mode = blur_mode::bilateral;
    b.depth = bilateral_depth::seed_raw;
    b.raw_depth_k = 1000.0f;
    return b;
}

// Taos SSAOPass (seeds 000, 002): 16 crytek samples, 4×4 noise, half resolution,
// world-space G-buffer normals, range check 1 − smoothstep(0, radius, |Δz|), output
// clamp(1 − occlusion/N · strength, 0, 1), then the bilateral 'quality' blur on raw
// depth × 1000. The seeds give no radius, bias or strength: 0.5, 0.025 and 1.0 are ours
// (Unique Engine's radius and bias, and the unscaled average).
inline ssao_preset taos_ssao()
{
    ssao_preset p{"taos_ssao", {}, taos_quality_blur()};
    p.ssao.samples = 16;
    p.ssao.radius = 0.5f;     // ours
    p.ssao.bias = 0.025f;     // ours
    p.ssao.strength = 1.0f;   // ours
    p.ssao.output = ssao_output::strength;
    p.ssao.range_check = ssao_range_check::taos;
    p.ssao.kernel = "crytek";
    p.ssao.noise_size = 4;
    p.ssao.half_resolution = true;
    p.ssao.normals = normal_source::gbuffer_world;
    p.ssao.point_cloud_fallback = false;
    return p;
}

// Taos GTAOPass (seed 001): radius 1.0, thickness bias 0.1, strength exponent 2.0, and
// "the same separable bilateral / box-blur pipelines as SSAO" — the 'quality' blur.
// Slices × steps are not in the seed: 2 × 3 is DESIGN.md's default (ours). Half
// resolution and G-buffer world normals are assumed from Taos' SSAO pass.
inline gtao_preset taos_gtao()
{
    gtao_preset p{"taos_gtao", {}, taos_quality_blur()};
    p.gtao.radius = 1.0f;
    p.gtao.thickness_bias = 0.1f;
    p.gtao.falloff_range = 0.0f;  // seed 001: a hard cut-off
    p.gtao.thin_occluder = 0.0f;   // seed 001: plain distance
    p.gtao.strength = 2.0f;
    p.gtao.slices = 2;  // ours (DESIGN.md default)
    p.gtao.steps = 3;   // ours (DESIGN.md default)
    p.gtao.half_resolution = true;
    p.gtao.normals = normal_source::gbuffer_world;
    return p;
}

// Unique Engine UeSSAOPass (seed 003): radius 0.5, bias 0.025, power 1.0, intensity 1.0,
// 32 hemisphere samples, view-space normals from its normal pre-pass, output
// pow(1 − occlusion/N, power) mixed by intensity, then a bilateral blur "comparing depth
// differences". Not stated by the seed, so ours: the blur's depth term (linear view
// depth, sharpness 10 per world unit), the range check (Taos'), the crytek kernel, the
// 4×4 noise tile and half resolution.
inline ssao_preset unique_engine_ssao()
{
    ssao_preset p{"unique_engine_ssao", {}, {}};
    p.ssao.samples = 32;
    p.ssao.radius = 0.5f;
    p.ssao.bias = 0.025f;
    p.ssao.output = ssao_output::power_intensity;
    p.ssao.power = 1.0f;
    p.ssao.intensity = 1.0f;
    p.ssao.range_check = ssao_range_check::taos;  // ours
    p.ssao.kernel = "crytek";                     // ours
    p.ssao.noise_size = 4;                        // ours
    p.ssao.half_resolution = true;                // ours
    p.ssao.normals = normal_source::gbuffer_view;
    p.blur.mode = blur_mode::bilateral;
    p.blur.depth = bilateral_depth::linear;       // ours
    p.blur.linear_sharpness = 10.0f;              // ours
    return p;
}

// The point-cloud viewer's ssao.wgsl (seed 004): 64 samples, 4×4 noise, range check
// smoothstep(0, 1, radius / |Δz|), ao = 1 − occlusion/64 (the strength form with
// strength 1), full resolution, normals reconstructed from depth, the point-cloud
// fallback on, no blur. Its radius and bias are uniforms without values in the seed:
// 0.5 and 0.025 are ours.
inline ssao_preset pointcloud_viewer_ssao()
{
    ssao_preset p{"pointcloud_viewer_ssao", {}, {}};
    p.ssao.samples = 64;
    p.ssao.radius = 0.5f;   // ours
    p.ssao.bias = 0.025f;   // ours
    p.ssao.output = ssao_output::strength;
    p.ssao.strength = 1.0f;
    p.ssao.range_check = ssao_range_check::seed004;
    p.ssao.kernel = "crytek";  // ours (the seed only says "64 hemisphere samples")
    p.ssao.noise_size = 4;
    p.ssao.half_resolution = false;
    p.ssao.normals = normal_source::reconstructed;
    p.ssao.point_cloud_fallback = true;
    p.blur.mode = blur_mode::none;
    return p;
}

} // namespace presets

} // namespace aogen
