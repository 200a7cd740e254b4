#!/usr/bin/env python3
"""How many samples the viewer's noise target takes on each scene (BENCHMARKS.md, "Viewer
convergence").

Renders every scene of sampler_bench.py at 16 and 64 spp and reports the film's own noise
estimate (`noise_relmse` of `hipr render --stats-json`), and from the 64-spp estimate (relMSE
falls as 1/samples) the samples and the time on this machine that a noise target needs.

    python3 tools/convergence_bench.py [OUTDIR] [--size 128] [--target 5e-4] [--scenes a,b]
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sampler_bench import HIPR, SCENES, scenes_to_run  # noqa: E402


def render(scene, flags, spp, size, out_dir, name):
    stats = os.path.join(out_dir, "%s_%d.json" % (name, spp))
    image = os.path.join(out_dir, "%s_%d.exr" % (name, spp))
    subprocess.run([HIPR, "render", scene, "-o", image, "--spp", str(spp), "--width", str(size),
                    "--height", str(size), "--stats-json", stats, "-q"] + flags, check=True)
    with open(stats) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out_dir", nargs="?", default="/tmp/hipr_convergence")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--target", type=float, default=5e-4, help="the viewer's default")
    parser.add_argument("--scenes", help="comma-separated names (default: all there)")
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    wanted = args.scenes.split(",") if args.scenes else None
    print("| scene | relMSE estimate 16 spp | 64 spp | ratio (1/n: 0.25) | spp to %.0e | s to it (this machine) |"
          % args.target)
    print("|---|---|---|---|---|---|")
    for name, scene, flags in scenes_to_run(SCENES, wanted):
        early = render(scene, flags, 16, args.size, args.out_dir, name)
        later = render(scene, flags, 64, args.size, args.out_dir, name)
        needed = 64.0 * later["noise_relmse"] / args.target
        seconds = later["render_seconds"] / 64.0 * needed
        print("| %s | %.2e | %.2e | %.2f | %.0f | %.1f |" % (
            name, early["noise_relmse"], later["noise_relmse"],
            later["noise_relmse"] / early["noise_relmse"], needed, seconds))


if __name__ == "__main__":
    main()
