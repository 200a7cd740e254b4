#!/usr/bin/env python3
"""Is one hipr render faster than another? Paired, alternated timings with an interval.

The machines these benches run on are shared: one render's `render_cpu_seconds` moves by
10-20 % from run to run, more than most changes to the kernel are worth. This runs the two
configurations (two binaries, two flag sets, or both) in pairs, A then B and B then A by turns,
so that whatever loads the machine meanwhile weighs on both alike, and reports the median of
the per-pair ratios B / A with a distribution-free interval for it (the order statistics a sign
test would accept at about 90 %), besides each side's median. A change is measured only when
the interval excludes 1. With --same-image it also checks that the two render the same image
bit for bit (hipr compare --metric max), the claim a pure speed change makes.

usage: python3 tools/time_ab.py SCENE [--a BIN] [--b BIN] [--a-flags "..."] [--b-flags "..."]
       [--size N] [--spp N] [--pairs N] [--threads N] [--same-image] [--json OUT]
       (default BINs: build/hipr; --threads sets LP_NUM_THREADS, lavapipe's worker threads)
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sampler_bench import HIPR, render_stats  # noqa: E402


def render(binary, scene, flags, size, spp, out_exr, env):
    """CPU seconds of one render, the image written to out_exr."""
    return render_stats(scene, out_exr, size, spp, flags, binary, env)["render_cpu_seconds"]


def median_interval(values, confidence=0.9):
    """Order statistics (lo, hi) that bracket the median with at least `confidence` (binomial)."""
    data = sorted(values)
    n = len(data)
    # Largest k with P(Binomial(n, 1/2) < k) <= (1 - confidence) / 2: [x_k, x_(n-1-k)] covers it.
    tail = (1.0 - confidence) / 2.0
    k, cumulative = 0, 0.0
    while k < n // 2:
        p = math.comb(n, k) / 2.0 ** n
        if cumulative + p > tail:
            break
        cumulative += p
        k += 1
    if k == 0:
        return None  # too few pairs for any interval at this confidence
    return data[k - 1], data[n - k]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("--a", default=HIPR, help="binary of configuration A")
    ap.add_argument("--b", default=HIPR, help="binary of configuration B")
    ap.add_argument("--a-flags", default="", help="more `hipr render` flags for A")
    ap.add_argument("--b-flags", default="", help="more `hipr render` flags for B")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--pairs", type=int, default=10)
    ap.add_argument("--threads", type=int, default=0, help="LP_NUM_THREADS (0: lavapipe's default)")
    ap.add_argument("--same-image", action="store_true", help="also require the two images to be equal bit for bit")
    ap.add_argument("--json", default="", help="write the timings and the summary here")
    args = ap.parse_args()
    if args.pairs < 1 or args.size < 1 or args.spp < 1:
        ap.error("--pairs, --size and --spp must be positive")
    env = dict(os.environ)
    if args.threads > 0:
        env["LP_NUM_THREADS"] = str(args.threads)
    configs = {"A": (args.a, args.a_flags.split()), "B": (args.b, args.b_flags.split())}
    with tempfile.TemporaryDirectory() as work:
        images = {name: os.path.join(work, name + ".exr") for name in configs}
        # Untimed, once each: lavapipe compiles a kernel variant at its first dispatch.
        for name, (binary, flags) in configs.items():
            render(binary, args.scene, flags, 16, 1, images[name], env)
        seconds = {"A": [], "B": []}
        for i in range(args.pairs):
            for name in ("A", "B") if i % 2 == 0 else ("B", "A"):
                binary, flags = configs[name]
                seconds[name].append(render(binary, args.scene, flags, args.size, args.spp, images[name], env))
        same = None
        if args.same_image:
            compare = subprocess.run([args.a, "compare", images["A"], images["B"], "--metric", "max", "-q"], env=env)
            same = compare.returncode == 0
    ratios = [b / a for a, b in zip(seconds["A"], seconds["B"]) if a > 0]
    interval = median_interval(ratios)
    summary = {"scene": args.scene, "size": args.size, "spp": args.spp, "pairs": args.pairs,
               "median_cpu_seconds": {name: statistics.median(v) for name, v in seconds.items()},
               "ratio_b_over_a": statistics.median(ratios), "ratio_interval_90": interval,
               "same_image": same, "seconds": seconds}
    print("A %s %s: median %.3f CPU s" % (args.a, args.a_flags, summary["median_cpu_seconds"]["A"]))
    print("B %s %s: median %.3f CPU s" % (args.b, args.b_flags, summary["median_cpu_seconds"]["B"]))
    verdict = "not measured apart (interval holds 1)"
    if interval is None:
        verdict = "too few pairs for an interval"
    elif interval[1] < 1.0:
        verdict = "B faster"
    elif interval[0] > 1.0:
        verdict = "B slower"
    shown = "[%.3f, %.3f]" % interval if interval else "none"
    print("B / A per pair: median %.3f, ~90 %% interval %s: %s" % (summary["ratio_b_over_a"], shown, verdict))
    if same is not None:
        print("images: " + ("the same bit for bit" if same else "DIFFERENT"))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(summary, f, indent=2)
    return 0 if same is not False else 1


if __name__ == "__main__":
    sys.exit(main())
