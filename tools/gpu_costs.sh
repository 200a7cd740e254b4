#!/bin/bash
# What issues 40 and 41 ask to be stated per device, at each size (default 128x128 and
# 1920x1080): the display denoiser's cost (the filter alone, as a viewer's frame pays it, and
# with the image read back), the path guide's training time per scene state and its device
# bytes, and the render time of 32 spp with the light tree, with power-only light selection and
# with guiding (the tree rendered twice, first and last: the spread between the two is the noise
# of the others). Compilation stays out only where the driver compiles at pipeline creation or
# caches what it compiled (NVIDIA's does both); on lavapipe the ratios include compiling. BENCHMARKS.md, "On a GPU: the denoiser, the guide and the light tree".
#   bash tools/gpu_costs.sh [HIPR] [SCENES] [OUT] ["WxH WxH ..."]
# Prints a Markdown table per size; every render's --stats-json stays in OUT.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
hipr=${1:-$root/build/hipr}
scenes=${2:-$root/../shared/scenes}
out=${3:-$root/out/gpu_costs}
sizes=${4:-128x128 1920x1080}
mkdir -p "$out"
studio="--env $scenes/EnvMaps/studio_small_03_1k.hdr"

# name | scene | extra options
runs=(
  "cornell_box|$root/assets/scenes/cornell_box.gltf|"
  "cornell_sphere|$root/assets/scenes/cornell_sphere.glb|"
  "lamp_hall|$root/assets/scenes/lamp_hall.glb|"
  "CornellBox|$scenes/CornellBox/cornellBox.gltf|"
  "LightsPunctualLamp|$scenes/LightsPunctualLamp/LightsPunctualLamp.gltf|"
  "GlassVaseFlowers|$scenes/GlassVaseFlowers/GlassVaseFlowers.glb|$studio"
  "SheenChair|$scenes/SheenChair/SheenChair.gltf|$studio"
  "DamagedHelmet|$scenes/DamagedHelmet/DamagedHelmet.glb|$studio"
)
for size in $sizes; do
  width=${size%x*}
  height=${size#*x}
  for run in "${runs[@]}"; do
    IFS='|' read -r name scene extra <<<"$run"
    [ -f "$scene" ] || { echo "skipping $name: no $scene" >&2; continue; }
    base="$out/$name.$size"
    render() {  # render VARIANT SPP [OPTIONS...]
      local variant=$1 spp=$2
      shift 2
      # shellcheck disable=SC2086
      "$hipr" render "$scene" -o "$base.$variant.exr" --width "$width" --height "$height" --spp "$spp" \
        --stats-json "$base.$variant.json" -q $extra "$@" || echo "FAILED: $name $size $variant" >&2
    }
    render denoise 4 --denoise
    render tree 32
    render power 32 --light-selection power
    # The guided kernels' first use compiles them where a driver compiles at the first dispatch
    # (lavapipe); a driver's shader cache then serves the measured render.
    render guided_warm-up 1 --guiding
    render guided 32 --guiding
    render tree2 32
  done
done

python3 - "$out" "$sizes" <<'PY'
import json, pathlib, sys
out, sizes = pathlib.Path(sys.argv[1]), sys.argv[2].split()

def stats(path):
    return json.loads(path.read_text()) if path.exists() else None

for size in sizes:
    print(f"\n{size}:\n")
    print("| scene | device | filter on the device (ms: prepare + a-trous + blend + temporal) | filter, wall (ms) | "
          "filter + read-back (ms) | guide training (ms per state) | guide (MiB) | "
          "32 spp, tree (ms, two runs) | power / tree | guided / tree |")
    print("|---|---|---|---:|---:|---:|---:|---|---:|---:|")
    for denoise in sorted(out.glob(f"*.{size}.denoise.json")):
        name = denoise.name[: -len(f".{size}.denoise.json")]
        d = stats(denoise)
        t1, t2, p, g = (stats(out / f"{name}.{size}.{v}.json") for v in ("tree", "tree2", "power", "guided"))
        if not all((t1, t2, p, g)):
            print(f"| {name} | (a render failed) |")
            continue
        tree = min(t1["render_seconds"], t2["render_seconds"])
        training = 1000 * g["guide_training_seconds"] / max(g["guide_trainings"], 1)
        gpu = d.get("denoise_filter_gpu_seconds")
        on_device = (f'{1000 * gpu["total"]:.2f} ({1000 * gpu["prepare"]:.2f} + {1000 * gpu["atrous"]:.2f} + '
                     f'{1000 * gpu["blend"]:.2f} + {1000 * gpu.get("temporal", 0.0):.2f})' if gpu else "-")
        print(f'| {name} | {d["device"]} | {on_device} | {1000 * d["denoise_filter_seconds"]:.2f} | '
              f'{1000 * d["denoise_seconds"]:.2f} | {training:.1f} | {g["guide_bytes"] / 2**20:.1f} | '
              f'{1000 * t1["render_seconds"]:.1f}, {1000 * t2["render_seconds"]:.1f} | '
              f'{p["render_seconds"] / tree:.2f} | {g["render_seconds"] / tree:.2f} |')
PY
