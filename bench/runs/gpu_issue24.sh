#!/bin/bash
# The GPU run behind BENCHMARKS.md's "issue 24" section: the report on the device image, which
# has no Python plotting (no matplotlib) and no browser — report.html, report.md, results.json
# and error_vs_time.svg must all be written by aogen_report alone. The default matrix at
# 1920x1080 on three scenes against a 1024-ray reference; the page is then opened in chromium
# here (tests/report/page: "a report made by aogen_report"). setup.sh says what to carry.
# Not yet run: no device was lent in the session that wrote it (2026-12-05).
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
clocks() { nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1; }
python3 -c 'import matplotlib' >> $L 2>&1 && echo "matplotlib: present" >> $L || echo "matplotlib: absent" >> $L
clocks
echo "== report" >> $L; timeout 420 $B/aogen_report --size 1920x1080 --rays 1024 --scenes room,engine,terrain --no-feature-saving --out /tmp/r24 >> $L 2>&1; echo "rc $?" >> $L
clocks
ls -l /tmp/r24 >> $L
cd /tmp && tar -cf $OUT/report24.tar r24/report.html r24/report.md r24/results.json r24/error_vs_time.svg 2>>$L
