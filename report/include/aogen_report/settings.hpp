// aogen_report/settings.hpp — what the report runs a variant with on a scene: "the
// variant's default parameters", scaled to the scene's AO radius, and whether the variant
// can run on the scene at all.
//
//     std::string why = aogen_report::cannot_run(v, scene);        // "" when it can
//     aogen::vulkan::chain_settings s = aogen_report::default_settings(v, scene);
//     aogen_report::require_radius_works(scene);                     // before any work
//
// Defaults are what a user gets (aogen/params.hpp), each technique's row of
// report_techniques.hpp scaling its lengths to the scene's AO radius R (the ground truth's
// radius): every technique's tuned defaults, its radius <technique>_params::radius_per_ao_radius
// × R (VBAO's thickness and SAO's bias are shares of the radius, so they scale by themselves);
// SSAO's bias keeps its ratio to the radius; SSAO variants with the seeds' step decisions or
// Unique Engine's power/intensity output (which the tuner does not search) run the seed
// presets at the hemisphere R. The linear bilateral depth term's sharpness (10 per unit at
// R = 1) scales with 1/R, so every scene is seen at the same relative scale.
#pragma once

#include "report_techniques.hpp"

#include <aogen/params.hpp>
#include <aogen/presets.hpp>
#include <aogen/vulkan/chain.hpp>
#include <aogen_scenes/gbuffer.hpp>
#include <aogen_scenes/scene.hpp>

#include <algorithm>
#include <string>

namespace aogen_report {

// The scene's camera with the variant's depth convention: the same picture, the depth
// buffer written the way the variant reads it.
inline aogen::scenes::scene for_variant(aogen::scenes::scene s, const aogen::variant& v)
{
    s.camera.depth = v.depth;
    return s;
}

// The G-buffer a scene's renderer uploads, from its ray-cast `g`: depth and normals, and --
// the built-in scenes being one grey material -- finalize_params' default albedo in every
// pixel (read by -mbg variants only, which therefore write their -mb twin's AO).
inline aogen::vulkan::gbuffer renderer_gbuffer(const aogen::scenes::gbuffer& g)
{
    return aogen::with_uniform_albedo(aogen::scenes::to_gbuffer<aogen::vulkan::gbuffer>(g), aogen::finalize_params{}.albedo);
}

// Why `v` cannot run on `s` ("" when it can): its projection is not the camera's, or it
// reads a normal buffer the renderer does not have.
inline std::string cannot_run(const aogen::variant& v, const aogen::scenes::scene& s)
{
    const bool ortho_camera = s.camera.projection == aogen::scenes::projection_kind::orthographic;
    if ((v.projection == aogen::projection_kind::orthographic) != ortho_camera)
        return std::string("the variant is ") + (ortho_camera ? "perspective" : "orthographic") + ", the camera is not";
    if (v.normals != aogen::normal_source::reconstructed && s.renderer.normals == aogen::scenes::normal_space::none)
        return "the variant reads a normal buffer; the scene's renderer has none";
    return "";
}

// The AO radii R for which every setting default_settings derives from R lies in its
// parameter's range (params.hpp): the SSAO, GTAO, VBAO and SAO radii (each a multiple of R),
// SSAO's bias (a fixed fraction of its radius) and the linear blur's sharpness (10 per unit at R = 1, so 10 / R).
struct radius_range {
    double lo, hi;
};
inline radius_range ao_radius_range()
{
    const double sharpness = aogen::blur_params{}.linear_sharpness; // at R = 1
    double hi = report_technique_table.front().max_ao_radius();
    for (const report_technique& t : report_technique_table) hi = std::min(hi, t.max_ao_radius());
    return {sharpness / double(aogen::blur_params::linear_sharpness_range.hi), hi};
}

// aogen::error naming the scene's ao_radius unless the default settings can be made from it.
inline void require_radius_works(const aogen::scenes::scene& s)
{
    const radius_range r = ao_radius_range();
    if (!(s.ao_radius >= r.lo && s.ao_radius <= r.hi))
        aogen::fail(s.source + ": ao_radius", aogen::format_number(s.ao_radius) + " is outside what the variants' settings take",
                    "valid: " + aogen::format_number(r.lo) + ".." + aogen::format_number(r.hi) + " world units");
}

inline aogen::vulkan::chain_settings default_settings(const aogen::variant& v, const aogen::scenes::scene& s)
{
    const float R = float(s.ao_radius);
    aogen::vulkan::chain_settings c;
    for (const report_technique& t : report_technique_table) t.at_radius(c, v, R);
    c.blur = v.blur_depth == aogen::bilateral_depth::seed_raw ? aogen::presets::taos_quality_blur() : aogen::blur_params{};
    c.blur.linear_sharpness = c.blur.linear_sharpness / R;
    const aogen::scenes::scene seen = for_variant(s, v);
    c.camera.world_to_view = seen.camera.world_to_view();
    c.camera.proj = seen.camera.projection_matrix();
    return c;
}

} // namespace aogen_report
