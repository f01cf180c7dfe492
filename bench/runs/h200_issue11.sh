#!/bin/bash
# The H200 run behind BENCHMARKS.md's issue-11 figures (device tool): the default matrix and
# ten fp16 twins at 1080p in one report, then the vulkan tests (setup.sh says what to carry).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
{ date; nvidia-smi; nvidia-smi -q -d CLOCK | head -40; } > $OUT/smi.txt 2>&1
echo "== all 1080p" >> $L; timeout 420 $B/aogen_report --size 1920x1080 --rays 1024 --scenes room,stairs,engine,teapots,terrain --variants bench/runs/h200_all.json --python /tmp/fakepy --out /tmp/a1080 >> $L 2>&1; echo "rc $?" >> $L
echo "== vulkan tests" >> $L; timeout 90 $B/aogen_vulkan_tests >> $L 2>&1; echo "rc $?" >> $L
cd /tmp && tar -czf $OUT/reports.tar.gz a1080/results.json a1080/report.md 2>>$L
