#!/usr/bin/env python3
"""Error against samples per pixel and efficiency, Sobol against the random sampler.

For each scene: a high-spp reference (hipr, Sobol, its own seed), then renders at a few spp
with each sampler and --seeds seeds (two by default); RMSE against the reference (hipr compare --metric rmse),
render time from `hipr render --stats-json` (CPU seconds of all threads, robust to a busy
machine) and efficiency 1 / (RMSE^2 x time). At 1 and 4 spp, how blue the noise is: the RMSE
seen through an 8x8 box filter (render and reference reduced by `oiiotool --resize:filter=box`),
and at 1 spp its ratio to the full-resolution RMSE (white noise keeps about 1/8 of its error
through the filter, blue noise less). Writes OUTDIR/sampler.json and OUTDIR/sampler.md (the
tables of BENCHMARKS.md, "Sampler").

usage: python3 tools/sampler_bench.py [OUTDIR] [--size N] [--ref-spp N] [--spp 4,16,64,256]
       [--seeds N] [--scenes name,...]   (default OUTDIR: bench-results)
Scenes whose error is a few bright outliers (caustics through glass, small bright lamps) need
more seeds before their RMSE says anything.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
HIPR = os.path.join(ROOT, "build", "hipr")
SHARED = os.path.join(ROOT, "..", "shared", "scenes")
STUDIO = os.path.join(SHARED, "EnvMaps", "studio_small_03_1k.hdr")

# name, scene, extra flags; shared scenes are skipped when ../shared is not there.
SCENES = [
    ("cornell_box", os.path.join(ROOT, "assets/scenes/cornell_box.gltf"), []),
    ("cornell_sphere", os.path.join(ROOT, "assets/scenes/cornell_sphere.glb"), []),
    ("CornellBox", os.path.join(SHARED, "CornellBox/cornellBox.gltf"), []),
    ("LightsPunctualLamp", os.path.join(SHARED, "LightsPunctualLamp/LightsPunctualLamp.gltf"), []),
    ("SheenChair", os.path.join(SHARED, "SheenChair/SheenChair.gltf"), ["--env", STUDIO]),
    ("GlassVaseFlowers", os.path.join(SHARED, "GlassVaseFlowers/GlassVaseFlowers.glb"), ["--env", STUDIO]),
]
SAMPLERS = ["random", "sobol"]


def scenes_to_run(scenes, wanted):
    """The (name, scene, flags) of `scenes` named in `wanted` (all when None) whose files are there."""
    for name, scene, flags in scenes:
        if wanted and name not in wanted:
            continue
        if not os.path.exists(scene) or any(f.endswith(".hdr") and not os.path.exists(f) for f in flags):
            print("(skipped %s: %s is not there)" % (name, scene))
            continue
        yield name, scene, flags
BLUE_NOISE_SPP = [1, 4]  # 1 must be there (the ratio column)
BOX = 8


def render_stats(scene, out_exr, size, spp, flags, binary=HIPR, env=None):
    """One `hipr render` of a size x size image at spp, with more flags: the image goes to out_exr
    and its --stats-json report (render_cpu_seconds among it) is returned. The benches that time
    renders (light_bench.py, time_ab.py) share it."""
    stats = out_exr + ".json"
    subprocess.run([binary, "render", scene, "-o", out_exr, "--stats-json", stats, "-q", "--width", str(size),
                    "--height", str(size), "--spp", str(spp)] + flags, check=True, env=env)
    with open(stats) as f:
        return json.load(f)


def render(scene, flags, size, spp, sampler, seed, out_exr, depth):
    return render_stats(scene, out_exr, size, spp,
                        ["--sampler", sampler, "--seed", str(seed), "--max-depth", str(depth)] + flags)


def rmse(image, reference):
    with tempfile.NamedTemporaryFile(suffix=".json") as tmp:
        subprocess.run([HIPR, "compare", image, reference, "--metric", "rmse", "--threshold", "1e30", "--json",
                        tmp.name, "-q"], check=True)
        with open(tmp.name) as f:
            return json.load(f)["value"]


def box_filtered(image, size):
    out = image[:-len(".exr")] + "_box.exr"
    subprocess.run(["oiiotool", image, "--resize:filter=box", "%dx%d" % (size // BOX, size // BOX), "-o", out],
                   check=True)
    return out


def main():
    ap = argparse.ArgumentParser(prog="sampler_bench.py")
    ap.add_argument("outdir", nargs="?", default="bench-results")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--ref-spp", type=int, default=4096)
    ap.add_argument("--spp", default="4,16,64,256")
    ap.add_argument("--max-depth", type=int, default=32)
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--scenes", default="")
    args = ap.parse_args()
    spps = [int(s) for s in args.spp.split(",")]
    seeds = list(range(1, args.seeds + 1))
    wanted = set(args.scenes.split(",")) if args.scenes else None
    work = os.path.join(args.outdir, "sampler")
    os.makedirs(work, exist_ok=True)
    results = []
    for name, scene, flags in scenes_to_run(SCENES, wanted):
        print("== %s" % name, flush=True)
        reference = os.path.join(work, "%s_reference.exr" % name)
        ref_stats = render(scene, flags, args.size, args.ref_spp, "sobol", 1000, reference, args.max_depth)
        row = {"scene": name, "reference_spp": args.ref_spp, "points": []}
        for spp in spps:
            for sampler in SAMPLERS:
                errors, seconds = [], []
                for seed in seeds:
                    image = os.path.join(work, "%s_%s_%d_%d.exr" % (name, sampler, spp, seed))
                    stats = render(scene, flags, args.size, spp, sampler, seed, image, args.max_depth)
                    errors.append(rmse(image, reference))
                    seconds.append(stats["render_cpu_seconds"])
                mse = sum(e * e for e in errors) / len(errors)
                time = sum(seconds) / len(seconds)
                row["points"].append({"spp": spp, "sampler": sampler, "rmse": math.sqrt(mse), "cpu_seconds": time,
                                      "efficiency": 1.0 / (mse * time) if mse > 0 else float("inf")})
                print("  %-6s %5d spp  rmse %.5f  %.2f cpu s" % (sampler, spp, math.sqrt(mse), time), flush=True)
        reference_box = box_filtered(reference, args.size)
        for spp in BLUE_NOISE_SPP:
            for sampler in SAMPLERS:
                full_mse, box_mse = 0.0, 0.0
                for seed in seeds:
                    image = os.path.join(work, "%s_%s_%d_%d_blue.exr" % (name, sampler, spp, seed))
                    render(scene, flags, args.size, spp, sampler, seed, image, args.max_depth)
                    full_mse += rmse(image, reference) ** 2 / len(seeds)
                    box_mse += rmse(box_filtered(image, args.size), reference_box) ** 2 / len(seeds)
                row["points"].append({"spp": spp, "sampler": sampler, "rmse_full": math.sqrt(full_mse),
                                      "rmse_box": math.sqrt(box_mse)})
                print("  %-6s %5d spp  RMSE %.5f, through the box filter %.5f" %
                      (sampler, spp, math.sqrt(full_mse), math.sqrt(box_mse)), flush=True)
        row["device"] = ref_stats["device"]
        results.append(row)
    name = "sampler" + ("_" + "_".join(sorted(wanted)) if wanted else "")
    with open(os.path.join(args.outdir, name + ".json"), "w") as f:
        json.dump({"size": args.size, "max_depth": args.max_depth, "seeds": seeds, "scenes": results}, f, indent=2)
    with open(os.path.join(args.outdir, name + ".md"), "w") as f:
        f.write(tables(results, spps))
    print(tables(results, spps))


def tables(results, spps):
    def point(row, spp, sampler, key="rmse"):
        return next(p for p in row["points"] if p["spp"] == spp and p["sampler"] == sampler and key in p)

    out = "RMSE against the scene's own reference (random -> sobol):\n\n"
    out += "| scene | " + " | ".join("%d spp" % s for s in spps) + " |\n"
    out += "|---|" + "---|" * len(spps) + "\n"
    for row in results:
        cells = ["%.4f -> %.4f" % (point(row, s, "random")["rmse"], point(row, s, "sobol")["rmse"]) for s in spps]
        out += "| %s | %s |\n" % (row["scene"], " | ".join(cells))
    out += "\nEfficiency 1/(RMSE^2 x CPU time), sobol over random:\n\n"
    out += "| scene | " + " | ".join("%d spp" % s for s in spps) + " |\n"
    out += "|---|" + "---|" * len(spps) + "\n"
    for row in results:
        cells = ["%.2fx" % (point(row, s, "sobol")["efficiency"] / point(row, s, "random")["efficiency"]) for s in spps]
        out += "| %s | %s |\n" % (row["scene"], " | ".join(cells))
    def box(row, spp, sampler):
        return point(row, spp, sampler, "rmse_box")

    out += "\nBlue noise: RMSE through a %dx%d box filter (random -> sobol), and at 1 spp its ratio to the\n" % (BOX, BOX)
    out += "full-resolution RMSE (white noise keeps about %.3f; lower is bluer):\n\n" % (1.0 / BOX)
    out += "| scene | " + " | ".join("%d spp, filtered" % s for s in BLUE_NOISE_SPP) + " | 1 spp, ratio |\n"
    out += "|---|" + "---|" * (len(BLUE_NOISE_SPP) + 1) + "\n"
    for row in results:
        cells = ["%.4f -> %.4f" % (box(row, s, "random")["rmse_box"], box(row, s, "sobol")["rmse_box"])
                 for s in BLUE_NOISE_SPP]
        ratio = [box(row, 1, x)["rmse_box"] / box(row, 1, x)["rmse_full"] for x in SAMPLERS]
        cells.append("%.3f -> %.3f" % tuple(ratio))
        out += "| %s | %s |\n" % (row["scene"], " | ".join(cells))
    return out


if __name__ == "__main__":
    sys.exit(main())
