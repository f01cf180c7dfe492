#!/bin/bash
# Which workgroup the 3x3 denoise wants (BENCHMARKS.md's issue 43 section, session 10): the
# full-resolution chain at XeGTAO High's counts with the 3x3 and the 5x5, each in 8x8 (the
# default), 16x8 and 16x16 groups, in one report run at 1920x1080 on room, engine and terrain
# (interleaved rounds: an A/B on one warm GPU); per pass times in results.json's pass_ms. The
# workgroup is the whole chain's (every pass of a -wgXxY variant), so the AO pass moves too.
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue43_denoise3_groups.sh
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
S=room,engine,terrain
V=
for blur in denoise denoise3; do
  for wg in "" -wg16x8 -wg16x16; do
    V=$V${V:+,}gtao-3x3-full-$blur-gbufview-std-persp-cs$wg
  done
done
clocks
echo "== groups" >> $L
timeout 250 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
  --no-fetch-floor --out /tmp/groups >> $L 2>&1
echo "rc $?" >> $L
clocks
cd /tmp && tar -czf $OUT/groups.tar.gz groups/results.json 2>>$L
