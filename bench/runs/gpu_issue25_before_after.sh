#!/bin/bash
# Issue 25's cost to the variants that use none of it (BENCHMARKS.md, "issue 25 before and
# after"): the frame rotation (one complex product per pixel in the AO pass), the albedo member
# and ao_output's pixel argument, the bent normals' ao_value (a float without -bn). Six
# default-matrix variants timed by the build before issue 25 (e8f3af4, .carry/pack_old.tar.xz:
# its aogen_report, the same libraries) and by this one, as a frame loop runs (3 rounds of 20
# iterations after the warm-up), at 1920x1080 on room and engine; the two builds alternate
# ABBA ($1: "old new" or "new old") so that a drift in the clocks shows as a difference
# between the pairs.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/old && tar -xJf .carry/pack_old.tar.xz -C /tmp/old
V=gtao-2x2-half-denoise,gtao-3x3-half-denoise,gtao-4x4-half-noblur,vbao-3x3-half-bilateral,ssao-s16-half-bilateral,sao-s16-half-denoise
V=$(echo $V | sed 's/\([^,]*\)/\1-gbufworld-std-persp-cs/g')
common=(--size 1920x1080 --rays 1024 --scenes room,engine --variants $V --no-feature-saving)
n=0
for build in ${1:-old new}; do
  n=$((n + 1)); clocks; echo "== $build ($n)" >> $L
  if [ $build = old ]; then timeout 280 /tmp/old/bin/aogen_report "${common[@]}" --out /tmp/r$n >> $L 2>&1
  else timeout 280 $B/aogen_report "${common[@]}" --frames 1 --out /tmp/r$n >> $L 2>&1; fi
  echo "rc $?" >> $L
  cp /tmp/r$n/results.json $OUT/${build}_$n.json 2>>$L
done
clocks
