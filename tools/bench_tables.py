#!/usr/bin/env python3
"""Turns the outputs of tools/bench.sh into the Markdown tables of BENCHMARKS.md.

usage: bench_tables.py OUTDIR
"""
import glob
import json
import math
import os
import sys

POLICIES = ["hipr", "oracle", "full", "scanline", "spiral", "random"]


def num(value):
    """JSON null (a NaN, or an event that never happened) as NaN."""
    return float("nan") if value is None else value


def with_hipr(summaries):
    """(scene, edit) pairs whose edit has a hipr run: every table compares against it."""
    return [(scene, e) for scene, s in summaries for e in s["edits"] if "hipr" in e["policies"]]


def geomean(values):
    values = [v for v in values if v > 0]  # NaN compares false: left out
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def auc_table(summaries, key, title):
    lines = [f"#### {title}", "",
             "| scene | edit | " + " | ".join(POLICIES) + " | hipr / full | hipr / oracle |",
             "|---|---|" + "---:|" * (len(POLICIES) + 2)]
    for scene, edit in with_hipr(summaries):
        p = edit["policies"]
        cells = [f"{num(p[name][key]):.4g}" if name in p else "" for name in POLICIES]
        ratios = [num(p["hipr"][key]) / num(p[other][key]) if other in p and p[other][key] else float("nan")
                  for other in ["full", "oracle"]]
        lines.append(f"| {scene} | {edit['name']} | " + " | ".join(cells) +
                     f" | {ratios[0]:.2f} | {ratios[1]:.2f} |")
    return lines


def feedback_table(summaries):
    lines = ["#### Feedback and overhead (hipr)", "",
             "| scene | edit | changed tiles | first feedback (work / ms) | changed tiles shown (work / ms) "
             "| same for full (work) | scheduler overhead share |",
             "|---|---|---:|---:|---:|---:|---:|"]
    def pair(work, ms):
        return "never" if work is None else f"{work:.3f} / {ms:.0f}"
    for scene, edit in with_hipr(summaries):
        h = edit["policies"]["hipr"]
        full = edit["policies"].get("full", {})
        lines.append(
            f"| {scene} | {edit['name']} | {edit['changed_tiles']}/{edit['tiles']} "
            f"| {pair(h['first_feedback_work'], h['first_feedback_ms'])} "
            f"| {pair(h['changed_tiles_shown_work'], h['changed_tiles_shown_ms'])} "
            f"| {num(full.get('changed_tiles_shown_work')):.3f} | {100 * num(h['overhead_share']):.1f} % |")
    return lines


def ratio_lines(summaries):
    lines = ["#### Geometric means over all edits", "", "| ratio | horizon 1 | horizon 4 | horizon 16 |",
             "|---|---:|---:|---:|"]
    for other in ["full", "oracle"]:
        for metric in ["relmse", "flip"]:
            row = []
            for suffix in ["", "_4", "_16"]:
                key = f"auc_{metric}{suffix}"
                row.append(geomean([num(e["policies"]["hipr"][key]) / e["policies"][other][key]
                                    for _, e in with_hipr(summaries)
                                    if other in e["policies"] and e["policies"][other][key]]))
            lines.append(f"| hipr / {other}, {metric} AUC | " + " | ".join(f"{v:.3f}" for v in row) + " |")
    return lines


def drag_table(drags):
    """Drags (hipr bench --drag): mean error while dragging and over the work unit after it."""
    lines = ["#### Drags: 20 small moves in a row (`hipr bench --drag`), mean error while dragging and after", "",
             "| scene | drag | policy | drag work | relMSE during | FLIP during | relMSE after | FLIP after |",
             "|---|---|---|---:|---:|---:|---:|---:|"]
    for scene, summary in drags:
        for edit in summary["edits"]:
            for name, p in edit["policies"].items():
                if "drag_work" not in p:
                    continue
                lines.append(f"| {scene} | {edit['name']} | {name} | {p['drag_work']:.3f} "
                             f"| {p['auc_relmse_during_drag']:.4g} | {p['auc_flip_during_drag']:.4g} "
                             f"| {p['auc_relmse_after_drag']:.4g} | {p['auc_flip_after_drag']:.4g} |")
    if drags and "hipr" in drags[0][1]["edits"][0]["policies"]:
        lines += ["", "hipr / full, geometric mean over the drags: " + ", ".join(
            f"{metric} {phase} {geomean([s['ratios'][f'hipr_vs_full_auc_{metric}_{phase}_drag'] for _, s in drags if s['ratios'].get(f'hipr_vs_full_auc_{metric}_{phase}_drag')]):.3f}"
            for phase in ["during", "after"] for metric in ["relmse", "flip"])]
    return lines


def lights_table(lights):
    """Light edits with relighting (hipr) and without (--no-relight): relMSE and FLIP AUC(1)."""
    lines = ["#### Light edits: hipr relit at once (light groups) against full and hipr --no-relight", "",
             "| scene | edit | hipr relMSE | --no-relight | full | hipr / full | hipr FLIP | --no-relight | full |"
             " hipr / full |", "|---|---|" + "---:|" * 8]
    for name, runs in sorted(lights.items()):
        if "relight" not in runs or "no-relight" not in runs:
            continue
        for edit, off in zip(runs["relight"]["edits"], runs["no-relight"]["edits"]):
            p, q = edit["policies"], off["policies"]
            drag = "drag_work" in p["hipr"]
            cells = []
            for metric in ["relmse", "flip"]:
                key = f"auc_{metric}_during_drag" if drag else f"auc_{metric}"
                h, n, f = num(p["hipr"][key]), num(q["hipr"][key]), num(p["full"][key])
                cells += [f"{h:.4g}", f"{n:.4g}", f"{f:.4g}", f"{h / f:.3f}" if f else ""]
            label = edit["name"] + (" (mean during the drag)" if drag else "")
            lines.append(f"| {name} | {label} | " + " | ".join(cells) + " |")
    return lines


def focus_table(focuses):
    """Attention-guided rendering (focus ops, --cold-start): the focus region's error AUC(1)."""
    lines = ["#### Focus: error of the focus region over the first work unit, hipr with and without the focus", "",
             "| scene | measured | relMSE hipr+focus | hipr | full | ratio | FLIP hipr+focus | hipr | full | ratio |",
             "|---|---|" + "---:|" * 8]
    ratios = {"relmse": [], "flip": []}
    for scene, summary in focuses:
        for edit in summary["edits"]:
            p = edit["policies"]
            if "hipr+focus" not in p:
                continue
            cells = []
            for metric in ["relmse", "flip"]:
                key = f"auc_focus_{metric}"
                f, h = num(p["hipr+focus"][key]), num(p["hipr"][key])
                full = num(p["full"][key]) if "full" in p else float("nan")
                if h > 0:
                    ratios[metric].append(f / h)
                cells += [f"{f:.4g}", f"{h:.4g}", f"{full:.4g}", f"{f / h:.3f}" if h > 0 else ""]
            lines.append(f"| {scene} | {edit['name']} | " + " | ".join(cells) + " |")
    if ratios["relmse"]:
        lines += ["", "hipr+focus / hipr in the focus region, geometric mean: " +
                  ", ".join(f"{metric} {geomean(values):.3f}" for metric, values in ratios.items())]
    return lines


def difference_table(summaries, blends, leads):
    """hipr (the difference estimate, the edit's lead) against its ablations, hipr with blend
    (OUTDIR/blend_<scene>) and hipr without the lead (OUTDIR/nolead_<scene>, when measured), and
    full: relMSE and FLIP AUC(1), relMSE AUC(4)."""
    keys = [("auc_relmse", "relMSE AUC(1)"), ("auc_flip", "FLIP AUC(1)"), ("auc_relmse_4", "relMSE AUC(4)")]
    lead = bool(leads)
    columns = "hipr | blend | full | hipr / full | blend / full" + (" | no lead / full" if lead else "")
    lines = ["#### After an edit: hipr against hipr with blend, hipr without the edit's lead and full", "",
             "| scene | edit | " + " | ".join(f"{t}: {columns}" for _, t in keys) + " |",
             "|---|---|" + "---:|" * ((6 if lead else 5) * len(keys))]
    ratios = {key: ([], [], []) for key, _ in keys}
    for scene, summary in summaries:
        if scene not in blends or (lead and scene not in leads):
            continue
        unled = leads[scene]["edits"] if lead else [None] * len(summary["edits"])
        for edit, ablated, without in zip(summary["edits"], blends[scene]["edits"], unled):
            p, q = edit["policies"], ablated["policies"]
            if "hipr" not in p or "full" not in p or "hipr" not in q:
                continue
            cells = []
            for key, _ in keys:
                h, b, f = num(p["hipr"][key]), num(q["hipr"][key]), num(p["full"][key])
                cells += [f"{h:.4g}", f"{b:.4g}", f"{f:.4g}", f"{h / f:.3f}", f"{b / f:.3f}"]
                ratios[key][0].append(h / f)
                ratios[key][1].append(b / f)
                if lead:
                    n = num(without["policies"]["hipr"][key])
                    cells.append(f"{n / f:.3f}")
                    ratios[key][2].append(n / f)
            lines.append(f"| {scene} | {edit['name']} | " + " | ".join(cells) + " |")
    lines.append("")
    for key, title in keys:
        with_all, with_blend, without_lead = ratios[key]
        if with_all:
            lines.append(f"- {title} hipr / full, geometric mean over {len(with_all)} edits: "
                         f"{geomean(with_all):.3f} (blend: {geomean(with_blend):.3f}"
                         + (f"; no lead: {geomean(without_lead):.3f}" if without_lead else "")
                         + f"); worst {max(with_all):.3f}")
    return lines


def throughput_lines(folder):
    runs = {}
    for path in sorted(glob.glob(os.path.join(folder, "throughput", "*.json"))):
        name = os.path.basename(path)[:-5]
        base, _, round_name = name.rpartition("_r")
        with open(path) as f:
            runs.setdefault(base, {})[round_name] = json.load(f)
    if not runs:
        return []
    lines = ["#### Render throughput (`hipr render --stats-json`)", "",
             "| run | size, spp | M samples/s (rounds) | M rays/s (rounds) | rays/sample |", "|---|---|---|---|---:|"]
    for base, rounds in runs.items():
        stats = [rounds[k] for k in sorted(rounds)]
        s0 = stats[0]
        samples = ", ".join("%.3f" % (s["samples_per_second"] / 1e6) for s in stats)
        rays = ", ".join("%.2f" % (s["rays_per_second"] / 1e6) for s in stats)
        lines.append(f"| {base} | {s0['width']}x{s0['height']}, {s0['spp']} | {samples} | {rays} "
                     f"| {s0['rays_per_sample']:.2f} |")
    if "cornell_box" in runs and "cornell_box_uber" in runs:
        ratios = [runs["cornell_box"][k]["samples_per_second"] / runs["cornell_box_uber"][k]["samples_per_second"]
                  for k in sorted(runs["cornell_box"]) if k in runs["cornell_box_uber"]]
        lines += ["", "Specialized / uber kernel on the Cornell box, per round: " +
                  ", ".join(f"{r:.2f}x" for r in ratios)]
    return lines


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    summaries, drags, lights, blends, leads, focuses = [], [], {}, {}, {}, []
    for path in sorted(glob.glob(os.path.join(argv[1], "*", "summary.json"))):
        with open(path) as f:
            name = os.path.basename(os.path.dirname(path))
            if name.startswith("blend_"):
                blends[name.removeprefix("blend_")] = json.load(f)
            elif name.startswith("nolead_"):
                leads[name.removeprefix("nolead_")] = json.load(f)
            elif name.startswith("focus_"):
                focuses.append((name.removeprefix("focus_"), json.load(f)))
            elif name.startswith("lights_"):
                scene, _, variant = name.removeprefix("lights_").rpartition("_")
                lights.setdefault(scene, {})[variant] = json.load(f)
            else:
                (drags if name.startswith("drag_") else summaries).append((name.removeprefix("drag_"), json.load(f)))
    out = []
    if summaries:
        out += auc_table(summaries, "auc_relmse", "relMSE AUC over the first work unit (lower is better)") + [""]
        out += auc_table(summaries, "auc_flip", "FLIP AUC over the first work unit") + [""]
        out += auc_table(summaries, "auc_relmse_4", "relMSE AUC over the first 4 work units") + [""]
        out += ratio_lines(summaries) + [""]
    if summaries and blends:
        out += difference_table(summaries, blends, leads) + [""]
        out += feedback_table(summaries) + [""]
    if drags:
        out += drag_table(drags) + [""]
    if lights:
        out += lights_table(lights) + [""]
    if focuses:
        out += focus_table(focuses) + [""]
    out += throughput_lines(argv[1])
    print("\n".join(out))


if __name__ == "__main__":
    main(sys.argv)
