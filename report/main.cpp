// aogen_report — how far each AO variant is from the ray-traced truth, and what it costs.
//
//     aogen_report [--scenes crease,room,my_scene.json] [--variants spec.json | NAME,NAME]
//                  [--size 320x180] [--rays 1024] [--frames 8] [--rounds 3] [--iterations 20] [--budget-ms 1000] [--warmup-ms 500]
//                  [--motion-variants spec.json | NAME,NAME | none] [--history blend=0.1,clamp=variance,...]
//                  [--device NAME] [--out out/report]
//
// Writes into --out: report.html (the whole report as one self-contained page: the plot,
// a sortable, filterable table, every variant's images on every scene), report.md (the
// tables), results.json (every number), error_vs_time.svg (the plot, drawn here; no
// Python), motion_vs_time.svg (the plot in motion, with the report in motion) and strips/<scene>.png (reference | variant | |error| for the Pareto-optimal
// variants, each row labelled). The set is written after every scene (marked partial
// until the last), all files or none, so an interrupted run keeps what it measured.
// Progress goes to stderr. A bad argument, scene or variant is one line on stderr and
// exit status 1 (2 for command-line syntax), before anything is written; every file is
// written to a temporary name and renamed.
#include <aogen_report/arguments.hpp>
#include <aogen_report/markdown.hpp>
#include <aogen_report/page.hpp>
#include <aogen_report/pareto.hpp>
#include <aogen_report/run.hpp>
#include <aogen_report/suite_page.hpp>
#include <aogen_report/suite_report.hpp>

#include <aogen/matrix.hpp>
#include <aogen_tools/files.hpp>
#include <aogen_tools/options.hpp>
#include <aogen_tools/variant_spec.hpp>

#include <CLI/CLI.hpp>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace {

using aogen::tools::json_reader;

using aogen_report::comma_list;
using aogen_report::ends_with;
using aogen_report::grid_for_rays;
using aogen_report::load_scenes;
using aogen_report::parse_size;

// A variant spec file (see `aogen generate --variants`) or canonical names; empty: the
// default matrix.
std::vector<aogen::variant> load_variants(const std::string& list)
{
    if (list.empty()) return aogen::default_matrix();
    if (ends_with(list, ".json")) {
        const nlohmann::json doc = json_reader::parse(aogen::tools::read_file(list), list);
        return aogen::tools::variants_from_json(json_reader(doc, list));
    }
    std::vector<aogen::variant> out;
    for (const std::string& name : comma_list(list)) aogen::append_unique(out, aogen::variant_from_name(name));
    return out;
}

// A scene name as a file name: letters, digits, '-' and '_' kept, anything else '_'
// (scene files may name scenes "box on a floor"; Markdown links break at spaces).
std::string file_stem(const std::string& name)
{
    std::string stem = name;
    for (char& c : stem)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    return stem;
}

// Per scene, the variants Pareto-optimal on it by time and calibrated error (fastest
// first, at most 8): reference | variant | |error|; then each variant's bent normals that has
// them: reference | variant | angle.
std::map<std::string, aogen_report::strip_file> add_strips(const aogen_report::report_data& d, aogen::tools::file_set& out)
{
    std::map<std::string, aogen_report::strip_file> files;
    const std::vector<size_t> order = aogen_report::detail::by_time(d.variants);
    for (size_t s = 0; s < d.scenes.size(); ++s) {
        std::vector<double> ms, rmse;
        for (size_t i : order) {
            const aogen_report::run_record& r = d.variants[i].runs[s];
            ms.push_back(r.ran() ? r.ms.median : std::nan(""));
            rmse.push_back(r.ran() ? r.calibrated.rmse : std::nan(""));
        }
        const std::vector<bool> optimal = aogen_report::pareto_optimal(ms, rmse);
        const aogen_report::scene_record& scene = d.scenes[s];
        aogen_report::strip strip(scene.truth.width, scene.truth.height);
        aogen_report::strip_file file{"strips/" + file_stem(scene.scene.name) + ".png", {}};
        std::vector<size_t> rows;
        for (size_t k = 0; k < order.size(); ++k)
            if (optimal[k]) rows.push_back(k);
        std::sort(rows.begin(), rows.end(), [&](size_t a, size_t b) { return ms[a] < ms[b]; });
        for (size_t k : rows) {
            if (file.variants.size() == 8) break;
            const aogen_report::variant_record& v = d.variants[order[k]];
            // The label's RMSE is the default-parameter one: what the row's panels show.
            strip.add_row(scene.truth.ao, v.runs[s].ao.full(scene.truth.width, scene.truth.height), scene.truth.valid,
                          aogen_report::strip_label(v.name, ms[k], v.runs[s].plain.rmse));
            file.variants.push_back(v.name);
        }
        // Then every variant with bent normals (-bn), fastest first: reference | variant | angle.
        for (size_t k = 0; k < order.size(); ++k) {
            const aogen_report::variant_record& v = d.variants[order[k]];
            const aogen_report::run_record& r = v.runs[s];
            if (!r.ran() || r.bent_normal_rgb.empty()) continue;
            strip.add_bent_normal_row(scene.truth.bent_normal, aogen_report::normals_of_bytes(r.bent_normal_rgb), scene.truth.valid,
                                      aogen_report::bent_strip_label(v.name, r.bent.mean_degrees));
            file.variants.push_back(v.name + " (bent normal)");
        }
        if (file.variants.empty()) continue;
        out.add(file.path, aogen_report::encode_png(strip.image()));
        files[scene.scene.name] = file;
    }
    return files;
}

// The report's files but the strips: results.json, report.md, report.html and the plot;
// the page's images from `images`, which keeps them for the run's next set.
void add_report(aogen::tools::file_set& set, const aogen_report::report_data& d, const aogen_report::report_meta& meta,
                const std::map<std::string, aogen_report::strip_file>& strips, aogen_report::page_images& images)
{
    set.add("results.json", aogen_report::results_json(d, meta));
    set.add("report.md", aogen_report::report_markdown(d, meta, strips));
    set.add("report.html", aogen_report::report_page(d, meta, &images));
    set.add("error_vs_time.svg", aogen_report::error_time_svg(aogen_report::plot_points(d), aogen_report::plot_title(d), d.frames));
    if (!d.motion.empty()) set.add("motion_vs_time.svg", aogen_report::motion_time_svg(aogen_report::motion_plot_points(d), aogen_report::motion_plot_title(d)));
}

// Where a report's `total` seconds went, for its last line: the phases, the summaries and
// the writing (the partial sets after each scene and the final set), and what is left.
std::string where_the_time_went(const aogen_report::phase_times& p, double final_write, double total)
{
    using aogen_report::detail::fixed;
    const double named = p.compile + p.trace + p.score + p.time + p.summarise + p.motion + p.write + final_write;
    return fixed(total, 1) + " s in all: compile " + fixed(p.compile, 1) + " s, trace " + fixed(p.trace, 1) + " s, score " + fixed(p.score, 1) +
           " s, time " + fixed(p.time, 1) + " s, summaries " + fixed(p.summarise, 1) + " s, in motion " + fixed(p.motion, 1) + " s, writing " + fixed(p.write + final_write, 1) +
           " s (after each scene " + fixed(p.write, 1) + " s, the final set " + fixed(final_write, 1) + " s), the rest " + fixed(total - named, 1) +
           " s; " + std::to_string(p.runs) + " variant × scene runs";
}

// Built-in case names or case JSON files; empty: every built-in case.
std::vector<aogen_report::stability_case> load_cases(const std::string& list)
{
    std::vector<aogen_report::stability_case> out;
    const std::vector<std::string> items = list.empty() ? aogen_report::builtin_case_names() : comma_list(list);
    for (const std::string& item : items)
        out.push_back(ends_with(item, ".json") ? aogen_report::read_case(aogen::tools::read_file(item), item) : aogen_report::builtin_case(item));
    return out;
}

// aogen_report --suite stability: every variant on every case, report.html, report.md and
// results.json into `out`; with `check`, exit 1 when any run fails.
int stability_main(const std::string& cases, const std::string& variants, int rays, const std::string& device, bool validation,
                   const std::string& out, bool check, const std::string& command, const std::function<void(const std::string&)>& progress)
{
    aogen_report::suite_settings s;
    s.cases = load_cases(cases);
    s.variants = variants.empty() ? aogen_report::suite_variants() : load_variants(variants);
    s.grid = grid_for_rays(rays);
    s.device.name = device, s.device.validation = validation;
    s.progress = progress;
    aogen::tools::require_writable_folder(out, "--out");
    const aogen_report::suite_data d = aogen_report::run_suite(s);
    aogen::tools::file_set set(out);
    set.add("results.json", aogen_report::suite_json(d, command));
    set.add("report.md", aogen_report::suite_markdown(d, command));
    set.add("report.html", aogen_report::suite_page(d, command));
    set.commit();
    progress("wrote " + (std::filesystem::path(out) / "report.md").string() + ": " + std::to_string(d.failures()) + " failed runs");
    if (check && d.failures() > 0)
        aogen::fail("stability suite", std::to_string(d.failures()) + (d.failures() == 1 ? " run" : " runs") + " failed (see " + (std::filesystem::path(out) / "report.md").string() + ")",
                    "valid: every case passing");
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"aogen_report: each AO variant's error against ray-traced ground truth, and its run time"};
    std::string scenes, variants, size = "320x180", out = "out/report", device;
    // 32 × 32 stratified rays per pixel: the reference's own noise (RMS of its per-pixel
    // standard error) is then at most 0.0059 on the built-in scenes (the point cloud; 0.0038
    // on the others), a sixth of the smallest variant error (0.035), and it adds to an RMSE in
    // quadrature: against 4,096 rays' reference (noise at most 0.0022) no variant's per-scene
    // RMSE moved by more than 0.0001, for a quarter of the tracing (213 s -> 55 s of the
    // default report; issue 49, BENCHMARKS.md).
    int rays = 1024;
    int frames = aogen_report::report_settings{}.frames;
    aogen::vulkan::timing_options timing = aogen_report::report_settings{}.timing;
    bool validation = false, no_saving = false, no_floor = false;
    std::string motion_variants, history;
    app.add_option("--scenes", scenes, "built-in scene names or scene .json files, comma-separated (default: every built-in scene; "
                                       "rolling_sphere in motion only); those with a camera path also run in motion")
        ->check(aogen::tools::not_empty("scene names or files"));
    app.add_option("--variants", variants, "a variant spec .json (as aogen generate --variants) or names, comma-separated (default: the default matrix)")
        ->check(aogen::tools::not_empty("a spec file or variant names"));
    app.add_option("--size", size, "every scene's resolution, WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--rays", rays, "reference rays per pixel: the square of an even number >= 32")->capture_default_str()
        ->check(aogen::tools::integer_in(1, 65536)); // grid_for_rays says which counts work
    app.add_option("--frames", frames, "frames averaged for the error after a temporal accumulation (a still camera, their plain mean; 1: none)")
        ->capture_default_str()->check(aogen::tools::integer_in(aogen_report::report_settings::frames_range.lo, aogen_report::report_settings::frames_range.hi));
    app.add_option("--rounds", timing.rounds, "timing rounds per scene: every chain's iterations, interleaved, in one submission (any of these four: also on a CPU device, which otherwise runs 1 round of 1 iteration, no warm-up)")
        ->capture_default_str()->check(aogen::tools::integer_in(1, 1000));
    app.add_option("--iterations", timing.iterations, "back-to-back iterations of every chain in each round (the most, under --budget-ms)")
        ->capture_default_str()->check(aogen::tools::integer_in(1, 1000));
    app.add_option("--budget-ms", timing.budget_ms, "fewer iterations where a scene's rounds would take longer than this (0: always --iterations)")
        ->capture_default_str()->check(aogen::tools::number_in(0.0, 3600000.0));
    app.add_option("--warmup-ms", timing.warmup_ms, "continuous untimed GPU work before each scene's timing, in ms")
        ->capture_default_str()->check(aogen::tools::number_in(0.0, 60000.0));
    app.add_option("--device", device, "use the Vulkan device whose name contains this (default: AOGEN_VULKAN_DEVICE, a discrete GPU, lavapipe)");
    app.add_option("--out", out, "the report directory")->capture_default_str()->check(aogen::tools::not_empty("a directory path"));
    app.add_flag("--validation", validation, "enable the Khronos validation layer");
    app.add_flag("--no-feature-saving", no_saving, "skip the point-cloud-fallback comparison");
    app.add_flag("--no-fetch-floor", no_floor, "do not time each variant's fetch and bandwidth floors");
    app.add_option("--motion-variants", motion_variants,
                   "the variants run in motion along every scene with a camera path: a spec .json or names, comma-separated, or none "
                   "(default: the default variant and cheap GTAO chains, each with and without the history pass, and gtao-4x4-half-noblur)")
        ->check(aogen::tools::not_empty("a spec file, variant names or none"));
    app.add_option("--history", history, "the history pass's settings over its defaults, key=value comma-separated: blend, clamp "
                                         "(none, range, min_max, variance), range, widening, gamma, depth_tolerance (aogen/params.hpp's history_params)")
        ->check(aogen::tools::not_empty("key=value settings"));
    std::string suite, cases;
    bool check = false;
    app.add_option("--suite", suite, "run a suite instead of the error-against-time report: stability")
        ->check(CLI::IsMember({"stability"}));
    app.add_option("--cases", cases, "with --suite stability: built-in case names or case .json files, comma-separated (default: all 30)")
        ->check(aogen::tools::not_empty("case names or files"));
    app.add_flag("--check", check, "with --suite stability: exit 1 when any case fails (for CI)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return 0;
    } catch (const CLI::ParseError& e) { // one line, as every other error: CLI11's exit() prints two
        std::cerr << "aogen_report: " << aogen::tools::parse_error_line(app, e, "aogen_report") << "\n";
        return 2;
    }

    const auto start = std::chrono::steady_clock::now();
    const auto progress = [&](const std::string& line) {
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cerr << "aogen_report " << std::fixed << std::setprecision(1) << t << "s " << line << std::endl;
    };
    std::ostringstream command;
    for (int i = 0; i < argc; ++i) command << (i ? " " : "") << (i ? argv[i] : "aogen_report");
    try {
        // Options that belong to the other mode are refused, not ignored.
        const std::vector<std::string> report_only{"--scenes", "--size", "--frames", "--rounds", "--iterations", "--budget-ms", "--warmup-ms",
                                                   "--no-feature-saving", "--no-fetch-floor", "--motion-variants", "--history"};
        for (const std::string& o : report_only)
            if (!suite.empty() && app.count(o) > 0)
                aogen::fail(o, "is an option of the error-against-time report, not of --suite " + suite, "valid: leave it out with --suite");
        for (const char* o : {"--cases", "--check"})
            if (suite.empty() && app.count(o) > 0) aogen::fail(o, "goes with --suite stability", "valid: --suite stability " + std::string(o));
        if (!suite.empty())
            return stability_main(cases, variants, app.count("--rays") ? rays : 1024, device, validation, out, check, command.str(), progress);

        aogen_report::report_settings s;
        parse_size(size, s.width, s.height);
        s.grid = grid_for_rays(rays);
        s.frames = frames;
        s.timing = timing;
        for (const char* o : {"--rounds", "--iterations", "--budget-ms", "--warmup-ms"}) s.timing_given = s.timing_given || app.count(o) > 0;
        s.device.name = device, s.device.validation = validation;
        s.feature_saving = !no_saving;
        s.fetch_floor = !no_floor;
        s.scenes = load_scenes(scenes);
        s.motion_scenes = aogen_report::load_motion_scenes(scenes);
        s.variants = load_variants(variants);
        if (app.count("--history")) s.history = aogen_report::parse_history(history);
        if (app.count("--motion-variants")) s.motion_variants = motion_variants == "none" ? std::vector<aogen::variant>{} : load_variants(motion_variants);
        s.progress = progress;
        const std::filesystem::path folder(out);
        // Everything a run needs besides its own work, checked before it starts.
        aogen::tools::require_writable_folder(folder, "--out");
        // After every scene but the last: the report so far, marked partial, as one set. The
        // page's images are encoded once each, kept across the sets.
        aogen_report::page_images images;
        s.scene_done = [&](const aogen_report::report_data& so_far) {
            if (so_far.scenes.size() == s.scenes.size()) return;
            const aogen_report::report_meta partial{command.str(), false};
            aogen::tools::file_set set(folder);
            add_report(set, so_far, partial, {}, images);
            set.commit();
            s.progress("wrote the " + std::to_string(so_far.scenes.size()) + " scenes so far to " + (folder / "results.json").string());
        };
        const aogen_report::report_data d = aogen_report::run_report(s);
        // The finished report: every file made first, then written all together.
        const auto final_start = std::chrono::steady_clock::now();
        const aogen_report::report_meta meta{command.str(), true};
        aogen::tools::file_set set(folder);
        add_report(set, d, meta, add_strips(d, set), images);
        set.commit();
        const double final_write = std::chrono::duration<double>(std::chrono::steady_clock::now() - final_start).count();
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        s.progress("wrote " + (folder / "report.md").string() + "; " + where_the_time_went(d.phases, final_write, total));
    } catch (const aogen::error& e) {
        std::cerr << "aogen_report: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "aogen_report: " << aogen::tools::exception_line(e) << "\n";
        return 1;
    }
    return 0;
}
