// aogen_tools/variant_spec.hpp — variant specs and scene files, read from JSON.
//
// A variant spec (`aogen generate --variants SPEC.json`) names variants and/or
// matrices whose axes are lists of values:
//   {"variants": ["ssao-s16-half-bilateral-gbufworld-std-persp-cs"],
//    "matrices": [{"technique": ["ssao"], "samples": [8, 16], "blur": ["box", "none"],
//                  "resolution": ["half"], "stage": ["compute", "fragment"]}]}
// Matrix keys (each a list; an absent key keeps the default variant's value):
//   technique, samples, slices, steps, blur, bilateral_depth, normals, point_cloud,
//   depth, projection, resolution (half|full), stage, range_check, output.
//
// A scene file (`--scene SCENE.json`) says what the renderer has and needs:
//   {"normals": "gbuffer_world" | "gbuffer_view" | "reconstructed", "point_clouds": false,
//    "depth": "standard" | "reversed" | "reversed_infinite",
//    "projection": "perspective" | "orthographic", "blur": "bilateral" | "box" | "none",
//    "half_resolution_ok": true}
// Every key is optional; unknown keys are errors.
#pragma once

#include "json_reader.hpp"

#include <aogen/matrix.hpp>
#include <aogen/selection.hpp>

namespace aogen::tools {

namespace detail {

// A list of enum names under `key`, each read through `table`.
template <class E, size_t N>
std::vector<E> name_list(const json_reader& in, const char* key, const std::array<enum_name<E>, N>& table)
{
    std::vector<E> values;
    const json_reader list = in.array(key);
    for (size_t i = 0; i < list.size(); ++i) values.push_back(names::value_of(table, list.at(i).as_string(), list.at(i).path()));
    if (values.empty()) fail(list.path(), "is empty", "valid: at least one value");
    return values;
}

inline std::vector<int> int_list(const json_reader& in, const char* key, int lo, int hi)
{
    std::vector<int> values;
    const json_reader list = in.array(key);
    for (size_t i = 0; i < list.size(); ++i) values.push_back(static_cast<int>(list.at(i).as_unsigned(lo, hi)));
    if (values.empty()) fail(list.path(), "is empty", "valid: at least one value");
    return values;
}

inline std::vector<bool> bool_list(const json_reader& in, const char* key, const char* on, const char* off)
{
    std::vector<bool> values;
    const json_reader list = in.array(key);
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string s = list.at(i).as_string();
        if (s != on && s != off) fail(list.at(i).path(), "'" + s + "' is not a known name", std::string("valid: ") + on + ", " + off);
        values.push_back(s == on);
    }
    if (values.empty()) fail(list.path(), "is empty", "valid: at least one value");
    return values;
}

inline variant_matrix matrix_from_json(const json_reader& in)
{
    in.only_keys({"technique", "samples", "slices", "steps", "blur", "bilateral_depth", "normals", "point_cloud",
                  "depth", "projection", "resolution", "stage", "range_check", "output"});
    variant_matrix m;
    if (in.has("technique")) m.techniques = name_list(in, "technique", technique_names);
    if (in.has("samples")) m.ssao_samples = int_list(in, "samples", 1, 256);
    if (in.has("slices")) m.gtao_slices = int_list(in, "slices", 1, 16);
    if (in.has("steps")) m.gtao_steps = int_list(in, "steps", 1, 16);
    if (in.has("blur")) m.blur = name_list(in, "blur", blur_mode_names);
    if (in.has("bilateral_depth")) m.blur_depth = name_list(in, "bilateral_depth", bilateral_depth_names);
    if (in.has("normals")) m.normals = name_list(in, "normals", normal_source_names);
    if (in.has("point_cloud")) m.point_cloud_fallback = bool_list(in, "point_cloud", "on", "off");
    if (in.has("depth")) m.depth = name_list(in, "depth", depth_convention_names);
    if (in.has("projection")) m.projection = name_list(in, "projection", projection_kind_names);
    if (in.has("resolution")) m.half_resolution = bool_list(in, "resolution", "half", "full");
    if (in.has("stage")) m.stage = name_list(in, "stage", pipeline_stage_names);
    if (in.has("range_check")) m.range_check = name_list(in, "range_check", ssao_range_check_names);
    if (in.has("output")) m.output = name_list(in, "output", ssao_output_names);
    return m;
}

} // namespace detail

inline std::vector<variant> variants_from_json(const json_reader& in)
{
    in.only_keys({"variants", "matrices"});
    std::vector<variant> out;
    if (in.has("variants")) {
        const json_reader list = in.array("variants");
        for (size_t i = 0; i < list.size(); ++i) {
            try {
                append_unique(out, variant_from_name(list.at(i).as_string()));
            } catch (const error& e) {
                fail(list.at(i).path(), e.what(), "");
            }
        }
    }
    if (in.has("matrices")) {
        const json_reader list = in.array("matrices");
        for (size_t i = 0; i < list.size(); ++i)
            for (const variant& v : expand(detail::matrix_from_json(list.at(i)))) append_unique(out, v);
    }
    if (out.empty()) fail(in.path(), "names no variant", "valid: a non-empty \"variants\" or \"matrices\" list");
    return out;
}

inline scene_needs scene_from_json(const json_reader& in)
{
    in.only_keys({"normals", "point_clouds", "depth", "projection", "blur", "half_resolution_ok"});
    scene_needs s;
    if (in.has("normals")) s.normals = names::value_of(normal_source_names, in.string("normals"), in.path() + ".normals");
    if (in.has("point_clouds")) s.point_clouds = in.boolean("point_clouds");
    if (in.has("depth")) s.depth = names::value_of(depth_convention_names, in.string("depth"), in.path() + ".depth");
    if (in.has("projection"))
        s.projection = names::value_of(projection_kind_names, in.string("projection"), in.path() + ".projection");
    if (in.has("blur")) s.blur = names::value_of(blur_mode_names, in.string("blur"), in.path() + ".blur");
    if (in.has("half_resolution_ok")) s.half_resolution_ok = in.boolean("half_resolution_ok");
    return s;
}

} // namespace aogen::tools
