#!/bin/bash
# Issue 25's albedo G-buffer (-mbg) on an NVIDIA GPU (BENCHMARKS.md, "the albedo G-buffer"):
#   1. the multi-bounce GPU tests on NVIDIA's driver, unvalidated (the image has no validation
#      layer: AOGEN_TESTS_OPTIONAL_DEPS=1): -mb against the paper's fit, -mbg against the fit
#      at each pixel's albedo luminance, a grey G-buffer against -mb, the missing albedo;
#   2. three variants with their -mb and -mbg twins timed in one run as a frame loop runs
#      (3 rounds of 20 iterations after the warm-up, fetch floors on), at 1920x1080 on room,
#      engine and terrain: the last pass is the denoise, the AO pass, the upsample.
# Carries .carry/pack.tar.xz and .gl (setup.sh, which also defines clocks).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
clocks
echo "== tests" >> $L
AOGEN_TESTS_OPTIONAL_DEPS=1 timeout 150 $B/aogen_vulkan_tests "vulkan: a -mb*,vulkan: an albedo*" >> $L 2>&1; echo "rc $?" >> $L
V=""
for t in gtao-3x3-half-denoise gtao-3x3-full-noblur ssao-s16-half-bilateral; do
  for x in "" -mb -mbg; do V=$V${V:+,}$t-gbufworld-std-persp-cs$x; done
done
clocks
echo "== report" >> $L
timeout 400 $B/aogen_report --size 1920x1080 --rays 1024 --frames 1 --scenes room,engine,terrain --variants $V --no-feature-saving --out /tmp/rmbg >> $L 2>&1; echo "rc $?" >> $L
clocks
cp /tmp/rmbg/results.json $OUT/mbg_1080p.json 2>>$L
cp /tmp/rmbg/report.md $OUT/mbg_1080p.md 2>>$L
