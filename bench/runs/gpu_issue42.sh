#!/bin/bash
# The device run behind BENCHMARKS.md's issue 42 section (the history pass), at 1920x1080 on
# room, stairs, engine and rolling_sphere (the built-in scenes with a camera path). Two
# phases, one device call each (each under the 10-minute limit):
#   time     the history pass's cost: gtao-2x2-half-denoise and gtao-1x4-half-noblur without
#            and with the pass (-hist, -histmv), and gtao-4x4-half-noblur, timed in the same
#            interleaved rounds after the warm-up (the report's GPU protocol), each beside its
#            fetch and bandwidth floors; per pass times in results.json (pass_ms). A 1024-ray
#            reference; no report in motion.
#   motion   the report in motion at 1080p: the default motion variants along the four paths,
#            frames 8..15 against 256-ray references; the still part for one variant only.
# Usage (from the device tool, carry [".gl", ".carry"]): bash bench/runs/gpu_issue42.sh time|motion
# setup.sh says what to carry (bench/device/pack.sh makes .carry/pack.tar.xz).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
S=room,stairs,engine,rolling_sphere
G=gtao-2x2-half-denoise-gbufworld-std-persp-cs
case "$1" in
time)
  V=$G,$G-hist,$G-histmv,gtao-1x4-half-noblur-gbufworld-std-persp-cs,gtao-1x4-half-noblur-gbufworld-std-persp-cs-histmv,gtao-4x4-half-noblur-gbufworld-std-persp-cs
  clocks
  echo "== time" >> $L
  timeout 540 $B/aogen_report --size 1920x1080 --scenes $S --variants $V --motion-variants none --no-feature-saving --out /tmp/time >> $L 2>&1
  echo "rc $?" >> $L
  clocks
  cd /tmp && tar -czf $OUT/time.tar.gz time/results.json time/report.md 2>>$L
  ;;
motion)
  clocks
  echo "== motion" >> $L
  timeout 560 $B/aogen_report --size 1920x1080 --scenes $S --variants $G --no-feature-saving --no-fetch-floor --out /tmp/motion >> $L 2>&1
  echo "rc $?" >> $L
  clocks
  cd /tmp && tar -czf $OUT/motion.tar.gz motion/results.json motion/report.md 2>>$L
  ;;
*)
  echo "usage: gpu_issue42.sh time|motion" >&2
  exit 2
  ;;
esac
