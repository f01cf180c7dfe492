#!/bin/bash
# The lavapipe run behind BENCHMARKS.md's issue 43 section: the build before the change and
# this one, one after the other on the idle 2-core machine, at 320x180 on room, engine and
# terrain, with the variants of the issue's table -- lavapipe's times (the CPU running the
# shaders through LLVM), a second source beside the static counts, never a GPU figure.
# Order after, before, after: the two "after" runs disagreeing would show the machine drifting. 1024-ray references (the fewest --rays takes).
# Usage: bash bench/runs/lavapipe_issue43.sh BEFORE_BIN_DIR OUT_DIR
#   BEFORE_BIN_DIR: a directory holding the earlier build's aogen_report (for instance
#   `tar -xJf .carry/before.tar.xz -C /tmp/before ./bin/aogen_report` gives /tmp/before/bin)
set -euo pipefail
cd "$(dirname "$0")/../.."
before=$1
out=$2
S=room,engine,terrain
V=gtao-3x3-full-denoise-gbufview-std-persp-cs,gtao-2x2-half-denoise-gbufworld-std-persp-cs,ssao-s16-half-bilateral-gbufworld-std-persp-cs
run() { # $1 label, $2 binary directory
  "$2/aogen_report" --size 320x180 --rays 1024 --scenes $S --variants $V --motion-variants none --no-feature-saving \
    --no-fetch-floor --rounds 5 --iterations 3 --warmup-ms 200 --out "$out/$1" > "$out/$1.log" 2>&1
}
mkdir -p "$out"
run after1 build/report
run before "$before"
run after2 build/report
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
runs = {k: {v["name"]: v for v in json.load(open(f"{out}/{k}/results.json"))["variants"]} for k in ("after1", "before", "after2")}
print("| variant | before ms | after ms (1st) | after ms (2nd) | after / before | RMSE before | RMSE after |")
print("|---|---:|---:|---:|---:|---:|---:|")
for name, b in runs["before"].items():
    a1, a2 = runs["after1"][name], runs["after2"][name]
    ratio = (a1["ms"] + a2["ms"]) / 2 / b["ms"]
    print(f"| `{name}` | {b['ms']:.3f} | {a1['ms']:.3f} | {a2['ms']:.3f} | {ratio:.3f} | {b['rmse']:.5f} | {a1['rmse']:.5f} |")
PY
