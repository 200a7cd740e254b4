#!/usr/bin/env bash
# The benchmark suite (BENCHMARKS.md): `hipr bench` on the shipped scenes and, when
# ../shared/scenes is beside the repository, on real scenes; then render throughput and the
# specialized-vs-uber kernel comparison. Writes OUTDIR/<scene>/{curves.csv,summary.json,plot.png},
# OUTDIR/throughput/*.json and OUTDIR/tables.md (the tables BENCHMARKS.md shows).
# usage: bash tools/bench.sh [OUTDIR]        (default: bench-results)
# Environment: HIPR_BENCH_SIZE (default 128), HIPR_BENCH_SPP (default 64).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh >/dev/null
out=${1:-bench-results}
rm -rf "$out/throughput"
mkdir -p "$out/throughput"
size=${HIPR_BENCH_SIZE:-128}
spp=${HIPR_BENCH_SPP:-64}
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.json}
shared=../shared/scenes
studio="$shared/EnvMaps/studio_small_03_1k.hdr"

bench() {
  local name=$1
  shift
  echo "== bench $name"
  rm -rf "${out:?}/$name"  # no stale edit images from an earlier run with other edits
  build/hipr bench "$@" -o "$out/$name" --width "$size" --height "$size" --spp "$spp"
}

bench cornell_box assets/scenes/cornell_box.gltf assets/scenes/cornell_box.edits.json
bench cornell_sphere assets/scenes/cornell_sphere.glb assets/scenes/cornell_sphere.edits.json
if [ -d "$shared" ]; then
  bench CornellBox "$shared/CornellBox/cornellBox.gltf" tools/bench/CornellBox.edits.json
  bench GlassVaseFlowers "$shared/GlassVaseFlowers/GlassVaseFlowers.glb" tools/bench/GlassVaseFlowers.edits.json --env "$studio"
  bench SheenChair "$shared/SheenChair/SheenChair.gltf" tools/bench/SheenChair.edits.json --env "$studio"
  bench LightsPunctualLamp "$shared/LightsPunctualLamp/LightsPunctualLamp.gltf" tools/bench/LightsPunctualLamp.edits.json
else
  echo "(no $shared: the real-scene benchmarks are skipped)"
fi

# Ablations on the same edits: hipr with the blend display rule (what the difference estimate
# refines), in OUTDIR/blend_<scene>, and hipr without the edit's lead (--edit-lead 0), in
# OUTDIR/nolead_<scene>.
ablate() {
  local variant=$1 name=$2
  shift 2
  local flags=(--display blend)
  [ "$variant" = nolead ] && flags=(--edit-lead 0)
  echo "== $variant $name"
  rm -rf "${out:?}/${variant}_$name"
  build/hipr bench "$@" -o "$out/${variant}_$name" --width "$size" --height "$size" --spp "$spp" --policies hipr \
    "${flags[@]}"
}
for variant in blend nolead; do
  ablate $variant cornell_box assets/scenes/cornell_box.gltf assets/scenes/cornell_box.edits.json
  ablate $variant cornell_sphere assets/scenes/cornell_sphere.glb assets/scenes/cornell_sphere.edits.json
  if [ -d "$shared" ]; then
    ablate $variant CornellBox "$shared/CornellBox/cornellBox.gltf" tools/bench/CornellBox.edits.json
    ablate $variant GlassVaseFlowers "$shared/GlassVaseFlowers/GlassVaseFlowers.glb" \
      tools/bench/GlassVaseFlowers.edits.json --env "$studio"
    ablate $variant SheenChair "$shared/SheenChair/SheenChair.gltf" tools/bench/SheenChair.edits.json --env "$studio"
    ablate $variant LightsPunctualLamp "$shared/LightsPunctualLamp/LightsPunctualLamp.gltf" \
      tools/bench/LightsPunctualLamp.edits.json
  fi
done

# Drags: 20 small moves in a row, one every 1/16 of a frame's work, in steps of 1/64 of the frame
# (as the viewer spends a frame's budget), for hipr and full.
drag_tiles=$(((size / 8) * (size / 8) / 64))
drag_tiles=$((drag_tiles > 0 ? drag_tiles : 1))
drag() {
  local name=$1
  shift
  echo "== drag $name"
  rm -rf "${out:?}/drag_$name"
  build/hipr bench "$@" -o "$out/drag_$name" --width "$size" --height "$size" --spp "$spp" --drag 0.0625 \
    --tiles-per-step "$drag_tiles" --policies hipr,full --ref-spp 256
}
drag cornell_box assets/scenes/cornell_box.gltf tools/bench/cornell_box.drag.json
drag cornell_sphere assets/scenes/cornell_sphere.glb tools/bench/cornell_sphere.drag.json
if [ -d "$shared" ]; then
  drag CornellBox "$shared/CornellBox/cornellBox.gltf" tools/bench/CornellBox.drag.json
fi

# An estimator on and off: KIND NAME FLAG args... runs hipr and full as they are, then again
# with --FLAG (the estimator off). Results in OUTDIR/KIND_NAME_{on,FLAG}.
with_and_without() {
  local kind=$1 name=$2 flag=$3
  shift 3
  for run in on "$flag"; do
    echo "== $kind $name ($run)"
    rm -rf "${out:?}/${kind}_${name}_$run"
    build/hipr bench "$@" -o "$out/${kind}_${name}_$run" --width "$size" --height "$size" --spp "$spp" \
      --policies hipr,full $([ "$run" = "$flag" ] && echo "--$flag")
  done
}

# Camera moves (tools/bench/*.camera.json; an orbit as a drag): hipr reprojects the image before
# each; again with --no-reproject for the comparison. Results in OUTDIR/camera_*.
camera() { with_and_without camera "$1" no-reproject "${@:2}"; }
camera cornell_box assets/scenes/cornell_box.gltf tools/bench/cornell_box.camera.json
camera cornell_box_orbit assets/scenes/cornell_box.gltf tools/bench/cornell_box.orbit.json \
  --drag 0.0625 --tiles-per-step 4 --ref-spp 256
if [ -d "$shared" ]; then
  camera SheenChair "$shared/SheenChair/SheenChair.gltf" tools/bench/SheenChair.camera.json --env "$studio"
fi

# Light edits (tools/bench/*.lights.json, a lamp slider dragged): hipr relights them at once from
# its light groups; again with --no-relight for the comparison. Results in OUTDIR/lights_*.
lights() { with_and_without lights "$1" no-relight "${@:2}"; }
lights cornell_sphere assets/scenes/cornell_sphere.glb tools/bench/cornell_sphere.lights.json
lights cornell_sphere_drag assets/scenes/cornell_sphere.glb tools/bench/cornell_sphere.lightdrag.json \
  --drag 0.0625 --tiles-per-step "$drag_tiles" --ref-spp 256
if [ -d "$shared" ]; then
  lights LightsPunctualLamp "$shared/LightsPunctualLamp/LightsPunctualLamp.gltf" tools/bench/LightsPunctualLamp.lights.json
  lights SheenChair "$shared/SheenChair/SheenChair.gltf" tools/bench/SheenChair.lights.json --env "$studio"
fi

# Attention-guided rendering (tools/bench/*.focus.json): the scene from nothing (--cold-start)
# and camera edits, hipr with and without the script's focus, the focus region measured.
# Results in OUTDIR/focus_*.
focus() {
  local name=$1
  shift
  echo "== focus $name"
  rm -rf "${out:?}/focus_$name"
  build/hipr bench "$@" -o "$out/focus_$name" --width "$size" --height "$size" --spp "$spp" --cold-start \
    --policies hipr,full
}
focus cornell_box assets/scenes/cornell_box.gltf tools/bench/cornell_box.focus.json
focus cornell_sphere assets/scenes/cornell_sphere.glb tools/bench/cornell_sphere.focus.json
if [ -d "$shared" ]; then
  focus CornellBox "$shared/CornellBox/cornellBox.gltf" tools/bench/CornellBox.focus.json
  focus SheenChair "$shared/SheenChair/SheenChair.gltf" tools/bench/SheenChair.focus.json --env "$studio"
fi

# Throughput: three interleaved rounds, so a noisy neighbour hits every configuration alike.
render() {
  local name=$1 scene=$2
  shift 2
  build/hipr render "$scene" -o "$out/throughput/$name.exr" --stats-json "$out/throughput/$name.json" -q "$@"
}
# Lavapipe compiles a kernel at its first dispatch (seconds to a minute) and Mesa's shader cache
# keeps it: a tiny render of each configuration first, so no round pays for compilation.
render warmup assets/scenes/cornell_box.gltf --width 16 --height 16 --spp 1
render warmup assets/scenes/cornell_box.gltf --width 16 --height 16 --spp 1 --uber-kernel
if [ -d "$shared" ]; then
  render warmup "$shared/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb" \
    --width 16 --height 16 --spp 1 --env "$studio"
fi
rm -f "$out/throughput/warmup".*
for round in 1 2 3; do
  echo "== throughput round $round"
  render "cornell_box_r$round" assets/scenes/cornell_box.gltf --width 256 --height 256 --spp 64
  render "cornell_box_uber_r$round" assets/scenes/cornell_box.gltf --width 256 --height 256 --spp 64 --uber-kernel
  if [ -d "$shared" ]; then
    render "MetalRoughSpheres_r$round" "$shared/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb" \
      --width 256 --height 256 --spp 16 --env "$studio"
  fi
done
/usr/bin/python3 tools/bench_tables.py "$out" >"$out/tables.md.tmp"
mv "$out/tables.md.tmp" "$out/tables.md"
echo "wrote $out/tables.md"
