#!/bin/bash
# The 3x3 denoise in quads (BENCHMARKS.md's issue 43 section, session 11): the build before
# (.carry/before.tar.xz: e686f19's pack, one pixel per invocation, a vec3 tile) and this one
# (.carry/pack.tar.xz: a 2 x 2 quad per invocation from a 4 x 4 window, a tile of packed
# words), after / before / after in one call on one warm GPU, at 1920x1080 on room, engine and
# terrain: the three 3x3 chains of the issue's goals, the full-resolution one also in 16x16
# groups, and the 5x5 chain as the control (the same shaders in both builds: its times must
# agree). Per pass times in results.json's pass_ms.
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue43_denoise3_quads.sh
# Before: cp the old pack to .carry/before.tar.xz, rebuild, bash bench/device/pack.sh.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/before && tar -xJf .carry/before.tar.xz -C /tmp/before
S=room,engine,terrain
V=gtao-3x3-full-denoise3-gbufview-std-persp-cs,gtao-3x3-full-denoise3-gbufview-std-persp-cs-wg16x16,gtao-2x2-half-denoise3-gbufworld-std-persp-cs
V=$V,ssao-s16-half-denoise3-gbufworld-std-persp-cs,gtao-3x3-full-denoise-gbufview-std-persp-cs
run() { # $1 label, $2 binary directory
  clocks
  echo "== $1" >> $L
  timeout 175 $2/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
    --no-fetch-floor --out /tmp/$1 >> $L 2>&1
  echo "rc $?" >> $L
  clocks
}
run after1 $B
run before /tmp/before/bin
run after2 $B
cd /tmp && tar -czf $OUT/quads.tar.gz after1/results.json before/results.json after2/results.json 2>>$L
