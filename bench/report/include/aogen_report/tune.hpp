// aogen_report/tune.hpp — a search for a variant's parameters against the ray-traced truth:
// the defaults a user should get, found the way XeGTAO's auto-tune finds its own.
//
// WHAT
//   tune(settings) takes variants of one technique, training scenes and validation scenes,
//   and searches for the one set of parameter values with the lowest mean RMSE over the
//   variants and training scenes (each weighted equally, default output: no calibration
//   afterwards; one variant finds its own best values, several the best common ones) by grid_search.hpp's narrowing grid
//   (`points` values per axis, `rounds` rounds). The axes (tune_axes):
//     gtao   radius_scale (the radius as a multiple of the scene's R), strength (the final
//            power: visibility^strength), thickness_bias (the cut-off radius·(1 + 10·t));
//     vbao   radius_scale, strength, thickness (each sample's depth, a fraction of the radius);
//     ssao   radius_scale, strength (1 − occlusion·strength); the bias stays 5 % of the
//            radius, as the presets have it.
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
#include "reference.hpp"
#include "settings.hpp"
#include "suite.hpp"

#include <aogen/vulkan/chain.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace aogen_report {

// The axes tune() searches for `v`'s technique.
inline std::vector<search_axis> tune_axes(const aogen::variant& v)
{
    if (v.tech == aogen::technique::gtao) return {{"radius_scale", 0.5, 2.0}, {"strength", 0.25, 3.0}, {"thickness_bias", 0.0, 0.6}};
    if (v.tech == aogen::technique::vbao) return {{"radius_scale", 0.5, 2.0}, {"strength", 0.25, 3.0}, {"thickness", 0.05, 2.0}};
    if (v.output == aogen::ssao_output::power_intensity)
        aogen::fail("tune", aogen::to_name(v) + " has the power/intensity output", "valid: GTAO, VBAO, or SSAO with the strength output");
    return {{"radius_scale", 0.5, 4.0}, {"strength", 0.5, 8.0}};
}

// The report's default settings for `v` on `s` with the axes' values `x` applied.
inline aogen::vulkan::chain_settings tuned_settings(const aogen::variant& v, const aogen::scenes::scene& s, const std::vector<double>& x)
{
    aogen::vulkan::chain_settings c = default_settings(v, s);
    const float R = float(s.ao_radius);
    if (v.tech == aogen::technique::gtao) {
        c.gtao.radius = float(x[0]) * R, c.gtao.strength = float(x[1]), c.gtao.thickness_bias = float(x[2]);
    } else if (v.tech == aogen::technique::vbao) {
        c.vbao.radius = float(x[0]) * R, c.vbao.strength = float(x[1]), c.vbao.thickness = float(x[2]);
    } else {
        const float bias_ratio = c.ssao.bias / c.ssao.radius;
        c.ssao.radius = float(x[0]) * R, c.ssao.bias = bias_ratio * c.ssao.radius, c.ssao.strength = float(x[1]);
    }
    return c;
}

struct tune_settings {
    std::vector<aogen::variant> variants; // one technique; searched jointly: one set of values for all
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

// One scene, ready for any variant: its reference traced once, and its G-buffers made and
// uploaded once per normal space and depth convention the variants read (run.hpp's
// gbuffer_cache, as the report does).
class tune_scene {
public:
    tune_scene(aogen::vulkan::context& ctx, const aogen::scenes::scene& s, int grid)
        : prepared_(prepare(s, grid)), gbuffers_(ctx, prepared_.scene, *prepared_.tracer)
    {
    }

    // The RMSE of variant `v` (chain `c`) with `settings` against this scene's reference.
    double rmse(aogen::vulkan::context& ctx, const aogen::variant& v, const aogen::vulkan::chain& c, const aogen::vulkan::chain_settings& settings)
    {
        const int W = prepared_.truth.width, H = prepared_.truth.height;
        const auto [tw, th] = aogen::vulkan::target_size(v, W, H);
        const aogen::vulkan::chain_result out =
            aogen::vulkan::bound_chain(ctx, c.passes(), gbuffers_.gpu(v), aogen::vulkan::inputs_for(v, settings, tw, th), tw, th).run_once();
        return compare(upsample(out.ao, tw, th, tw == W ? 1 : 2, W, H), prepared_.truth.ao, prepared_.truth.valid).rmse;
    }
    const aogen::scenes::scene& scene() const { return prepared_.scene; }

private:
    prepared_scene prepared_;
    gbuffer_cache gbuffers_; // refers to prepared_'s scene and tracer: declared after it
};

using settings_maker = std::function<aogen::vulkan::chain_settings(const aogen::variant&, const aogen::scenes::scene&)>;

// The mean over `scenes` of variant `v`'s RMSE with the settings `make` gives.
inline double mean_rmse(aogen::vulkan::context& ctx, const aogen::variant& v, const aogen::vulkan::chain& c,
                        std::vector<std::unique_ptr<tune_scene>>& scenes, const settings_maker& make)
{
    double sum = 0;
    for (auto& s : scenes) sum += s->rmse(ctx, v, c, make(v, s->scene()));
    return scenes.empty() ? 0.0 : sum / double(scenes.size());
}

} // namespace detail

inline tune_result tune(aogen::vulkan::context& ctx, const tune_settings& t)
{
    if (t.variants.empty()) aogen::fail("tune", "has no variant", "valid: at least one variant");
    tune_result r;
    r.axes = tune_axes(t.variants.front());
    std::vector<std::unique_ptr<aogen::vulkan::chain>> chains;
    for (const aogen::variant& v : t.variants) {
        if (tune_axes(v).size() != r.axes.size() || v.tech != t.variants.front().tech)
            aogen::fail("tune", aogen::to_name(v) + " is not the technique of " + aogen::to_name(t.variants.front()), "valid: variants of one technique");
        r.variants.push_back(aogen::to_name(v));
        chains.push_back(std::make_unique<aogen::vulkan::chain>(ctx, v));
    }
    std::vector<std::unique_ptr<detail::tune_scene>> train, validate;
    for (const aogen::scenes::scene& s : t.train) require_radius_works(s), train.push_back(std::make_unique<detail::tune_scene>(ctx, s, t.grid));
    for (const aogen::scenes::scene& s : t.validate) require_radius_works(s), validate.push_back(std::make_unique<detail::tune_scene>(ctx, s, t.grid));
    t.progress(std::to_string(t.variants.size()) + " variants, " + std::to_string(train.size()) + " training and " + std::to_string(validate.size()) +
               " validation scenes ready");

    // The mean over variants of each variant's mean over `scenes`; per variant into `each`.
    const auto joint = [&](std::vector<std::unique_ptr<detail::tune_scene>>& scenes, const detail::settings_maker& make, std::vector<double>* each) {
        double sum = 0;
        for (size_t i = 0; i < t.variants.size(); ++i) {
            const double e = detail::mean_rmse(ctx, t.variants[i], *chains[i], scenes, make);
            if (each) each->push_back(e);
            sum += e;
        }
        return sum / double(t.variants.size());
    };
    const auto at = [](const std::vector<double>& x) {
        return [x](const aogen::variant& v, const aogen::scenes::scene& s) { return tuned_settings(v, s, x); };
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
    // The report's defaults on the axes (settings.hpp).
    if (t.variants.front().tech == aogen::technique::gtao) {
        const aogen::gtao_params p;
        r.default_point = {aogen::gtao_params::radius_per_ao_radius, p.strength, p.thickness_bias};
    } else if (t.variants.front().tech == aogen::technique::vbao) {
        const aogen::vbao_params p;
        r.default_point = {aogen::vbao_params::radius_per_ao_radius, p.strength, p.thickness};
    } else {
        r.default_point = {1.0, aogen::presets::taos_ssao().ssao.strength};
    }
    return r;
}

} // namespace aogen_report
