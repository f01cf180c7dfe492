// aogen/axes.hpp — the choices a variant fixes at compile time, as enums with their names.
//
// WHAT
//   One enum per choice axis of a variant (variant.hpp), each with its table of canonical
//   names (lower case, '_' between words) read by to_name(), the *_from_name() readers, the
//   command line and JSON through names.hpp; the readers also accept '-' for '_'
//   ("gbuffer-world", as docs/design.md § Variant axes spells the axis values):
//
//     technique          ssao, gtao, vbao, sao; has_slices(t): GTAO and VBAO count slices ×
//                        steps; has_samples(t): SSAO and SAO count samples
//     pipeline_stage     compute or fragment; stage_of(s): the shader stage it compiles to
//     projection_kind    perspective or orthographic
//     depth_convention   standard, reversed, reversed_infinite (declared in math.hpp, whose
//                        projections take it; its names are here)
//     normal_source      G-buffer world or view normals, or reconstructed from depth
//     ssao_output        how SSAO turns its occlusion sum into AO
//     ssao_range_check   how SSAO weights an occluding sample by its depth difference
//     ssao_decisions     whether SSAO's per-sample decisions are smooth weights or steps
//     blur_mode          the denoise pass: bilateral, box, denoise, denoise3 or none
//     bilateral_depth    the bilateral blur's depth term
//     upsample_mode      how a half-resolution target reaches the screen
//     multi_bounce_mode  whether, and with which albedo, the last pass adds multi-bounce light
//
// USAGE
//     #include <aogen/axes.hpp>
//     aogen::to_name(aogen::blur_mode::box);                  // "box"
//     aogen::blur_mode_from_name("gaussian", "--blur");
//     // throws "--blur: 'gaussian' is not a known name (valid: bilateral, box, none, denoise, denoise3)"
//
// WHY
//   A choice a variant makes is compiled into its shaders (a #define), so it lives on the
//   variant only; the run-time settings of each pass (params.hpp) do not repeat it. Both
//   the variant and the code that reads a variant's settings name these enums, so they sit
//   here, below both, needing only names.hpp.
#pragma once

#include "math.hpp"
#include "names.hpp"
#include "stages.hpp"

#include <array>
#include <cstddef>
#include <string_view>

namespace aogen {

enum class technique { ssao, gtao, vbao, sao };
inline constexpr std::array<enum_name<technique>, 4> technique_names{{
    {technique::ssao, "ssao"},
    {technique::gtao, "gtao"},
    {technique::vbao, "vbao"}, // visibility bitmask (Therrien et al. 2023)
    {technique::sao, "sao"},   // scalable ambient obscurance (McGuire, Mara, Luebke 2012)
}};

// What a technique counts per pixel: kernel samples or spiral taps (SSAO, SAO: the variant's
// `samples`, name token s<N> -- the SSAO family, two estimators of the same screen-space
// obscurance) or slices and steps per side (GTAO's horizons, VBAO's bitmasks: `slices` and
// `steps`, token <S>x<N>, quality.hpp's presets). One row per technique, in technique_names'
// order: a technique without its row does not compile. The rest of what a technique is lives
// in its row of techniques.hpp's table, above the variant.
enum class count_kind { samples, slices_and_steps };
struct technique_counts_row {
    technique value;
    count_kind counts;
    const char* unit; // what one count is called: "samples", "taps", "slices" (then steps)
};
inline constexpr std::array<technique_counts_row, technique_names.size()> technique_counts{{
    {technique::ssao, count_kind::samples, "samples"},
    {technique::gtao, count_kind::slices_and_steps, "slices"},
    {technique::vbao, count_kind::slices_and_steps, "slices"},
    {technique::sao, count_kind::samples, "taps"},
}};
namespace detail {
constexpr bool technique_counts_complete()
{
    for (size_t i = 0; i < technique_counts.size(); ++i)
        if (technique_counts[i].value != technique_names[i].value) return false;
    return true;
}
} // namespace detail
static_assert(detail::technique_counts_complete(), "technique_counts: one row per technique, in technique_names' order");

// Whether technique `t` counts slices and steps per side, or samples (false for a value
// outside the enumeration: validate() names it).
inline constexpr bool has_slices(technique t)
{
    return size_t(t) < technique_counts.size() && technique_counts[size_t(t)].counts == count_kind::slices_and_steps;
}
inline constexpr bool has_samples(technique t)
{
    return size_t(t) < technique_counts.size() && technique_counts[size_t(t)].counts == count_kind::samples;
}

enum class pipeline_stage { compute, fragment };
inline constexpr std::array<enum_name<pipeline_stage>, 2> pipeline_stage_names{{
    {pipeline_stage::compute, "compute"},
    {pipeline_stage::fragment, "fragment"},
}};

// The shader stage of a variant's AO pass (its fragment passes also need a vertex shader).
inline shader_stage stage_of(pipeline_stage s)
{
    switch (s) {
    case pipeline_stage::compute: return shader_stage::compute;
    case pipeline_stage::fragment: return shader_stage::fragment;
    }
    names::fail_unlisted(pipeline_stage_names, s, "stage");
}

enum class projection_kind { perspective, orthographic };
inline constexpr std::array<enum_name<projection_kind>, 2> projection_kind_names{{
    {projection_kind::perspective, "perspective"},
    {projection_kind::orthographic, "orthographic"},
}};

inline constexpr std::array<enum_name<depth_convention>, 3> depth_convention_names{{
    {depth_convention::standard, "standard"},
    {depth_convention::reversed, "reversed"},
    {depth_convention::reversed_infinite, "reversed_infinite"},
}};

// Where a pass gets its surface normal from (docs/design.md § Variant axes).
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

// How an SSAO pass turns the occlusion sum into its output (the numbers each form reads,
// strength or power and intensity, are ssao_params').
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

// How much one occluding SSAO sample counts, from the view-space depth difference
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

// How SSAO decides, per sample, whether the sample is occluded, judged at all, or read from
// the plane or the texel under it (templates/ssao.glsl; the bands are params.hpp's
// ssao_bands).
enum class ssao_decisions {
    // Ours, the default: every decision a weight that moves continuously with its input over
    // a narrow band -- the vote past the bias, the own-texel skip, the screen's border, the
    // plane-or-texel reading at silhouettes, the point-cloud billboard test. A depth that
    // rounds differently (another depth convention, another GPU) then moves a pixel by
    // about as much as it moved the depth, never by a whole vote times the strength.
    smooth,
    // The seeds' steps: a sample is occluded or not (scene z > sample z + bias), judged or
    // not, read from the plane or from its texel. What the seeds' presets compile.
    step,
};
inline constexpr std::array<enum_name<ssao_decisions>, 2> ssao_decisions_names{{
    {ssao_decisions::smooth, "smooth"},
    {ssao_decisions::step, "step"},
}};

// The denoise pass after the AO pass.
enum class blur_mode {
    bilateral,  // Taos 'quality': two-pass separable 7-tap Gaussian with a depth term
    box,        // Taos 'performance': single-pass 4×4 unweighted box average
    none,       // raw AO (ssao.wgsl has no blur)
    denoise,    // ours: single-pass 5×5 edge-aware filter (blur_denoise.glsl), one pass
                // instead of the bilateral's two, for XeGTAO's denoiser's cost
    denoise3,   // ours: single-pass 3×3 filter of XeGTAO's kernel size (blur_denoise3.glsl) whose
                // edges the AO pass writes beside the AO (common/edges.glsl): it reads no depth.
                // Compute stage, no bent normals (the edges take the channels the normal would)
};
inline constexpr std::array<enum_name<blur_mode>, 5> blur_mode_names{{
    {blur_mode::bilateral, "bilateral"},
    {blur_mode::box, "box"},
    {blur_mode::none, "none"},
    {blur_mode::denoise, "denoise"},
    {blur_mode::denoise3, "denoise3"},
}};

// The depth term of the bilateral blur, which stops AO bleeding across silhouettes (its
// constants, raw_depth_k and linear_sharpness, are blur_params').
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

// Multi-bounce (the GTAO paper's fit, common/core.glsl's ao_multi_bounce): whether the
// chain's last pass brightens the AO it writes by the light inter-reflected between surfaces
// of albedo rho, and where rho comes from.
enum class multi_bounce_mode {
    off,
    // One albedo for the whole image: finalize_params::albedo, a uniform (-mb).
    uniform_albedo,
    // Each pixel's own, from the renderer's albedo G-buffer (-mbg; bindings.hpp's gbuffer_albedo
    // role): for an engine with materials, whose dark and bright surfaces bounce apart.
    gbuffer_albedo,
};
// The spec's spellings (JSON's `multi_bounce`): "on" is the uniform albedo, as it was when
// multi-bounce had no other source.
inline constexpr std::array<enum_name<multi_bounce_mode>, 3> multi_bounce_mode_names{{
    {multi_bounce_mode::off, "off"},
    {multi_bounce_mode::uniform_albedo, "on"},
    {multi_bounce_mode::gbuffer_albedo, "gbuffer"},
}};

// The history pass (history.glsl; docs/design.md § The history pass): whether the chain
// keeps the AO of earlier frames -- the temporal filter UE5's, HDRP's and three.js's GTAO run
// after their spatial one -- and how it finds where a pixel was a frame ago.
enum class history_mode {
    off,
    // By the camera alone: this frame's and the previous frame's view and projection (the
    // pass's uniforms) move a static surface's point to where it was (-hist).
    camera,
    // By the renderer's motion vectors (bindings.hpp's motion role, a full-resolution
    // texture), which also follow objects that move; the camera still gives the depth the
    // point had, for the disocclusion test (-histmv).
    motion_vectors,
};
inline constexpr std::array<enum_name<history_mode>, 3> history_mode_names{{
    {history_mode::off, "off"},
    {history_mode::camera, "camera"},
    {history_mode::motion_vectors, "motion_vectors"},
}};

static_assert(names::distinct(technique_names) && names::distinct(pipeline_stage_names) &&
              names::distinct(projection_kind_names) && names::distinct(depth_convention_names) &&
              names::distinct(normal_source_names) && names::distinct(ssao_output_names) &&
              names::distinct(ssao_range_check_names) && names::distinct(ssao_decisions_names) && names::distinct(blur_mode_names) &&
              names::distinct(bilateral_depth_names) && names::distinct(upsample_mode_names) &&
              names::distinct(multi_bounce_mode_names) && names::distinct(history_mode_names));

// Enum -> canonical name. A value outside the enumeration throws aogen::error.
inline const char* to_name(technique v) { return names::name_of(technique_names, v, "technique"); }
inline const char* to_name(pipeline_stage v) { return names::name_of(pipeline_stage_names, v, "stage"); }
inline const char* to_name(projection_kind v) { return names::name_of(projection_kind_names, v, "projection"); }
inline const char* to_name(depth_convention v) { return names::name_of(depth_convention_names, v, "depth"); }
inline const char* to_name(normal_source v) { return names::name_of(normal_source_names, v, "normals"); }
inline const char* to_name(ssao_output v) { return names::name_of(ssao_output_names, v, "output"); }
inline const char* to_name(ssao_range_check v) { return names::name_of(ssao_range_check_names, v, "range check"); }
inline const char* to_name(ssao_decisions v) { return names::name_of(ssao_decisions_names, v, "decisions"); }
inline const char* to_name(blur_mode v) { return names::name_of(blur_mode_names, v, "blur"); }
inline const char* to_name(bilateral_depth v) { return names::name_of(bilateral_depth_names, v, "bilateral depth"); }
inline const char* to_name(upsample_mode v) { return names::name_of(upsample_mode_names, v, "upsample"); }
inline const char* to_name(multi_bounce_mode v) { return names::name_of(multi_bounce_mode_names, v, "multi-bounce"); }
inline const char* to_name(history_mode v) { return names::name_of(history_mode_names, v, "history"); }

// Name -> enum. An unknown name throws aogen::error listing the valid names; `subject`
// is what the message names (pass the option or JSON path the user wrote, e.g. "--blur").
inline technique technique_from_name(std::string_view name, std::string_view subject = "technique")
{
    return names::value_of(technique_names, name, subject);
}
inline normal_source normal_source_from_name(std::string_view name, std::string_view subject = "normals")
{
    return names::value_of(normal_source_names, name, subject);
}
inline ssao_output ssao_output_from_name(std::string_view name, std::string_view subject = "output")
{
    return names::value_of(ssao_output_names, name, subject);
}
inline ssao_range_check ssao_range_check_from_name(std::string_view name, std::string_view subject = "range check")
{
    return names::value_of(ssao_range_check_names, name, subject);
}
inline ssao_decisions ssao_decisions_from_name(std::string_view name, std::string_view subject = "decisions")
{
    return names::value_of(ssao_decisions_names, name, subject);
}
inline blur_mode blur_mode_from_name(std::string_view name, std::string_view subject = "blur")
{
    return names::value_of(blur_mode_names, name, subject);
}
inline bilateral_depth bilateral_depth_from_name(std::string_view name, std::string_view subject = "bilateral depth")
{
    return names::value_of(bilateral_depth_names, name, subject);
}
inline upsample_mode upsample_mode_from_name(std::string_view name, std::string_view subject = "upsample")
{
    return names::value_of(upsample_mode_names, name, subject);
}

} // namespace aogen
