#!/usr/bin/env python3
"""What each variant setting costs in code, and how long generation takes.

    python3 bench/variant_cost.py [--aogen build/generator/aogen] [--runs 5]

Runs `aogen generate` of the default matrix (all targets) --runs times into a scratch
directory and reports the median wall time, then reads manifest.json and prints, per
variant, the SPIR-V instruction count of its AO shader and of its whole pass chain,
as ratios to the default variant (ssao-s16-half-bilateral-gbufworld-std-persp-cs).
Instruction counts are deterministic (same inputs, same SPIR-V); GPU run times come
from the Vulkan harness's report.
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

DEFAULT = "ssao-s16-half-bilateral-gbufworld-std-persp-cs"

# What one axis costs: each pair differs from its first member in that axis alone.
FEATURE_PAIRS = [
    ("point-cloud fallback", "ssao-s64-full-noblur-recon-std-persp-fs-rc004", "ssao-s64-full-noblur-recon-std-persp-fs-pc-rc004"),
    ("view-space G-buffer normals", DEFAULT, "ssao-s16-half-bilateral-gbufview-std-persp-cs"),
    ("reconstructed normals", DEFAULT, "ssao-s16-half-bilateral-recon-std-persp-cs"),
    ("reversed-infinite depth", DEFAULT, "ssao-s16-half-bilateral-gbufworld-revinf-persp-cs"),
    ("orthographic projection", DEFAULT, "ssao-s16-half-bilateral-gbufworld-std-ortho-cs"),
    ("full resolution", DEFAULT, "ssao-s16-full-bilateral-gbufworld-std-persp-cs"),
    ("seed-exact bilateral depth", DEFAULT, "ssao-s16-half-bilateral-gbufworld-std-persp-cs-rawdepth"),
    ("box blur", DEFAULT, "ssao-s16-half-box-gbufworld-std-persp-cs"),
    ("seed 004 range check", DEFAULT, "ssao-s16-half-bilateral-gbufworld-std-persp-cs-rc004"),
    ("power/intensity output", DEFAULT, "ssao-s16-half-bilateral-gbufworld-std-persp-cs-powint"),
    ("GTAO instead of SSAO", DEFAULT, "gtao-2x3-half-bilateral-gbufworld-std-persp-cs"),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--aogen", default="build/generator/aogen")
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()

    times = []
    with tempfile.TemporaryDirectory() as scratch:
        for run in range(args.runs):
            out = os.path.join(scratch, f"run{run}")  # a fresh directory: every file is written
            start = time.perf_counter()
            subprocess.run([args.aogen, "generate", "--quiet", "--out", out], check=True)
            times.append(time.perf_counter() - start)
        manifest = json.load(open(os.path.join(scratch, "run0", "manifest.json")))

    variants = manifest["variants"]
    print(f"aogen generate, default matrix ({len(variants)} variants, all targets): "
          f"median {statistics.median(times):.2f} s over {args.runs} runs "
          f"(min {min(times):.2f}, max {max(times):.2f})")

    def chain(v):
        return sum(p["spirv_instructions"] for p in v["passes"])

    with tempfile.TemporaryDirectory() as scratch:
        names = sorted({n for _, a, b in FEATURE_PAIRS for n in (a, b)})
        subprocess.run([args.aogen, "generate", "--quiet", "--targets", "spv", "--out", scratch] + names, check=True)
        by_name = {v["name"]: v for v in json.load(open(os.path.join(scratch, "manifest.json")))["variants"]}
    def chain(v):
        return sum(p["spirv_instructions"] for p in v["passes"])

    print("\n| feature | AO shader: without → with | ratio | whole chain: without → with | ratio |")
    print("|---|---:|---:|---:|---:|")
    for feature, without, with_ in FEATURE_PAIRS:
        a, b = by_name[without], by_name[with_]
        ai, bi, ac, bc = a["spirv_instructions"], b["spirv_instructions"], chain(a), chain(b)
        print(f"| {feature} | {ai} → {bi} | {bi / ai:.2f} | {ac} → {bc} | {bc / ac:.2f} |")

    base = next(v for v in variants if v["name"] == DEFAULT)
    print(f"\n| variant | AO shader instructions | ratio | chain instructions | ratio |")
    print("|---|---:|---:|---:|---:|")
    for v in variants:
        ao, ch = v["spirv_instructions"], chain(v)
        print(f"| {v['name']} | {ao} | {ao / base['spirv_instructions']:.2f} | {ch} | {ch / chain(base):.2f} |")


if __name__ == "__main__":
    main()
