#!/bin/bash
# Workgroups for the half-resolution chains (BENCHMARKS.md's issue 43 section, session 10): the
# default GTAO chain with the 5x5 and the 3x3, the default SSAO chain and SAO's, each in 8x8 (the
# default), 16x8 and 16x16 groups, in one report run at 1920x1080 on room, engine and terrain
# (interleaved rounds: an A/B on one warm GPU); per pass times in results.json's pass_ms. The
# group is every pass's of a -wgXxY variant.
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue43_groups_half.sh
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
S=room,engine,terrain
V=
for chain in gtao-2x2-half-denoise gtao-2x2-half-denoise3 ssao-s16-half-bilateral sao-s16-half-denoise; do
  for wg in "" -wg16x8 -wg16x16; do
    V=$V${V:+,}$chain-gbufworld-std-persp-cs$wg
  done
done
clocks
echo "== groups_half" >> $L
timeout 250 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
  --no-fetch-floor --out /tmp/groups_half >> $L 2>&1
echo "rc $?" >> $L
clocks
cd /tmp && tar -czf $OUT/groups_half.tar.gz groups_half/results.json 2>>$L
