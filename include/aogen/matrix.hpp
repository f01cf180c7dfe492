// aogen/matrix.hpp — sets of variants: the cartesian product of axis values.
//
// WHAT
//   A matrix lists, per axis, the values to combine; expand() returns every
//   combination as a canonical variant, in a fixed order, without duplicates (axes a
//   technique ignores collapse: GTAO × four SSAO sample counts is one GTAO variant).
//   combinations(m) is how many the matrix lists before they collapse (saturating, so a
//   product of long lists cannot overflow): what a tool bounds before it expands a
//   user's matrix.
//   default_matrix() is the set `aogen generate` builds when no variant is named:
//     SSAO 8/16/32/64 samples × blur bilateral/box/denoise/none × full/half, compute;
//     GTAO slices 1, 2, 3, 4, 8 × steps 2, 3, 4 × blur bilateral/box/denoise/none, compute
//     (half resolution: the default, docs/design.md § Variant axes);
//     half-resolution variants end with the depth-aware upsample;
//     the seeds' own configurations as fragment variants (presets.hpp: Taos SSAO, Taos
//     GTAO, Unique Engine SSAO, the point-cloud viewer's ssao.wgsl), without it;
//     VBAO at quality.hpp's four presets (1×2, 2×2, 3×3, 9×3), half resolution,
//     bilateral blur, and High (3×3) at full resolution, compute;
//     SAO 8/16/32 taps × blur bilateral/denoise × full/half, compute;
//     and with bent normals (-bn): GTAO 2×2, 3×3 and 4×4 at half resolution with the
//     denoiser, GTAO 3×3 at full resolution without a blur, and VBAO's High preset, compute;
//     and the 3×3 denoise (-denoise3): GTAO 2×2 and 3×3 at half resolution, 3×3 at full
//     (XeGTAO High's counts), SSAO and SAO with 16 samples at half resolution, compute.
//
// USAGE
//     aogen::variant_matrix m;                  // one value per axis: the default variant
//     m.samples = {8, 16};
//     m.blur = {aogen::blur_mode::box, aogen::blur_mode::none};
//     std::vector<aogen::variant> vs = aogen::expand(m);   // 4 variants
#pragma once

#include "presets.hpp"
#include "quality.hpp"
#include "variant.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace aogen {

struct variant_matrix {
    std::vector<technique> techniques{technique::ssao};
    std::vector<int> samples{16};
    std::vector<int> slices{2};
    std::vector<int> steps{3};
    std::vector<blur_mode> blur{blur_mode::bilateral};
    std::vector<bilateral_depth> blur_depth{bilateral_depth::linear};
    std::vector<normal_source> normals{normal_source::gbuffer_world};
    std::vector<bool> point_cloud_fallback{false};
    std::vector<depth_convention> depth{depth_convention::standard};
    std::vector<projection_kind> projection{projection_kind::perspective};
    std::vector<bool> half_resolution{true};
    std::vector<pipeline_stage> stage{pipeline_stage::compute};
    std::vector<ssao_range_check> range_check{ssao_range_check::taos};
    std::vector<ssao_output> output{ssao_output::strength};
    std::vector<ssao_decisions> decisions{ssao_decisions::smooth};
    std::vector<bool> fp16{false};
    std::vector<upsample_mode> upsample{upsample_mode::depth_aware};
    std::vector<multi_bounce_mode> multi_bounce{multi_bounce_mode::off};
    std::vector<bool> bent_normals{false}; // on: GTAO and VBAO compute variants only, not with denoise3 (others skip it)
    std::vector<history_mode> history{history_mode::off}; // on: variants without bent normals only (others skip it)
};

// Appends canonical(v) unless an equal variant is already in `out`.
inline void append_unique(std::vector<variant>& out, const variant& v)
{
    const variant c = canonical(v);
    for (const variant& existing : out)
        if (existing == c) return;
    out.push_back(c);
}

// The product of the axes' value counts, at most `cap` + 1 (past the cap it saturates).
inline size_t combinations(const variant_matrix& m, size_t cap = size_t(1) << 40)
{
    size_t product = 1;
    for (size_t n : {m.techniques.size(), m.samples.size(), m.slices.size(), m.steps.size(), m.blur.size(), m.blur_depth.size(),
                     m.normals.size(), m.point_cloud_fallback.size(), m.depth.size(), m.projection.size(), m.half_resolution.size(),
                     m.stage.size(), m.range_check.size(), m.output.size(), m.decisions.size(), m.fp16.size(), m.upsample.size(), m.multi_bounce.size(),
                     m.bent_normals.size(), m.history.size()})
        product = n == 0 ? 0 : std::min(product * std::min(n, cap + 1), cap + 1);
    return product;
}

// Every combination, technique-major, in the order the axes' values are listed.
// Combinations that are invalid (a point-cloud fallback with GTAO, fp16 with SAO) are skipped.
inline std::vector<variant> expand(const variant_matrix& m)
{
    std::vector<variant> out;
    std::set<std::string> seen; // canonical names: append_unique's test, in log time
    variant v;
    for (technique t : m.techniques)
    for (int samples : m.samples)
    for (int slices : m.slices)
    for (int steps : m.steps)
    for (blur_mode blur : m.blur)
    for (bilateral_depth bd : m.blur_depth)
    for (normal_source n : m.normals)
    for (bool pc : m.point_cloud_fallback)
    for (depth_convention d : m.depth)
    for (projection_kind p : m.projection)
    for (bool half : m.half_resolution)
    for (pipeline_stage stage : m.stage)
    for (ssao_range_check rc : m.range_check)
    for (ssao_output o : m.output)
    for (ssao_decisions dec : m.decisions)
    for (bool fp16 : m.fp16)
    for (upsample_mode up : m.upsample)
    for (multi_bounce_mode mb : m.multi_bounce)
    for (bool bn : m.bent_normals)
    for (history_mode hist : m.history) {
        v.tech = t, v.samples = samples, v.slices = slices, v.steps = steps;
        v.blur = blur, v.blur_depth = bd, v.normals = n, v.point_cloud_fallback = pc;
        v.depth = d, v.projection = p, v.half_resolution = half, v.stage = stage;
        v.range_check = rc, v.output = o, v.decisions = dec, v.fp16 = fp16, v.upsample = up, v.multi_bounce = mb;
        v.bent_normals = bn, v.history = hist;
        if (pc && t != technique::ssao) continue;
        if (fp16 && t == technique::sao) continue;
        if (bn && (!has_slices(t) || stage != pipeline_stage::compute)) continue;
        if (hist != history_mode::off && bn) continue;
        if (blur == blur_mode::denoise3 && (bn || stage != pipeline_stage::compute)) continue;
        validate(v);
        const variant c = canonical(v);
        if (seen.insert(to_name(c)).second) out.push_back(c);
    }
    return out;
}

// VBAO's share of the default matrix: the four quality presets as a renderer would pick them
// (half resolution, bilateral blur), and High at full resolution -- five variants, so the
// report's run time grows by about what five GTAO variants cost.
inline std::vector<variant> vbao_default_variants()
{
    std::vector<variant> out;
    variant v;
    v.tech = technique::vbao;
    for (const quality_preset& p : quality_presets) {
        apply_quality(v, p);
        append_unique(out, v);
    }
    apply_quality(v, quality_preset_from_name("high"));
    v.half_resolution = false;
    append_unique(out, v);
    return out;
}

// The seeds' own configurations, as the fragment variants their engines run (presets.hpp:
// their half-resolution targets without aogen's upsample pass, as the seeds have none).
inline std::vector<variant> seed_variants()
{
    std::vector<variant> out;
    for (const preset& p : presets::seeds()) append_unique(out, p.variant);
    return out;
}

// Bent normals' share of the default matrix: GTAO as engines that use bent normals run it --
// half resolution with the denoiser at three costs, and High at full resolution unblurred --
// and VBAO's High preset as the default matrix has it, so the report scores the bent normal
// of each against the truth's.
inline std::vector<variant> bent_normal_default_variants()
{
    variant_matrix m;
    m.techniques = {technique::gtao};
    m.bent_normals = {true};
    m.blur = {blur_mode::denoise};
    std::vector<variant> out;
    for (int n : {2, 3, 4}) {
        m.slices = {n}, m.steps = {n};
        for (const variant& v : expand(m)) append_unique(out, v);
    }
    m.slices = {3}, m.steps = {3}, m.blur = {blur_mode::none}, m.half_resolution = {false};
    for (const variant& v : expand(m)) append_unique(out, v);
    variant vbao = vbao_default_variants()[2]; // High: 3×3, half resolution, bilateral
    vbao.bent_normals = true;
    append_unique(out, vbao);
    return out;
}

// The 3×3 denoise's share of the default matrix: beside the 5×5 denoise of the same AO in
// the matrix above, so the report sets their errors and times side by side -- the default
// GTAO chains (2×2, 3×3 at half resolution), XeGTAO High's counts at full resolution, and
// the default SSAO and SAO sample counts at half resolution.
inline std::vector<variant> denoise3_default_variants()
{
    variant_matrix m;
    m.techniques = {technique::gtao};
    m.blur = {blur_mode::denoise3};
    std::vector<variant> out;
    for (int n : {2, 3}) {
        m.slices = {n}, m.steps = {n};
        for (const variant& v : expand(m)) append_unique(out, v);
    }
    m.slices = {3}, m.steps = {3}, m.half_resolution = {false}; // XeGTAO High's counts at full resolution
    for (const variant& v : expand(m)) append_unique(out, v);
    for (technique t : {technique::ssao, technique::sao}) {
        variant_matrix s;
        s.techniques = {t}, s.samples = {16}, s.blur = {blur_mode::denoise3};
        for (const variant& v : expand(s)) append_unique(out, v);
    }
    return out;
}

inline std::vector<variant> default_matrix()
{
    const std::vector<blur_mode> all_blurs{blur_mode::bilateral, blur_mode::box, blur_mode::denoise, blur_mode::none};
    variant_matrix ssao;
    ssao.samples = {8, 16, 32, 64};
    ssao.blur = all_blurs;
    ssao.half_resolution = {false, true};
    variant_matrix gtao;
    gtao.techniques = {technique::gtao};
    gtao.slices = {1, 2, 3, 4, 8};
    gtao.steps = {2, 3, 4};
    gtao.blur = all_blurs;
    std::vector<variant> out = expand(ssao);
    for (const variant& v : expand(gtao)) append_unique(out, v);
    for (const variant& v : seed_variants()) append_unique(out, v);
    for (const variant& v : vbao_default_variants()) append_unique(out, v);
    variant_matrix sao; // after the others: they keep their order
    sao.techniques = {technique::sao};
    sao.samples = {8, 16, 32};
    sao.blur = {blur_mode::bilateral, blur_mode::denoise};
    sao.half_resolution = {false, true};
    for (const variant& v : expand(sao)) append_unique(out, v);
    for (const variant& v : bent_normal_default_variants()) append_unique(out, v); // last, likewise
    for (const variant& v : denoise3_default_variants()) append_unique(out, v);    // after them, likewise
    return out;
}

} // namespace aogen
