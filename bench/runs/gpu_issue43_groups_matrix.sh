#!/bin/bash
# Which workgroup the default matrix wants (BENCHMARKS.md's issue 43 section, session 11): fifteen
# compute chains that stand for the default matrix -- every technique, both resolutions, every
# blur, bent normals -- each in 8x8 (the default until then), 16x8 (128 invocations: the most
# Vulkan, ESSL 3.1 and WebGPU guarantee everywhere) and 16x16 groups, at 1920x1080 on room,
# engine and terrain. Two report runs, each holding every group of its chains (interleaved
# rounds: the A/B of one chain is on one warm GPU in one run); per pass times in pass_ms.
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue43_groups_matrix.sh
cd "$(dirname "$0")/../.."
[ -z "$DRY" ] && . bench/device/setup.sh
S=room,engine,terrain
run_set() { # $1 the run's name, then its chains
  local name=$1 V= chain wg
  shift
  for chain in "$@"; do
    local base=${chain%%+*} tail= # chain+TOKENS: tokens after the stage (-bn)
    [ "$base" != "$chain" ] && tail=-${chain#*+}
    for wg in "" -wg16x8 -wg16x16; do V=$V${V:+,}$base-std-persp-cs$tail$wg; done
  done
  [ -n "$DRY" ] && { echo "$V" | tr , "\n"; return; } # DRY=1: print the names only
  clocks
  echo "== $name" >> $L
  timeout 280 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
    --no-fetch-floor --out /tmp/$name >> $L 2>&1
  echo "rc $?" >> $L
  clocks
  (cd /tmp && tar -czf $OUT/$name.tar.gz $name/results.json 2>>$L)
}
run_set groups_a ssao-s16-half-bilateral-gbufworld ssao-s16-full-bilateral-gbufworld ssao-s32-half-box-gbufworld \
  ssao-s8-full-noblur-gbufworld sao-s16-half-denoise-gbufworld sao-s32-full-bilateral-gbufworld vbao-3x3-half-bilateral-gbufworld
run_set groups_b gtao-2x2-half-denoise-gbufworld gtao-2x3-half-bilateral-gbufworld gtao-4x4-half-noblur-gbufworld \
  gtao-3x3-full-denoise-gbufworld gtao-8x4-full-box-gbufworld vbao-3x3-full-bilateral-gbufworld gtao-3x3-half-denoise-gbufworld+bn \
  gtao-3x3-half-denoise3-gbufworld
