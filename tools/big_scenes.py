#!/usr/bin/env python3
"""Load, BVH build and first-image times and memory against triangle count (issue 42).

Usage: python3 tools/big_scenes.py [--triangles 1000,10000,...] [--hipr build/hipr]
                                   [--out DIR] [--size 256]

For each count, writes terrain_<N>.glb with the shipped generator (tools/make_scenes.py
--triangles), then times `hipr render SCENE --spp 1` (the first image, from the command's start
to the written file) and reads its --stats-json: load seconds (parse and decode), setup seconds
(device, upload, acceleration structures, kernels), the acceleration structures' build seconds
alone, the device bytes hipr allocated and the process's peak resident bytes. Per-triangle costs
are the slope between the two largest scenes, so fixed costs (the device, the kernels, the
environment) cancel. Prints a Markdown table (BENCHMARKS.md "Big scenes"). A scene the device
cannot hold is reported with hipr's one-line error.
"""

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_COUNTS = [1_000, 10_000, 100_000, 1_000_000, 10_000_000]


def generate(triangles, out_dir):
    path = out_dir / f"terrain_{triangles}.glb"
    if not path.exists():
        subprocess.run([sys.executable, str(ROOT / "tools" / "make_scenes.py"), "--triangles",
                        str(triangles), "--out", str(out_dir)], check=True, stdout=subprocess.DEVNULL)
    return path


def measure(hipr, scene, size, out_dir):
    stats_path = out_dir / f"{scene.stem}.json"
    image = out_dir / f"{scene.stem}.png"
    command = [hipr, "render", str(scene), "-o", str(image), "--spp", "1", "--width", str(size),
               "--height", str(size), "--stats-json", str(stats_path), "-q"]
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if result.returncode != 0:
        return {"error": (result.stderr.strip().splitlines() or ["exit %d" % result.returncode])[-1],
                "exit": result.returncode}
    stats = json.loads(stats_path.read_text())
    stats["first_image_seconds"] = seconds
    stats["file_bytes"] = scene.stat().st_size
    return stats


def mib(n):
    return n / (1 << 20)


def table(rows):
    lines = ["| triangles | file MiB | load s | BVH build s | setup s | first image s | device MiB | peak RSS MiB |",
             "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for count, s in rows:
        if "error" in s:
            lines.append(f"| {count:,} | | | | | exit {s['exit']}: {s['error']} | | |")
            continue
        lines.append(f"| {s['triangles']:,} | {mib(s['file_bytes']):.1f} | {s['load_seconds']:.2f} | "
                     f"{s['blas_build_seconds']:.2f} | {s['setup_seconds']:.2f} | "
                     f"{s['first_image_seconds']:.2f} | {mib(s['device_bytes']):.0f} | "
                     f"{mib(s['peak_resident_bytes']):.0f} |")
    done = [s for _, s in rows if "error" not in s]
    if len(done) >= 2:
        a, b = done[-2], done[-1]
        dt = b["triangles"] - a["triangles"]
        lines += ["", f"Per triangle (slope from {a['triangles']:,} to {b['triangles']:,}): "
                  f"{(b['device_bytes'] - a['device_bytes']) / dt:.0f} device bytes, "
                  f"{(b['peak_resident_bytes'] - a['peak_resident_bytes']) / dt:.0f} host bytes at peak, "
                  f"{(b['load_seconds'] - a['load_seconds']) / dt * 1e9:.0f} ns to load, "
                  f"{(b['blas_build_seconds'] - a['blas_build_seconds']) / dt * 1e9:.0f} ns to build "
                  f"the BVH. Device: {b['device']} ({b['traversal']} traversal)."]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--triangles", default=",".join(map(str, DEFAULT_COUNTS)),
                        help="comma-separated triangle counts")
    parser.add_argument("--hipr", default=str(ROOT / "build" / "hipr"))
    parser.add_argument("--out", type=Path, help="where scenes and results go (default: a temporary folder)")
    parser.add_argument("--size", type=int, default=256, help="image width and height")
    args = parser.parse_args()
    counts = [int(c) for c in args.triangles.split(",") if c]
    with tempfile.TemporaryDirectory(prefix="hipr-big-") as temporary:
        out_dir = args.out or Path(temporary)
        out_dir.mkdir(parents=True, exist_ok=True)
        rows = []
        for count in counts:
            scene = generate(count, out_dir)
            rows.append((count, measure(args.hipr, scene, args.size, out_dir)))
            print(f"{count:,} triangles: done", file=sys.stderr)
        print(table(rows))


if __name__ == "__main__":
    main()
