#!/bin/bash
# The device run behind BENCHMARKS.md's issue 43 section on the 3x3 denoise: this build
# (.carry/pack.tar.xz, made by bench/device/pack.sh after scripts/build.sh) at 1920x1080 on
# room, engine and terrain, each 3x3 chain beside its 5x5 (or bilateral) twin on the same AO
# pass, in one report run: the report interleaves the variants' rounds, so the twins are timed
# A/B on the same warm GPU; per pass times (pass_ms) give the denoise passes alone. The run is
# made twice: a drift of the clocks shows as the two runs disagreeing.
#   gtao-3x3-full-denoise(3)-gbufview   XeGTAO High's counts at full resolution (issue 43's goal:
#                                       AO <= 0.121 ms, chain <= 0.151 ms, denoise <= 0.017 ms)
#   gtao-2x2-half-denoise(3)            the default GTAO chain (<= 0.045 ms)
#   ssao-s16-half-bilateral / -denoise3 the default SSAO chain (<= 0.050 ms)
# 1024-ray references (the fewest --rays takes), errors at 1080p from the same runs.
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue43_denoise3.sh
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
S=room,engine,terrain
V=gtao-3x3-full-denoise-gbufview-std-persp-cs,gtao-3x3-full-denoise3-gbufview-std-persp-cs
V=$V,gtao-2x2-half-denoise-gbufworld-std-persp-cs,gtao-2x2-half-denoise3-gbufworld-std-persp-cs
V=$V,ssao-s16-half-bilateral-gbufworld-std-persp-cs,ssao-s16-half-denoise3-gbufworld-std-persp-cs
run() { # $1 label
  clocks
  echo "== $1" >> $L
  timeout 250 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
    --out /tmp/$1 >> $L 2>&1
  echo "rc $?" >> $L
  clocks
}
run first
run second
cd /tmp && tar -czf $OUT/denoise3.tar.gz first/results.json second/results.json first/report.md 2>>$L
