// aogen/variant.hpp — one AO shader variant as a value: its axes, its name, its defines.
//
// WHAT
//   A variant fixes, at compile time, every choice an AO pass makes: the technique and
//   its sample counts, the blur, where normals come from, the depth convention and
//   projection, the resolution and the pipeline stage. The shader templates read these
//   as #defines (`defines()`, plan.hpp), so whatever a variant does not use is not in its code.
//
//   Every variant has a canonical, human-readable name that parses back into the same
//   value, e.g.
//       ssao-s16-half-bilateral-gbufworld-std-persp-cs
//       gtao-2x3-full-box-recon-rev-ortho-fs
//       vbao-3x3-half-bilateral-gbufworld-std-persp-cs
//       sao-s16-half-denoise-gbufworld-std-persp-cs
//   The tokens, in order: technique (+ samples, or slices x steps), resolution, blur,
//   normals, depth, projection, stage; then only the axes that differ from their
//   default, each a token of its own: `rawdepth` (seed-exact bilateral depth term),
//   `pc` (point-cloud fallback), `rc004` (seed 004's range check), `powint` (Unique
//   Engine's power/intensity output), `step` (the seeds' step decisions in SSAO, not
//   ours smooth ones), `fp16` (16-bit arithmetic in the AO pass), `nearest`
//   (a half-resolution target left for the caller to upsample), `mip5` (a depth MIP chain of
//   5 levels, read by far taps: depth_mips.hpp), `deint` (the AO pass dispatched as 4 x 4
//   interleaved layers), `bn` (bent normals written beside the AO), `mb` (multi-bounce in
//   the last pass's finalize step, one albedo) or `mbg` (the same, each pixel's albedo from
//   the G-buffer), `hist` or `histmv` (the history pass, reprojecting by the camera or by the
//   renderer's motion vectors), `wg16x16` (workgroup size).
//
// USAGE
//     aogen::variant v;                          // the defaults: ssao-s16-half-bilateral-...
//     v.samples = 32;
//     std::string name = aogen::to_name(v);      // "ssao-s32-half-bilateral-gbufworld-std-persp-cs"
//     aogen::variant w = aogen::variant_from_name(name);   // == v
//     aogen::validate(v);                        // throws aogen::error naming the axis
//
// WHY
//   Structural axes are preprocessor defines rather than specialization constants:
//   spirv-opt's performance passes do not fold specialization constants, and a define
//   removes the code outright, so the saving is real in every target language.
#pragma once

#include "axes.hpp"
#include "depth_mips.hpp"
#include "error.hpp"
#include "names.hpp"
#include "range.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace aogen {

// Every axis of a variant, with its default (docs/design.md § Variant axes). The enums are
// axes.hpp's; the counts' ranges sit beside them, as params.hpp's ranges sit beside its fields.
struct variant {
    technique tech = technique::ssao;
    // SSAO's kernel samples per pixel, N. Taos: 16, Unique Engine: 32, ssao.wgsl: 64.
    // SAO's spiral taps per pixel (has_samples: the same field and name token).
    static constexpr int_range samples_range{1, 256};
    int samples = 16;
    // GTAO's and VBAO's (has_slices) slice directions per pixel, rotated per pixel by noise,
    // and horizon samples per side of each slice. Defaults: 2 and 3.
    static constexpr int_range slices_range{1, 16};
    int slices = 2;
    static constexpr int_range steps_range{1, 16};
    int steps = 3;
    blur_mode blur = blur_mode::bilateral;
    bilateral_depth blur_depth = bilateral_depth::linear; // bilateral only
    normal_source normals = normal_source::gbuffer_world;
    bool point_cloud_fallback = false; // ssao only (seed 004)
    depth_convention depth = depth_convention::standard;
    projection_kind projection = projection_kind::perspective;
    bool half_resolution = true;
    pipeline_stage stage = pipeline_stage::compute;
    // Compute only: the workgroup's size, each side in range, at most 1024 invocations.
    static constexpr int_range workgroup_side_range{1, 32};
    static constexpr int max_workgroup_invocations = 1024;
    int workgroup_x = 8, workgroup_y = 8;
    // The shared memory a workgroup may use on every device: Vulkan's, ESSL 3.1's and WebGPU's
    // guaranteed minimum (maxComputeSharedMemorySize, maxComputeWorkgroupStorageSize).
    static constexpr int min_shared_memory_bytes = 16384;
    ssao_range_check range_check = ssao_range_check::taos; // ssao only
    ssao_output output = ssao_output::strength;            // ssao only
    // SSAO's per-sample decisions: smooth weights (ours) or the seeds' steps (axes.hpp).
    ssao_decisions decisions = ssao_decisions::smooth;     // ssao only
    // 16-bit floats for the AO pass's arithmetic where its precision allows it (GTAO's
    // slice integration and horizon cosines, SSAO's tangent frame, sample offsets and
    // weights); depth reconstruction, screen positions and sums stay 32-bit. Needs the
    // device's shaderFloat16 (VK_KHR_shader_float16_int8). Default: off. Not
    // with SAO: its per-tap sum is a ratio of squared lengths that 16 bits cannot hold.
    bool fp16 = false;
    // How a half-resolution target reaches the screen (upsample_mode): by the depth-aware
    // upsample pass (the default; the chain's output is then screen-sized) or not at all.
    upsample_mode upsample = upsample_mode::depth_aware; // half resolution only
    // The levels of the depth MIP chain the AO pass's taps read (depth_mips.hpp), level 0 the
    // depth buffer itself: 1 is none; 2..5 add a prefilter pass before the AO pass that builds
    // levels 1..N-1 (compute only: the prefilter reduces 16 x 16 blocks in shared memory).
    static constexpr int_range depth_mips_range = depth_mips::levels_range;
    int depth_mips = 1;
    // Compute only: the AO pass's invocations walk the target as 4 x 4 interleaved layers
    // (deinterleaved_layers: invocation (x, y) of layer (i, j) shades pixel (4x + i, 4y + j)),
    // so the invocations of one warp shade pixels 4 apart with one noise rotation (the tile
    // is 4 x 4) and their taps land side by side -- the cache coherence of deinterleaved
    // rendering (Bavoil 2014) without splitting the depth buffer: every pixel reads what it
    // read before, so the output is the same bit for bit. Workgroup sides a multiple of 4.
    bool deinterleaved = false;
    // Multi-bounce: the chain's last pass brightens the AO it writes by the inter-reflections
    // of surfaces of albedo rho (the GTAO paper's fit, common/core.glsl's ao_multi_bounce):
    // one rho for the image (finalize_params::albedo, -mb) or each pixel's from the albedo
    // G-buffer (-mbg). Every technique. Default: off.
    multi_bounce_mode multi_bounce = multi_bounce_mode::off;
    // Bent normals: every pass also writes the pixel's bent normal -- the cosine-weighted mean
    // of its unoccluded directions, in view space -- beside the AO, which needs a four-channel
    // output (AO in .r, the normal in .gba: common/core.glsl's ao_value). GTAO and VBAO,
    // compute stage (a fragment pass's target is one channel). Default: off.
    bool bent_normals = false;
    // The history pass (history.glsl): after the spatial filter, at the AO target's
    // resolution and before the upsample, the chain blends this frame's filtered AO with its
    // own output of the previous frame, found by the camera (-hist) or the renderer's motion
    // vectors (-histmv), rejected where the surface there was another (a depth test) and
    // clamped to this frame's neighbourhood (history_params). Compute or fragment (there it
    // writes two colour attachments); not with bent normals (the history holds the AO
    // alone). Default: off.
    history_mode history = history_mode::off;
};

// The side of the pixel lattice a deinterleaved AO pass walks one layer of: the side of the
// 4 x 4 noise tile slice techniques use and SSAO's default.
inline constexpr int deinterleaved_layers = 4;

// ---------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------

namespace detail {

// How many times validate(variant) has run in this process. Not a feature: it lets a test
// pin that a plan (codegen/plan.hpp) validates a variant once and nothing after it again.
inline std::atomic<unsigned long>& validations()
{
    static std::atomic<unsigned long> count{0};
    return count;
}

} // namespace detail

// The shared memory of the 3 × 3 denoise's tile in x × y groups (blur_denoise3.glsl's COST):
// (2 x + 2) × (2 y + 2) texels of one 32-bit word.
inline constexpr int denoise3_tile_bytes(int x, int y) { return (2 * x + 2) * (2 * y + 2) * 4; }

inline void validate(const variant& v)
{
    ++detail::validations();
    names::require_listed(technique_names, v.tech, "technique");
    // The counts are named for the technique that reads them ("vbao slices", "sao taps"); a
    // count the technique does not read is still checked, under its bare name.
    const std::string tech = names::name_of(technique_names, v.tech, "technique");
    const std::string sampled = has_samples(v.tech) ? tech + " " + technique_counts[size_t(v.tech)].unit : "samples";
    require_in(sampled, v.samples, variant::samples_range);
    require_in(has_slices(v.tech) ? tech + " slices" : "slices", v.slices, variant::slices_range);
    require_in(has_slices(v.tech) ? tech + " steps" : "steps", v.steps, variant::steps_range);
    names::require_listed(blur_mode_names, v.blur, "blur");
    names::require_listed(bilateral_depth_names, v.blur_depth, "bilateral depth");
    names::require_listed(normal_source_names, v.normals, "normals");
    names::require_listed(depth_convention_names, v.depth, "depth");
    names::require_listed(projection_kind_names, v.projection, "projection");
    names::require_listed(pipeline_stage_names, v.stage, "stage");
    names::require_listed(ssao_range_check_names, v.range_check, "range check");
    names::require_listed(ssao_output_names, v.output, "output");
    names::require_listed(ssao_decisions_names, v.decisions, "decisions");
    names::require_listed(upsample_mode_names, v.upsample, "upsample");
    names::require_listed(multi_bounce_mode_names, v.multi_bounce, "multi-bounce");
    require_in("workgroup x", v.workgroup_x, variant::workgroup_side_range);
    require_in("workgroup y", v.workgroup_y, variant::workgroup_side_range);
    if (v.workgroup_x * v.workgroup_y > variant::max_workgroup_invocations)
        fail("workgroup", std::to_string(v.workgroup_x) + "x" + std::to_string(v.workgroup_y) + " is over " +
                              std::to_string(variant::max_workgroup_invocations) + " invocations",
             "valid: x * y <= " + std::to_string(variant::max_workgroup_invocations));
    require_in("depth mips", v.depth_mips, variant::depth_mips_range);
    if (v.depth_mips > 1 && v.stage != pipeline_stage::compute)
        fail("depth mips", std::to_string(v.depth_mips) + " levels need the compute stage (the prefilter pass reduces the depth in shared memory)",
             "valid: 1 (no MIP chain) with the fragment stage");
    if (v.deinterleaved && v.stage != pipeline_stage::compute)
        fail("deinterleaved", "dispatch needs the compute stage (a fragment pass shades the pixel it is drawn at)", "valid: off with the fragment stage");
    if (v.deinterleaved && (v.workgroup_x % deinterleaved_layers != 0 || v.workgroup_y % deinterleaved_layers != 0))
        fail("deinterleaved", "dispatch needs workgroup sides that are multiples of " + std::to_string(deinterleaved_layers) + ", not " +
                                  std::to_string(v.workgroup_x) + "x" + std::to_string(v.workgroup_y) + " (the groups must cover every layer)",
             "valid: e.g. wg8x8, wg16x8, wg16x16");
    if (v.point_cloud_fallback && v.tech != technique::ssao)
        fail("point-cloud fallback", std::string("is an SSAO feature (seed 004), not available with ") + names::name_of(technique_names, v.tech, "technique"),
             "valid: off with gtao, vbao and sao");
    if (v.fp16 && v.tech == technique::sao)
        fail("fp16", "is not available with sao (its taps' sum divides squared lengths, past 16-bit range)", "valid: off with sao");
    if (v.bent_normals && !has_slices(v.tech))
        fail("bent normals", std::string("come from GTAO's and VBAO's slices, not available with ") + names::name_of(technique_names, v.tech, "technique"),
             "valid: gtao, vbao, or off");
    if (v.bent_normals && v.stage != pipeline_stage::compute)
        fail("bent normals", "need the compute stage (a fragment pass writes one channel, the AO)", "valid: off with the fragment stage");
    if (v.blur == blur_mode::denoise3 && v.stage != pipeline_stage::compute)
        fail("blur denoise3", "needs the compute stage (its AO pass writes the edges beside the AO, in its storage image)",
             "valid: denoise3 with the compute stage, or denoise, bilateral, box, none with the fragment stage");
    if (v.blur == blur_mode::denoise3 && v.bent_normals)
        fail("blur denoise3", "is not available with bent normals (its edges take the output's channels the bent normal would)",
             "valid: denoise3 without -bn, or denoise, bilateral, box, none with -bn");
    if (v.blur == blur_mode::denoise3 && denoise3_tile_bytes(v.workgroup_x, v.workgroup_y) > variant::min_shared_memory_bytes)
        fail("blur denoise3",
             "needs " + std::to_string(denoise3_tile_bytes(v.workgroup_x, v.workgroup_y)) + " bytes of shared memory in " + std::to_string(v.workgroup_x) +
                 "x" + std::to_string(v.workgroup_y) + " groups, over the " + std::to_string(variant::min_shared_memory_bytes) + " every device has",
             "valid: workgroups with (x + 1) * (y + 1) <= 1024, e.g. wg16x16, wg32x16");
    names::require_listed(history_mode_names, v.history, "history");
    if (v.history != history_mode::off && v.bent_normals)
        fail("history", "is not available with bent normals (the history holds the AO alone, and would blur the normal's frames apart)",
             "valid: off with -bn, or the variant without -bn");
}

// ---------------------------------------------------------------------------------
// Passes and their defines
// ---------------------------------------------------------------------------------

// A variant runs as a chain: (with a depth MIP chain) the prefilter pass that builds it, the
// AO pass, its blur passes, then (half resolution with the depth-aware upsample) the upsample
// pass, the only one whose output is screen-sized.
enum class pass_kind { ao, blur_x, blur_y, blur_box, blur_denoise, upsample, prefilter, history, blur_denoise3 };
inline constexpr std::array<enum_name<pass_kind>, 9> pass_kind_names{{
    {pass_kind::ao, "ao"},
    {pass_kind::blur_x, "blur_x"},
    {pass_kind::blur_y, "blur_y"},
    {pass_kind::blur_box, "blur_box"},
    {pass_kind::blur_denoise, "blur_denoise"},
    {pass_kind::upsample, "upsample"},
    {pass_kind::prefilter, "prefilter"},
    {pass_kind::history, "history"},
    {pass_kind::blur_denoise3, "blur_denoise3"},
}};

// Does `v` blend its AO with the previous frame's in a history pass (history.glsl)?
inline bool has_history_pass(const variant& v) { return v.history != history_mode::off; }

// Does `v` start with the prefilter pass (a depth MIP chain)?
inline bool has_prefilter_pass(const variant& v) { return v.depth_mips > 1; }

// Does `v` end with the depth-aware upsample pass?
inline bool has_upsample_pass(const variant& v)
{
    return v.half_resolution && v.upsample == upsample_mode::depth_aware;
}

// The side of the square of output pixels one invocation of `pass` writes: 2 for the
// upsample pass in compute (one invocation per target texel, each writing the 2 × 2 screen
// pixels it covers: upsample.glsl) and for the 3 × 3 denoise (a 2 × 2 quad of target pixels
// from one 4 × 4 window: blur_denoise3.glsl), 1 for every other pass. A compute pass is
// dispatched over its output's size divided by this, rounded up.
inline int pixels_per_invocation(pass_kind pass, pipeline_stage stage)
{
    if (pass == pass_kind::prefilter) return depth_mips::pixels_per_invocation; // 2 × 2 depth texels each
    if (stage != pipeline_stage::compute) return 1;
    return pass == pass_kind::upsample || pass == pass_kind::blur_denoise3 ? 2 : 1;
}

// The workgroup a compute pass runs in: the variant's (`variant_group`), but the
// prefilter's own 8 × 8, which its reduction through shared memory is written for.
inline std::pair<int, int> workgroup_of(pass_kind pass, std::pair<int, int> variant_group)
{
    if (pass == pass_kind::prefilter) return {depth_mips::workgroup_side, depth_mips::workgroup_side};
    return variant_group;
}

inline std::pair<int, int> workgroup_of(const variant& v, pass_kind pass) { return workgroup_of(pass, {v.workgroup_x, v.workgroup_y}); }

inline std::vector<pass_kind> passes(const variant& v)
{
    std::vector<pass_kind> p;
    if (has_prefilter_pass(v)) p.push_back(pass_kind::prefilter);
    p.push_back(pass_kind::ao);
    switch (v.blur) {
    case blur_mode::bilateral: p.insert(p.end(), {pass_kind::blur_x, pass_kind::blur_y}); break;
    case blur_mode::box: p.push_back(pass_kind::blur_box); break;
    case blur_mode::denoise: p.push_back(pass_kind::blur_denoise); break;
    case blur_mode::denoise3: p.push_back(pass_kind::blur_denoise3); break;
    case blur_mode::none: break;
    default: names::fail_unlisted(blur_mode_names, v.blur, "blur");
    }
    if (has_history_pass(v)) p.push_back(pass_kind::history); // at the target's resolution, before the upsample
    if (has_upsample_pass(v)) p.push_back(pass_kind::upsample);
    return p;
}

// Does `pass` of `v` add the multi-bounce light? The chain's last pass does, once, on what
// the renderer reads -- never a pass whose output a later pass filters.
inline bool applies_multi_bounce(const variant& v, pass_kind pass)
{
    return v.multi_bounce != multi_bounce_mode::off && pass == passes(v).back();
}

// Does `pass` of `v` read the albedo G-buffer (bindings.hpp's gbuffer_albedo role)? The pass
// that applies a -mbg variant's multi-bounce.
inline bool reads_albedo(const variant& v, pass_kind pass)
{
    return v.multi_bounce == multi_bounce_mode::gbuffer_albedo && applies_multi_bounce(v, pass);
}

struct define {
    std::string name;
    std::string value; // empty: a plain #define NAME
};

// The #defines of a pass (aogen::defines) are plan.hpp's: a technique's come from its row of the
// table (techniques.hpp), which stands above this header.

// ---------------------------------------------------------------------------------
// Canonical form, name, hash
// ---------------------------------------------------------------------------------

// `v` with every field its axes make irrelevant reset to the default (GTAO ignores the
// SSAO sample count, only the bilateral blur has a depth term, ...), so that two
// variants that compile to the same shaders compare equal and have one name.
inline variant canonical(variant v)
{
    const variant d;
    if (!has_samples(v.tech)) v.samples = d.samples;
    if (v.tech != technique::ssao) {
        v.range_check = d.range_check, v.output = d.output, v.decisions = d.decisions;
        v.point_cloud_fallback = d.point_cloud_fallback;
    }
    if (!has_slices(v.tech)) v.slices = d.slices, v.steps = d.steps;
    if (v.blur != blur_mode::bilateral) v.blur_depth = d.blur_depth;
    if (v.stage != pipeline_stage::compute) v.workgroup_x = d.workgroup_x, v.workgroup_y = d.workgroup_y, v.deinterleaved = d.deinterleaved;
    if (!v.half_resolution) v.upsample = d.upsample;
    return v;
}

inline bool operator==(const variant& a, const variant& b)
{
    const variant x = canonical(a), y = canonical(b);
    return x.tech == y.tech && x.samples == y.samples && x.slices == y.slices &&
           x.steps == y.steps && x.blur == y.blur && x.blur_depth == y.blur_depth && x.normals == y.normals &&
           x.point_cloud_fallback == y.point_cloud_fallback && x.depth == y.depth && x.projection == y.projection &&
           x.half_resolution == y.half_resolution && x.stage == y.stage && x.workgroup_x == y.workgroup_x &&
           x.workgroup_y == y.workgroup_y && x.range_check == y.range_check && x.output == y.output && x.decisions == y.decisions && x.fp16 == y.fp16 &&
           x.upsample == y.upsample && x.depth_mips == y.depth_mips && x.deinterleaved == y.deinterleaved && x.multi_bounce == y.multi_bounce &&
           x.bent_normals == y.bent_normals && x.history == y.history;
}
inline bool operator!=(const variant& a, const variant& b) { return !(a == b); }

namespace detail {

// The short spellings of the axes inside a variant name (the tables above hold the
// long ones used by JSON and the command line).
inline constexpr std::array<enum_name<blur_mode>, 5> blur_tokens{{
    {blur_mode::bilateral, "bilateral"}, {blur_mode::box, "box"}, {blur_mode::none, "noblur"}, {blur_mode::denoise, "denoise"},
    {blur_mode::denoise3, "denoise3"}}};
inline constexpr std::array<enum_name<normal_source>, 3> normal_tokens{{
    {normal_source::gbuffer_world, "gbufworld"}, {normal_source::gbuffer_view, "gbufview"},
    {normal_source::reconstructed, "recon"}}};
inline constexpr std::array<enum_name<depth_convention>, 3> depth_tokens{{
    {depth_convention::standard, "std"}, {depth_convention::reversed, "rev"},
    {depth_convention::reversed_infinite, "revinf"}}};
inline constexpr std::array<enum_name<projection_kind>, 2> projection_tokens{{
    {projection_kind::perspective, "persp"}, {projection_kind::orthographic, "ortho"}}};
inline constexpr std::array<enum_name<pipeline_stage>, 2> stage_tokens{{
    {pipeline_stage::compute, "cs"}, {pipeline_stage::fragment, "fs"}}};

// The extras of a variant name, in the order a canonical name writes them (name_of); what
// variant_from_name accepts after the eight fixed tokens, and what `aogen list` shows.
inline constexpr std::array<const char*, 15> extra_tokens{
    {"rawdepth", "pc", "rc004", "powint", "step", "fp16", "nearest", "mip<N>", "deint", "bn", "mb", "mbg", "hist", "histmv", "wg<X>x<Y>"}};

inline std::string extra_token_list()
{
    std::string out;
    for (const char* t : extra_tokens) out += (out.empty() ? "" : ", ") + std::string(t);
    return out;
}

inline std::vector<std::string> split(const std::string& s, char separator)
{
    std::vector<std::string> parts(1);
    for (char c : s) {
        if (c == separator) parts.emplace_back();
        else parts.back().push_back(c);
    }
    return parts;
}

// A decimal integer token in [lo, hi] after `prefix` ("s16" → 16); -1 when it is not one.
inline int parse_count(const std::string& token, size_t from = 0)
{
    if (token.size() <= from || token.size() - from > 3) return -1;
    int value = 0;
    for (size_t i = from; i < token.size(); ++i) {
        if (token[i] < '0' || token[i] > '9') return -1;
        value = value * 10 + (token[i] - '0');
    }
    return value;
}

} // namespace detail

namespace detail {

// to_name(v) for a `v` already validated (a plan's).
inline std::string name_of(const variant& input)
{
    const variant v = canonical(input);
    const variant d;
    std::string name = names::name_of(technique_names, v.tech, "technique");
    if (has_samples(v.tech)) name += "-s" + std::to_string(v.samples);
    else name += "-" + std::to_string(v.slices) + "x" + std::to_string(v.steps);
    name += v.half_resolution ? "-half" : "-full";
    name += std::string("-") + names::name_of(detail::blur_tokens, v.blur, "blur");
    name += std::string("-") + names::name_of(detail::normal_tokens, v.normals, "normals");
    name += std::string("-") + names::name_of(detail::depth_tokens, v.depth, "depth");
    name += std::string("-") + names::name_of(detail::projection_tokens, v.projection, "projection");
    name += std::string("-") + names::name_of(detail::stage_tokens, v.stage, "stage");
    if (v.blur_depth != d.blur_depth) name += "-rawdepth";
    if (v.point_cloud_fallback) name += "-pc";
    if (v.range_check != d.range_check) name += "-rc004";
    if (v.output != d.output) name += "-powint";
    if (v.decisions != d.decisions) name += "-step";
    if (v.fp16) name += "-fp16";
    if (v.upsample != d.upsample) name += "-nearest";
    if (v.depth_mips != d.depth_mips) name += "-mip" + std::to_string(v.depth_mips);
    if (v.deinterleaved) name += "-deint";
    if (v.bent_normals) name += "-bn";
    if (v.multi_bounce == multi_bounce_mode::uniform_albedo) name += "-mb";
    if (v.multi_bounce == multi_bounce_mode::gbuffer_albedo) name += "-mbg";
    if (v.history == history_mode::camera) name += "-hist";
    if (v.history == history_mode::motion_vectors) name += "-histmv";
    if (v.workgroup_x != d.workgroup_x || v.workgroup_y != d.workgroup_y)
        name += "-wg" + std::to_string(v.workgroup_x) + "x" + std::to_string(v.workgroup_y);
    return name;
}

} // namespace detail

// The canonical name: "ssao-s16-half-bilateral-gbufworld-std-persp-cs" and extras.
inline std::string to_name(const variant& v)
{
    validate(v);
    return detail::name_of(v);
}

// Parses a name written by to_name (extras in any order, each at most once).
inline variant variant_from_name(const std::string& name)
{
    const std::string subject = "variant name " + quote(name, 40);
    const std::vector<std::string> t = detail::split(name, '-');
    if (t.size() < 8)
        fail(subject, "has " + std::to_string(t.size()) + " tokens, too few",
             "valid: ssao|sao-s<N>, gtao|vbao-<S>x<N>, half|full, bilateral|box|denoise[3]|noblur, gbufworld|gbufview|recon, std|rev|revinf, "
             "persp|ortho, cs|fs, then extras; aogen list");
    variant v;
    v.tech = names::value_of(technique_names, t[0], subject + " technique");
    if (has_samples(v.tech)) {
        if (t[1].size() < 2 || t[1][0] != 's' || (v.samples = detail::parse_count(t[1], 1)) < 0)
            fail(subject, quote(t[1]) + " is not a sample count", "valid: s1..s256");
    } else {
        const std::vector<std::string> ss = detail::split(t[1], 'x');
        if (ss.size() != 2 || (v.slices = detail::parse_count(ss[0])) < 0 || (v.steps = detail::parse_count(ss[1])) < 0)
            fail(subject, quote(t[1]) + " is not slices x steps", "valid: e.g. 2x3, each 1..16");
    }
    if (t[2] != "half" && t[2] != "full") fail(subject + " resolution", quote(t[2]) + " is not a resolution", "valid: half, full");
    v.half_resolution = t[2] == "half";
    v.blur = names::value_of(detail::blur_tokens, t[3], subject + " blur");
    v.normals = names::value_of(detail::normal_tokens, t[4], subject + " normals");
    v.depth = names::value_of(detail::depth_tokens, t[5], subject + " depth");
    v.projection = names::value_of(detail::projection_tokens, t[6], subject + " projection");
    v.stage = names::value_of(detail::stage_tokens, t[7], subject + " stage");
    std::vector<std::string> seen;
    for (size_t i = 8; i < t.size(); ++i) {
        const std::string& x = t[i];
        const std::string kind = x.rfind("wg", 0) == 0 ? "wg" : x.rfind("mip", 0) == 0 ? "mip" : x == "mbg" ? "mb" : x == "histmv" ? "hist" : x;
        if (std::find(seen.begin(), seen.end(), kind) != seen.end()) {
            if (kind == "mb" && std::find(t.begin() + 8, t.begin() + i, x) == t.begin() + i)
                fail(subject, quote(x) + " is a second multi-bounce extra", "valid: one of mb, mbg");
            if (kind == "hist" && std::find(t.begin() + 8, t.begin() + i, x) == t.begin() + i)
                fail(subject, quote(x) + " is a second history extra", "valid: one of hist, histmv");
            fail(subject, quote(x) + " appears twice", "valid: each extra once");
        }
        seen.push_back(kind);
        if (x == "rawdepth") v.blur_depth = bilateral_depth::seed_raw;
        else if (x == "pc") v.point_cloud_fallback = true;
        else if (x == "rc004") v.range_check = ssao_range_check::seed004;
        else if (x == "powint") v.output = ssao_output::power_intensity;
        else if (x == "step") v.decisions = ssao_decisions::step;
        else if (x == "fp16") v.fp16 = true;
        else if (x == "nearest") v.upsample = upsample_mode::nearest;
        else if (x == "deint") v.deinterleaved = true;
        else if (x == "bn") v.bent_normals = true;
        else if (x == "mb") v.multi_bounce = multi_bounce_mode::uniform_albedo;
        else if (x == "mbg") v.multi_bounce = multi_bounce_mode::gbuffer_albedo;
        else if (x == "hist") v.history = history_mode::camera;
        else if (x == "histmv") v.history = history_mode::motion_vectors;
        else if (kind == "mip") {
            if ((v.depth_mips = detail::parse_count(x, 3)) < 0) fail(subject, quote(x) + " is not a depth MIP level count", "valid: mip2..mip5");
        } else if (kind == "wg") {
            const std::vector<std::string> wg = detail::split(x.substr(2), 'x');
            if (wg.size() != 2 || (v.workgroup_x = detail::parse_count(wg[0])) < 0 || (v.workgroup_y = detail::parse_count(wg[1])) < 0)
                fail(subject, quote(x) + " is not a workgroup size", "valid: wg<X>x<Y>, e.g. wg16x16");
        } else fail(subject, quote(x) + " is not a known extra", "valid: " + detail::extra_token_list());
    }
    try {
        validate(v);
    } catch (const error& e) {
        fail(subject, e.what(), "");
    }
    if (to_name(v) != name) fail(subject, "is not in canonical form", "valid: " + to_name(v));
    return canonical(v);
}

// A stable 64-bit hash of the variant: FNV-1a of its canonical name, as 16 hex digits.
inline std::string hash(const variant& v)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (char c : to_name(v)) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    static const char digits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 15; i >= 0; --i, h >>= 4) out[i] = digits[h & 15];
    return out;
}

} // namespace aogen
