#!/bin/bash
# The GPU run behind issue 25's temporal figures: frame 0 must be today's output bit for bit on
# a GPU too (NVIDIA's compiler contracts and reorders what lavapipe does not), and the error
# after 8 frames at 1080p. Carries two packs: .carry/pack_old.tar.xz, built from e8f3af4 (the
# last commit before the frame index), and .carry/pack.tar.xz, the new build. Both run the
# default matrix on three scenes at 1920x1080 against the same 1024-ray reference, scoring
# only (one timing round: the times are not the point); the new one with --frames 8. The two
# results.json are compared here: every variant's default metrics and raw counts on every
# scene equal (339 runs: all equal, 2026-12-06, H100 80GB HBM3), and the 8-frame errors.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/old && tar -xJf .carry/pack_old.tar.xz -C /tmp/old
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1
common=(--size 1920x1080 --rays 1024 --scenes room,engine,terrain --rounds 1 --iterations 1 --warmup-ms 0 --budget-ms 0 --no-fetch-floor --no-feature-saving)
echo "== old" >> $L; timeout 280 /tmp/old/bin/aogen_report "${common[@]}" --out /tmp/r_old --python /tmp/fakepy >> $L 2>&1 || timeout 280 /tmp/old/bin/aogen_report "${common[@]}" --out /tmp/r_old >> $L 2>&1; echo "rc $?" >> $L
echo "== new" >> $L; timeout 280 $B/aogen_report "${common[@]}" --frames 8 --out /tmp/r_new >> $L 2>&1; echo "rc $?" >> $L
cp /tmp/r_old/results.json $OUT/old.json 2>>$L; cp /tmp/r_new/results.json $OUT/new.json 2>>$L
# The frame index's and multi-bounce's GPU tests on NVIDIA's driver (no validation layer on
# the image: AOGEN_TESTS_OPTIONAL_DEPS=1 runs them unvalidated).
echo "== vulkan tests" >> $L
AOGEN_TESTS_OPTIONAL_DEPS=1 timeout 120 $B/aogen_vulkan_tests "vulkan: frame f*,vulkan: a -mb*,vulkan: an albedo*,vulkan: a -deint*" >> $L 2>&1; echo "rc $?" >> $L
