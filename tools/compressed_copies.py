#!/usr/bin/env python3
"""Renders compressed copies of scenes against their originals (BENCHMARKS.md, "Compressed glTF").

For every scene given (default: the shipped ones and ../shared/scenes), glTF-Transform
(tools/node_modules, installed by tools/setup-deps.sh) writes a Draco, a meshopt, a quantized and,
when the scene has images, a WebP copy. hipr renders the original with seeds 0 and 1 and each copy
with seed 0; a copy passes when its FLIP against the original's seed-0 image is at most 1.5x the
FLIP between the original's two seeds, plus 0.002 (quantization moves vertices slightly). Prints a
Markdown table; exits 1 when a copy fails to load or to pass.

  python3 tools/compressed_copies.py [--size 128] [--spp 32] [--keep DIR] [SCENE ...]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CLI = ROOT / "tools" / "node_modules" / "@gltf-transform" / "cli" / "bin" / "cli.js"
COMMANDS = ["draco", "meshopt", "quantize", "webp"]


def default_scenes():
    scenes = sorted(p for p in (ROOT / "assets" / "scenes").iterdir()
                    if p.suffix in (".gltf", ".glb") and "_moved" not in p.stem)
    shared = ROOT.parent / "shared" / "scenes"
    if shared.is_dir():
        for folder in sorted(shared.iterdir()):
            if folder.name == "InvalidInputs" or not folder.is_dir():
                continue
            scenes += sorted(p for p in folder.iterdir() if p.suffix in (".gltf", ".glb"))
    return scenes


def has_images(scene):
    data = scene.read_bytes()
    if scene.suffix == ".glb":
        length = int.from_bytes(data[12:16], "little")
        data = data[20:20 + length]
    return bool(json.loads(data).get("images"))


def run(command, **kwargs):
    return subprocess.run(command, capture_output=True, text=True, **kwargs)


def render(hipr, scene, output, args, seed):
    result = run([hipr, "render", str(scene), "--width", str(args.size), "--height",
                  str(args.size), "--spp", str(args.spp), "--seed", str(seed), "-o", str(output),
                  "-q"], env=dict(os.environ))
    if result.returncode != 0:
        raise RuntimeError(result.stderr.strip().splitlines()[-1] if result.stderr else "failed")


def flip(hipr, a, b, folder):
    report = folder / "compare.json"
    run([hipr, "compare", str(a), str(b), "--threshold", "1", "--json", str(report), "-q"])
    return json.loads(report.read_text())["value"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenes", nargs="*", type=Path)
    parser.add_argument("--hipr", default=str(ROOT / "build" / "hipr"))
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=32)
    parser.add_argument("--keep", type=Path, help="write the copies and images here")
    args = parser.parse_args()
    if not CLI.exists():
        sys.exit("compressed_copies: glTF-Transform is not installed (npm ci --prefix tools)")
    work = args.keep or Path(tempfile.mkdtemp(prefix="hipr-compressed-"))
    work.mkdir(parents=True, exist_ok=True)
    failures = 0
    print(f"{args.size}x{args.size}, {args.spp} spp. FLIP of each copy against the original "
          "(seed 0 both); limit = 1.5 x seeds + 0.002")
    print()
    print("| scene | seeds | limit | " + " | ".join(COMMANDS) + " |")
    print("|---|---|---|" + "---|" * len(COMMANDS))
    for scene in args.scenes or default_scenes():
        folder = work / scene.stem
        folder.mkdir(exist_ok=True)
        try:
            render(args.hipr, scene, folder / "seed0.exr", args, 0)
            render(args.hipr, scene, folder / "seed1.exr", args, 1)
        except RuntimeError as error:
            print(f"| {scene.name} | original does not render: {error} |")
            continue
        seeds = flip(args.hipr, folder / "seed1.exr", folder / "seed0.exr", folder)
        limit = 1.5 * seeds + 0.002
        cells = []
        for command in COMMANDS:
            if command == "webp" and not has_images(scene):
                cells.append("(no images)")
                continue
            copy = folder / f"{command}.glb"
            made = run(["node", str(CLI), command, str(scene), str(copy)])
            if made.returncode != 0:
                cells.append("tool failed")
                continue
            try:
                render(args.hipr, copy, folder / f"{command}.exr", args, 0)
            except RuntimeError as error:
                cells.append(f"**refused**: {error}")
                failures += 1
                continue
            value = flip(args.hipr, folder / f"{command}.exr", folder / "seed0.exr", folder)
            ok = value <= limit
            failures += not ok
            cells.append(f"{value:.4f}" + ("" if ok else " **over**"))
        print(f"| {scene.name} | {seeds:.4f} | {limit:.4f} | " + " | ".join(cells) + " |",
              flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
