#!/usr/bin/env python3
"""What geometry edits cost, and whether repeating them leaks (issue 19; BENCHMARKS.md).

    tools/geometry_edits.py SCENE NODE [--cycles N] [--hipr build/hipr] [-- replay options]

Runs `hipr replay` twice on SCENE from a scratch folder:
1. costs: duplicate NODE, deform it (x1.2 in y), delete the copy, import SCENE's own file (a copy
   beside the script) and delete the import; per op the GPU update time, the BLAS builds and
   their time (summary.json's blas_builds, blas_build_seconds, parts.scene);
2. cycles: N duplicate/delete pairs of NODE, one scheduling step each; device memory (every
   live Vulkan buffer) and the resident set after the first and the last cycle.
Prints one JSON object. Extra arguments after `--` go to both replays (size, spp...).
"""
import argparse
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile


def replay(hipr, scene, script, out, extra):
    command = [hipr, "replay", str(scene), str(script), "-o", str(out), "-q"] + extra
    subprocess.run(command, check=True)
    return json.loads((out / "summary.json").read_text())["edits"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene", type=pathlib.Path)
    parser.add_argument("node")
    parser.add_argument("--cycles", type=int, default=1000)
    parser.add_argument("--hipr", default="build/hipr")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    extra = argv[split + 1:]

    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        shutil.copy(args.scene, folder / ("imported" + args.scene.suffix))
        costs = folder / "costs.json"
        costs.write_text(json.dumps({"edits": [
            {"op": "duplicate", "node": args.node, "as": "copy", "translate": [0.5, 0, 0]},
            {"op": "deform", "node": args.node,
             "matrix": [1, 0, 0, 0, 0, 1.2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]},
            {"op": "delete", "node": "copy"},
            {"op": "import", "file": "imported" + args.scene.suffix, "as": "imported", "translate": [-0.5, 0, 0]},
            {"op": "delete", "node": "imported"},
        ]}))
        edits = replay(args.hipr, args.scene, costs, folder / "costs", extra)
        ops = [{"edit": e["edit"], "update_ms": 1000 * e["parts"]["scene_update_seconds"], "blas_builds": e["blas_builds"],
                "blas_build_ms": 1000 * e["blas_build_seconds"]} for e in edits]

        cycles = folder / "cycles.json"
        pairs = []
        for i in range(args.cycles):
            pairs.append({"op": "duplicate", "node": args.node, "as": "copy", "translate": [0.01 * (i % 7), 0, 0]})
            pairs.append({"op": "delete", "node": "copy"})
        cycles.write_text(json.dumps({"edits": pairs}))
        edits = replay(args.hipr, args.scene, cycles, folder / "cycles", extra + ["--steps", "1"])
        first, last = edits[1], edits[-1]
        mib = 1.0 / (1 << 20)
        print(json.dumps({
            "scene": str(args.scene),
            "ops": ops,
            "cycles": args.cycles,
            "device_mib_after_first": first["device_bytes"] * mib,
            "device_mib_after_last": last["device_bytes"] * mib,
            "resident_mib_after_first": first["resident_bytes"] * mib,
            "resident_mib_after_last": last["resident_bytes"] * mib,
        }, indent=2))


if __name__ == "__main__":
    sys.exit(main())
