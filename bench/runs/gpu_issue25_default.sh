#!/bin/bash
# Issue 25's goal at the report's defaults: every built-in scene at 320x180 against the
# 4096-ray reference, 8 frames per variant (the default) — the error after 8 frames of every
# variant beside its single frame. Errors only (one quick timing round); errors do not depend
# on the device beyond 1/255 a pixel. Carries .carry/pack.tar.xz (setup.sh).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm --format=csv >> $L 2>&1
timeout 500 $B/aogen_report --rounds 1 --iterations 1 --warmup-ms 0 --budget-ms 0 --no-fetch-floor --no-feature-saving --out /tmp/r_default >> $L 2>&1; echo "rc $?" >> $L
cp /tmp/r_default/results.json $OUT/default.json 2>>$L
