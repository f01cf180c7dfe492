#!/usr/bin/env python3
"""Two reports' results.json compared in every figure that is not a time.

    python3 bench/compare_results.py before/results.json after/results.json [--tolerance X]

Walks both files together and prints every path where they differ: a value, a length, a key
one has and the other lacks. Left out, because they are measured, not computed: times and
everything made from them (keys ending in `ms`, `_ms_p10`, `_ms_p90`, `ratio`, `ratio_p10`,
`ratio_p90`, the phases' seconds, the Pareto flags, a scene's timed iterations and whether its
clock settled), the clocks, and the command line. Every error, raw count, instruction count,
name and hash is compared, exactly unless --tolerance X allows |a - b| <= X for numbers.
Exits 1 when anything differs, 0 when nothing does. With --largest: instead of the list, the
largest |before - after| of each figure (by its key), beside the larger report's largest
reference noise -- for a change meant to move figures by less than their noise (fewer
reference rays). Only reads.
"""
import argparse
import json
import sys

TIME_KEYS = {"ms", "ms_p10", "ms_p90", "floor_ms", "bandwidth_ms", "floor_ratio", "bandwidth_ratio", "pass_ms",
             "timed_gpu_ms", "timed_wall_ms", "phases_s", "pareto", "pareto_calibrated", "pareto_accumulated", "ratio",
             "ratio_p10", "ratio_p90", "selected_ms", "everything_on_ms", "iterations", "settled", "clocks", "command",
             "timing"}  # the timing protocol (rounds, iterations, warm-up, budget, CPU device): how times were taken


LARGEST = {}  # per figure's name: the largest |before - after| seen (--largest prints them)


def compare(a, b, path, tolerance, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k in TIME_KEYS and path != ".timing":
                continue
            if k not in a or k not in b:
                out.append(f"{path}.{k}: only in {'after' if k not in a else 'before'}")
            else:
                compare(a[k], b[k], f"{path}.{k}", tolerance, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} items before, {len(b)} after")
        for i, (x, y) in enumerate(zip(a, b)):
            name = x.get("name") or x.get("scene") if isinstance(x, dict) else None
            compare(x, y, f"{path}[{name if name else i}]", tolerance, out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not isinstance(b, bool):
        leaf = path.rsplit(".", 1)[-1].split("[")[0]
        LARGEST[leaf] = max(LARGEST.get(leaf, 0.0), abs(a - b))
        if abs(a - b) > tolerance:
            out.append(f"{path}: {a!r} before, {b!r} after")
    elif a != b:
        out.append(f"{path}: {a!r} before, {b!r} after")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("before")
    p.add_argument("after")
    p.add_argument("--tolerance", type=float, default=0.0, help="largest |before - after| allowed for a number (default 0: equal)")
    p.add_argument("--largest", action="store_true",
                   help="print, per figure's name, the largest |before - after|, beside the reports' largest reference noise")
    args = p.parse_args()
    with open(args.before) as f:
        before = json.load(f)
    with open(args.after) as f:
        after = json.load(f)
    out = []
    compare(before, after, "", args.tolerance, out)
    if args.largest:
        noise = max(s.get("truth_noise_rms", 0.0) for r in (before, after) for s in r.get("scenes", []))
        print(f"largest reference noise (truth_noise_rms, either report): {noise:.5f}")
        for leaf in sorted(LARGEST):
            if LARGEST[leaf] > 0:
                print(f"  {leaf}: largest |before - after| {LARGEST[leaf]:.5f}")
        return
    for line in out[:200]:
        print(line)
    if len(out) > 200:
        print(f"... and {len(out) - 200} more")
    print(f"compare_results: {len(out)} differences outside the times" + ("" if out else " (every other figure equal)"))
    sys.exit(1 if out else 0)


if __name__ == "__main__":
    main()
