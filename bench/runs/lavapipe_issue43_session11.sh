#!/bin/bash
# The lavapipe A/B behind BENCHMARKS.md's issue 43 section, session 11: the build before the
# session (OLD_PACK: e686f19's bench/device/pack.sh output, .carry/before.tar.xz) and this one,
# old / new / old / new on the idle 2-core machine, on five scenes at the default 320x180: the
# 3x3 chains (the 3x3 pass in quads), the default GTAO chain and VBAO High (slice taps read
# first) and the default SSAO chain (its shaders the same in both: the control). Prints per
# pass medians and new / old of the sums. Lavapipe's times (the CPU running the shaders) are a
# second source beside the device's, never a GPU figure.
# Usage: bash bench/runs/lavapipe_issue43_session11.sh OLD_PACK OUT_DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
old_pack=$1 out=$2
mkdir -p "$out/old_build" && tar -xJf "$old_pack" -C "$out/old_build"
V=gtao-2x2-half-denoise3-gbufworld-std-persp-cs,gtao-3x3-full-denoise3-gbufworld-std-persp-cs,ssao-s16-half-denoise3-gbufworld-std-persp-cs
V=$V,gtao-2x2-half-denoise-gbufworld-std-persp-cs,ssao-s16-half-bilateral-gbufworld-std-persp-cs,vbao-3x3-half-bilateral-gbufworld-std-persp-cs
for r in old new old2 new2; do
  case $r in
    old*) bin=(env LD_LIBRARY_PATH=$out/old_build/lib $out/old_build/bin/aogen_report) ;;
    new*) bin=(build/report/aogen_report) ;;
  esac
  "${bin[@]}" --variants $V --scenes room,engine,terrain,stairs,teapots --motion-variants none --no-feature-saving --no-fetch-floor \
    --rounds 5 --iterations 3 --out "$out/$r" > "$out/$r.log" 2>&1
done
python3 - "$out" <<'PY'
import json, statistics as st, sys
def load(r):
    out = {}
    for v in json.load(open(f"{sys.argv[1]}/{r}/results.json"))["variants"]:
        sc = [s for s in v["scenes"] if s.get("pass_ms")]
        out[v["name"]] = {p: st.median(s["pass_ms"][i] for s in sc) for i, p in enumerate(v["passes"])}
    return out
R = {r: load(r) for r in ["old", "new", "old2", "new2"]}
for n in R["old"]:
    print(n)
    for p in R["old"][n]:
        o, w, o2, w2 = (R[r][n][p] for r in ["old", "new", "old2", "new2"])
        print(f"  {p:14s} old {o:.3f} new {w:.3f} old2 {o2:.3f} new2 {w2:.3f}  new2/old2 {w2 / o2:.3f}")
PY
