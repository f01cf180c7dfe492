#!/bin/bash
# The 3x3 denoise in motion (BENCHMARKS.md's issue 43 section, session 10): the report in
# motion on lavapipe at the default size along the four built-in camera paths, the 3x3 beside
# the 5x5 on gtao-2x2-half with and without the history pass, the default SSAO chain's
# bilateral beside the 3x3, and gtao-4x4-half-noblur. Errors, ghosting and flicker are the
# shaders' arithmetic and hold on any device; the still part is one variant only.
# Usage: bash bench/runs/lavapipe_issue43_denoise3_motion.sh OUT_DIR   (about a minute)
set -euo pipefail
cd "$(dirname "$0")/../.."
M=gtao-2x2-half-denoise-gbufworld-std-persp-cs,gtao-2x2-half-denoise3-gbufworld-std-persp-cs
M=$M,gtao-2x2-half-denoise-gbufworld-std-persp-cs-histmv,gtao-2x2-half-denoise3-gbufworld-std-persp-cs-histmv
M=$M,ssao-s16-half-bilateral-gbufworld-std-persp-cs,ssao-s16-half-denoise3-gbufworld-std-persp-cs
M=$M,gtao-4x4-half-noblur-gbufworld-std-persp-cs
build/report/aogen_report --variants gtao-2x2-half-denoise-gbufworld-std-persp-cs --scenes room,stairs,engine,rolling_sphere \
  --motion-variants $M --no-fetch-floor --no-feature-saving --out "$1" > "$1.log" 2>&1
grep -A9 '^| variant | error | ghosting | flicker' "$1/report.md"
