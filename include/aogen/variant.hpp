// aogen/variant.hpp — one AO shader variant as a value: its axes, its name, its defines.
//
// WHAT
//   A variant fixes, at compile time, every choice an AO pass makes: the technique and
//   its sample counts, the blur, where normals come from, the depth convention and
//   projection, the resolution and the pipeline stage. The shader templates read these
//   as #defines (see `defines()`), so whatever a variant does not use is not in its code.
//
//   Every variant has a canonical, human-readable name that parses back into the same
//   value, e.g.
//       ssao-s16-half-bilateral-gbufworld-std-persp-cs
//       gtao-2x3-full-box-recon-rev-ortho-fs
//   The tokens, in order: technique (+ samples, or slices x steps), resolution, blur,
//   normals, depth, projection, stage; then only the axes that differ from their
//   default, each a token of its own: `rawdepth` (seed-exact bilateral depth term),
//   `pc` (point-cloud fallback), `rc004` (seed 004's range check), `powint` (Unique
//   Engine's power/intensity output), `wg16x16` (workgroup size).
//
// USAGE
//     aogen::variant v;                          // the defaults: ssao-s16-half-bilateral-...
//     v.ssao_samples = 32;
//     std::string name = aogen::to_name(v);      // "ssao-s32-half-bilateral-gbufworld-std-persp-cs"
//     aogen::variant w = aogen::variant_from_name(name);   // == v
//     aogen::validate(v);                        // throws aogen::error naming the axis
//
// WHY
//   Structural axes are preprocessor defines rather than specialization constants:
//   spirv-opt's performance passes do not fold specialization constants, and a define
//   removes the code outright, so the saving is real in every target language.
#pragma once

#include "error.hpp"
#include "math.hpp"
#include "names.hpp"
#include "params.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace aogen {

enum class technique { ssao, gtao };
inline constexpr std::array<enum_name<technique>, 2> technique_names{{
    {technique::ssao, "ssao"},
    {technique::gtao, "gtao"},
}};

enum class pipeline_stage { compute, fragment };
inline constexpr std::array<enum_name<pipeline_stage>, 2> pipeline_stage_names{{
    {pipeline_stage::compute, "compute"},
    {pipeline_stage::fragment, "fragment"},
}};

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

// Every axis of a variant, with DESIGN.md's defaults.
struct variant {
    technique tech = technique::ssao;
    int ssao_samples = 16;     // ssao: 1..256
    int gtao_slices = 2;       // gtao: 1..16
    int gtao_steps = 3;        // gtao: steps per side, 1..16
    blur_mode blur = blur_mode::bilateral;
    bilateral_depth blur_depth = bilateral_depth::linear; // bilateral only
    normal_source normals = normal_source::gbuffer_world;
    bool point_cloud_fallback = false; // ssao only (seed 004)
    depth_convention depth = depth_convention::standard;
    projection_kind projection = projection_kind::perspective;
    bool half_resolution = true;
    pipeline_stage stage = pipeline_stage::compute;
    int workgroup_x = 8, workgroup_y = 8; // compute only: 1..32 each, at most 1024 invocations
    ssao_range_check range_check = ssao_range_check::taos; // ssao only
    ssao_output output = ssao_output::strength;            // ssao only
};

// ---------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------

inline void validate(const variant& v)
{
    names::require_listed(technique_names, v.tech, "technique");
    require_range("ssao samples", v.ssao_samples, ssao_params::samples_range.lo, ssao_params::samples_range.hi);
    require_range("gtao slices", v.gtao_slices, gtao_params::slices_range.lo, gtao_params::slices_range.hi);
    require_range("gtao steps", v.gtao_steps, gtao_params::steps_range.lo, gtao_params::steps_range.hi);
    names::require_listed(blur_mode_names, v.blur, "blur");
    names::require_listed(bilateral_depth_names, v.blur_depth, "bilateral depth");
    names::require_listed(normal_source_names, v.normals, "normals");
    names::require_listed(depth_convention_names, v.depth, "depth");
    names::require_listed(projection_kind_names, v.projection, "projection");
    names::require_listed(pipeline_stage_names, v.stage, "stage");
    names::require_listed(ssao_range_check_names, v.range_check, "range check");
    names::require_listed(ssao_output_names, v.output, "output");
    require_range("workgroup x", v.workgroup_x, 1, 32);
    require_range("workgroup y", v.workgroup_y, 1, 32);
    if (v.workgroup_x * v.workgroup_y > 1024)
        fail("workgroup", std::to_string(v.workgroup_x) + "x" + std::to_string(v.workgroup_y) + " is over 1024 invocations",
             "valid: x * y <= 1024");
    if (v.point_cloud_fallback && v.tech != technique::ssao)
        fail("point-cloud fallback", "is an SSAO feature (seed 004), not available with gtao", "valid: off with gtao");
}

// ---------------------------------------------------------------------------------
// Passes and their defines
// ---------------------------------------------------------------------------------

// A variant runs as a chain: the AO pass, then its blur passes.
enum class pass_kind { ao, blur_x, blur_y, blur_box };
inline constexpr std::array<enum_name<pass_kind>, 4> pass_kind_names{{
    {pass_kind::ao, "ao"},
    {pass_kind::blur_x, "blur_x"},
    {pass_kind::blur_y, "blur_y"},
    {pass_kind::blur_box, "blur_box"},
}};

inline std::vector<pass_kind> passes(const variant& v)
{
    switch (v.blur) {
    case blur_mode::bilateral: return {pass_kind::ao, pass_kind::blur_x, pass_kind::blur_y};
    case blur_mode::box: return {pass_kind::ao, pass_kind::blur_box};
    case blur_mode::none: return {pass_kind::ao};
    }
    names::fail_unlisted(blur_mode_names, v.blur, "blur");
}

struct define {
    std::string name;
    std::string value; // empty: a plain #define NAME
};

// The #defines the templates read for one pass of `v`. Names are AO_<AXIS>_<VALUE> for
// choices (exactly one of each group is defined) and AO_<AXIS> N for counts.
inline std::vector<define> defines(const variant& v, pass_kind pass)
{
    validate(v);
    std::vector<define> d;
    auto choice = [&d](const char* axis, const char* value) {
        std::string name = std::string("AO_") + axis + "_";
        for (const char* c = value; *c; ++c) name += static_cast<char>(*c >= 'a' && *c <= 'z' ? *c - 'a' + 'A' : *c);
        d.push_back({name, ""});
    };
    auto count = [&d](const char* name, int value) { d.push_back({name, std::to_string(value)}); };

    choice("STAGE", names::name_of(pipeline_stage_names, v.stage, "stage"));
    if (v.stage == pipeline_stage::compute) count("AO_WORKGROUP_X", v.workgroup_x), count("AO_WORKGROUP_Y", v.workgroup_y);
    choice("DEPTH", names::name_of(depth_convention_names, v.depth, "depth"));
    choice("PROJECTION", names::name_of(projection_kind_names, v.projection, "projection"));
    if (v.half_resolution) d.push_back({"AO_HALF_RESOLUTION", ""});
    choice("PASS", names::name_of(pass_kind_names, pass, "pass"));
    if (pass == pass_kind::ao) {
        choice("TECHNIQUE", names::name_of(technique_names, v.tech, "technique"));
        choice("NORMALS", names::name_of(normal_source_names, v.normals, "normals"));
        if (v.tech == technique::ssao) {
            count("AO_SSAO_SAMPLES", v.ssao_samples);
            choice("RANGE_CHECK", names::name_of(ssao_range_check_names, v.range_check, "range check"));
            choice("OUTPUT", names::name_of(ssao_output_names, v.output, "output"));
            if (v.point_cloud_fallback) d.push_back({"AO_POINT_CLOUD_FALLBACK", ""});
        } else {
            count("AO_GTAO_SLICES", v.gtao_slices);
            count("AO_GTAO_STEPS", v.gtao_steps);
        }
    } else if (pass != pass_kind::blur_box) {
        choice("BILATERAL_DEPTH", names::name_of(bilateral_depth_names, v.blur_depth, "bilateral depth"));
    }
    return d;
}

} // namespace aogen
