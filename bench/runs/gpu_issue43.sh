#!/bin/bash
# The device run behind BENCHMARKS.md's issue 43 section (the tap's arithmetic): the build
# before the change (.carry/before.tar.xz: bin/aogen_report of 8e41ab3) and this one
# (.carry/pack.tar.xz), one after the other in the same call on the same warm GPU, at
# 1920x1080 on room, engine and terrain, with the variants of the issue's table:
#   gtao-3x3-full-denoise-gbufview   XeGTAO High's slices and steps at full resolution
#   gtao-2x2-half-denoise            the default GTAO chain
#   ssao-s16-half-bilateral          the default SSAO chain
# each beside its fetch and bandwidth floors (the report's GPU protocol: warm-up, interleaved
# rounds, medians and p10-p90; per pass times in results.json's pass_ms). The order is
# after, before, after: a drift of the clocks between the two builds shows as the two
# "after" runs disagreeing. 1024-ray references, the fewest --rays takes (both builds score against the same truth).
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue43.sh
# Before: mv .carry/pack.tar.xz .carry/before.tar.xz (the old build's pack), rebuild, then
# bash bench/device/pack.sh (this build's).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/before && tar -xJf .carry/before.tar.xz -C /tmp/before
S=room,engine,terrain
V=gtao-3x3-full-denoise-gbufview-std-persp-cs,gtao-2x2-half-denoise-gbufworld-std-persp-cs,ssao-s16-half-bilateral-gbufworld-std-persp-cs
run() { # $1 label, $2 binary directory
  clocks
  echo "== $1" >> $L
  timeout 170 $2/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
    --out /tmp/$1 >> $L 2>&1
  echo "rc $?" >> $L
  clocks
}
run after1 $B
run before /tmp/before/bin
run after2 $B
cd /tmp && tar -czf $OUT/ab.tar.gz after1/results.json before/results.json after2/results.json after1/report.md before/report.md 2>>$L
