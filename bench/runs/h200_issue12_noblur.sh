#!/bin/bash
# The H200 run behind BENCHMARKS.md's issue-12 noblur figures: GTAO at half resolution
# without a blur (the depth-aware upsample only) at the slice counts where that scores best,
# and three denoise variants again, for the spread across runs (setup.sh says what to carry).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,power.draw --format=csv >> $L 2>&1
echo "== noblur 1080p" >> $L; timeout 400 $B/aogen_report --size 1920x1080 --rays 1024 --scenes room,stairs,engine,teapots,terrain --variants bench/runs/h200_issue12_noblur.json --no-feature-saving --python /tmp/fakepy --out /tmp/n1080 >> $L 2>&1; echo "rc $?" >> $L
cd /tmp && tar -czf $OUT/reports.tar.gz n1080/results.json n1080/report.md 2>>$L
