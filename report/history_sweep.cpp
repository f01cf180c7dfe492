// aogen_history_sweep — the search behind the history pass's defaults (history_params): one
// history variant run in motion (aogen_report/motion.hpp) along every scene with a path,
// under each blend and clamp of a grid, against its twin without the pass and a reference
// variant's single frames; per setting the means over the scenes of the error in motion,
// ghosting and flicker, and their ratios to the twin's.
//
//   aogen_history_sweep [--variant NAME] [--reference NAME] [--scenes a,b,...] [--size WxH]
//                       [--device NAME] [--out sweep.json]
//
// Prints a Markdown table (BENCHMARKS.md keeps it) and writes every figure to --out. The
// frames' G-buffers and references are made once per scene and shared by every setting.
#include <aogen_report/arguments.hpp>
#include <aogen_report/motion.hpp>
#include <aogen_tools/files.hpp>
#include <aogen_tools/options.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <sstream>

namespace {

std::string fixed(double x, int digits)
{
    std::ostringstream o;
    o << std::fixed << std::setprecision(digits) << x;
    return o.str();
}

// The settings searched: each clamp at a few widths, each at three blends.
std::vector<std::pair<std::string, aogen::history_params>> grid()
{
    std::vector<std::pair<std::string, aogen::history_params>> out;
    for (const float blend : {0.05f, 0.1f, 0.2f}) {
        const std::string b = "blend=" + fixed(blend, 2) + ",";
        for (const std::string clamp : {"clamp=none", "clamp=range,range=0.05", "clamp=range,range=0.1", "clamp=range,range=0.2",
                                        "clamp=min_max,widening=0", "clamp=min_max,widening=0.05", "clamp=variance,gamma=1",
                                        "clamp=variance,gamma=1.5", "clamp=variance,gamma=2"})
            out.push_back({b + clamp, aogen_report::parse_history(b + clamp)});
    }
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"aogen_history_sweep: the history pass's blend and clamp searched by the error in motion"};
    std::string variant = "gtao-2x2-half-denoise-gbufworld-std-persp-cs-histmv", reference = "gtao-4x4-half-noblur-gbufworld-std-persp-cs";
    std::string scenes = "room,stairs,engine,rolling_sphere", size = "320x180", device, out;
    app.add_option("--variant", variant, "the history variant searched")->capture_default_str();
    app.add_option("--reference", reference, "a variant whose single frames the error is set against")->capture_default_str();
    app.add_option("--scenes", scenes, "scenes with a camera path")->capture_default_str();
    app.add_option("--size", size, "WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--device", device, "the Vulkan device whose name contains this");
    app.add_option("--out", out, "where to write every figure (JSON)");
    CLI11_PARSE(app, argc, argv);
    try {
        int w = 0, h = 0;
        aogen_report::parse_size(size, w, h);
        const aogen::variant v = aogen::variant_from_name(variant);
        if (!aogen::has_history_pass(v)) aogen::fail("--variant", variant + " has no history pass", "valid: a -hist or -histmv variant");
        aogen::variant twin = v;
        twin.history = aogen::history_mode::off;
        aogen::vulkan::device_options o;
        o.name = device;
        aogen::vulkan::context ctx(o);
        const aogen::vulkan::chain with(ctx, aogen::codegen::make_plan(v)), without(ctx, aogen::codegen::make_plan(twin)),
            dear(ctx, aogen::codegen::make_plan(aogen::variant_from_name(reference)));
        const std::vector<std::pair<std::string, aogen::history_params>> settings = grid();
        std::vector<aogen_report::motion_record> sum(settings.size()), twin_sum(1), dear_sum(1);
        auto add = [](aogen_report::motion_record& into, const aogen_report::motion_record& r) {
            into.error += r.error, into.ghosting += r.ghosting, into.flicker += r.flicker;
        };
        std::vector<std::string> used;
        for (aogen::scenes::scene s : aogen_report::load_scenes(scenes)) {
            s.camera.width = w, s.camera.height = h;
            std::cerr << "aogen_history_sweep: " << s.name << "\n";
            aogen_report::motion_scene m(ctx, s, {});
            used.push_back(s.name);
            add(twin_sum[0], m.score(without));
            add(dear_sum[0], m.score(dear));
            for (size_t i = 0; i < settings.size(); ++i) add(sum[i], m.score(with, settings[i].second));
        }
        const double n = double(used.size());
        std::cout << "| history settings | error | ghosting | flicker | error / twin's | ghosting / twin's | flicker / twin's | error / " << reference
                  << "'s |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
        nlohmann::json j{{"variant", variant}, {"reference", reference}, {"scenes", used}, {"size", size}, {"device", ctx.device_name()},
                         {"twin", {{"error", twin_sum[0].error / n}, {"ghosting", twin_sum[0].ghosting / n}, {"flicker", twin_sum[0].flicker / n}}},
                         {"reference_error", dear_sum[0].error / n}};
        for (size_t i = 0; i < settings.size(); ++i) {
            const aogen_report::motion_record& r = sum[i];
            std::cout << "| " << settings[i].first << " | " << fixed(r.error / n, 4) << " | " << fixed(r.ghosting / n, 4) << " | " << fixed(r.flicker / n, 4)
                      << " | " << fixed(r.error / twin_sum[0].error, 3) << " | " << fixed(r.ghosting / twin_sum[0].ghosting, 3) << " | "
                      << fixed(r.flicker / twin_sum[0].flicker, 3) << " | " << fixed(r.error / dear_sum[0].error, 3) << " |\n";
            j["settings"].push_back({{"history", settings[i].first}, {"error", r.error / n}, {"ghosting", r.ghosting / n}, {"flicker", r.flicker / n}});
        }
        std::cout << "| (twin, no history) | " << fixed(twin_sum[0].error / n, 4) << " | " << fixed(twin_sum[0].ghosting / n, 4) << " | "
                  << fixed(twin_sum[0].flicker / n, 4) << " | 1 | 1 | 1 | " << fixed(twin_sum[0].error / dear_sum[0].error, 3) << " |\n"
                  << "| (" << reference << ", single frames) | " << fixed(dear_sum[0].error / n, 4) << " | " << fixed(dear_sum[0].ghosting / n, 4) << " | "
                  << fixed(dear_sum[0].flicker / n, 4) << " | | | | 1 |\n";
        if (!out.empty()) aogen::tools::write_file(out, j.dump(2) + "\n");
    } catch (const std::exception& e) {
        std::cerr << "aogen_history_sweep: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
