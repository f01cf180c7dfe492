// aogen/params.hpp — the run-time settings of each AO pass, their defaults and ranges.
//
// One plain struct per pass (XeGTAO style): every number an SSAO, GTAO, VBAO, SAO or blur pass
// reads at run time -- what its uniform block and the data it uploads (kernel, noise tile)
// carry -- is a field here, with its default, its valid range and its meaning written next
// to it. The ranges are `static constexpr` members beside the fields (range.hpp), so the
// documentation, `validate()` and the command line all read the same numbers.
//
//   ssao_params   hemisphere SSAO (Taos SSAOPass, Unique Engine UeSSAOPass, ssao.wgsl)
//   gtao_params   ground-truth AO, slice/horizon based (Taos GTAOPass)
//   vbao_params   visibility-bitmask AO: GTAO's slices with a 32-sector mask and a thickness
//   sao_params    scalable ambient obscurance: the Alchemy estimator over spiral taps
//   blur_params   the passes after the AO pass, whichever its technique: the bilateral
//                 blur's and the denoise filter's weights and depth terms, and the
//                 depth-aware upsample's
//   finalize_params  what the chain's last pass does to the AO it writes: the albedo of a
//                 multi-bounce variant (-mb)
//   history_params   the history pass of a -hist or -histmv variant: how much of each new
//                 frame it takes, how it clamps the history, when it rejects it, and the
//                 convention of the renderer's motion vectors
//   ao_settings   all seven: what a chain of any variant reads (chain_inputs.hpp)
//
// What a variant compiles in -- sample, slice and step counts, the blur, where normals
// come from, half resolution, SSAO's output form and range check -- is not here: those
// are the variant's axes (variant.hpp, axes.hpp), stored there only. The seeds' own
// configurations, a variant and its settings each, are presets.hpp's.
//
// Usage:
//
//     #include <aogen/params.hpp>
//
//     aogen::ssao_params p;                  // the defaults
//     p.radius = 0.8f;                       // tune a field
//     aogen::validate(p);  // throws aogen::error, e.g.
//                          // "ssao.radius: nan is not a finite number (valid: > 0 and <= 1e+15)"
//
//     aogen::ssao_params::radius_range;                    // {0, 1e15, lower bound excluded}
//     aogen::to_string(aogen::ssao_params::radius_range);  // "> 0 and <= 1e+15"
//
// Nothing here touches a GPU: these are the numbers that kernel.hpp, noise.hpp,
// uniforms.hpp and the shader templates consume. Fields are float because that is what
// reaches the shader; validation rejects NaN, infinities and out-of-range values. Errors
// follow error.hpp: "<struct>.<field>: <value> <problem> (valid: <range>)".
//
// Numbers the seeds state are used exactly. Numbers the seeds leave open are marked
// "(ours)" where they are chosen.
#pragma once

#include "error.hpp"
#include "names.hpp"
#include "range.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace aogen {

// The largest world length a setting may hold (a radius, a bias). Not a limit of taste but
// of float arithmetic: every radius is capped at the screen's extent at the pixel's depth
// before it is used (ssao.glsl's ao_ssao_radius, common/slices.glsl's ao_slice_radius), so
// what must stay finite is the one length that is not capped, VBAO's thickness (up to 100 ×
// its radius, params below), and its square: (100 · 1e15)² = 1e34 < FLT_MAX ≈ 3.4e38.
inline constexpr float max_world_length = 1e15f;

namespace detail {

inline std::string field(std::string_view prefix, std::string_view name)
{
    std::string s(prefix);
    if (!s.empty()) s += '.';
    s.append(name);
    return s;
}

} // namespace detail

// One float setting of a params struct: its name (as error messages, JSON and the TypeScript
// module spell it), the field and its range. Each struct's table (ssao_float_settings, ...,
// after the struct) lists its float settings in the order validate() checks them: validate()
// walks the table, and `aogen generate --targets ts` declares the TypeScript settings from it
// (name, default, range), so the two cannot disagree.
template <class P>
struct float_setting {
    const char* name;
    float P::*field;
    float_range range;
};

namespace detail {

// require_in for each of `table`'s settings of `p`, in the table's order.
template <class P, std::size_t N>
void require_settings(const P& p, const std::array<float_setting<P>, N>& table, std::string_view prefix)
{
    for (const float_setting<P>& s : table) require_in(field(prefix, s.name), p.*s.field, s.range);
}

} // namespace detail

// ---------------------------------------------------------------------------------
// SSAO
// ---------------------------------------------------------------------------------
//
// Crytek-style view-space hemisphere SSAO (seeds 000, 002, 003, 004): per pixel, N kernel
// samples in the normal-oriented hemisphere (rotated by a tiled noise vector) are
// projected to the screen; a sample is occluded when the scene surface there is closer
// to the camera than the sample by more than `bias`. Each vote is weighted by the range
// check, summed to `occlusion`, and turned into the output. N, the range check and the
// output form are the variant's (variant::samples, range_check, output).
//
// The defaults of strength and radius_per_ao_radius are tuned: the values with the lowest
// mean RMSE against ray-traced AO over eight SSAO variants of the default matrix (8 to 64
// samples, half and full resolution, bilateral, box and no blur) on the ten built-in scenes
// with normals, found by `aogen_tune --joint` (a narrowing grid, 75 settings) and checked on
// six mesh scenes the search did not see: 42 % lower error on the training scenes (0.104 ->
// 0.060) and 16 % on the unseen ones (0.039 -> 0.032) than the seeds' radius R and strength
// 1 (BENCHMARKS.md, 2026-12-01 and 2026-12-05: the search re-run with the smooth decisions
// lands on the same values). They hold on every depth convention because every
// per-sample decision is a smooth weight (ssao_bands below): a strength of 3.3 multiplies
// each vote, and with the seeds' steps one vote flipping at the bias moved a pixel by 0.2.
// The seeds' values stay in presets::taos_ssao() and the other SSAO presets.
struct ssao_params {
    // Hemisphere radius in view-space units; also the range check's scale.
    // 0.5 is Unique Engine's default (and ours for Taos SSAO and ssao.wgsl). To match
    // ambient occlusion of radius R (a ray-traced reference's), use radius_per_ao_radius · R
    // (and keep the bias at the same share of it): the Crytek kernel gathers its samples
    // near the origin (0.1 + 0.9·(i/N)² of the radius), so a hemisphere of radius R sees
    // mostly the first half of it (tuned).
    static constexpr float_range radius_range{0.0f, max_world_length, true};
    static constexpr float radius_per_ao_radius = 2.03125f;
    float radius = 0.5f;

    // Depth-comparison bias in view-space units: occluded when
    // scene_z > sample_z + bias (toward the camera). Avoids self-occlusion ("acne").
    static constexpr float_range bias_range{0.0f, max_world_length, false};
    float bias = 0.025f;

    // The variant's output ssao_output::strength: out = clamp(1 − occlusion/N · strength, 0, 1).
    // 0 = no AO, 1 = the plain average (the seeds'), > 1 darkens (saturates sooner). Tuned:
    // 3.3125 with the radius above (the seeds' 1 reads a sixth of the true occlusion on the
    // closed-form scenes: votes are counted over a volume, true AO over directions).
    static constexpr float_range strength_range{0.0f, 100.0f, false};
    float strength = 3.3125f;

    // Output ssao_output::power_intensity: ao = pow(1 − occlusion/N, power). Must be > 0 (GLSL's
    // pow(0, y) is undefined for y <= 0). Unique Engine default 1.0.
    static constexpr float_range power_range{0.0f, 100.0f, true};
    float power = 1.0f;

    // Output ssao_output::power_intensity: out = clamp(mix(1, ao, intensity), 0, 1).
    // 0 = no AO, 1 = full AO, > 1 extrapolates (Unique Engine's example uses 1.5).
    static constexpr float_range intensity_range{0.0f, 100.0f, false};
    float intensity = 1.0f;

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
};

// ssao_params's float settings, in validate()'s order (float_setting).
inline constexpr std::array<float_setting<ssao_params>, 5> ssao_float_settings{{
    {"radius", &ssao_params::radius, ssao_params::radius_range},
    {"bias", &ssao_params::bias, ssao_params::bias_range},
    {"strength", &ssao_params::strength, ssao_params::strength_range},
    {"power", &ssao_params::power, ssao_params::power_range},
    {"intensity", &ssao_params::intensity, ssao_params::intensity_range},
}};

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

// The bands over which SSAO's smooth decisions (variant::decisions, ssao_decisions::smooth;
// templates/ssao.glsl) hand over from one outcome to the other where the seeds step: each
// is centred on the seeds' threshold (so the votes add up as the steps' do) and as narrow as
// keeps the weight's slope harmless -- a
// depth one rounding step off moves the weight by that step over the band, under 1/255
// (tests/compiler/test_ssao_decisions.cpp) -- and wide enough that the depth conventions'
// rounding (reversed against standard depth: up to 1e-3 of the radius on distant surfaces)
// falls well inside it.
namespace ssao_bands {
// The vote rises from 0 to 1 over this share of the radius (at most the bias), centred where
// the scene's z is the sample's plus the bias.
inline constexpr float vote_per_radius = 0.05f;
// A sample counts from 0 at its pixel's own texel's edge (half a pixel from the pixel's
// centre, in the larger of x and y) to fully this many pixels past it: a sample in its own
// texel compares the surface with itself and can measure only depth quantization. Narrow:
// the Crytek kernel gathers its samples near the pixel, and every sample in the band counts
// less than the seeds' step counts it (half a pixel read the plank's and the sphere's
// contact occlusion a fifth lighter than the steps; an eighth reads the plank 10 % lighter,
// the other closed-form scenes within 2 %).
inline constexpr float self_pixels = 0.125f;
// A sample is judged from 0 at the screen's border to fully this many pixels inside it.
inline constexpr float edge_pixels = 1.0f;
// The plane reading (the bilinear depth under the sample) hands over to the texel reading
// (its texel's own depth at its centre) as the four texels around the sample go off one
// plane: over this share of their spread past depth.glsl's silhouette threshold (a quarter
// of the spread).
inline constexpr float plane_per_spread = 0.2f;
// The point-cloud fallback's tests (point_cloud above). A neighbour is at the same depth
// within the tolerance, and not from 1 + this many tolerances on: the tolerance, 5e-6, is only
// 84 ulps of a depth near 1, so a narrower band would step by more than 1/255 per ulp.
inline constexpr float point_cloud_same_per_tolerance = 4.0f;
// A ring neighbour is a cavity's rim from the threshold on, fully from 1 + this many
// thresholds.
inline constexpr float point_cloud_cavity_per_threshold = 1.0f;
} // namespace ssao_bands

// How far from its pixel a slice tap (GTAO, VBAO) may read the texel under it at the texel's
// centre instead of the plane's depth under the tap itself (common/slices.glsl's
// ao_slice_tap_surface). The texel's centre is a true surface point, up to 0.71 pixels off the
// slice's line, so the direction to it is off the slice's plane by at most 0.71 / distance
// radians: 2.5 degrees at 16 pixels, where an open plane's horizon moves by second order (the
// slice integral is flat at the hemisphere's edge) -- below 1/255. Nearer taps keep the exact
// bilinear reading (issue 11). On the H200 at 1080p, reading every tap at its texel's centre
// took a quarter off the AO pass at the same error (BENCHMARKS.md, 2026-12-03).
namespace slice_taps {
inline constexpr float texel_centre_pixels = 16.0f;
} // namespace slice_taps

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
};

// gtao_params's float settings, in validate()'s order (float_setting).
inline constexpr std::array<float_setting<gtao_params>, 5> gtao_float_settings{{
    {"radius", &gtao_params::radius, gtao_params::radius_range},
    {"thickness_bias", &gtao_params::thickness_bias, gtao_params::thickness_bias_range},
    {"falloff_range", &gtao_params::falloff_range, gtao_params::falloff_range_range},
    {"thin_occluder", &gtao_params::thin_occluder, gtao_params::thin_occluder_range},
    {"strength", &gtao_params::strength, gtao_params::strength_range},
}};

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
};

// vbao_params's float settings, in validate()'s order (float_setting).
inline constexpr std::array<float_setting<vbao_params>, 3> vbao_float_settings{{
    {"radius", &vbao_params::radius, vbao_params::radius_range},
    {"thickness", &vbao_params::thickness, vbao_params::thickness_range},
    {"strength", &vbao_params::strength, vbao_params::strength_range},
}};

// ---------------------------------------------------------------------------------
// SAO
// ---------------------------------------------------------------------------------
//
// Scalable ambient obscurance (McGuire, Mara, Luebke, HPG 2012; templates/sao.glsl): the
// Alchemy estimator (McGuire et al., HPG 2011) over N taps on a spiral in screen space
// (spiral.hpp), each reading the depth buffer -- or a level of the depth MIP chain, far taps a
// coarser one (variant::depth_mips) -- for the surface point Q there. With v = (Q − P) / radius
// (P the pixel's view-space position, n its normal) each tap adds
//     f(v) · max(0, v·n − bias) / (v·v + epsilon),   f(v) = max(0, 1 − v·v)³,
// and out = clamp(1 − 2 · intensity · sum / N, 0, 1)^contrast. Every length is a share of the
// radius -- the paper's sum has units of an inverse length and a bias in world units, ours is
// dimensionless -- so the same settings serve a scene in micrometres and one in kilometres.
// Nothing in it steps: the bias is a ramp, f falls to 0 at the radius, a tap off screen or on
// background fades over a pixel as SSAO's smooth decisions do.
//
// The defaults of radius_per_ao_radius, bias and intensity are tuned as GTAO's: the values with
// the lowest mean RMSE against ray-traced AO over eight SAO variants of the default matrix (8
// to 32 taps, half and full resolution, bilateral and denoise) on the ten built-in scenes with
// normals, found by `aogen_tune --joint` (a narrowing grid, 375 settings) and checked on six
// mesh scenes the search did not see: 22 % lower error on the training scenes (0.078 ->
// 0.061) and 21 % on the unseen ones (0.037 -> 0.029) than the first choice (radius R, the
// paper's intensity 1, bias 0.02; BENCHMARKS.md, 2026-12-05).
struct sao_params {
    // World-space radius of the disc the taps cover (the view-plane disc through P,
    // projected). To match ambient occlusion of radius R, use radius_per_ao_radius · R.
    static constexpr float_range radius_range{0.0f, max_world_length, true};
    // Tuned: 2.69 R -- the cubic falloff weighs a tap at half the radius by 0.42 and one at
    // 0.8 of it by 0.05, so the disc must reach well past the AO radius to see it.
    static constexpr float radius_per_ao_radius = 2.6875f;
    float radius = 1.0f;

    // The share of the radius a tap must rise above P's tangent plane (v·n) before it
    // occludes: depth quantization and tessellation make flat surfaces slightly concave. The
    // paper's bias is a depth-proportional length; ours the radius's share. Tuned: 0.05.
    static constexpr float_range bias_range{0.0f, 1.0f, false};
    float bias = 0.05f;

    // The paper's sigma: how strongly the sum darkens. Tuned: 1.22 (the paper's default 1).
    static constexpr float_range intensity_range{0.0f, 100.0f, false};
    float intensity = 1.21875f;

    // The paper's k: the visibility raised to it (> 0; 1 leaves it linear).
    static constexpr float_range contrast_range{0.0f, 100.0f, true};
    float contrast = 1.0f;

    // The paper's epsilon, as a share of the radius squared: keeps a tap at P itself finite.
    // The paper's 0.01 (world units squared at a radius of about 1).
    static constexpr float epsilon = 0.01f;
};

// sao_params's float settings, in validate()'s order (float_setting).
inline constexpr std::array<float_setting<sao_params>, 4> sao_float_settings{{
    {"radius", &sao_params::radius, sao_params::radius_range},
    {"bias", &sao_params::bias, sao_params::bias_range},
    {"intensity", &sao_params::intensity, sao_params::intensity_range},
    {"contrast", &sao_params::contrast, sao_params::contrast_range},
}};

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

    // The 3 × 3 denoise (blur_denoise3.glsl): weights w(x) · w(y) · edges, w over offsets
    // −1..1 = (½, 1, ½) (ours): a 3-tap filter cannot give the 4 × 4 tile's four phases one
    // weight each, as the 5 × 5's does; (½, 1, ½) removes its period-2 pattern entirely and
    // halves its period-4 one; beside a = 1 its RMSE is lower on GTAO and SAO, higher on
    // SSAO, 0.2 % lower over the five pairs of the default report (BENCHMARKS.md). Centre
    // first, then offset 1.
    static constexpr std::array<float, 2> denoise3_weights{1.0f, 0.5f};

    // The 3 × 3 denoise's edge between neighbouring target pixels a and b, written by the AO
    // pass (common/edges.glsl): exp(−denoise3_edge_sharpness · |z(a) − z(b)| / min(|z(a)|, |z(b)|)),
    // z the view depth. Relative, not per world unit like linear_sharpness: the AO pass has
    // no blur settings in its uniforms, and a relative step is what a depth buffer resolves
    // -- the same edges at every scale of scene. 16 (ours): neighbours 1 % apart in depth
    // weigh e^-0.16 ≈ 0.85, 10 % apart e^-1.6 ≈ 0.20, 50 % (a silhouette) e^-8 ≈ 0.0003. The
    // default report's RMSE, 3×3 over 5×5 on the same AO, geometric mean of its five pairs:
    // 0.992 at 16, 0.994 at 32, 1.003 at 64 (2026-12-07, BENCHMARKS.md).
    static constexpr float denoise3_edge_sharpness = 16.0f;

    // The variant's blur_depth bilateral_depth::seed_raw: weight · exp(−|Δ raw depth| · raw_depth_k). Seed: 1000.
    // 0 turns the depth term off (a plain Gaussian).
    static constexpr float_range raw_depth_k_range{0.0f, 1e6f, false};
    float raw_depth_k = 1000.0f;

    // blur_depth bilateral_depth::linear: weight · exp(−|Δz_view| · linear_sharpness), per world unit. The
    // denoise filter and the depth-aware upsample use the same term.
    // 10 (ours): a step of 0.1 world units gets weight e^-1 ≈ 0.37. 0 turns it off.
    // A sharpness is an inverse length, so a scene in micrometres needs one in the
    // millions: 10 per unit scaled to an AO radius of 1e-6 is 1e7. The range reaches 1e12
    // (a radius of 1e-11); the product with |Δz| can only overflow to +inf, whose weight
    // is 0.
    static constexpr float_range linear_sharpness_range{0.0f, 1e12f, false};
    float linear_sharpness = 10.0f;
};

// blur_params's float settings, in validate()'s order (float_setting).
inline constexpr std::array<float_setting<blur_params>, 2> blur_float_settings{{
    {"raw_depth_k", &blur_params::raw_depth_k, blur_params::raw_depth_k_range},
    {"linear_sharpness", &blur_params::linear_sharpness, blur_params::linear_sharpness_range},
}};

// ---------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------
//
// Each throws aogen::error on the first field outside its range, naming
// "<prefix>.<field>", the value and the valid range or names.

inline void validate(const ssao_params& p, std::string_view prefix = "ssao")
{
    using detail::field;
    using P = ssao_params;
    detail::require_settings(p, ssao_float_settings, prefix);

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
}

inline void validate(const gtao_params& p, std::string_view prefix = "gtao")
{
    detail::require_settings(p, gtao_float_settings, prefix);
}

inline void validate(const vbao_params& p, std::string_view prefix = "vbao")
{
    detail::require_settings(p, vbao_float_settings, prefix);
}

inline void validate(const sao_params& p, std::string_view prefix = "sao")
{
    detail::require_settings(p, sao_float_settings, prefix);
}

inline void validate(const blur_params& p, std::string_view prefix = "blur")
{
    detail::require_settings(p, blur_float_settings, prefix);
}

// ---------------------------------------------------------------------------------
// Finalize: what the chain's last pass does to the AO it writes
// ---------------------------------------------------------------------------------
struct finalize_params {
    // Multi-bounce (a -mb variant: variant::multi_bounce): the albedo rho of the surfaces
    // around the pixel, whose inter-reflections brighten the visibility v by the GTAO
    // paper's fit (Jimenez et al. 2016, eq. 10; common/core.glsl's ao_multi_bounce):
    //     out = max(v, ((v a + b) v + c) v),  a = 2.0404 rho - 0.3324,
    //     b = -4.7951 rho + 0.6417,  c = 2.7552 rho + 0.6903.
    // One albedo for the whole image (a renderer with an albedo G-buffer would read it per
    // pixel); 0 leaves v as it is, 1 is a white room. Default 0.5 (ours): a mid-grey world.
    static constexpr float_range albedo_range{0.0f, 1.0f, false};
    float albedo = 0.5f;
};

// finalize_params's float settings, in validate()'s order (float_setting).
inline constexpr std::array<float_setting<finalize_params>, 1> finalize_float_settings{{
    {"albedo", &finalize_params::albedo, finalize_params::albedo_range},
}};

inline void validate(const finalize_params& p, std::string_view prefix = "finalize")
{
    detail::require_settings(p, finalize_float_settings, prefix);
}

// ---------------------------------------------------------------------------------
// History: the history pass of a -hist or -histmv variant (history.glsl)
// ---------------------------------------------------------------------------------

// How the history is held to this frame's neighbourhood of filtered AO (the 3 x 3 AO target
// pixels around the pixel) before it is blended, so that what the depth test lets through
// -- a surface whose light changed, a thin occluder moving over it -- cannot linger.
enum class history_clamp {
    none,     // no clamp: the depth test alone rejects
    range,    // to the pixel's own AO +- range (UE5's GTAO temporal filter: +-0.1)
    min_max,  // to the neighbourhood's [min, max], widened by min_max_widening (HDRP's GTAO, three.js)
    variance, // to mean +- variance_gamma standard deviations of the neighbourhood (Salvi 2016's variance clipping)
};
inline constexpr std::array<enum_name<history_clamp>, 4> history_clamp_names{{
    {history_clamp::none, "none"},
    {history_clamp::range, "range"},
    {history_clamp::min_max, "min_max"},
    {history_clamp::variance, "variance"},
}};

// The unit of a motion vector's two components.
enum class motion_units {
    uv,     // a share of the screen's width and height (Unity, Godot)
    ndc,    // normalised device coordinates, [-1, 1] across the screen: twice uv (UE5, three.js)
    pixels, // screen pixels
};
inline constexpr std::array<enum_name<motion_units>, 3> motion_units_names{{
    {motion_units::uv, "uv"},
    {motion_units::ndc, "ndc"},
    {motion_units::pixels, "pixels"},
}};

// Which way a motion vector points.
enum class motion_direction {
    previous_to_current, // current position - previous position (UE5, Unity, three.js)
    current_to_previous, // previous position - current position (where to read the history)
};
inline constexpr std::array<enum_name<motion_direction>, 2> motion_direction_names{{
    {motion_direction::previous_to_current, "previous_to_current"},
    {motion_direction::current_to_previous, "current_to_previous"},
}};

// Which way a motion vector's y grows on the screen.
enum class motion_y {
    up,   // y grows up the screen, as NDC's does (UE5, three.js, Unity's uv)
    down, // y grows down, as pixel rows and Vulkan's, D3D's and WebGPU's uv do
};
inline constexpr std::array<enum_name<motion_y>, 2> motion_y_names{{
    {motion_y::up, "up"},
    {motion_y::down, "down"},
}};

// The renderer's motion vectors as a -histmv variant reads them (bindings.hpp's motion role:
// .rg of a full-resolution texture, per screen pixel). The default is the convention UE5 and
// three.js write: NDC units, current minus previous, y up.
struct motion_convention {
    motion_units units = motion_units::ndc;
    motion_direction direction = motion_direction::previous_to_current;
    motion_y y = motion_y::up;
};

struct history_params {
    // This frame's weight in the output once the history is long: out = mix(history, this
    // frame, w) with w = max(blend, 1 / (n + 1)) for a history of n frames. So the first frames
    // after a reset or a disocclusion are averaged evenly -- a still camera's n-th output is
    // the plain mean of its n frames, the mean the report's accumulated figure scores -- and
    // from n = 1 / blend - 1 on, each frame's share decays by (1 - blend) per frame: an
    // exponential window of about 2 / blend - 1 frames. 1 keeps no history.
    // Default 0.1 (UE5's AmbientOcclusionTemporalBlendWeight, three.js's alpha; HDRP's
    // feedback 0.85..0.95 is 0.05..0.15 here), chosen in motion (aogen_history_sweep,
    // BENCHMARKS.md § 2026-12-07 (session 8)) over 0.05 and 0.2 for four chains with the pass
    // (gtao-1x4- and 2x2-half, -noblur and -denoise): 0.2 has an error in motion 0.9-1.7 %
    // lower for each, 0.1 a flicker 2-12 % lower -- within the 0.25x of the twin's that
    // gtao-1x4-half-noblur-histmv reaches only at 0.1 (0.23x; 0.26x at 0.2). 0.05 acts as
    // 0.1 over the report's 12 frames (w = 1 / (n + 1) stays above it).
    static constexpr float_range blend_range{0.01f, 1.0f, false};
    float blend = 0.1f;

    // The clamp (history_clamp), and its width for each kind; only the clamp's own is read.
    // Default: min_max widened by 0.05 (HDRP's box; its widening by motion left out), chosen
    // by the mean error in motion of the four chains above against no clamp, ranges of 0.05,
    // 0.1 and 0.2 (UE5's kind), the plain box and variance clipping at gamma 1, 1.5 and 2. A range
    // clamp suits a spatially filtered AO only: about a noisy pixel's own value it holds the
    // history to that pixel's noise (gtao-1x4-half-noblur-histmv: range 0.2 0.0735, min_max
    // 0.0589).
    history_clamp clamp = history_clamp::min_max;
    // range: the history stays within this of the pixel's AO. UE5: 0.1; 0.2 (ours: the lowest error of the three ranges).
    static constexpr float_range range_range{0.0f, 1.0f, false};
    float range = 0.2f;
    // min_max: added to both ends of the neighbourhood's [min, max]. HDRP widens by motion; 0.05 (ours).
    static constexpr float_range min_max_widening_range{0.0f, 1.0f, false};
    float min_max_widening = 0.05f;
    // variance: gamma, in standard deviations. Salvi's 1..1.25; 1 (ours).
    static constexpr float_range variance_gamma_range{0.0f, 16.0f, false};
    float variance_gamma = 1.0f;

    // Disocclusion: a history texel is another surface's, and is not used, when the view
    // depth it holds differs from the depth this pixel's point had in the previous frame by
    // more than this share of it. The test reads the history's 2 x 2 texels about the point,
    // each up to a texel from it, so a plane seen at a grazing angle needs room for its depth's
    // change over a texel. 0.05 (ours). Range (0, 1].
    static constexpr float_range depth_tolerance_range{0.0f, 1.0f, true};
    float depth_tolerance = 0.05f;

    // How the renderer's motion vectors are written (a -histmv variant's).
    motion_convention motion;
};

// history_params's float settings, in validate()'s order (float_setting).
inline constexpr std::array<float_setting<history_params>, 5> history_float_settings{{
    {"blend", &history_params::blend, history_params::blend_range},
    {"range", &history_params::range, history_params::range_range},
    {"min_max_widening", &history_params::min_max_widening, history_params::min_max_widening_range},
    {"variance_gamma", &history_params::variance_gamma, history_params::variance_gamma_range},
    {"depth_tolerance", &history_params::depth_tolerance, history_params::depth_tolerance_range},
}};

inline void validate(const history_params& p, std::string_view prefix = "history")
{
    using detail::field;
    detail::require_settings(p, history_float_settings, prefix);
    names::require_listed(history_clamp_names, p.clamp, field(prefix, "clamp"));
    names::require_listed(motion_units_names, p.motion.units, field(prefix, "motion.units"));
    names::require_listed(motion_direction_names, p.motion.direction, field(prefix, "motion.direction"));
    names::require_listed(motion_y_names, p.motion.y, field(prefix, "motion.y"));
}

// ---------------------------------------------------------------------------------
// All passes
// ---------------------------------------------------------------------------------

// The run-time settings of every pass a chain may run: a variant reads the ones of its
// technique and blur (chain_inputs.hpp packs them), so one value serves any variant.
struct ao_settings {
    ssao_params ssao;
    gtao_params gtao;
    vbao_params vbao;
    sao_params sao;
    blur_params blur;
    finalize_params finalize;
    history_params history;
};

inline void validate(const ao_settings& s)
{
    validate(s.ssao, "ssao");
    validate(s.gtao, "gtao");
    validate(s.vbao, "vbao");
    validate(s.sao, "sao");
    validate(s.blur, "blur");
    validate(s.finalize, "finalize");
    validate(s.history, "history");
}

} // namespace aogen
