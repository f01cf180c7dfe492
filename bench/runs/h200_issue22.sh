#!/bin/bash
# The H200 run behind BENCHMARKS.md's issue-22 section: the binaries of commit 5147c3e (before
# the denoise's shared edges and the upsample's shared candidates: .carry/old/) and of the
# issue's work (the depth MIP chain as -mipN twins), one after the other on the same device,
# 1920x1080, room, stairs, engine, teapots, terrain, a 1024-ray reference (deterministic: both
# runs score against the same truth). The passes whose code did not change between the two
# binaries are the run-to-run control. setup.sh says what to carry.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/old && tar -xJf .carry/old.tar.xz -C /tmp/old
S=room,stairs,engine,teapots,terrain
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1
echo "== new" >> $L; timeout 280 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants bench/runs/h200_issue22_new.json --no-feature-saving --python /tmp/fakepy --out /tmp/new >> $L 2>&1; echo "rc $?" >> $L
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1
echo "== old" >> $L; timeout 200 /tmp/old/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants bench/runs/h200_issue22_old.json --no-feature-saving --python /tmp/fakepy --plot-script report/plot_error_vs_time.py --out /tmp/old_r >> $L 2>&1; echo "rc $?" >> $L
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1
cd /tmp && tar -czf $OUT/reports.tar.gz new/results.json new/report.md old_r/results.json old_r/report.md 2>>$L
