#!/usr/bin/env python3
"""What the settings cost, as ratios within one report run, and how far from their floors.

    python3 report_ratios.py out/report/results.json [--other other/results.json]

Reads an aogen_report results.json and prints the tables BENCHMARKS.md records:
  - the Pareto front by calibrated error (fastest first);
  - what each setting costs: one axis changed at a time, time as a ratio to the same
    chain without the change, all taken in the same timing rounds (interleaved);
  - time over fetch floor: the median, range and extremes per technique;
  - the feature saving: selected / everything-on time ratios over the point-cloud twins;
  - the raw diagnostics: variants with raw values outside [0, 1] or non-finite.
With --other (the same settings on another device), the largest differences of the
default and calibrated errors between the two runs.
Only reads; every number comes from the file.
"""
import argparse
import json
import statistics


def load(path):
    with open(path) as f:
        return json.load(f)


def by_name(results):
    return {v["name"]: v for v in results["variants"]}


# One axis changed at a time: (what, [(variant, baseline), ...]) — each ratio is
# variant time / baseline time.
COST_ROWS = [
    ("SSAO samples 8 / 32 / 64, to 16 (half, no blur)",
     [("ssao-s8-half-noblur-gbufworld-std-persp-cs", "ssao-s16-half-noblur-gbufworld-std-persp-cs"),
      ("ssao-s32-half-noblur-gbufworld-std-persp-cs", "ssao-s16-half-noblur-gbufworld-std-persp-cs"),
      ("ssao-s64-half-noblur-gbufworld-std-persp-cs", "ssao-s16-half-noblur-gbufworld-std-persp-cs")]),
    ("SSAO full / half resolution (s16, no blur)",
     [("ssao-s16-full-noblur-gbufworld-std-persp-cs", "ssao-s16-half-noblur-gbufworld-std-persp-cs")]),
    ("SSAO box; bilateral, to no blur (s16, half)",
     [("ssao-s16-half-box-gbufworld-std-persp-cs", "ssao-s16-half-noblur-gbufworld-std-persp-cs"),
      ("ssao-s16-half-bilateral-gbufworld-std-persp-cs", "ssao-s16-half-noblur-gbufworld-std-persp-cs")]),
    ("GTAO 1x2 / 4x2 / 8x2 / 4x4 / 8x4, to 2x2 (half, no blur)",
     [(f"gtao-{s}-half-noblur-gbufworld-std-persp-cs", "gtao-2x2-half-noblur-gbufworld-std-persp-cs") for s in ("1x2", "4x2", "8x2", "4x4", "8x4")]),
    ("GTAO 2x2 / SSAO s16 (half, no blur)",
     [("gtao-2x2-half-noblur-gbufworld-std-persp-cs", "ssao-s16-half-noblur-gbufworld-std-persp-cs")]),
]


def fmt(x, digits=3):
    return "–" if x is None else f"{x:.{digits}f}"


def ratio_cell(v, pairs):
    cells = []
    for a, b in pairs:
        if a in v and b in v and v[a]["ms"] and v[b]["ms"]:
            cells.append(f"{v[a]['ms'] / v[b]['ms']:.2f}")
        else:
            cells.append("–")
    return " / ".join(cells)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results")
    ap.add_argument("--other", help="the same report from another device: error agreement")
    args = ap.parse_args()
    r = load(args.results)
    v = by_name(r)
    scenes = r["scenes"]
    print(f"# {r['device']}: {len(scenes)} scenes at {scenes[0]['width']}x{scenes[0]['height']}, {len(v)} variants")
    c = r["clocks"]
    print(f"SM clock during the timed rounds: median {c['median']} MHz, {c['min']}-{c['max']} ({c['samples']} readings); max {c.get('max_sm_mhz')}")
    gpu = sum(s["timed_gpu_ms"] for s in scenes)
    wall = sum(s["timed_wall_ms"] for s in scenes)
    print(f"timestamp span / wall clock of the timed rounds: {gpu:.1f} / {wall:.1f} ms = {gpu / wall:.4f}" if wall else "no timing rounds")
    print(f"iterations per round: {sorted(set(s['iterations'] for s in scenes))}; all warm-ups settled: {all(s['settled'] for s in scenes)}")
    p = r["phases_s"]
    print(f"phases (s): compile {p['compile']:.1f}, trace {p['trace']:.1f}, score {p['score']:.1f}, time {p['time']:.1f}; "
          f"variants phase {(p['compile'] + p['score'] + p['time']) / max(1, p['runs']):.3f} s per variant x scene ({p['runs']} runs)")

    print("\n## Pareto front by calibrated error, fastest first")
    print("| variant | ms | p10–p90 | floor ms | × floor | RMSE default | RMSE calibrated |\n|---|---:|---:|---:|---:|---:|---:|")
    for x in sorted((x for x in v.values() if x["pareto_calibrated"]), key=lambda x: x["ms"]):
        print(f"| `{x['name']}` | {fmt(x['ms'])} | {fmt(x['ms_p10'])}–{fmt(x['ms_p90'])} | {fmt(x['floor_ms'])} | {fmt(x['floor_ratio'], 2)} | "
              f"{fmt(x['rmse'], 4)} | {fmt(x['rmse_calibrated'], 4)} |")

    print("\n## What a setting costs (time ratios, same rounds)")
    for what, pairs in COST_ROWS:
        print(f"| {what} | {ratio_cell(v, pairs)} |")

    print("\n## Time over fetch floor")
    for tech in ("ssao", "gtao"):
        for stage in ("compute", "fragment"):
            ratios = sorted((x["floor_ratio"], x["name"]) for x in v.values() if x["technique"] == tech and x["stage"] == stage and x["floor_ratio"])
            if not ratios:
                continue
            med = statistics.median(q for q, _ in ratios)
            print(f"{tech} {stage}: {len(ratios)} variants, median {med:.2f}, {ratios[0][0]:.2f} ({ratios[0][1]}) – {ratios[-1][0]:.2f} ({ratios[-1][1]})")

    f = r["feature_saving"]
    if f:
        ratios = sorted(x["ratio"] for x in f if x["ratio"])
        print(f"\n## Feature saving: {len(f)} pairs, selected / everything-on time median {statistics.median(ratios):.3f} "
              f"({ratios[0]:.3f}–{ratios[-1]:.3f}); AO instructions {statistics.median(x['selected_instructions'] for x in f)} vs "
              f"{statistics.median(x['everything_on_instructions'] for x in f)}")
        straddle = [x["selected"] for x in f if x["ratio_p10"] and x["ratio_p90"] and x["ratio_p10"] <= 1 <= x["ratio_p90"]]
        print(f"pairs whose p10–p90 straddles 1: {len(straddle)}")

    bad = [x for x in v.values() if x["raw"]["nan"] or x["raw"]["inf"] or x["raw"]["below_zero"] or x["raw"]["above_one"]]
    print(f"\n## Raw diagnostics: {len(bad)} variants with raw NaN/Inf or values outside [0, 1]")
    for x in bad:
        raw = x["raw"]
        print(f"  {x['name']}: NaN {raw['nan']}, Inf {raw['inf']}, below 0 {raw['below_zero']}, above 1 {raw['above_one']}, max excess {raw['max_excess']:.3g}")

    if args.other:
        o = by_name(load(args.other))
        worst = {"rmse": 0, "rmse_calibrated": 0}
        for name, x in v.items():
            if name in o:
                for key in worst:
                    if x[key] is not None and o[name][key] is not None:
                        worst[key] = max(worst[key], abs(x[key] - o[name][key]))
        print(f"\n## Against {load(args.other)['device']}: largest |ΔRMSE| default {worst['rmse']:.5f}, calibrated {worst['rmse_calibrated']:.5f}")


if __name__ == "__main__":
    main()
