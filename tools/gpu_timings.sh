#!/bin/bash
# Times hipr on whatever device it finds, at 1920x1080 by default: the setup (upload, BVH or
# acceleration structures, kernels), a full-frame pass (hipr render, 16 spp), the edit until its
# first step is on the display, and its parts: scene update, stage 1, a stage 2 step, stage 3's
# sort and a scheduled step (hipr replay's "parts"), and the viewer (headless, with its panels):
# its frame rate while re-rendering and each edit's latency to the first changed frame,
# for the shipped and shared scenes with their bench edit scripts (BENCHMARKS.md, "On a GPU").
# Also renders two small images twice, for the determinism contract on that device.
#   bash tools/gpu_timings.sh [HIPR] [SCENES] [OUT] [WIDTHxHEIGHT]
# Prints a Markdown table; everything it measured stays in OUT.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
hipr=${1:-$root/build/hipr}
scenes=${2:-$root/../shared/scenes}
out=${3:-$root/out/gpu}
size=${4:-1920x1080}
width=${size%x*}
height=${size#*x}
mkdir -p "$out"

# name | scene | edit script | extra options
runs=(
  "cornell_box|$root/assets/scenes/cornell_box.gltf|$root/tools/bench/cornell_box.camera.json|"
  "CornellBox|$scenes/CornellBox/cornellBox.gltf|$root/tools/bench/CornellBox.edits.json|"
  "SheenChair|$scenes/SheenChair/SheenChair.gltf|$root/tools/bench/SheenChair.edits.json|"
  "LightsPunctualLamp|$scenes/LightsPunctualLamp/LightsPunctualLamp.gltf|$root/tools/bench/LightsPunctualLamp.lights.json|"
  "GlassVaseFlowers|$scenes/GlassVaseFlowers/GlassVaseFlowers.glb|$root/tools/bench/GlassVaseFlowers.edits.json|"
  "DamagedHelmet|$scenes/DamagedHelmet/DamagedHelmet.glb||--env $scenes/EnvMaps/studio_small_03_1k.hdr"
  "MetalRoughSpheresNoTextures|$scenes/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb||"
)
for run in "${runs[@]}"; do
  IFS='|' read -r name scene edits extra <<<"$run"
  [ -f "$scene" ] || { echo "skipping $name: no $scene" >&2; continue; }
  # shellcheck disable=SC2086
  "$hipr" render "$scene" -o "$out/$name.exr" --width "$width" --height "$height" --spp 16 \
    --stats-json "$out/$name.render.json" -q $extra
  if [ -n "$edits" ]; then
    # shellcheck disable=SC2086
    "$hipr" replay "$scene" "$edits" -o "$out/$name.replay" --width "$width" --height "$height" --spp 4 \
      --steps 17 -q $extra
    # The viewer as a person uses it, without a display: an edit every 120 frames (the first once
    # the start is over), the frame budget adapting to the device.
    count=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["edits"]))' "$edits")
    # shellcheck disable=SC2086
    "$hipr" view "$scene" --headless --size "$size" --script "$edits" --script-start 120 --script-every 120 \
      --exit-after-frames $((120 * (count + 1))) --stats-json "$out/$name.view.json" -q $extra
  fi
done

# Determinism on this device: two processes, the same pixels.
for n in 1 2; do
  "$hipr" render "$root/assets/scenes/cornell_sphere.glb" -o "$out/determinism_$n.exr" --width 256 --height 256 \
    --spp 32 --seed 9 -q
done
"$hipr" compare "$out/determinism_1.exr" "$out/determinism_2.exr" --metric max --json "$out/determinism.json" -q \
  && echo "determinism: two processes gave bit-identical pixels" \
  || echo "determinism: two processes DIFFER (see $out/determinism.json)"

python3 - "$out" <<'PY'
import json, pathlib, statistics, sys
out = pathlib.Path(sys.argv[1])
print("| scene | device | traversal | size | triangles | setup (s) | full-frame pass (ms) | edit to first step shown (ms, median / max) | scene update (ms) | scene update allocations / submissions (most) | stage 1 (ms) | stage 2 step (ms) | stage 3 sort (ms) | scheduled step (ms) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for stats in sorted(out.glob("*.render.json")):
    name = stats.name[: -len(".render.json")]
    r = json.loads(stats.read_text())
    row = [name, r.get("device", "?"), r.get("traversal", "?"), f'{r["width"]}x{r["height"]}', str(r.get("triangles", "?")),
           f'{r["setup_seconds"]:.2f}', f'{1000 * r["render_seconds"] / r["spp"]:.1f}']
    summary = out / f"{name}.replay" / "summary.json"
    if summary.exists():
        s = json.loads(summary.read_text())
        edits = [e for e in s["edits"] if e.get("steps", 0) > 0]
        first = [1000 * e["first_step_seconds"] for e in edits]
        row.append(f"{statistics.median(first):.1f} / {max(first):.1f}")
        # Medians over the edits of each part (replay's "parts"; the first edit of a kind may compile).
        for key, count in (("scene_update_seconds", None), ("plan_seconds", None),
                           ("mean_leading_step_seconds", "leading_steps"), ("sort_seconds", None),
                           ("mean_step_seconds", "steps")):
            values = [1000 * e["parts"][key] for e in edits if count is None or e["parts"][count] > 0]
            row.append(f"{statistics.median(values):.2f}" if values else "-")  # "-": no such step ran
            if key == "scene_update_seconds":
                row.append(f'{max(e["parts"]["scene_update_allocations"] for e in edits)} / '
                           f'{max(e["parts"]["scene_update_submissions"] for e in edits)}')
    else:
        row += ["-"] * 7
    print("| " + " | ".join(row) + " |")

print()
print("| scene | device | presentation | size | viewer fps while re-rendering | frame ms (median / p95 / max) | host bytes per frame | edit to first changed frame (ms, each edit) |")
print("|---|---|---|---|---:|---|---:|---|")
for stats in sorted(out.glob("*.view.json")):
    v = json.loads(stats.read_text())
    r = v["rendering"]
    frames = (f'{r["frame_ms_median"]:.1f} / {r["frame_ms_p95"]:.1f} / {r["frame_ms_max"]:.1f}'
              if r["frames"] else "-")
    latencies = ", ".join(f'{1000 * e["latency_seconds"]:.1f}' for e in v["edits"])
    print(f'| {stats.name[: -len(".view.json")]} | {v["device"]} | {v["presentation"]} | {v["width"]}x{v["height"]} | '
          f'{r.get("fps", 0):.0f} | {frames} | {v["host_transfer_bytes_per_frame"]:.0f} | {latencies} |')
PY
