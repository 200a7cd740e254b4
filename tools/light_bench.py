#!/usr/bin/env python3
"""Estimators compared at equal samples: the light tree against selection by power alone
(--compare selection, the default), path guiding against BSDF sampling alone (--compare
guiding; the light tree in both), or another hipr binary's defaults against this build's
(--compare build --baseline BIN: a change to an estimator, before and after).

For each scene: a reference (hipr, --ref-spp, the tree, no guiding, a seed no measured render
uses), then --seeds renders with each of the two at --spp, alternating seed by seed; RMSE
against the reference (hipr compare), render time from `hipr render --stats-json`
(render_cpu_seconds: CPU seconds of all threads, the tree's walk and the guide's training
included; alternating, what else loads a shared machine weighs on both alike) and efficiency
1 / (RMSE^2 x time). It also checks that both are unbiased: the image mean over seeds against
the reference's, in units of the standard error of their difference. Writes OUTDIR/light.json
and OUTDIR/light.md (BENCHMARKS.md, "Light selection"), or guiding.json and guiding.md ("Path
guiding").

usage: python3 tools/light_bench.py [OUTDIR] [--compare selection|guiding|build] [--baseline BIN]
       [--size N] [--ref-spp N] [--spp N] [--seeds N] [--scenes name,...] [--flags "..."]
       (default OUTDIR: bench-results; --flags: more `hipr render` flags for both)
"""
import argparse
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sampler_bench import HIPR, ROOT, SCENES as SAMPLER_SCENES, SHARED, STUDIO, render_stats, rmse, scenes_to_run  # noqa: E402

SCENES = [("lamp_hall", os.path.join(ROOT, "assets/scenes/lamp_hall.glb"), [])] + SAMPLER_SCENES + [
    ("DamagedHelmet", os.path.join(SHARED, "DamagedHelmet/DamagedHelmet.glb"), ["--env", STUDIO]),
]
# What each comparison runs: (name, flags) of the baseline, then of the estimator measured
# ("build": the same flags, the baseline rendered by --baseline).
COMPARISONS = {
    "selection": [("power", ["--light-selection", "power"]), ("tree", ["--light-selection", "tree"])],
    "guiding": [("bsdf", []), ("guided", ["--guiding"])],
    "build": [("before", []), ("now", [])],
}
OUTPUT_NAMES = {"selection": "light", "guiding": "guiding", "build": "build"}


def render(scene, flags, size, spp, seed, out_exr, binary=HIPR):
    return render_stats(scene, out_exr, size, spp, ["--seed", str(seed)] + flags, binary)


def binary_of(config, args):
    """The hipr that renders `config`: --baseline's for the baseline of --compare build."""
    return args.baseline if config == "before" else HIPR


def image_mean(image):
    """Mean over pixels and channels (oiiotool's statistics)."""
    out = subprocess.run(["oiiotool", image, "--printstats"], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        if "Stats Avg:" in line:
            values = [float(v) for v in line.split(":", 1)[1].split()[:3]]
            return sum(values) / len(values)
    raise RuntimeError("no statistics for " + image)


def main():
    ap = argparse.ArgumentParser(prog="light_bench.py")
    ap.add_argument("outdir", nargs="?", default="bench-results")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--ref-spp", type=int, default=4096)
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--seeds", type=int, default=16)
    ap.add_argument("--scenes", default="")
    ap.add_argument("--compare", choices=sorted(COMPARISONS), default="selection")
    ap.add_argument("--flags", default="", help="more hipr render flags, for every render")
    ap.add_argument("--baseline", default="", help="--compare build: the hipr binary of the baseline")
    args = ap.parse_args()
    if (args.compare == "build") != bool(args.baseline):
        ap.error("--baseline goes with --compare build")
    wanted = set(args.scenes.split(",")) if args.scenes else None
    output = OUTPUT_NAMES[args.compare]
    work = os.path.join(args.outdir, output)
    os.makedirs(work, exist_ok=True)
    results = []
    for name, scene, flags in scenes_to_run(SCENES, wanted):
        flags = flags + args.flags.split()
        print("== %s" % name, flush=True)
        reference = os.path.join(work, "%s_reference.exr" % name)
        ref_stats = render(scene, flags, args.size, args.ref_spp, 1000, reference)
        ref_mean = image_mean(reference)
        row = {"scene": name, "reference_spp": args.ref_spp, "device": ref_stats["device"]}
        configs = COMPARISONS[args.compare]
        for config, config_flags in configs:
            # Untimed, once: drivers that compile a kernel variant at its first dispatch (lavapipe)
            # and the shader cache then cost no measured render anything.
            render(scene, flags + config_flags, args.size, 1, 999, os.path.join(work, "warm_up.exr"),
                   binary_of(config, args))
        # The two alternate seed by seed, first one then the other first, so whatever else loads
        # the machine over the run (these machines are shared) weighs on both alike instead of on
        # whichever ran second.
        measured = {config: ([], [], []) for config, _ in configs}
        for seed in range(1, args.seeds + 1):
            for config, config_flags in (configs if seed % 2 else configs[::-1]):
                errors, seconds, means = measured[config]
                image = os.path.join(work, "%s_%s_%d.exr" % (name, config, seed))
                stats = render(scene, flags + config_flags, args.size, args.spp, seed, image, binary_of(config, args))
                errors.append(rmse(image, reference))
                seconds.append(stats["render_cpu_seconds"])
                means.append(image_mean(image))
        for config, _ in configs:
            errors, seconds, means = measured[config]
            mse = sum(e * e for e in errors) / len(errors)
            time = sum(seconds) / len(seconds)
            mean = sum(means) / len(means)
            # Standard error of the mean over seeds, widened by the reference's own (as noisy per
            # sample as the tree's renders, with ref-spp samples against spp x seeds).
            spread = math.sqrt(sum((m - mean) ** 2 for m in means) / max(len(means) - 1, 1) / len(means))
            spread *= math.sqrt(1.0 + args.spp * args.seeds / args.ref_spp)
            row[config] = {"rmse": math.sqrt(mse), "cpu_seconds": time,
                           "efficiency": 1.0 / (mse * time) if mse > 0 else float("inf"),
                           "mean": mean, "reference_mean": ref_mean,
                           "mean_error_in_standard_errors": (mean - ref_mean) / spread if spread > 0 else 0.0}
            print("  %-6s rmse %.5f  %.3f cpu s  mean %.5f (reference %.5f, %+.2f standard errors)" %
                  (config, math.sqrt(mse), time, mean, ref_mean, row[config]["mean_error_in_standard_errors"]),
                  flush=True)
        results.append(row)
    suffix = ("_" + "_".join(sorted(wanted))) if wanted else ""
    with open(os.path.join(args.outdir, "%s%s.json" % (output, suffix)), "w") as f:
        json.dump({"size": args.size, "spp": args.spp, "seeds": args.seeds, "compare": args.compare,
                   "flags": args.flags, "scenes": results}, f, indent=2)
    text = table(results, args)
    with open(os.path.join(args.outdir, "%s%s.md" % (output, suffix)), "w") as f:
        f.write(text)
    print(text)


def table(results, args):
    a, b = (name for name, _ in COMPARISONS[args.compare])
    lines = ["%dx%d, %d spp, %d seeds; references %d spp (this build, seed 1000); efficiency 1/(RMSE^2 x CPU s)%s\n" %
             (args.size, args.size, args.spp, args.seeds, args.ref_spp,
              "; flags " + args.flags if args.flags else ""), "",
             "| scene | RMSE {a} | RMSE {b} | CPU s {a} | CPU s {b} | efficiency {b} / {a} |"
             " mean off the reference (standard errors) {a} / {b} |".format(a=a, b=b),
             "|---|---|---|---|---|---|---|"]
    for row in results:
        p, t = row[a], row[b]
        lines.append("| %s | %.4f | %.4f | %.3f | %.3f | **%.2fx** | %+.1f / %+.1f |" % (
            row["scene"], p["rmse"], t["rmse"], p["cpu_seconds"], t["cpu_seconds"],
            t["efficiency"] / p["efficiency"], p["mean_error_in_standard_errors"], t["mean_error_in_standard_errors"]))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
