#!/bin/bash
# The H200 run behind BENCHMARKS.md's "issue 22, deinterleaved dispatch" section: each chain
# beside its -deint twin (the same output bit for bit: only the dispatch order differs) in one
# report run, 1920x1080, room, stairs, engine, teapots, terrain, a 1024-ray reference; then the
# binary of commit 5147c3e (.carry/old.tar.xz) on four chains whose AO pass the last session's
# fix-up returned to its old arithmetic (the control that was not re-timed). setup.sh says what
# to carry.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/old && tar -xJf .carry/old.tar.xz -C /tmp/old
S=room,stairs,engine,teapots,terrain
clocks() { nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1; }
clocks
echo "== new" >> $L; timeout 330 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants bench/runs/h200_issue22b_new.json --no-feature-saving --python /tmp/fakepy --out /tmp/new >> $L 2>&1; echo "rc $?" >> $L
clocks
echo "== old" >> $L; timeout 150 /tmp/old/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants bench/runs/h200_issue22b_old.json --no-feature-saving --python /tmp/fakepy --plot-script report/plot_error_vs_time.py --out /tmp/old_r >> $L 2>&1; echo "rc $?" >> $L
clocks
cd /tmp && tar -czf $OUT/reports.tar.gz new/results.json new/report.md old_r/results.json old_r/report.md 2>>$L
