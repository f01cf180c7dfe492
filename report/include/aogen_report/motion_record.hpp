// aogen_report/motion_record.hpp — what the report in motion runs and what it keeps of each
// run (motion.hpp runs it, motion_metrics.hpp works the figures out): plain values, no GPU and
// no scene, so that records.hpp and the metrics' tests can hold them.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace aogen_report {

// The report in motion (motion.hpp): what is run and scored along a scene's path.
struct motion_options {
    // Frames run from the path's start (at most the path's), and the first scored: frames
    // first_scored .. frames − 1 are traced and scored. A history of the default blend 0.1
    // weighs its frames 1 / (n + 1) until n = 9, then 0.1 each: frames 6 .. 11 score histories
    // of 7 to 12 frames, its even start into its steady window, as a renderer shows them a
    // fifth to two fifths of a second after a cut at 30 frames a second. 12 and 6 keep the
    // report in motion near 40 s of the default report (docs/report.md).
    int frames = 12;
    int first_scored = 6;
    int ghost_window = 4;  // a pixel whose point came into view within this many frames is a ghost pixel
    int grid = 16;         // reference rays per pixel: grid × grid (256: docs/report.md § In motion says what it costs)
    bool timed = false;    // time each chain after its path (the report's timing protocol: motion.hpp's score)
};

// One variant along one scene's path (motion.hpp).
struct motion_record {
    std::string variant, scene;
    std::vector<double> rmse; // per scored frame, against that frame's truth
    double error = 0;         // their mean
    double ghosting = 0;      // RMSE over the young pixels of the scored frames
    double flicker = 0;       // RMS frame-to-frame change of (AO − truth) at one point
    size_t ghost_pixels = 0, flicker_pixels = 0;
    double ms = NAN;          // one frame's GPU time on the path's last frame (motion_options::timed), else NaN
};

} // namespace aogen_report
