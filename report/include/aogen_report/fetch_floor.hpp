// aogen_report/fetch_floor.hpp — each variant's fetch floor: its passes' texel fetches with
// no arithmetic between them.
//
// WHAT
//   floor_sources(v) generates the compute shaders of v's floor: codegen::generate of v's
//   compute twin (same axes, stage compute, no point-cloud fallback) with the templates
//   whose arithmetic the floor drops replaced by report/floor/'s fetch-only files
//   (floor/README.md lists them and what each fetches). Everything else — defines,
//   bindings, the uniform block, depth and noise helpers, entry point, output image — is
//   the variant's own, so a floor binds exactly like its variant (bound_chain, same
//   chain_inputs) and runs on the same G-buffer in the same timing round.
//   A variant's time over its floor's says how much its arithmetic costs beyond the
//   memory traffic it cannot avoid: near 1 a variant is fetch-bound; far above it, either
//   the shading is heavy or the measurement is wrong, and the report shows which.
//
//   Fragment variants' floors are compute kernels (the fetches, not the raster path);
//   the point-cloud fallback's own ring of fetches is not in the floor, so a variant and its
//   point-cloud twin share one floor.
//
// USAGE
//     std::vector<aogen::codegen::shader_source> s = aogen_report::floor_sources(v);
//     aogen::vulkan::pass_pipelines floor(ctx, "floor of " + name, aogen::pipeline_stage::compute,
//                                         v.workgroup_x, v.workgroup_y, s, &cache);
//     // bind with aogen::vulkan::inputs_for(v, settings, tw, th), as the variant
#pragma once

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

// The text of floor/`name`, standing in for aogen template `path`.
inline std::string floor_replacement_file(const std::string& name, const std::string& path)
{
    for (const auto& t : floor_embedded::templates)
        if (t.path == name) return std::string(t.text);
    aogen::fail("fetch floor", "no floor template " + name + " for " + path, "valid: report/floor/ holds one per replaced template");
}

// The fetch-only file that stands in for aogen template `path`, or "" when it is kept.
inline std::string floor_replacement(const std::string& path)
{
    const std::array<const char*, 9> replaced{"common/normals.glsl", "common/slices.glsl", "ssao.glsl",         "gtao.glsl",    "vbao.glsl",
                                              "blur_bilateral.glsl", "blur_box.glsl",      "blur_denoise.glsl", "upsample.glsl"};
    if (std::find(replaced.begin(), replaced.end(), path) == replaced.end()) return "";
    // VBAO fetches what GTAO fetches (the same slices and steps): floor/vbao.glsl renames the
    // counts, then floor/gtao.glsl's loop follows.
    if (path == "vbao.glsl") return floor_replacement_file("vbao.glsl", path) + floor_replacement_file("gtao.glsl", path);
    return floor_replacement_file(path.substr(path.rfind('/') + 1), path); // floor/ is flat: common/normals.glsl is normals.glsl
}

// The floor's compute shaders, one per pass of `v`, named "<variant>.floor.<pass>.comp".
inline std::vector<aogen::codegen::shader_source> floor_sources(const aogen::variant& v)
{
    const aogen::variant twin = floor_variant(v);
    const aogen::codegen::template_reader read = [](const std::string& path) {
        const std::string floor = floor_replacement(path);
        return floor.empty() ? aogen::codegen::embedded_template(path) : floor;
    };
    std::vector<aogen::codegen::shader_source> out = aogen::codegen::generate(twin, read);
    const std::string name = aogen::to_name(v);
    for (aogen::codegen::shader_source& s : out)
        s.name = name + ".floor." + aogen::names::name_of(aogen::pass_kind_names, s.pass, "pass") + ".comp";
    return out;
}

} // namespace aogen_report
