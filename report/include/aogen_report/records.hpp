// aogen_report/records.hpp — what the report measured, as plain data: per scene, per variant,
// per run, and the feature saving.
//
// WHAT
//   scene_record     a scene as run, its reference, its clocks and timing rounds
//   ao_readback      a variant's AO as read back (8-bit), upsampled on demand
//   run_record       one variant on one scene: errors, powers, raw counts, times, bent normals
//   variant_record   one variant over every scene, with its summaries
//   feature_saving   a scene-selected variant beside its everything-on twin
//   report_data      all of it: what run.hpp fills, summary.hpp summarises and
//                    results_json.hpp and markdown.hpp write
//
// WHY
//   The writers read the records and nothing of the run: they need no Vulkan device, no
//   tracer, no compiler, and a test can fill a report_data by hand.
#pragma once

#include "calibrate.hpp"
#include "images.hpp"
#include "metrics.hpp"
#include "motion_record.hpp"
#include "reference.hpp"

#include <aogen/vulkan/chain.hpp>
#include <aogen/vulkan/timing.hpp>
#include <aogen_scenes/scene.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace aogen_report {

// A distribution of SM clock readings (MHz) while timing.
struct clock_record {
    double min = std::numeric_limits<double>::quiet_NaN(), median = min, max = min;
    size_t samples = 0;
};

struct scene_record {
    aogen::scenes::scene scene;      // as run (resolution applied)
    reference truth;
    size_t valid_pixels = 0;
    double truth_mean = 0;           // mean reference AO over valid pixels
    clock_record clocks;             // SM clock while this scene was timed (nvidia-smi)
    double timed_gpu_ms = 0, timed_wall_ms = 0; // the timing rounds: timestamp span, host wall clock
    int iterations = 0;              // per round, as run (the budget's choice)
    bool settled = true;             // every warm-up ended with two agreeing submissions
    bool mesh_only() const { return !scene.renderer.point_cloud; }
};

// A variant's AO as read back: the R8 target's 8-bit values at the target's resolution
// (a quarter of the screen at half resolution), kept for calibration and the strips at a
// quarter of the memory of floats; full() is the full-resolution image they are scored at.
struct ao_readback {
    int width = 0, height = 0, factor = 1; // target size; full resolution = ×factor (clamped)
    std::vector<uint8_t> unorm;

    static ao_readback of(const aogen::vulkan::chain_result& r, int factor)
    {
        ao_readback a{r.width, r.height, factor, std::vector<uint8_t>(r.ao.size())};
        for (size_t i = 0; i < r.ao.size(); ++i) a.unorm[i] = uint8_t(std::lround(r.ao[i] * 255.0f)); // exact: r.ao[i] = k / 255
        return a;
    }
    // Nearest upsampling to the screen's W × H (images.hpp), as floats k / 255.
    std::vector<float> full(int W, int H) const
    {
        std::vector<float> ao(unorm.size());
        for (size_t i = 0; i < unorm.size(); ++i) ao[i] = unorm[i] / 255.0f;
        return upsample(ao, width, height, factor, W, H);
    }
};

// One variant on one scene.
struct run_record {
    std::string skipped;                          // why it did not run; "" when it ran
    error_metrics plain, calibrated;              // default parameters; ao^power
    error_metrics accumulated;                    // the mean of frames 0..N-1 (report_data::frames)
    double power = 1;                             // fitted on the other scenes
    calibration_scene summary;                    // of the default-parameter AO
    std::vector<aogen::vulkan::raw_counts> raw;   // per pass, before the guard; empty: not measured
    std::vector<aogen::vulkan::spread> pass_ms;   // per pass
    aogen::vulkan::spread ms;                     // the whole chain, per iteration
    aogen::vulkan::spread floor_ms;               // its fetch floor, timed in the same rounds
    aogen::vulkan::spread bandwidth_ms;           // its bandwidth floor, likewise
    std::vector<double> round_ms;                 // the chain's median of each timing round
    ao_readback ao;                               // as read back (default parameters)
    bent_normal_metrics bent;                     // a -bn variant's bent normals against the truth's; NaN otherwise
    std::vector<uint8_t> bent_normal_rgb;         // its world-space bent normals, full resolution (normal_bytes): the strips'
    bool ran() const { return skipped.empty(); }
};

struct variant_record {
    aogen::variant v;
    std::string name;
    std::vector<std::string> passes;
    std::vector<uint32_t> instructions; // SPIR-V instructions per shader (after spirv-opt)
    uint32_t ao_instructions = 0;       // of the AO pass's shader (fragment: its fragment shader)
    double ao_tap_instructions = 0;     // its tap loop's instructions per tap (aogen/loops.hpp); 0: no loop left
    std::vector<run_record> runs;       // one per scene so far, in settings order
    // Summaries over the scenes it ran on.
    double rmse = std::numeric_limits<double>::quiet_NaN(), rmse_calibrated = rmse;
    double rmse_accumulated = rmse;                 // after report_data::frames frames
    double bent_degrees = rmse;                     // mean over scenes of the bent normals' mean angular error (-bn)
    double ms = rmse, ms_p10 = rmse, ms_p90 = rmse; // medians over scenes of each scene's median, p10, p90
    double floor_ms = rmse, floor_ratio = rmse;     // median over scenes of the fetch floor, and of time / floor
    double bandwidth_ms = rmse, bandwidth_ratio = rmse; // the same of the bandwidth floor
    aogen::vulkan::raw_counts raw;                  // summed over scenes and passes
    bool raw_measured = false;                      // a diagnostic build ran (fragment passes need fragment stores)
    bool pareto = false, pareto_calibrated = false, pareto_accumulated = false;
};

// The scene-selected variant beside the same variant with every feature compiled in.
struct feature_saving {
    std::string selected, everything_on;
    uint32_t selected_instructions = 0, everything_on_instructions = 0; // AO pass
    double selected_ms = 0, everything_on_ms = 0;                       // median over the mesh-only scenes
    aogen::vulkan::spread ratio;                                        // selected / everything on, per scene and round
    double selected_rmse = 0, everything_on_rmse = 0;                   // mean over the mesh-only scenes
    std::vector<std::string> left_out;                                  // what selection left out, and why
};

// Wall-clock seconds of the report's phases. `summarise` is the summaries after each scene
// (calibration, means, Pareto marks); `write`, the file sets written after each scene
// (the program's scene_done) -- the final set's writing is the program's to add.
struct phase_times {
    double compile = 0, trace = 0, score = 0, time = 0, summarise = 0, write = 0;
    double motion = 0; // the report in motion: its frames' G-buffers, references and runs
    size_t runs = 0; // variant × scene runs scored (twins included)
};

struct report_data {
    std::string device;
    int grid = 0;
    int frames = 1;                        // frames averaged for the accumulated error (temporal.hpp)
    aogen::vulkan::timing_options timing;  // the protocol that ran (run.hpp's cpu_timing on a CPU device)
    bool cpu_device = false;               // a CPU device (lavapipe): its times are the CPU's
    bool fetch_floor = true;
    double max_sm_mhz = 0;                 // nvidia-smi's clocks.max.sm; 0 when unknown
    clock_record clocks;                   // every SM clock reading while timing
    std::vector<scene_record> scenes;      // the scenes done so far
    std::vector<variant_record> variants;
    std::vector<variant_record> twins;     // the point-cloud twins of the feature saving
    std::vector<feature_saving> savings;
    motion_options motion_settings;        // what the report in motion ran
    aogen::history_params history;         // the history pass's settings, still and in motion
    std::vector<motion_record> motion;     // per variant and scene with a path (motion.hpp); empty: not run
    phase_times phases;
};

} // namespace aogen_report
