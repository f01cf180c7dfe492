// aogen/selection.hpp — from what a renderer has and needs to the variant it should run.
//
// WHAT
//   A scene_needs says what the renderer provides and wants: which normals its G-buffer
//   holds (world space, view space, or none), whether it draws point clouds, its depth
//   convention and projection, the blur it wants and whether half resolution is fine.
//   select() turns a base variant (technique, sample counts, stage) and those needs
//   into the variant that compiles exactly what the scene uses, and says, feature by
//   feature, what was compiled in and what was left out and why — the manifest records
//   both ("point-cloud fallback: the scene has no point clouds").
//
// USAGE
//     aogen::scene_needs scene;              // G-buffer world normals, no point clouds, ...
//     scene.normals = aogen::normal_source::reconstructed;   // no normal buffer
//     aogen::selection s = aogen::select(aogen::variant{}, scene);
//     s.v;          // ...-recon-...
//     s.left_out;   // {"normal buffer input", "the renderer has no normal buffer"}, ...
//
//   features(v) alone describes a variant without a scene; the reasons then say which
//   axis value left a feature out.
#pragma once

#include "techniques.hpp"
#include "variant.hpp"

#include <string>
#include <vector>

namespace aogen {

struct scene_needs {
    // Normals the renderer's G-buffer holds; reconstructed: it has none.
    normal_source normals = normal_source::gbuffer_world;
    bool point_clouds = false;
    depth_convention depth = depth_convention::standard;
    projection_kind projection = projection_kind::perspective;
    blur_mode blur = blur_mode::bilateral;
    bool half_resolution_ok = true;
};

struct left_out_feature {
    std::string feature;
    std::string why;
};

struct feature_list {
    std::vector<std::string> compiled;      // what the variant's code contains
    std::vector<left_out_feature> left_out; // what it does not, with the reason
};

struct selection {
    variant v;
    feature_list features;
};

namespace detail {

// One optional feature: compiled in when `present`, else left out for `why`.
inline void feature(feature_list& list, bool present, const std::string& name, const std::string& why)
{
    if (present) list.compiled.push_back(name);
    else list.left_out.push_back({name, why});
}

} // namespace detail

// What `v` compiles in and leaves out. With a scene, the reasons speak of the scene.
inline feature_list features(const variant& v, const scene_needs* scene = nullptr)
{
    validate(v);
    feature_list f;
    const bool ssao = v.tech == technique::ssao;
    const std::string tech = names::name_of(technique_names, v.tech, "technique");
    f.compiled.push_back(technique_of(v.tech).counts_text(v));
    const std::string no_pc = scene ? "the scene has no point clouds" : "not requested (variant without -pc)";
    if (ssao) detail::feature(f, v.point_cloud_fallback, "point-cloud fallback", no_pc);
    else f.left_out.push_back({"point-cloud fallback", "an SSAO feature; this variant is " + tech});

    const bool gbuffer = v.normals != normal_source::reconstructed;
    detail::feature(f, gbuffer, "normal buffer input", scene ? "the renderer has no normal buffer" : "normals are reconstructed");
    detail::feature(f, !gbuffer, "normal reconstruction from depth",
                    scene ? "the renderer has G-buffer normals" : "normals come from the G-buffer");
    if (gbuffer)
        detail::feature(f, v.normals == normal_source::gbuffer_world, "world-to-view normal rotation",
                        "the G-buffer normals are already in view space");

    const std::string blur_why = scene ? std::string("the scene wants ") + to_name(v.blur) + " blur"
                                       : std::string("the variant's blur is ") + to_name(v.blur);
    detail::feature(f, v.blur == blur_mode::bilateral, "bilateral blur", blur_why);
    detail::feature(f, v.blur == blur_mode::box, "box blur", blur_why);
    detail::feature(f, v.blur == blur_mode::denoise, "edge-aware denoise", blur_why);
    detail::feature(f, v.blur == blur_mode::denoise3, "3x3 denoise of the AO pass's edges", blur_why);
    f.compiled.push_back(std::string("depth: ") + names::name_of(depth_convention_names, v.depth, "depth"));
    f.compiled.push_back(std::string("projection: ") + names::name_of(projection_kind_names, v.projection, "projection"));
    f.compiled.push_back(v.half_resolution ? "half resolution" : "full resolution");
    if (!v.half_resolution)
        f.left_out.push_back({"half-resolution downsampling", scene && !scene->half_resolution_ok
                                                                  ? "the scene does not accept half resolution"
                                                                  : "the variant runs at full resolution"});
    detail::feature(f, has_upsample_pass(v), "depth-aware upsample",
                    v.half_resolution ? "the variant leaves its half-resolution target to the caller (-nearest)"
                                      : "the variant runs at full resolution");
    return f;
}

// The variant that runs `base`'s technique with exactly what `scene` has and needs.
inline selection select(variant base, const scene_needs& scene)
{
    base.normals = scene.normals;
    base.point_cloud_fallback = base.tech == technique::ssao && scene.point_clouds;
    base.depth = scene.depth;
    base.projection = scene.projection;
    base.blur = scene.blur;
    if (!scene.half_resolution_ok) base.half_resolution = false;
    const variant v = canonical(base);
    return {v, features(v, &scene)};
}

} // namespace aogen
