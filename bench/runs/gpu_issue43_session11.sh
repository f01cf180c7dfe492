#!/bin/bash
# Session 11's two changes on the device (BENCHMARKS.md's issue 43 section, session 11): the
# build before them (.carry/before.tar.xz: e686f19's pack) and this one (.carry/pack.tar.xz),
# after / before / after in one call on one warm GPU, at 1920x1080 on room, engine and terrain.
#   - the 3x3 denoise in 2x2 quads (one invocation, four pixels from one 4x4 window of a tile
#     of packed words): the blur_denoise3 pass of the -denoise3 chains;
#   - the slice taps read first (every compute slice tap's four texels read by one gather
#     before any test, both readings taken from it; the AO is the same to the bit): the AO pass
#     of the GTAO and VBAO chains.
# Variants: GTAO at XeGTAO High's counts at full resolution with the 3x3 (also in 16x16
# groups), the default GTAO chain with the 3x3, VBAO High, and the default SSAO chain as the
# control (its shaders are the same in both builds: its times must agree). Per pass times in
# results.json's pass_ms; the fetch floors are off to fit the call.
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue43_session11.sh
# Before: cp the old pack to .carry/before.tar.xz, rebuild, bash bench/device/pack.sh.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/before && tar -xJf .carry/before.tar.xz -C /tmp/before
S=room,engine,terrain
V=gtao-3x3-full-denoise3-gbufview-std-persp-cs,gtao-3x3-full-denoise3-gbufview-std-persp-cs-wg16x16,gtao-2x2-half-denoise3-gbufworld-std-persp-cs
V=$V,vbao-3x3-half-bilateral-gbufworld-std-persp-cs,ssao-s16-half-bilateral-gbufworld-std-persp-cs
run() { # $1 label, $2 binary directory
  clocks
  echo "== $1" >> $L
  timeout 150 $2/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
    --no-fetch-floor --out /tmp/$1 >> $L 2>&1
  echo "rc $?" >> $L
  clocks
  (cd /tmp && tar -czf $OUT/$1.tar.gz $1/results.json 2>>$L) # each run's as it ends: a call cut short keeps what ran
}
# RUNS (default "after1 before after2"): which, in order -- "after1 before" where device time is short.
for r in ${RUNS:-after1 before after2}; do
  case $r in before) run before /tmp/before/bin ;; *) run $r $B ;; esac
done
