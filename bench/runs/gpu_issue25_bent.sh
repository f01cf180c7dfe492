#!/bin/bash
# Issue 25's bent normals on an NVIDIA GPU (BENCHMARKS.md, "bent normals"):
#   1. the GPU tests of issue 25 on NVIDIA's driver, unvalidated (the image has no validation
#      layer: AOGEN_TESTS_OPTIONAL_DEPS=1): the frame index's oracle, multi-bounce against the
#      paper's fit (with its one-step bound), the deinterleaved twin, and the -bn chains (the
#      twin's AO bit for bit, unit normals, the lean out of the crease);
#   2. each -bn variant of the default matrix beside its twin, timed in one run as a frame loop
#      runs (3 rounds of 20 iterations after the warm-up, fetch floors on), with the bent
#      normals' angular error against the 1024-ray truth, at 1920x1080 on room, engine, terrain.
# Carries .carry/pack.tar.xz and .gl (setup.sh).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
clocks
echo "== tests" >> $L
AOGEN_TESTS_OPTIONAL_DEPS=1 timeout 240 $B/aogen_vulkan_tests "vulkan: frame f*,vulkan: a -mb*,vulkan: an albedo*,vulkan: a -deint*,vulkan: a -bn*,vulkan: a bent normal*" >> $L 2>&1; echo "rc $?" >> $L
V=gtao-2x2-half-denoise-gbufworld-std-persp-cs,gtao-2x2-half-denoise-gbufworld-std-persp-cs-bn
V=$V,gtao-3x3-half-denoise-gbufworld-std-persp-cs,gtao-3x3-half-denoise-gbufworld-std-persp-cs-bn
V=$V,gtao-4x4-half-denoise-gbufworld-std-persp-cs,gtao-4x4-half-denoise-gbufworld-std-persp-cs-bn
V=$V,gtao-3x3-full-noblur-gbufworld-std-persp-cs,gtao-3x3-full-noblur-gbufworld-std-persp-cs-bn
V=$V,vbao-3x3-half-bilateral-gbufworld-std-persp-cs,vbao-3x3-half-bilateral-gbufworld-std-persp-cs-bn
clocks
echo "== report" >> $L
timeout 420 $B/aogen_report --size 1920x1080 --rays 1024 --frames 1 --scenes room,engine,terrain --variants $V --no-feature-saving --out /tmp/rbn >> $L 2>&1; echo "rc $?" >> $L
clocks
cp /tmp/rbn/results.json $OUT/bent_1080p.json 2>>$L
cp /tmp/rbn/report.md $OUT/bent_1080p.md 2>>$L
