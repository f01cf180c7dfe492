// aogen_tune — the search behind aogen's tuned defaults (aogen_report/tune.hpp): per variant,
// the parameters with the lowest mean RMSE against the ray-traced truth on training scenes,
// checked on validation scenes the search did not see, beside the report's defaults.
//
//   aogen_tune [--variants NAME,...] [--joint] [--axes a,b,...] [--train a,b,...] [--validate c,d,...]
//              [--size WxH] [--rays N] [--points P] [--rounds K] [--device NAME] --out results.json
//
// --axes picks the parameters searched (tune.hpp's tune_axes: gtao radius_scale, strength,
// thickness_bias, falloff_range, thin_occluder; ssao radius_scale, strength); the others
// keep the report's defaults. Default: all of the technique's.
//
// Each variant is searched on its own; with --joint the variants (of one technique) share
// one set of values, the best for all of them together — what a product default must be.
//
// Prints a Markdown table (BENCHMARKS.md keeps them) and writes every figure to --out.
#include <aogen_report/arguments.hpp>
#include <aogen_tools/options.hpp>
#include <aogen_report/tune.hpp>

#include <aogen_tools/files.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace {

// The scenes of `list` (aogen_report's --scenes form) at w × h.
std::vector<aogen::scenes::scene> load(const std::string& list, int w, int h)
{
    std::vector<aogen::scenes::scene> out = aogen_report::load_scenes(list);
    for (aogen::scenes::scene& s : out) s.camera.width = w, s.camera.height = h;
    return out;
}

std::string fixed(double x, int digits)
{
    std::ostringstream o;
    o << std::fixed << std::setprecision(digits) << x;
    return o.str();
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"aogen_tune: search a variant's parameters against the ray-traced truth"};
    std::string variants = "gtao-2x3-half-bilateral-gbufworld-std-persp-cs,ssao-s16-half-bilateral-gbufworld-std-persp-cs";
    std::string train = "crease,groove,wall,sphere_on_plane,room,stairs,plank,engine,teapots,terrain";
    std::string validate = "atat,atat_far,dwarf,dwarf_far,spider,spider_far";
    std::string size = "320x180", device, out;
    int rays = 1024, points = 5, rounds = 3;
    bool joint = false;
    std::string axes;
    app.add_option("--variants", variants, "canonical names, comma-separated")->capture_default_str();
    app.add_option("--train", train, "built-in scenes or scene files the search fits")->capture_default_str();
    app.add_option("--validate", validate, "built-in scenes or scene files it is checked on")->capture_default_str();
    app.add_option("--size", size, "WxH of every scene")->capture_default_str();
    app.add_option("--rays", rays, "reference rays per pixel (the square of an even number, 32..256)")->capture_default_str();
    app.add_option("--points", points, "values per axis per round")->capture_default_str()->check(CLI::Range(2, 9));
    app.add_option("--rounds", rounds, "narrowing rounds")->capture_default_str()->check(CLI::Range(1, 8));
    app.add_option("--device", device, "the Vulkan device whose name contains this");
    app.add_option("--axes", axes, "the parameters to search, comma-separated (default: all of the technique's)")->capture_default_str();
    app.add_flag("--joint", joint, "search one set of values for all the variants together (they must share a technique)");
    app.add_option("--out", out, "results.json")->required();
    CLI11_PARSE(app, argc, argv);
    const auto start = std::chrono::steady_clock::now();
    try {
        int w = 0, h = 0;
        aogen_report::parse_size(size, w, h);
        const int grid = aogen_report::grid_for_rays(rays);
        aogen::vulkan::device_options o;
        o.name = device;
        aogen::vulkan::context ctx(o);
        nlohmann::json results = nlohmann::json::array();
        std::vector<std::vector<aogen::variant>> groups; // each searched on its own, or all together with --joint
        for (const std::string& name : aogen_report::comma_list(variants)) {
            if (!joint || groups.empty()) groups.emplace_back();
            groups.back().push_back(aogen::variant_from_name(name));
        }
        std::cout << "| variants | axes | defaults | train RMSE | validate RMSE | tuned | train RMSE | validate RMSE |\n|---|---|---|---:|---:|---|---:|---:|\n";
        for (const std::vector<aogen::variant>& group : groups) {
            aogen_report::tune_settings t;
            t.variants = group;
            t.axes = aogen_report::comma_list(axes);
            t.train = load(train, w, h), t.validate = load(validate, w, h);
            t.grid = grid, t.points = points, t.rounds = rounds;
            t.progress = [&](const std::string& line) {
                std::cerr << "aogen_tune " << fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1) << "s " << line << std::endl;
            };
            const aogen_report::tune_result r = aogen_report::tune(ctx, t);
            std::string axes, defaults, best, names;
            nlohmann::json j{{"variants", r.variants}, {"evaluations", r.evaluations}, {"train_rmse", r.train_rmse}, {"validate_rmse", r.validate_rmse},
                             {"default_train_rmse", r.default_train}, {"default_validate_rmse", r.default_validate},
                             {"variant_validate_rmse", r.variant_validate}, {"variant_default_validate_rmse", r.variant_default_validate}};
            for (size_t i = 0; i < r.axes.size(); ++i) {
                axes += (i ? ", " : "") + r.axes[i].name;
                defaults += (i ? ", " : "") + fixed(r.default_point[i], 3);
                best += (i ? ", " : "") + fixed(r.best[i], 3);
                j["best"][r.axes[i].name] = r.best[i];
                j["defaults"][r.axes[i].name] = r.default_point[i];
            }
            for (const std::string& n : r.variants) names += (names.empty() ? "" : ", ") + ("`" + n + "`");
            results.push_back(j);
            std::cout << "| " << names << " | " << axes << " | " << defaults << " | " << fixed(r.default_train, 4) << " | " << fixed(r.default_validate, 4)
                      << " | " << best << " | " << fixed(r.train_rmse, 4) << " | " << fixed(r.validate_rmse, 4) << " |" << std::endl;
        }
        nlohmann::json doc{{"train", train}, {"validate", validate}, {"size", size}, {"rays_per_pixel", rays}, {"points", points}, {"rounds", rounds},
                           {"device", ctx.device_name()}, {"variants", results}};
        aogen::tools::write_file(out, doc.dump(2) + "\n");
    } catch (const std::exception& e) {
        std::cerr << "aogen_tune: " << aogen::tools::exception_line(e) << "\n";
        return 1;
    }
    return 0;
}
