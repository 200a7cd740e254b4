#!/usr/bin/env python3
"""Plots `hipr bench` curves: error of the displayed image against work and against wall time.

usage: plot_bench.py curves.csv summary.json plot.png

One row per edit; columns: relMSE vs work, FLIP vs work, relMSE vs time, FLIP vs time; one line
per policy. The image shown after a step stays on screen until the next, so lines are steps.
`hipr bench` runs this script itself (it is embedded in the binary); it can also be rerun by hand.
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"hipr": "#d62728", "oracle": "#7f7f7f", "full": "#1f77b4", "scanline": "#2ca02c",
           "spiral": "#9467bd", "random": "#ff7f0e"}


def read_curves(path):
    curves = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = (int(row["edit"]), row["policy"])
            curves.setdefault(key, []).append(
                (float(row["work"]), float(row["wall_ms"]), float(row["relmse"]), float(row["flip"])))
    return curves


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__)
    curves = read_curves(argv[1])
    with open(argv[2]) as f:
        summary = json.load(f)
    edits = sorted({edit for edit, _ in curves})
    names = {i + 1: e["name"] for i, e in enumerate(summary.get("edits", []))}
    fig, axes = plt.subplots(len(edits), 4, figsize=(18, 3.6 * len(edits)), squeeze=False)
    for row, edit in enumerate(edits):
        policies = [p for (e, p) in curves if e == edit]
        for col, (x_index, y_index, x_label, y_label) in enumerate([
                (0, 2, "work since the edit (full-frame 1-spp passes)", "relMSE"),
                (0, 3, "work since the edit (full-frame 1-spp passes)", "FLIP"),
                (1, 2, "wall time since the edit (ms)", "relMSE"),
                (1, 3, "wall time since the edit (ms)", "FLIP")]):
            ax = axes[row][col]
            # The stale image (x = 0) is drawn from one left edge of the log axis for all policies.
            floor = 0.5 * min((p[x_index] for policy in policies for p in curves[(edit, policy)]
                               if p[x_index] > 0), default=1.0)
            for policy in policies:
                points = curves[(edit, policy)]
                xs = [max(p[x_index], floor) for p in points]
                ys = [p[y_index] for p in points]
                ax.step(xs, ys, where="post", label=policy, color=COLOURS.get(policy),
                        linewidth=2.2 if policy == "hipr" else 1.2)
            ax.set_xscale("log")
            ax.set_yscale("log")
            if x_index == 0:
                ax.axvline(1.0, color="black", linewidth=0.6, linestyle=":")
            ax.set_xlabel(x_label)
            ax.set_ylabel(y_label)
            ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
            if col == 0:
                ax.set_title(f"edit {edit}: {names.get(edit, '')}", loc="left", fontsize=10)
        axes[row][0].legend(fontsize=8)
    fig.suptitle(f"{summary.get('scene', '')}: error of the displayed image after an edit", fontsize=12)
    fig.tight_layout()
    fig.savefig(argv[3], dpi=90, format="png")


if __name__ == "__main__":
    main(sys.argv)
