// aogen_tools/variant_spec.hpp — variant specs and scene files, read from JSON.
//
// A variant spec (`aogen generate --variants SPEC.json`) names variants and/or
// matrices whose axes are lists of values:
//   {"variants": ["ssao-s16-half-bilateral-gbufworld-std-persp-cs"],
//    "matrices": [{"technique": ["ssao"], "samples": [8, 16], "blur": ["box", "none"],
//                  "resolution": ["half"], "stage": ["compute", "fragment"]}]}
// Matrix keys (each a list; an absent key keeps the default variant's value):
//   technique, samples, slices, steps, blur, bilateral_depth, normals, point_cloud,
//   depth, projection, resolution (half|full), stage, range_check, output,
//   decisions (smooth|step: SSAO's per-sample decisions, variant extra -step),
//   precision (fp32|fp16: 16-bit arithmetic in the AO pass, variant extra -fp16),
//   upsample (depth_aware|nearest: how a half-resolution target reaches the screen,
//   variant extra -nearest), multi_bounce (off|on|gbuffer: the last pass's multi-bounce
//   with one albedo, variant extra -mb, or each pixel's from the albedo G-buffer, -mbg), bent_normals (off|on: bent normals beside the AO, variant extra -bn; GTAO
//   and VBAO compute variants).
//
// A scene file (`--scene SCENE.json`) says what the renderer has and needs:
//   {"normals": "gbuffer_world" | "gbuffer_view" | "reconstructed", "point_clouds": false,
//    "depth": "standard" | "reversed" | "reversed_infinite",
//    "projection": "perspective" | "orthographic", "blur": "bilateral" | "box" | "denoise" | "none",
//    "half_resolution_ok": true}
// Every key is optional; unknown keys are errors.
#pragma once

#include "json_reader.hpp"

#include <algorithm>

#include <aogen/matrix.hpp>
#include <aogen/selection.hpp>

namespace aogen::tools {

// The most variants one spec (one run of the tools) makes, and the most combinations a
// matrix of it may list before equal ones collapse: a spec that would make 27 648 is
// refused at once, naming the count, rather than run for minutes.
inline constexpr size_t max_spec_variants = 2048;
inline constexpr size_t max_matrix_combinations = 100000;

// aogen::error unless `count` variants are at most max_spec_variants.
inline void require_variant_count(const std::string& subject, size_t count)
{
    if (count > max_spec_variants)
        fail(subject, "makes " + std::to_string(count) + " variants",
             "valid: at most " + std::to_string(max_spec_variants) + " per run; split it into smaller specs");
}

namespace detail {

// The variants of the matrix at `in`, bounded before and after it is expanded.
inline std::vector<variant> bounded_expand(const variant_matrix& m, const json_reader& in)
{
    if (combinations(m, max_matrix_combinations) > max_matrix_combinations)
        fail(in.path(), "lists more than " + std::to_string(max_matrix_combinations) + " combinations of its axes",
             "valid: at most " + std::to_string(max_matrix_combinations) + ", making at most " + std::to_string(max_spec_variants) + " variants");
    std::vector<variant> out = expand(m);
    require_variant_count(in.path(), out.size());
    return out;
}

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
        if (s != on && s != off) fail(list.at(i).path(), quote(s) + " is not a known name", std::string("valid: ") + on + ", " + off);
        values.push_back(s == on);
    }
    if (values.empty()) fail(list.path(), "is empty", "valid: at least one value");
    return values;
}

// An axis only one technique has, listed in a matrix without that technique, would be
// ignored without a word: refuse it instead.
inline void require_axes_used(const json_reader& in, const std::vector<technique>& techniques)
{
    const bool ssao = std::find(techniques.begin(), techniques.end(), technique::ssao) != techniques.end();
    const bool slices = std::any_of(techniques.begin(), techniques.end(), has_slices);
    const bool samples = std::any_of(techniques.begin(), techniques.end(), has_samples);
    if (in.has("samples") && !samples)
        fail(key_path(in.path(), "samples"), "is an SSAO and SAO axis, and this matrix makes neither", "valid: leave it out, or add \"ssao\" or \"sao\" to technique");
    for (const char* key : {"point_cloud", "range_check", "output", "decisions"})
        if (in.has(key) && !ssao)
            fail(key_path(in.path(), key), "is an SSAO axis, and this matrix makes no SSAO variant", "valid: leave it out, or add \"ssao\" to technique");
    for (const char* key : {"slices", "steps"})
        if (in.has(key) && !slices)
            fail(key_path(in.path(), key), "is a GTAO and VBAO axis, and this matrix makes neither", "valid: leave it out, or add \"gtao\" or \"vbao\" to technique");
    if (in.has("bent_normals") && !slices)
        fail(key_path(in.path(), "bent_normals"), "is a GTAO and VBAO axis (bent normals come from their slices), and this matrix makes neither",
             "valid: leave it out, or add \"gtao\" or \"vbao\" to technique");
}

inline variant_matrix matrix_from_json(const json_reader& in)
{
    in.only_keys({"technique", "samples", "slices", "steps", "blur", "bilateral_depth", "normals", "point_cloud",
                  "depth", "projection", "resolution", "stage", "range_check", "output", "decisions", "precision", "upsample", "multi_bounce",
                  "bent_normals", "history"});
    variant_matrix m;
    if (in.has("technique")) m.techniques = name_list(in, "technique", technique_names);
    require_axes_used(in, m.techniques);
    if (in.has("samples")) m.samples = int_list(in, "samples", 1, 256);
    if (in.has("slices")) m.slices = int_list(in, "slices", 1, 16);
    if (in.has("steps")) m.steps = int_list(in, "steps", 1, 16);
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
    if (in.has("decisions")) m.decisions = name_list(in, "decisions", ssao_decisions_names);
    if (in.has("precision")) m.fp16 = bool_list(in, "precision", "fp16", "fp32");
    if (in.has("upsample")) m.upsample = name_list(in, "upsample", upsample_mode_names);
    if (in.has("multi_bounce")) m.multi_bounce = name_list(in, "multi_bounce", multi_bounce_mode_names);
    if (in.has("bent_normals")) m.bent_normals = bool_list(in, "bent_normals", "on", "off");
    if (in.has("history")) m.history = name_list(in, "history", history_mode_names);
    return m;
}

} // namespace detail

inline std::vector<variant> variants_from_json(const json_reader& in)
{
    in.only_keys({"variants", "matrices"});
    std::vector<variant> out;
    if (in.has("variants")) {
        const json_reader list = in.array("variants");
        require_variant_count(list.path(), list.size());
        for (size_t i = 0; i < list.size(); ++i) {
            const std::string name = list.at(i).as_string(); // names its own path when it is no string
            try {
                append_unique(out, variant_from_name(name));
            } catch (const error& e) {
                fail(list.at(i).path(), e.what(), ""); // the name's problem, at its place in the file
            }
        }
    }
    if (in.has("matrices")) {
        const json_reader list = in.array("matrices");
        for (size_t i = 0; i < list.size(); ++i) {
            for (const variant& v : detail::bounded_expand(detail::matrix_from_json(list.at(i)), list.at(i))) append_unique(out, v);
            require_variant_count(in.path(), out.size());
        }
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
