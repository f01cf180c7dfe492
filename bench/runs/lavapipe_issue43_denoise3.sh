#!/bin/bash
# The lavapipe run behind BENCHMARKS.md's issue 43 section on the 3x3 denoise: each -denoise3
# chain of the default report beside its -denoise twin (the 5x5 on the same AO pass) and the
# default SSAO chain's bilateral, in one report run at the default report's size and scenes
# (320x180, every built-in scene): the report interleaves the variants' rounds, so the twins'
# times are an A/B on one idle machine. Lavapipe's times (the CPU running the shaders through
# LLVM) are a second source beside the device's, never a GPU figure; the errors are the
# shaders' arithmetic and hold on any device.
# Usage: bash bench/runs/lavapipe_issue43_denoise3.sh OUT_DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
out=$1
V=
for base in gtao-2x2-half gtao-3x3-half gtao-3x3-full ssao-s16-half sao-s16-half; do
  V=$V${V:+,}$base-denoise-gbufworld-std-persp-cs,$base-denoise3-gbufworld-std-persp-cs
done
V=$V,ssao-s16-half-bilateral-gbufworld-std-persp-cs
build/report/aogen_report --variants $V --motion-variants none --no-feature-saving --no-fetch-floor \
  --rounds 5 --iterations 3 --out "$out" > "$out.log" 2>&1
python3 - "$out" <<'PY'
import json, sys
runs = {v["name"]: v for v in json.load(open(f"{sys.argv[1]}/results.json"))["variants"]}
print("| AO | 5x5 RMSE | 3x3 RMSE | 3x3 / 5x5 | 5x5 ms | 3x3 ms | 3x3 / 5x5 |")
print("|---|---:|---:|---:|---:|---:|---:|")
for name, five in runs.items():
    if "-denoise-" not in name: continue
    three = runs[name.replace("-denoise-", "-denoise3-")]
    base = name.split("-denoise-")[0]
    print(f"| {base} | {five['rmse']:.5f} | {three['rmse']:.5f} | {three['rmse'] / five['rmse']:.3f} | "
          f"{five['ms']:.3f} | {three['ms']:.3f} | {three['ms'] / five['ms']:.2f} |")
PY
