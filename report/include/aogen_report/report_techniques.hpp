// aogen_report/report_techniques.hpp — what the report does differently per technique: one row each.
//
// WHAT
//   report_technique_table   one row per technique, in aogen::technique_names' order (the
//                            library's own rows are aogen/techniques.hpp's):
//     at_radius        its settings at a scene's AO radius R (settings.hpp's default_settings):
//                      the tuned defaults (aogen/params.hpp) with every length scaled by R
//     max_ao_radius    the largest R for which those settings stay in their ranges
//     tune_axes        the parameters `aogen_tune` searches for it, with their ranges
//     fetch_floor      its AO template and the report/floor/ files that stand in for it in
//                      the fetch floor (fetch_floor.hpp)
//     style            its marker in the plot (svg_plot.hpp): colour and shape
//   report_technique_of(t), report_technique_named(name)
//
// ERRORS
//   A row left out, out of order or with a member unset does not compile (the static_assert
//   below); report_technique_of names a value outside the enumeration.
//
// WHY
//   Each of these was a list or an if-chain in its own file (settings.hpp, tune.hpp,
//   fetch_floor.hpp, svg_plot.hpp); a technique added to the library now has one row to
//   write here, and the compiler says so.
#pragma once

#include "grid_search.hpp"

#include <aogen/chain_inputs.hpp>
#include <aogen/params.hpp>
#include <aogen/presets.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace aogen_report {

// One parameter tune() can search: its range, the report's default on it (settings.hpp),
// and how a value reaches the chain's settings for a scene of AO radius R.
struct tune_axis {
    search_axis range;
    double (*default_value)();
    void (*apply)(aogen::chain_settings& c, float R, double x);
};

// A technique's marker in the plot.
struct technique_style {
    const char* colour;
    const char* shape; // circle, triangle, square, diamond
};

struct report_technique {
    aogen::technique id;
    void (*at_radius)(aogen::chain_settings& c, const aogen::variant& v, float R);
    double (*max_ao_radius)();
    std::vector<tune_axis> (*tune_axes)(const aogen::variant& v);
    const char* ao_template;                  // its AO pass's template ("gtao.glsl")
    std::array<const char*, 2> fetch_floor;   // report/floor/ files standing in for it, in order (nullptr: none)
    technique_style style;
};

namespace detail {

using settings = aogen::chain_settings; // aogen::vulkan::chain_settings is this one

// SSAO takes the tuned defaults (params.hpp), which need the smooth decisions; the seeds'
// step decisions and the power/intensity output (which the tuner does not search) run the
// seeds' values at the radius R. The bias keeps its ratio to the radius.
inline void ssao_at_radius(settings& c, const aogen::variant& v, float R)
{
    const bool seed_ssao = v.output == aogen::ssao_output::power_intensity || v.decisions == aogen::ssao_decisions::step;
    c.ssao = !seed_ssao ? aogen::ssao_params{}
             : v.output == aogen::ssao_output::power_intensity ? aogen::presets::unique_engine_ssao().settings.ssao
                                                               : aogen::presets::taos_ssao().settings.ssao;
    const float ssao_radius = seed_ssao ? R : aogen::ssao_params::radius_per_ao_radius * R;
    c.ssao.bias = c.ssao.bias / c.ssao.radius * ssao_radius;
    c.ssao.radius = ssao_radius;
}

// The larger of SSAO's two radii (the tuned one), and the bias at its share of it.
inline double ssao_max_ao_radius()
{
    const aogen::ssao_params ssao{};
    const double ssao_scale = aogen::ssao_params::radius_per_ao_radius; // > 1, the larger of the two outputs'
    const double bias_ratio = ssao.bias / ssao.radius;
    return std::min(double(aogen::ssao_params::radius_range.hi) / ssao_scale,
                    double(aogen::ssao_params::bias_range.hi) / (bias_ratio * ssao_scale));
}

//   ssao   radius_scale, strength (1 − occlusion·strength); the bias keeps its ratio to
//          the radius, as the presets have it
inline std::vector<tune_axis> ssao_tune_axes(const aogen::variant& v)
{
    if (v.output == aogen::ssao_output::power_intensity)
        aogen::fail("tune", aogen::to_name(v) + " has the power/intensity output", "valid: GTAO, VBAO, or SSAO with the strength output");
    return {
        {{"radius_scale", 0.5, 4.0}, [] { return double(aogen::ssao_params::radius_per_ao_radius); },
         [](settings& c, float R, double x) {
             const float radius = float(x) * R;
             c.ssao.bias *= radius / c.ssao.radius;
             c.ssao.radius = radius;
         }},
        {{"strength", 0.5, 8.0}, [] { return double(aogen::ssao_params{}.strength); },
         [](settings& c, float, double x) { c.ssao.strength = float(x); }},
    };
}

//   gtao   radius_scale (the radius as a multiple of the scene's R), strength (the final
//          power: visibility^strength), thickness_bias (the cut-off radius·(1 + 10·t)),
//          falloff_range (the share of the cut-off distance a sample fades over),
//          thin_occluder (how much longer depth offsets count)
inline std::vector<tune_axis> gtao_tune_axes(const aogen::variant&)
{
    return {
        {{"radius_scale", 0.5, 2.0}, [] { return double(aogen::gtao_params::radius_per_ao_radius); },
         [](settings& c, float R, double x) { c.gtao.radius = float(x) * R; }},
        {{"strength", 0.25, 3.0}, [] { return double(aogen::gtao_params{}.strength); }, [](settings& c, float, double x) { c.gtao.strength = float(x); }},
        {{"thickness_bias", 0.0, 0.6}, [] { return double(aogen::gtao_params{}.thickness_bias); },
         [](settings& c, float, double x) { c.gtao.thickness_bias = float(x); }},
        {{"falloff_range", 0.0, 1.0}, [] { return double(aogen::gtao_params{}.falloff_range); },
         [](settings& c, float, double x) { c.gtao.falloff_range = float(x); }},
        {{"thin_occluder", 0.0, 4.0}, [] { return double(aogen::gtao_params{}.thin_occluder); },
         [](settings& c, float, double x) { c.gtao.thin_occluder = float(x); }},
    };
}

//   vbao   radius_scale, strength, thickness (each sample's depth, a fraction of the radius)
inline std::vector<tune_axis> vbao_tune_axes(const aogen::variant&)
{
    return {
        {{"radius_scale", 0.5, 2.0}, [] { return double(aogen::vbao_params::radius_per_ao_radius); },
         [](settings& c, float R, double x) { c.vbao.radius = float(x) * R; }},
        {{"strength", 0.25, 3.0}, [] { return double(aogen::vbao_params{}.strength); }, [](settings& c, float, double x) { c.vbao.strength = float(x); }},
        {{"thickness", 0.05, 2.0}, [] { return double(aogen::vbao_params{}.thickness); },
         [](settings& c, float, double x) { c.vbao.thickness = float(x); }},
    };
}

//   sao    radius_scale, intensity (the Alchemy sum's sigma), bias (a share of the radius)
inline std::vector<tune_axis> sao_tune_axes(const aogen::variant&)
{
    return {
        {{"radius_scale", 0.5, 4.0}, [] { return double(aogen::sao_params::radius_per_ao_radius); },
         [](settings& c, float R, double x) { c.sao.radius = float(x) * R; }},
        {{"intensity", 0.25, 8.0}, [] { return double(aogen::sao_params{}.intensity); },
         [](settings& c, float, double x) { c.sao.intensity = float(x); }},
        {{"bias", 0.0, 0.2}, [] { return double(aogen::sao_params{}.bias); }, [](settings& c, float, double x) { c.sao.bias = float(x); }},
    };
}

} // namespace detail

inline constexpr std::array<report_technique, aogen::technique_names.size()> report_technique_table{{
    {aogen::technique::ssao, detail::ssao_at_radius, detail::ssao_max_ao_radius, detail::ssao_tune_axes, "ssao.glsl", {"ssao.glsl", nullptr},
     {"#1f77b4", "circle"}},
    {aogen::technique::gtao,
     [](detail::settings& c, const aogen::variant&, float R) {
         c.gtao = aogen::gtao_params{}; // the tuned defaults (params.hpp)
         c.gtao.radius = aogen::gtao_params::radius_per_ao_radius * R;
     },
     [] { return aogen::gtao_params::radius_range.hi / double(aogen::gtao_params::radius_per_ao_radius); }, detail::gtao_tune_axes, "gtao.glsl",
     {"gtao.glsl", nullptr}, {"#d62728", "triangle"}},
    {aogen::technique::vbao,
     [](detail::settings& c, const aogen::variant&, float R) {
         c.vbao = aogen::vbao_params{}; // its thickness is a share of the radius: it scales by itself
         c.vbao.radius = aogen::vbao_params::radius_per_ao_radius * R;
     },
     [] { return aogen::vbao_params::radius_range.hi / double(aogen::vbao_params::radius_per_ao_radius); }, detail::vbao_tune_axes,
     // VBAO fetches what GTAO fetches (the same slices and steps): floor/vbao.glsl renames the
     // counts, then floor/gtao.glsl's loop follows.
     "vbao.glsl", {"vbao.glsl", "gtao.glsl"}, {"#2ca02c", "square"}},
    {aogen::technique::sao,
     [](detail::settings& c, const aogen::variant&, float R) {
         c.sao = aogen::sao_params{}; // its bias is a share of the radius: nothing else scales
         c.sao.radius = aogen::sao_params::radius_per_ao_radius * R;
     },
     [] { return aogen::sao_params::radius_range.hi / double(aogen::sao_params::radius_per_ao_radius); }, detail::sao_tune_axes, "sao.glsl",
     {"sao.glsl", nullptr}, {"#9467bd", "diamond"}},
}};

namespace detail {

// Row i is technique i with every member set (a row left out is a value-initialised one).
constexpr bool report_technique_table_complete()
{
    for (std::size_t i = 0; i < report_technique_table.size(); ++i) {
        const report_technique& t = report_technique_table[i];
        if (t.id != aogen::technique_names[i].value || !t.at_radius || !t.max_ao_radius || !t.tune_axes || !t.ao_template ||
            !t.fetch_floor[0] || !t.style.colour || !t.style.shape)
            return false;
    }
    return true;
}

} // namespace detail

static_assert(detail::report_technique_table_complete(),
              "report_technique_table: every technique of aogen::technique_names needs its row, in the enumeration's order, with every member set");

inline const report_technique& report_technique_of(aogen::technique t)
{
    aogen::names::require_listed(aogen::technique_names, t, "technique");
    return report_technique_table[static_cast<std::size_t>(t)];
}

// The row whose technique is called `name` ("gtao"), or nullptr.
inline const report_technique* report_technique_named(const std::string& name)
{
    for (const report_technique& t : report_technique_table)
        if (name == aogen::to_name(t.id)) return &t;
    return nullptr;
}

} // namespace aogen_report
