#!/usr/bin/env python3
"""What the viewer shows frame by frame during a scripted camera move, against the converged
image of each view: FLIP per frame and the frame rate, for hipr, hipr --no-reproject (restarting
every camera edit) and full.

    python3 tools/viewer_frames.py assets/scenes/cornell_box.gltf tools/bench/cornell_box.orbit.json OUT

The script's edits must all be camera edits by matrix (an orbit, as tools/bench/*.orbit.json),
and the scene's camera node must have no parent: the reference of view k is the scene with that
node's matrix replaced, rendered by `hipr render` (copied with the files it reads into OUT/refs).
The viewer runs under Xvfb, converges the scene for --start frames, then applies one edit per
frame (--script-start, --script-every 1), writing every frame (--frames-dir); the frame rate is
over the frames from the first edit on, each timed without its read-back. Needs xvfb-run and
build/hipr.
"""
import argparse
import json
import shutil
import statistics
import subprocess
import sys
from pathlib import Path

HIPR = Path(__file__).resolve().parent.parent / "build" / "hipr"
VARIANTS = [("hipr", []), ("hipr_no_reproject", ["--no-reproject"]), ("full", ["--policy", "full"])]


def run(cmd):
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"failed ({result.returncode}): {' '.join(map(str, cmd))}\n{result.stderr.strip()}")
    return result


def camera_matrices(script):
    edits = json.loads(Path(script).read_text())["edits"]
    if not edits or any(e.get("op") != "camera" or "matrix" not in e for e in edits):
        sys.exit(f"{script}: every edit must be a camera edit by matrix")
    return [e["matrix"] for e in edits]


def write_references(scene, matrices, out, size, spp, extra):
    """refs/ref_K.exr: the converged image after K edits (K = 0: the scene as loaded)."""
    refs = out / "refs"
    refs.mkdir(parents=True, exist_ok=True)
    doc = json.loads(Path(scene).read_text())
    for item in doc.get("buffers", []) + doc.get("images", []):
        uri = item.get("uri", "")
        if uri and not uri.startswith("data:"):
            shutil.copy(Path(scene).parent / uri, refs / uri)
    camera = next((i for i, n in enumerate(doc["nodes"]) if "camera" in n), None)
    if camera is None or any(camera in n.get("children", []) for n in doc["nodes"]):
        sys.exit(f"{scene}: needs a camera node without a parent")
    paths = []
    for k, matrix in enumerate([None] + matrices):
        path = refs / f"ref_{k:03d}.exr"
        if matrix is not None:
            node = doc["nodes"][camera]
            for key in ("translation", "rotation", "scale"):
                node.pop(key, None)
            node["matrix"] = matrix
        view = refs / f"view_{k:03d}.gltf"
        view.write_text(json.dumps(doc))
        if not path.exists():
            run([HIPR, "render", view, "-o", path, "--width", size, "--height", size, "--spp", spp, "-q", *extra])
        paths.append(path)
    return paths


def viewer(scene, script, size, spp, start, frames, extra, flags):
    return ["xvfb-run", "-a", "-s", "-screen 0 900x700x24", HIPR, "view", scene, "--script", script,
            "--script-start", start, "--script-every", "1", "--no-ui", "--size", f"{size}x{size}", "--spp", spp,
            "--exit-after-frames", frames, *extra, *flags]


def flip(image, reference, scratch):
    run([HIPR, "compare", image, reference, "--metric", "flip", "--threshold", "1", "--json", scratch, "-q"])
    return json.loads(Path(scratch).read_text())["value"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("script")
    parser.add_argument("out")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--ref-spp", type=int, default=256)
    parser.add_argument("--start", type=int, default=300,
                        help="frame of the first edit: the frames before converge the scene as loaded")
    parser.add_argument("--frames", type=int, default=0,
                        help="frames measured from the first edit on (default: twice the edits)")
    parser.add_argument("extra", nargs="*", help="more options for hipr render and view (after --)")
    a = parser.parse_args()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    matrices = camera_matrices(a.script)
    frames = a.frames or 2 * len(matrices)
    last = a.start + frames - 1
    refs = write_references(a.scene, matrices, out, str(a.size), str(a.ref_spp), a.extra)
    rows = {}
    for name, flags in VARIANTS:
        shots = out / name
        shutil.rmtree(shots, ignore_errors=True)
        shots.mkdir()
        run(viewer(a.scene, a.script, a.size, str(a.spp), str(a.start), str(last), a.extra,
                   [*flags, "--frames-dir", shots]))
        # While the camera moves: every frame up to the first that shows the last edit.
        during, after, seen = [], [], []
        log = json.loads((shots / "frames.json").read_text())
        # The frame before the first edit: the scene as loaded, converged (or not: then --start is short).
        start_flip = flip(shots / log[a.start - 1]["file"], refs[0], out / "compare.json")
        for entry in log[a.start:]:
            edits = entry["script_edits"]
            error = flip(shots / entry["file"], refs[edits], out / "compare.json")
            moving = edits < len(matrices) or not any(e == len(matrices) for e in seen)
            (during if moving else after).append(error)
            seen.append(edits)
        rows[name] = {"flip_before": start_flip, "flip_during": statistics.mean(during), "flip_after": statistics.mean(after) if after else None,
                      # Frames from the first edit on, each timed without its read-back.
                      "fps": 1e3 / statistics.mean(e["frame_ms"] for e in log[a.start:]),
                      "frames_during": len(during), "frames_after": len(after)}
    (out / "summary.json").write_text(json.dumps(rows, indent=2) + "\n")
    print("| variant | FLIP before the first edit | mean FLIP while the camera moves | after (%d frames in all) | fps |"
          % frames)
    print("|---|---:|---:|---:|---:|")
    for name, r in rows.items():
        after = "-" if r["flip_after"] is None else "%.4f" % r["flip_after"]
        print("| %s | %.4f | %.4f | %s | %.1f |" % (name, r["flip_before"], r["flip_during"], after, r["fps"]))


if __name__ == "__main__":
    main()
