// aogen_report/tune.hpp — a search for a variant's parameters against the ray-traced truth:
// the defaults a user should get, found the way XeGTAO's auto-tune finds its own.
//
// WHAT
//   tune(settings) takes one variant, training scenes and validation scenes, and searches
//   the variant's continuous parameters for the lowest mean RMSE (each training scene weighted
//   equally, default output: no calibration afterwards) by grid_search.hpp's narrowing grid
//   (`points` values per axis, `rounds` rounds). The axes (tune_axes):
//     gtao   radius_scale (the radius as a multiple of the scene's R), strength (the final
//            power: visibility^strength), thickness_bias (the cut-off radius·(1 + 10·t));
//     ssao   radius_scale, strength (1 − occlusion·strength); the bias stays 5 % of the
//            radius, as the presets have it.
//   The result carries the best point, its training and validation RMSE, and the same two
//   for the report's defaults (the seed presets scaled to R: settings.hpp), so what the
//   search buys is read on scenes it did not see.
//
// USAGE
//     aogen_report::tune_settings s;
//     s.v = aogen::variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs");
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
#include <string>
#include <vector>

namespace aogen_report {

// The axes tune() searches for `v`'s technique.
inline std::vector<search_axis> tune_axes(const aogen::variant& v)
{
    if (v.tech == aogen::technique::gtao) return {{"radius_scale", 0.5, 2.0}, {"strength", 0.25, 3.0}, {"thickness_bias", 0.0, 0.6}};
    if (v.output == aogen::ssao_output::power_intensity)
        aogen::fail("tune", aogen::to_name(v) + " has the power/intensity output", "valid: GTAO, or SSAO with the strength output");
    return {{"radius_scale", 0.5, 2.0}, {"strength", 0.5, 8.0}};
}

// The report's default settings for `v` on `s` with the axes' values `x` applied.
inline aogen::vulkan::chain_settings tuned_settings(const aogen::variant& v, const aogen::scenes::scene& s, const std::vector<double>& x)
{
    aogen::vulkan::chain_settings c = default_settings(v, s);
    const float R = float(s.ao_radius);
    if (v.tech == aogen::technique::gtao) {
        c.gtao.radius = float(x[0]) * R, c.gtao.strength = float(x[1]), c.gtao.thickness_bias = float(x[2]);
    } else {
        const float bias_ratio = c.ssao.bias / c.ssao.radius;
        c.ssao.radius = float(x[0]) * R, c.ssao.bias = bias_ratio * c.ssao.radius, c.ssao.strength = float(x[1]);
    }
    return c;
}

struct tune_settings {
    aogen::variant v;
    std::vector<aogen::scenes::scene> train, validate;
    int grid = 32;  // reference rays per pixel: grid²
    int points = 5; // values per axis per round
    int rounds = 3;
    std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct tune_result {
    std::string variant;
    std::vector<search_axis> axes;
    std::vector<double> best;                     // one value per axis
    double train_rmse = 0, validate_rmse = 0;     // at best
    double default_train = 0, default_validate = 0; // the report's defaults
    std::vector<double> default_point;             // the defaults on the axes
    size_t evaluations = 0;
};

namespace detail {

// One scene, ready for one variant: the G-buffer uploaded once, its reference.
class tune_scene {
public:
    tune_scene(aogen::vulkan::context& ctx, const aogen::variant& v, const aogen::scenes::scene& s, int grid)
        : prepared_(prepare(s, grid)), v_(v)
    {
        aogen::scenes::gbuffer_options o;
        o.use_scene_normals = false;
        o.normals = v.normals == aogen::normal_source::gbuffer_view ? aogen::scenes::normal_space::view : aogen::scenes::normal_space::world;
        const aogen::scenes::scene seen = for_variant(prepared_.scene, v);
        const aogen::vulkan::gbuffer g =
            aogen::scenes::to_gbuffer<aogen::vulkan::gbuffer>(aogen::scenes::render_gbuffer(seen, *prepared_.tracer, o));
        width_ = g.width, height_ = g.height;
        uploaded_ = std::make_unique<aogen::vulkan::gpu_gbuffer>(ctx, g);
    }

    // The RMSE of `c` with `settings` against this scene's reference.
    double rmse(aogen::vulkan::context& ctx, const aogen::vulkan::chain& c, const aogen::vulkan::chain_settings& settings) const
    {
        const auto [tw, th] = aogen::vulkan::target_size(v_, width_, height_);
        const aogen::vulkan::chain_result out =
            aogen::vulkan::bound_chain(ctx, c.passes(), *uploaded_, aogen::vulkan::inputs_for(v_, settings, tw, th), tw, th).run_once();
        const std::vector<float> full = upsample(out.ao, tw, th, tw == width_ ? 1 : 2, width_, height_);
        return compare(full, prepared_.truth.ao, prepared_.truth.valid).rmse;
    }
    const aogen::scenes::scene& scene() const { return prepared_.scene; }

private:
    prepared_scene prepared_;
    aogen::variant v_;
    int width_ = 0, height_ = 0;
    std::unique_ptr<aogen::vulkan::gpu_gbuffer> uploaded_;
};

// The mean over `scenes` of the RMSE with the settings `settings` makes for each.
inline double mean_rmse(aogen::vulkan::context& ctx, const aogen::vulkan::chain& c, const std::vector<std::unique_ptr<tune_scene>>& scenes,
                        const std::function<aogen::vulkan::chain_settings(const aogen::scenes::scene&)>& settings)
{
    double sum = 0;
    for (const auto& s : scenes) sum += s->rmse(ctx, c, settings(s->scene()));
    return scenes.empty() ? 0.0 : sum / double(scenes.size());
}

} // namespace detail

inline tune_result tune(aogen::vulkan::context& ctx, const tune_settings& t)
{
    tune_result r;
    r.variant = aogen::to_name(t.v);
    r.axes = tune_axes(t.v);
    const aogen::vulkan::chain c(ctx, t.v);
    std::vector<std::unique_ptr<detail::tune_scene>> train, validate;
    for (const aogen::scenes::scene& s : t.train) {
        require_radius_works(s);
        train.push_back(std::make_unique<detail::tune_scene>(ctx, t.v, s, t.grid));
    }
    for (const aogen::scenes::scene& s : t.validate) {
        require_radius_works(s);
        validate.push_back(std::make_unique<detail::tune_scene>(ctx, t.v, s, t.grid));
    }
    t.progress(r.variant + ": " + std::to_string(train.size()) + " training and " + std::to_string(validate.size()) + " validation scenes ready");

    const auto at = [&](const std::vector<double>& x) {
        return [&t, x](const aogen::scenes::scene& s) { return tuned_settings(t.v, s, x); };
    };
    const auto defaults = [&](const aogen::scenes::scene& s) { return default_settings(t.v, s); };
    r.default_train = detail::mean_rmse(ctx, c, train, defaults);
    r.default_validate = detail::mean_rmse(ctx, c, validate, defaults);

    int round = 0;
    size_t seen = 0;
    const size_t per_round = [&] { size_t k = 1; for (size_t i = 0; i < r.axes.size(); ++i) k *= size_t(t.points); return k; }();
    const grid_search_result g = narrowing_grid_search(r.axes, t.points, t.rounds, [&](const std::vector<double>& x) {
        const double e = detail::mean_rmse(ctx, c, train, at(x));
        if (++seen % per_round == 0) t.progress(r.variant + ": round " + std::to_string(++round) + " done");
        return e;
    });
    r.best = g.best, r.train_rmse = g.value, r.evaluations = g.evaluations;
    r.validate_rmse = detail::mean_rmse(ctx, c, validate, at(r.best));
    // The defaults on the axes: the radius is R itself (settings.hpp), the rest the preset's.
    if (t.v.tech == aogen::technique::gtao) {
        const aogen::gtao_params g = aogen::presets::taos_gtao().gtao;
        r.default_point = {1.0, g.strength, g.thickness_bias};
    } else {
        r.default_point = {1.0, aogen::presets::taos_ssao().ssao.strength};
    }
    return r;
}

} // namespace aogen_report
