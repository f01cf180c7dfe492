#!/bin/bash
# The H200 run behind BENCHMARKS.md's issue-12 timing with the tuned GTAO defaults: the default
# matrix at 1080p (setup.sh says what to carry).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
echo "== tuned 1080p" >> $L; timeout 400 $B/aogen_report --size 1920x1080 --rays 1024 --scenes room,stairs,engine,teapots,terrain --variants bench/runs/h200_1080p.json --no-feature-saving --python /tmp/fakepy --out /tmp/t1080 >> $L 2>&1; echo "rc $?" >> $L
cd /tmp && tar -czf $OUT/reports.tar.gz t1080/results.json t1080/report.md 2>>$L
