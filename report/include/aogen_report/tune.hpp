// aogen_report/tune.hpp — a search for a variant's parameters against the ray-traced truth:
// the defaults a user should get, found the way XeGTAO's auto-tune finds its own.
//
// WHAT
//   tune(settings) takes variants of one technique, training scenes and validation scenes,
//   and searches for the one set of parameter values with the lowest mean RMSE over the
//   variants and training scenes (each weighted equally, default output: no calibration
//   afterwards; one variant finds its own best values, several the best common ones) by
//   grid_search.hpp's narrowing grid (`points` values per axis, `rounds` rounds) over the
//   axes tune_axes() lists for the technique, or the ones tune_settings::axes names (the
//   others keep the report's defaults).
//   The result carries the best point, its training and validation RMSE, and the same two
//   for the report's defaults (settings.hpp), so what the search buys is read on scenes it
//   did not see.
//
// USAGE
//     aogen_report::tune_settings s;
//     s.variants = {aogen::variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs")};
//     s.train = {...scenes...}, s.validate = {...};
//     aogen_report::tune_result r = aogen_report::tune(ctx, s);
#pragma once

#include "grid_search.hpp"
#include "metrics.hpp"
#include "report_techniques.hpp"
#include "scene_bench.hpp"
#include "settings.hpp"

#include <aogen/vulkan/chain.hpp>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aogen_report {

// The axes tune() can search for `v`'s technique: its row's (report_techniques.hpp).
inline std::vector<tune_axis> technique_axes(const aogen::variant& v) { return report_technique_of(v.tech).tune_axes(v); }

// technique_axes(v), then the one every chain has: blur_sharpness, the depth term's
// sharpness of the blurs and the upsample (blur_params::linear_sharpness) per 1 / R (a
// chain with neither does not read it).
inline std::vector<tune_axis> tune_axes(const aogen::variant& v)
{
    std::vector<tune_axis> axes = technique_axes(v);
    axes.push_back({{"blur_sharpness", 1.0, 100.0}, [] { return double(aogen::blur_params{}.linear_sharpness); },
                    [](aogen::vulkan::chain_settings& c, float R, double x) { c.blur.linear_sharpness = float(x) / R; }});
    return axes;
}

// The axes of `v`'s technique called `names` (all of them when `names` is empty); an
// aogen::error naming an unknown one and the valid names.
inline std::vector<tune_axis> tune_axes(const aogen::variant& v, const std::vector<std::string>& names)
{
    const std::vector<tune_axis> all = tune_axes(v);
    if (names.empty()) return all;
    std::vector<tune_axis> chosen;
    for (const std::string& name : names) {
        auto it = std::find_if(all.begin(), all.end(), [&](const tune_axis& a) { return a.range.name == name; });
        if (it == all.end()) {
            std::string valid;
            for (const tune_axis& a : all) valid += (valid.empty() ? "" : ", ") + a.range.name;
            aogen::fail("--axes", aogen::quote(name) + " is not a parameter of " + std::string(aogen::names::name_of(aogen::technique_names, v.tech, "technique")), "valid: " + valid);
        }
        chosen.push_back(*it);
    }
    return chosen;
}

// The report's default settings for `v` on `s` with the axes' values `x` applied.
inline aogen::vulkan::chain_settings tuned_settings(const aogen::variant& v, const aogen::scenes::scene& s, const std::vector<tune_axis>& axes,
                                                    const std::vector<double>& x)
{
    aogen::vulkan::chain_settings c = default_settings(v, s);
    for (size_t i = 0; i < axes.size(); ++i) axes[i].apply(c, float(s.ao_radius), x[i]);
    return c;
}

struct tune_settings {
    std::vector<aogen::variant> variants; // one technique; searched jointly: one set of values for all
    std::vector<std::string> axes;        // the parameters searched (tune_axes' names); empty: all
    std::vector<aogen::scenes::scene> train, validate;
    int grid = 32;  // reference rays per pixel: grid²
    int points = 5; // values per axis per round
    int rounds = 3;
    std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct tune_result {
    std::vector<std::string> variants;
    std::vector<search_axis> axes;
    std::vector<double> best;                       // one value per axis
    double train_rmse = 0, validate_rmse = 0;       // at best, the mean over variants and scenes
    double default_train = 0, default_validate = 0; // the report's defaults
    std::vector<double> default_point;              // the defaults on the axes
    std::vector<double> variant_default_validate, variant_validate; // per variant, on the validation scenes
    size_t evaluations = 0;
};

namespace detail {

using settings_maker = std::function<aogen::vulkan::chain_settings(const aogen::variant&, const aogen::scenes::scene&)>;

// The mean over `scenes` of variant `v`'s RMSE with the settings `make` gives.
inline double mean_rmse(const aogen::vulkan::chain& c, std::vector<std::unique_ptr<scene_bench>>& scenes, const settings_maker& make)
{
    double sum = 0;
    for (auto& s : scenes) sum += compare(s->run(c, make(c.plan().variant(), s->scene())).full, s->truth().ao, s->truth().valid).rmse;
    return scenes.empty() ? 0.0 : sum / double(scenes.size());
}

} // namespace detail

inline tune_result tune(aogen::vulkan::context& ctx, const tune_settings& t)
{
    if (t.variants.empty()) aogen::fail("tune", "has no variant", "valid: at least one variant");
    tune_result r;
    const std::vector<tune_axis> axes = tune_axes(t.variants.front(), t.axes);
    for (const tune_axis& a : axes) r.axes.push_back(a.range), r.default_point.push_back(a.default_value());
    std::vector<std::unique_ptr<aogen::vulkan::chain>> chains;
    for (const aogen::variant& v : t.variants) {
        if (tune_axes(v).size() != tune_axes(t.variants.front()).size() || v.tech != t.variants.front().tech)
            aogen::fail("tune", aogen::to_name(v) + " is not the technique of " + aogen::to_name(t.variants.front()), "valid: variants of one technique");
        r.variants.push_back(aogen::to_name(v));
        chains.push_back(std::make_unique<aogen::vulkan::chain>(ctx, aogen::codegen::make_plan(v)));
    }
    std::vector<std::unique_ptr<scene_bench>> train, validate;
    for (const aogen::scenes::scene& s : t.train) require_radius_works(s), train.push_back(std::make_unique<scene_bench>(ctx, s, t.grid));
    for (const aogen::scenes::scene& s : t.validate) require_radius_works(s), validate.push_back(std::make_unique<scene_bench>(ctx, s, t.grid));
    t.progress(std::to_string(t.variants.size()) + " variants, " + std::to_string(train.size()) + " training and " + std::to_string(validate.size()) +
               " validation scenes ready");

    // The mean over variants of each variant's mean over `scenes`; per variant into `each`.
    const auto joint = [&](std::vector<std::unique_ptr<scene_bench>>& scenes, const detail::settings_maker& make, std::vector<double>* each) {
        double sum = 0;
        for (size_t i = 0; i < t.variants.size(); ++i) {
            const double e = detail::mean_rmse(*chains[i], scenes, make);
            if (each) each->push_back(e);
            sum += e;
        }
        return sum / double(t.variants.size());
    };
    const auto at = [&axes](const std::vector<double>& x) {
        return [&axes, x](const aogen::variant& v, const aogen::scenes::scene& s) { return tuned_settings(v, s, axes, x); };
    };
    const detail::settings_maker defaults = [](const aogen::variant& v, const aogen::scenes::scene& s) { return default_settings(v, s); };
    r.default_train = joint(train, defaults, nullptr);
    r.default_validate = joint(validate, defaults, &r.variant_default_validate);

    int round = 0;
    size_t seen = 0;
    size_t per_round = 1;
    for (size_t i = 0; i < r.axes.size(); ++i) per_round *= size_t(t.points);
    const grid_search_result g = narrowing_grid_search(r.axes, t.points, t.rounds, [&](const std::vector<double>& x) {
        const double e = joint(train, at(x), nullptr);
        if (++seen % per_round == 0) t.progress("round " + std::to_string(++round) + " done");
        return e;
    });
    r.best = g.best, r.train_rmse = g.value, r.evaluations = g.evaluations;
    r.validate_rmse = joint(validate, at(r.best), &r.variant_validate);
    return r;
}

} // namespace aogen_report
