#!/usr/bin/env python3
"""Light selection: the light tree against selection by power alone, at equal samples.

For each scene: a reference (hipr, --ref-spp, the tree, a seed no measured render uses), then
--seeds renders with each selection at --spp; RMSE against the reference (hipr compare),
render time from `hipr render --stats-json` (render_cpu_seconds: CPU seconds of all threads,
robust to a busy machine, the tree's walk included) and efficiency 1 / (RMSE^2 x time). It also
checks that both selections are unbiased: the image mean over seeds against the reference's, in
units of the standard error of their difference. Writes OUTDIR/light.json and OUTDIR/light.md (BENCHMARKS.md,
"Light selection").

usage: python3 tools/light_bench.py [OUTDIR] [--size N] [--ref-spp N] [--spp N] [--seeds N]
       [--scenes name,...]   (default OUTDIR: bench-results)
"""
import argparse
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sampler_bench import HIPR, ROOT, SCENES as SAMPLER_SCENES, SHARED, STUDIO, rmse  # noqa: E402

SCENES = [("lamp_hall", os.path.join(ROOT, "assets/scenes/lamp_hall.glb"), [])] + SAMPLER_SCENES + [
    ("DamagedHelmet", os.path.join(SHARED, "DamagedHelmet/DamagedHelmet.glb"), ["--env", STUDIO]),
]
SELECTIONS = ["power", "tree"]


def render(scene, flags, size, spp, selection, seed, out_exr):
    stats = out_exr + ".json"
    subprocess.run([HIPR, "render", scene, "-o", out_exr, "--stats-json", stats, "-q", "--width", str(size),
                    "--height", str(size), "--spp", str(spp), "--light-selection", selection, "--seed", str(seed)]
                   + flags, check=True)
    with open(stats) as f:
        return json.load(f)


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
    args = ap.parse_args()
    wanted = set(args.scenes.split(",")) if args.scenes else None
    work = os.path.join(args.outdir, "light")
    os.makedirs(work, exist_ok=True)
    results = []
    for name, scene, flags in SCENES:
        if wanted and name not in wanted:
            continue
        if not os.path.exists(scene) or any(f.endswith(".hdr") and not os.path.exists(f) for f in flags):
            print("(skipped %s: %s is not there)" % (name, scene))
            continue
        print("== %s" % name, flush=True)
        reference = os.path.join(work, "%s_reference.exr" % name)
        ref_stats = render(scene, flags, args.size, args.ref_spp, "tree", 1000, reference)
        ref_mean = image_mean(reference)
        row = {"scene": name, "reference_spp": args.ref_spp, "device": ref_stats["device"]}
        for selection in SELECTIONS:
            errors, seconds, means = [], [], []
            for seed in range(1, args.seeds + 1):
                image = os.path.join(work, "%s_%s_%d.exr" % (name, selection, seed))
                stats = render(scene, flags, args.size, args.spp, selection, seed, image)
                errors.append(rmse(image, reference))
                seconds.append(stats["render_cpu_seconds"])
                means.append(image_mean(image))
            mse = sum(e * e for e in errors) / len(errors)
            time = sum(seconds) / len(seconds)
            mean = sum(means) / len(means)
            # Standard error of the mean over seeds, widened by the reference's own (as noisy per
            # sample as the tree's renders, with ref-spp samples against spp x seeds).
            spread = math.sqrt(sum((m - mean) ** 2 for m in means) / max(len(means) - 1, 1) / len(means))
            spread *= math.sqrt(1.0 + args.spp * args.seeds / args.ref_spp)
            row[selection] = {"rmse": math.sqrt(mse), "cpu_seconds": time,
                              "efficiency": 1.0 / (mse * time) if mse > 0 else float("inf"),
                              "mean": mean, "reference_mean": ref_mean,
                              "mean_error_in_standard_errors": (mean - ref_mean) / spread if spread > 0 else 0.0}
            print("  %-5s rmse %.5f  %.3f cpu s  mean %.5f (reference %.5f, %+.2f standard errors)" %
                  (selection, math.sqrt(mse), time, mean, ref_mean, row[selection]["mean_error_in_standard_errors"]),
                  flush=True)
        results.append(row)
    suffix = ("_" + "_".join(sorted(wanted))) if wanted else ""
    with open(os.path.join(args.outdir, "light%s.json" % suffix), "w") as f:
        json.dump({"size": args.size, "spp": args.spp, "seeds": args.seeds, "scenes": results}, f, indent=2)
    text = table(results, args)
    with open(os.path.join(args.outdir, "light%s.md" % suffix), "w") as f:
        f.write(text)
    print(text)


def table(results, args):
    lines = ["%dx%d, %d spp, %d seeds; references %d spp (tree, seed 1000); efficiency 1/(RMSE^2 x CPU s)\n" %
             (args.size, args.size, args.spp, args.seeds, args.ref_spp), "",
             "| scene | RMSE power | RMSE tree | CPU s power | CPU s tree | efficiency tree / power |"
             " mean off the reference (standard errors) power / tree |",
             "|---|---|---|---|---|---|---|"]
    for row in results:
        p, t = row["power"], row["tree"]
        lines.append("| %s | %.4f | %.4f | %.3f | %.3f | **%.2fx** | %+.1f / %+.1f |" % (
            row["scene"], p["rmse"], t["rmse"], p["cpu_seconds"], t["cpu_seconds"],
            t["efficiency"] / p["efficiency"], p["mean_error_in_standard_errors"], t["mean_error_in_standard_errors"]))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
