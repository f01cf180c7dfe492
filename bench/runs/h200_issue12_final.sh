#!/bin/bash
# The H200 run behind BENCHMARKS.md's final issue-12 timing: every half-resolution GTAO of the
# default matrix with the bilateral blur and the single-pass denoise (with the depth-aware
# upsample; four without it), GTAO at full resolution, VBAO at its presets, SSAO's default
# beside its denoise twin; 1920x1080 on room, stairs, engine, teapots, terrain (setup.sh says
# what to carry).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,power.draw --format=csv >> $L 2>&1
echo "== final 1080p" >> $L; timeout 560 $B/aogen_report --size 1920x1080 --rays 1024 --scenes room,stairs,engine,teapots,terrain --variants bench/runs/h200_issue12_final.json --no-feature-saving --python /tmp/fakepy --out /tmp/f1080 >> $L 2>&1; echo "rc $?" >> $L
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,power.draw --format=csv >> $L 2>&1
cd /tmp && tar -czf $OUT/reports.tar.gz f1080/results.json f1080/report.md 2>>$L
