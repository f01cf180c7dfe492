#!/bin/bash
# The H200 run behind BENCHMARKS.md's "issue 22, far slice taps" section: the binary before the
# change (commit ce2a11c, every slice tap the exact bilinear reading: .carry/prev.tar.xz) and
# after it (taps from 16 pixels on read their texel's centre), one after the other on the same
# device, 1920x1080, room, stairs, engine, teapots, terrain, a 1024-ray reference; SSAO (code
# unchanged) is the control. Then the stability suite on the H200 for the slice variants of
# the default matrix. setup.sh says what to carry.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
mkdir -p /tmp/prev && tar -xJf .carry/prev.tar.xz -C /tmp/prev
S=room,stairs,engine,teapots,terrain
V=bench/runs/h200_issue22c.json
clocks() { nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1; }
clocks
echo "== new" >> $L; timeout 170 $B/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --no-feature-saving --python /tmp/fakepy --out /tmp/new >> $L 2>&1; echo "rc $?" >> $L
clocks
echo "== prev" >> $L; timeout 170 /tmp/prev/bin/aogen_report --size 1920x1080 --rays 1024 --scenes $S --variants $V --no-feature-saving --python /tmp/fakepy --out /tmp/prev_r >> $L 2>&1; echo "rc $?" >> $L
clocks
G=gtao-1x2-half-bilateral-gbufworld-std-persp-cs,gtao-2x3-half-denoise-gbufworld-std-persp-cs,gtao-3x3-full-denoise-gbufview-std-persp-cs,gtao-4x4-full-noblur-gbufworld-std-persp-cs,vbao-2x3-half-bilateral-gbufworld-std-persp-cs,vbao-3x3-full-noblur-recon-std-persp-cs,gtao-2x3-half-bilateral-recon-rev-ortho-cs
echo "== stability" >> $L; timeout 200 $B/aogen_report --suite stability --check --variants $G --out /tmp/stab >> $L 2>&1; echo "rc $?" >> $L
cd /tmp && tar -czf $OUT/reports.tar.gz new/results.json new/report.md prev_r/results.json prev_r/report.md stab/*.md stab/*.json 2>>$L
