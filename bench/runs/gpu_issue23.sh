#!/bin/bash
# The GPU run (an H200 when one is lent; 2026-12-05 it ran on an H100) behind BENCHMARKS.md's "issue 23" section: SSAO with its tuned defaults and
# smooth decisions beside the seeds' values and steps (the -step variant runs the seeds'
# radius R and strength 1), SAO, and the GTAO variants the issue measures against, in one
# report run at 1920x1080 on room, stairs, engine, teapots, terrain against a 1024-ray
# reference; then the stability suite on the H200 for SSAO-family variants. setup.sh says
# what to carry.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
S=room,stairs,engine,teapots,terrain
clocks() { nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1; }
clocks
echo "== report" >> $L; timeout 300 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants bench/runs/gpu_issue23.json --no-feature-saving --python /tmp/fakepy --out /tmp/new >> $L 2>&1; echo "rc $?" >> $L
clocks
F=ssao-s16-half-bilateral-gbufworld-std-persp-cs,ssao-s8-full-box-gbufworld-std-persp-cs,ssao-s32-half-denoise-gbufworld-std-persp-cs,ssao-s16-half-bilateral-recon-rev-ortho-cs,sao-s16-half-bilateral-gbufworld-std-persp-cs,sao-s8-full-denoise-gbufworld-std-persp-cs,sao-s32-half-denoise-gbufworld-std-persp-cs,sao-s16-half-denoise-recon-rev-ortho-cs
echo "== stability" >> $L; timeout 200 $B/aogen_report --suite stability --check --variants $F --out /tmp/stab >> $L 2>&1; echo "rc $?" >> $L
cd /tmp && tar -czf $OUT/reports.tar.gz new/results.json new/report.md stab/*.md stab/*.json 2>>$L
