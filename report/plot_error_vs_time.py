#!/usr/bin/env python3
"""error_vs_time.png of an aogen report: each variant's mean RMSE against its run time.

    python3 plot_error_vs_time.py out/report/results.json out/report/error_vs_time.png

Two panels, default parameters and calibrated (ao^p fitted on the other scenes): a
scatter on a log time axis, one marker per technique (SSAO circles, GTAO triangles, VBAO squares),
filled for compute variants and hollow for fragment ones, and the Pareto front (the
variants no other beats on both time and error) drawn as a step line with its points
labelled. The PNG is written to a temporary name and renamed.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

MARKERS = {"ssao": "o", "gtao": "^", "vbao": "s", "sao": "D"}
COLOURS = {"ssao": "#1f77b4", "gtao": "#d62728", "vbao": "#2ca02c", "sao": "#9467bd"}


def short(name):
    """The axes that tell variants apart in the default matrix."""
    return "-".join(name.split("-")[:4])


def panel(ax, variants, error_key, pareto_key, title):
    for technique, marker in MARKERS.items():
        for stage, filled in (("compute", True), ("fragment", False)):
            pts = [v for v in variants if v["technique"] == technique and v["stage"] == stage
                   and v["ms"] is not None and v[error_key] is not None]
            if not pts:
                continue
            ax.scatter([v["ms"] for v in pts], [v[error_key] for v in pts], marker=marker, s=28,
                       facecolors=COLOURS[technique] if filled else "none", edgecolors=COLOURS[technique],
                       alpha=0.75, label=f"{technique.upper()} ({stage})")
    front = sorted((v for v in variants if v[pareto_key]), key=lambda v: (v["ms"], v[error_key]))
    if front:
        ax.step([v["ms"] for v in front], [v[error_key] for v in front], where="post", color="black",
                linewidth=1.2, label="Pareto front")
        for v in front:
            ax.annotate(short(v["name"]), (v["ms"], v[error_key]), textcoords="offset points", xytext=(4, 4), fontsize=6)
    ax.set_xscale("log")
    ax.set_xlabel("GPU time per frame, ms (median, log scale)")
    ax.set_ylabel("RMSE against ray-traced AO (mean over scenes)")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_error_vs_time.py RESULTS.json OUT.png")
    source, target = sys.argv[1], sys.argv[2]
    with open(source, encoding="utf-8") as f:
        results = json.load(f)
    variants = [v for v in results["variants"] if v["ms"] is not None and math.isfinite(v["ms"])]
    if not variants:
        sys.exit(f"{source}: no variant has a run time (valid: a report made on a device with timestamps)")
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5), sharex=True)
    panel(axes[0], variants, "rmse", "pareto", "Default parameters")
    panel(axes[1], variants, "rmse_calibrated", "pareto_calibrated", "Calibrated (ao^p, p fitted on the other scenes)")
    fig.suptitle(f"aogen: AO error against run time — {results['device']}, {len(results['scenes'])} scenes, "
                 f"{results['rays_per_pixel']} reference rays per pixel", fontsize=10)
    fig.tight_layout()
    temporary = f"{target}.tmp{os.getpid()}.png"
    fig.savefig(temporary, dpi=110)
    os.replace(temporary, target)


if __name__ == "__main__":
    main()
