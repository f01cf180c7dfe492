#!/bin/bash
# The GPU runs behind the temporal step offset (issue 25; BENCHMARKS.md "the frames move the
# steps"). Carries two packs: .carry/pack_old.tar.xz, the aogen_report of 086d6bb (frames turn
# the slices only), and .carry/pack.tar.xz, the build whose frames also move the inner steps.
#   $1 = frames: the default matrix on room, engine and terrain at 1920x1080 against one
#        1024-ray reference, both builds with --frames 8, scoring only (one timing round):
#        frame 0 must be the same on NVIDIA's compiler too (every variant's default metrics
#        and raw counts equal), and the 8-frame errors compare the two designs. Then the
#        temporal GPU tests on NVIDIA's driver.
#   $1 = cost: what the step offset costs a frame loop (a subtract and a select per step):
#        six variants timed by the two builds, ABBA, 3 rounds of 20 iterations after the
#        warm-up, 1920x1080, room and engine.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/old && tar -xJf .carry/pack_old.tar.xz -C /tmp/old
if [ "$1" = frames ]; then
  common=(--size 1920x1080 --rays 1024 --scenes room,engine,terrain --rounds 1 --iterations 1 --warmup-ms 0 --budget-ms 0 --no-fetch-floor --no-feature-saving --frames 8)
  clocks; echo "== old" >> $L; timeout 270 /tmp/old/bin/aogen_report "${common[@]}" --out /tmp/r_old >> $L 2>&1; echo "rc $?" >> $L
  clocks; echo "== new" >> $L; timeout 270 $B/aogen_report "${common[@]}" --out /tmp/r_new >> $L 2>&1; echo "rc $?" >> $L
  cp /tmp/r_old/results.json $OUT/frames_old.json 2>>$L; cp /tmp/r_new/results.json $OUT/frames_new.json 2>>$L
  echo "== vulkan tests" >> $L
  AOGEN_TESTS_OPTIONAL_DEPS=1 timeout 40 $B/aogen_vulkan_tests "vulkan: frame f*,vulkan: a step offset*" >> $L 2>&1; echo "rc $?" >> $L
else
  V=gtao-2x2-half-denoise,gtao-3x3-half-denoise,gtao-4x4-half-noblur,gtao-3x3-full-denoise,vbao-3x3-half-bilateral,ssao-s16-half-bilateral
  V=$(echo $V | sed 's/\([^,]*\)/\1-gbufworld-std-persp-cs/g')
  common=(--size 1920x1080 --rays 1024 --scenes room,engine --variants $V --no-feature-saving --frames 1)
  n=0
  for build in old new new old; do
    n=$((n + 1)); clocks; echo "== $build ($n)" >> $L
    if [ $build = old ]; then timeout 140 /tmp/old/bin/aogen_report "${common[@]}" --out /tmp/r$n >> $L 2>&1
    else timeout 140 $B/aogen_report "${common[@]}" --out /tmp/r$n >> $L 2>&1; fi
    echo "rc $?" >> $L
    cp /tmp/r$n/results.json $OUT/cost_${build}_$n.json 2>>$L
  done
  clocks
fi
