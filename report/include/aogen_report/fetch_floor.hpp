// aogen_report/fetch_floor.hpp — each variant's two floors: its passes' texel fetches with no
// arithmetic between them, and its passes' inputs read once.
//
// WHAT
//   floor_of(plan, kind) generates the compute shaders of one of a planned variant's floors:
//   codegen::generate of its compute twin (same axes, stage compute, no point-cloud fallback) with the
//   templates whose work the floor drops replaced by report/floor/'s files
//   (report/floor/README.md lists them and what each reads). Everything else — defines, bindings, the uniform block,
//   depth and noise helpers, entry point, output image — is the variant's own, so a floor
//   binds exactly like its variant (bound_chain, same chain_inputs) and runs on the same
//   G-buffer in the same timing round.
//     floor_kind::fetch      the same fetches at the same positions as the variant's passes
//                            (floor/*.glsl): time / floor says how much the arithmetic costs
//                            beyond the variant's own memory traffic; near 1 it is fetch-bound.
//     floor_kind::bandwidth  each pass's inputs read once at its own pixel and its output
//                            written once (floor/bandwidth/*.glsl): time / bandwidth floor says
//                            how far a variant is from the memory system itself, not from our
//                            own fetch pattern (a scattered pattern can sit near its fetch
//                            floor and far above this one).
//
//   Fragment variants' floors are compute kernels (the fetches, not the raster path);
//   the point-cloud fallback's own ring of fetches is not in the floor, so a variant and its
//   point-cloud twin share one floor.
//
// USAGE
//     const aogen_report::floor_shaders f = aogen_report::floor_of(plan, aogen_report::floor_kind::fetch);
//     aogen::vulkan::pass_pipelines floor(ctx, f.plan, f.sources, &cache, "the fetch floor of " + plan.name());
//     // bind with plan.inputs(settings, w, h), as the variant
#pragma once

#include "report_techniques.hpp"

#include <aogen/codegen.hpp>
#include <aogen_report/floor_templates_embedded.hpp>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace aogen_report {

// The variant whose shaders the floor is made from: compute, without the fallback.
inline aogen::variant floor_variant(aogen::variant v)
{
    v.stage = aogen::pipeline_stage::compute;
    v.point_cloud_fallback = false;
    return v;
}

enum class floor_kind { fetch, bandwidth };

// The text of floor/`name`, standing in for aogen template `path`.
inline std::string floor_replacement_file(const std::string& name, const std::string& path)
{
    for (const auto& t : floor_embedded::templates)
        if (t.path == name) return std::string(t.text);
    aogen::fail("floor", "no floor template " + name + " for " + path, "valid: report/floor/ holds one per replaced template");
}

// The fetch floor's stand-in for aogen template `path`, or "" when it is kept: a technique's
// AO template is replaced by its row's floor files (report_techniques.hpp), in order.
inline std::string fetch_floor_replacement(const std::string& path)
{
    for (const report_technique& t : report_technique_table) {
        if (path != t.ao_template) continue;
        std::string text;
        for (const char* file : t.fetch_floor)
            if (file) text += floor_replacement_file(file, path);
        return text;
    }
    const std::array<const char*, 8> replaced{"common/normals.glsl", "common/slices.glsl", "blur_bilateral.glsl", "blur_box.glsl",
                                              "blur_denoise.glsl",   "blur_denoise3.glsl", "upsample.glsl",      "prefilter.glsl"};
    if (std::find(replaced.begin(), replaced.end(), path) == replaced.end()) return "";
    return floor_replacement_file(path.substr(path.rfind('/') + 1), path); // floor/ is flat: common/normals.glsl is normals.glsl
}

// The bandwidth floor's stand-in for aogen template `path`, or "" when it is kept: one file
// for every AO pass and one for every blur, since what they must read does not depend on
// the technique or the filter.
inline std::string bandwidth_floor_replacement(const std::string& path)
{
    struct stand_in {
        const char* replaced;
        const char* file;
    };
    static constexpr stand_in stand_ins[] = {
        {"common/normals.glsl", "bandwidth/normals.glsl"}, {"common/slices.glsl", "bandwidth/slices.glsl"},
        {"blur_bilateral.glsl", "bandwidth/blur.glsl"},
        {"blur_box.glsl", "bandwidth/blur.glsl"},          {"blur_denoise.glsl", "bandwidth/blur.glsl"},
        {"blur_denoise3.glsl", "bandwidth/blur_ao_only.glsl"}, // it reads no depth
        {"upsample.glsl", "bandwidth/upsample.glsl"},
        {"prefilter.glsl", "prefilter.glsl"}, // reads its input once already: both floors are one kernel
    };
    for (const report_technique& t : report_technique_table)
        if (path == t.ao_template) return floor_replacement_file("bandwidth/ao.glsl", path); // every technique's AO pass
    for (const stand_in& s : stand_ins)
        if (path == s.replaced) return floor_replacement_file(s.file, path);
    return "";
}

// The stand-in for aogen template `path` in a floor of `kind`, or "" when it is kept.
inline std::string floor_replacement(floor_kind kind, const std::string& path)
{
    return kind == floor_kind::fetch ? fetch_floor_replacement(path) : bandwidth_floor_replacement(path);
}

// The shaders of one floor of a planned variant: the plan they are made from and its sources.
struct floor_shaders {
    aogen::codegen::plan plan;                           // the compute twin's, under the floor's templates
    std::vector<aogen::codegen::shader_source> sources;  // one compute shader per pass
};

// The plan a planned variant's floors are made from: its compute twin's (floor_variant) --
// `p` itself where the twin is p's variant (a compute variant without the fallback), so that
// only a fragment or point-cloud variant's twin, another variant, is planned.
inline aogen::codegen::plan floor_base(const aogen::codegen::plan& p)
{
    const aogen::variant twin = floor_variant(p.variant());
    return twin == p.variant() ? p : aogen::codegen::make_plan(twin);
}

// One floor of the planned variant `p`: `base` (floor_base(p)) under the templates of `kind`
// (plan::with_options: not planned again) and its compute shaders, named
// "<variant>.floor.<pass>.comp" (the fetch floor) or "<variant>.bandwidth.<pass>.comp".
inline floor_shaders floor_of(const aogen::codegen::plan& p, const aogen::codegen::plan& base, floor_kind kind)
{
    aogen::codegen::options o;
    o.templates = [kind](const std::string& path) {
        const std::string floor = floor_replacement(kind, path);
        return floor.empty() ? aogen::codegen::embedded_template(path) : floor;
    };
    floor_shaders f{base.with_options(o), {}};
    f.sources = aogen::codegen::generate(f.plan);
    const std::string name = p.name() + (kind == floor_kind::fetch ? ".floor." : ".bandwidth.");
    for (aogen::codegen::shader_source& s : f.sources) s.name = name + aogen::names::name_of(aogen::pass_kind_names, s.pass, "pass") + ".comp";
    return f;
}

// The same with floor_base(p) worked out here (one floor of one variant).
inline floor_shaders floor_of(const aogen::codegen::plan& p, floor_kind kind = floor_kind::fetch) { return floor_of(p, floor_base(p), kind); }

} // namespace aogen_report
