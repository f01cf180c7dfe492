// Temporal accumulation against the truth: the frame index (aogen/temporal.hpp) turns every
// pixel's noise rotation frame by frame, so the plain mean of N frames — what TAA's history
// holds under a still camera — integrates over more directions than one frame can.
//
//   - the goal, on the closed-form scenes: 8 frames of the cheap
//     gtao-2x2-half-denoise are closer to the truth than one frame of gtao-4x4-half-noblur,
//     which takes four times its slice steps;
//   - the sequence: after 8 frames van der Corput's turns (and Sobol's steps) leave less
//     noise (distance to the converged mean, 128 frames) than white noise's in every variant,
//     and than the golden ratio's (with R2's steps) over the five variants together — not in
//     each: in the denoised gtao-3x2 the golden ratio's is lower (BENCHMARKS.md § Reference
//     measurements). Summed over the scenes and printed side by side: these are the
//     measurements behind the default (temporal.hpp).
// The planted faults these tests must catch are in tests/mutants/mutants.json.
#include "accuracy/truth_scenes.hpp"

#include <aogen_report/metrics.hpp>

#include <cmath>
#include <iostream>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_temporal_test {

using namespace aogen;
using namespace aogen_test;

namespace {

const char* const closed_form_scenes[] = {"crease", "groove", "sphere_on_plane", "plank", "wall"};

double rmse_against_truth(const std::vector<float>& ao, const truth_scene& t)
{
    return aogen_report::compare(ao, t.truth.ao, t.truth.valid).rmse;
}

// RMS difference of two images over the pixels with geometry.
double rms_between(const std::vector<float>& a, const std::vector<float>& b, const truth_scene& t)
{
    return aogen_report::compare(a, b, t.truth.valid).rmse;
}

} // namespace

TEST_CASE("accuracy: temporal: 8 frames of gtao-2x2-half-denoise beat one frame of gtao-4x4-half-noblur")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const variant cheap = variant_from_name("gtao-2x2-half-denoise-gbufworld-std-persp-cs");
    const variant dear = variant_from_name("gtao-4x4-half-noblur-gbufworld-std-persp-cs");
    double cheap_one = 0, cheap_eight = 0, dear_one = 0;
    for (const char* scene : closed_form_scenes) {
        const truth_scene& t = truth_of(scene);
        const double c1 = rmse_against_truth(ao_of(*ctx, cheap, t), t);
        const double c8 = rmse_against_truth(mean_of_frames(*ctx, cheap, t, 8), t);
        const double d1 = rmse_against_truth(ao_of(*ctx, dear, t), t);
        std::cout << "temporal on " << scene << ": gtao-2x2-half-denoise " << c1 << " (1 frame), " << c8 << " (8 frames); gtao-4x4-half-noblur " << d1
                  << " (1 frame)\n";
        cheap_one += c1, cheap_eight += c8, dear_one += d1;
    }
    const double n = std::size(closed_form_scenes);
    INFO("mean RMSE: gtao-2x2-half-denoise " << cheap_one / n << " (1 frame), " << cheap_eight / n << " (8 frames); gtao-4x4-half-noblur "
                                            << dear_one / n << " (1 frame)");
    CHECK(cheap_eight < dear_one);
    CHECK(cheap_eight < cheap_one); // and the frames are what did it: one frame of it is not
    CHECK_FALSE(cheap_one < dear_one);
    require_clean(*ctx);
}

TEST_CASE("accuracy: temporal: van der Corput's 8 frames leave less noise than white noise's in every variant and the golden ratio's over all")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    double all_noise[3] = {0, 0, 0};
    for (const char* name : {"gtao-2x2-full-noblur-gbufworld-std-persp-cs", "gtao-3x2-half-denoise-gbufworld-std-persp-cs",
                             "vbao-2x3-full-noblur-gbufworld-std-persp-cs", "ssao-s16-full-noblur-gbufworld-std-persp-cs",
                             "sao-s16-full-noblur-gbufworld-std-persp-cs"}) {
        const variant v = variant_from_name(name);
        double noise[3] = {0, 0, 0}, error[3] = {0, 0, 0};
        const temporal::sequence sequences[3] = {temporal::sequence::van_der_corput, temporal::sequence::golden_ratio, temporal::sequence::white};
        for (const char* scene : closed_form_scenes) {
            const truth_scene& t = truth_of(scene);
            const std::vector<float> converged = mean_of_frames(*ctx, v, t, 128);
            for (int k = 0; k < 3; ++k) {
                const std::vector<float> eight = mean_of_frames(*ctx, v, t, 8, sequences[k]);
                noise[k] += rms_between(eight, converged, t);
                error[k] += rmse_against_truth(eight, t);
            }
        }
        std::cout << name << " after 8 frames, summed over the scenes: noise (RMS to 128 frames) ";
        for (int k = 0; k < 3; ++k) std::cout << temporal::to_name(sequences[k]) << " " << noise[k] << (k < 2 ? ", " : "; ");
        std::cout << "RMSE against the truth ";
        for (int k = 0; k < 3; ++k) std::cout << temporal::to_name(sequences[k]) << " " << error[k] << (k < 2 ? ", " : "\n");
        INFO(name << ": noise after 8 frames, van der Corput " << noise[0] << ", golden ratio " << noise[1] << ", white " << noise[2]);
        CHECK(noise[0] < noise[2]);
        for (int k = 0; k < 3; ++k) all_noise[k] += noise[k];
    }
    INFO("noise after 8 frames over the variants, van der Corput " << all_noise[0] << ", golden ratio " << all_noise[1] << ", white "
                                                                     << all_noise[2]);
    CHECK(all_noise[0] < all_noise[1]);
    require_clean(*ctx);
}

} // namespace unity_temporal_test
