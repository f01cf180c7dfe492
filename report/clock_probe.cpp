// aogen_clock_probe — how long a GPU takes to reach its working clock, and how fast it
// leaves it: the measurement behind the report's default warm-up (vulkan::timing_options).
//
//     aogen_clock_probe [--variant NAME] [--scene room] [--size 1920x1080] [--seconds 2]
//                       [--idle-ms 3000] [--device NAME] [--out probe.json]
//
// On one bound chain (the variant on the scene's G-buffer, every resource device-local):
//   1. idle for --idle-ms, then ramp: for --seconds, short back-to-back batches of the
//      chain (each ~2 ms of work), every iteration timestamped; each batch's median
//      iteration time against the wall-clock time since the ramp began, with nvidia-smi's
//      SM clock sampled meanwhile (clocks.hpp) — the time at which the iteration time
//      settles is the warm-up a timing needs;
//   2. idle gaps: for each gap, 300 ms of continuous work, the gap, then 10 iterations —
//      how long a pause (the host scoring, compiling or tracing) may be before the clock
//      drops and a warm-up is needed again.
// Writes JSON (stdout, or --out): {device, variant, size, steady_ms, ramp: [{t_ms, ms}],
// clocks: [{t_ms, mhz}], gaps: [{gap_ms, first_ms, median_ms}]}. A benchmark, not a test:
// it asserts nothing and never changes a clock or power setting.
#include <aogen_report/clocks.hpp>
#include <aogen_tools/options.hpp>
#include <aogen_report/settings.hpp>

#include <aogen/vulkan/timing.hpp>
#include <aogen_scenes/gbuffer.hpp>
#include <aogen_tools/files.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <thread>

namespace {

using steady = std::chrono::steady_clock;

double ms_since(steady::time_point t) { return std::chrono::duration<double, std::milli>(steady::now() - t).count(); }

// One batch of `iterations` back-to-back iterations, no warm-up: every iteration's time.
std::vector<double> batch(aogen::vulkan::context& ctx, const aogen::vulkan::bound_chain& b, int iterations)
{
    return aogen::vulkan::time_chain(ctx, b, {1, iterations, 0.0}).total_ms;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"aogen_clock_probe: how long the GPU takes to reach its working clock, and how fast it leaves it"};
    std::string variant_name = "gtao-3x3-full-bilateral-gbufview-std-persp-cs", scene_name = "room", size = "1920x1080", device, out;
    double seconds = 2, idle_ms = 3000;
    app.add_option("--variant", variant_name, "the chain to run")->capture_default_str();
    app.add_option("--scene", scene_name, "the built-in scene whose G-buffer it runs on")->capture_default_str();
    app.add_option("--size", size, "WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--seconds", seconds, "length of the ramp")->capture_default_str()->check(CLI::Range(0.1, 60.0));
    app.add_option("--idle-ms", idle_ms, "idle time before the ramp")->capture_default_str()->check(CLI::Range(0.0, 60000.0));
    app.add_option("--device", device, "the Vulkan device whose name contains this");
    app.add_option("--out", out, "write the JSON here instead of standard output");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        int w = 0, h = 0;
        if (std::sscanf(size.c_str(), "%dx%d", &w, &h) != 2 || w < 8 || h < 8 || w > 4096 || h > 4096)
            aogen::fail("--size", "\"" + size + "\" is not a size", "valid: WIDTHxHEIGHT, each 8..4096");
        const aogen::variant v = aogen::variant_from_name(variant_name);
        aogen::scenes::scene s = aogen::scenes::builtin_scene(scene_name);
        s.camera.width = w, s.camera.height = h;
        aogen::vulkan::context ctx({false, device});
        aogen_report::clock_monitor clocks(ctx.device_name(), 20);

        const std::unique_ptr<aogen::truth::scene> tracer = aogen::scenes::make_tracer(s);
        aogen::scenes::gbuffer_options o;
        o.use_scene_normals = false;
        o.normals = v.normals == aogen::normal_source::gbuffer_view ? aogen::scenes::normal_space::view : aogen::scenes::normal_space::world;
        const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(aogen_report::for_variant(s, v), *tracer, o);
        const aogen::vulkan::gpu_gbuffer uploaded(ctx, aogen_report::renderer_gbuffer(g));
        const aogen::vulkan::chain c(ctx, aogen::codegen::make_plan(v));
        const std::unique_ptr<aogen::vulkan::bound_chain> b = c.bind(uploaded, aogen_report::default_settings(v, s));
        if (ctx.timestamp_valid_bits() == 0) aogen::fail("device", ctx.device_name() + " has no timestamps", "valid: a device with timestamps");

        // The working clock's iteration time, to size the ramp's batches at ~2 ms.
        const double steady_ms = aogen::vulkan::time_chain(ctx, *b, {3, 50, 500.0}).total.median;
        const int per_batch = std::max(1, int(2.0 / std::max(steady_ms, 1e-3)));

        nlohmann::json j;
        j["device"] = ctx.device_name();
        j["variant"] = aogen::to_name(v);
        j["size"] = size;
        j["steady_ms"] = steady_ms;
        j["max_sm_mhz"] = clocks.max_mhz();

        std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(idle_ms));
        clocks.start();
        const auto ramp_start = steady::now();
        j["ramp"] = nlohmann::json::array();
        while (ms_since(ramp_start) < seconds * 1000) {
            const double t = ms_since(ramp_start);
            j["ramp"].push_back({{"t_ms", t}, {"ms", aogen::vulkan::spread_of(batch(ctx, *b, per_batch)).median}});
        }
        clocks.stop();
        j["clocks"] = nlohmann::json::array();
        for (const aogen_report::clock_monitor::sample& c : clocks.timeline()) j["clocks"].push_back({{"t_ms", c.ms}, {"mhz", c.mhz}});

        j["gaps"] = nlohmann::json::array();
        for (double gap : {0.0, 10.0, 50.0, 100.0, 250.0, 500.0, 1000.0, 2000.0}) {
            aogen::vulkan::time_chain(ctx, *b, {1, 1, 300.0}); // continuous work first
            std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(gap));
            const std::vector<double> after = batch(ctx, *b, 10);
            j["gaps"].push_back({{"gap_ms", gap}, {"first_ms", after.front()}, {"median_ms", aogen::vulkan::spread_of(after).median}});
        }
        const std::string text = j.dump(1) + "\n";
        if (out.empty()) std::cout << text;
        else aogen::tools::write_file(out, text);
    } catch (const std::exception& e) {
        std::cerr << "aogen_clock_probe: " << aogen::tools::exception_line(e) << "\n";
        return 1;
    }
    return 0;
}
