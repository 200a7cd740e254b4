#!/usr/bin/env bash
# Golden images of the shipped scenes, made and checked the way a screenshot-regression suite
# would: `hipr render` at a fixed size, sample count and seed, then `hipr compare` against the
# image stored in tests/data/golden/.
#   bash tools/golden.sh check HIPR SCENE    (exit 0 when the render matches its golden image)
#   bash tools/golden.sh update HIPR         (re-renders every golden image; review, then commit)
# Same build and device: the render is bit-identical (FLIP 0). The threshold only tolerates the
# float-level drift of another LLVM or Mesa version; a real change of the image goes far beyond.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:?usage: golden.sh check|update HIPR [SCENE]}
hipr=${2:?usage: golden.sh check|update HIPR [SCENE]}
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.json}
scenes=(cornell_box.gltf cornell_box_moved.gltf cornell_sphere.glb)
settings=(--width 64 --height 64 --spp 16 --seed 3 --max-depth 8 -q)
threshold=0.002        # mean FLIP
worst_threshold=0.1    # FLIP of the worst pixels (99.9th percentile): a handful of wrong pixels
                       # barely move the mean, they fail this

render() {  # SCENE OUT.exr
  "$hipr" render "assets/scenes/$1" -o "$2" "${settings[@]}"
}

case "$mode" in
  update)
    mkdir -p tests/data/golden
    for scene in "${scenes[@]}"; do render "$scene" "tests/data/golden/${scene%.*}.exr"; done
    echo "golden images written to tests/data/golden/"
    ;;
  check)
    scene=${3:?usage: golden.sh check HIPR SCENE}
    out=$(mktemp -d)
    trap 'rm -rf "$out"' EXIT
    render "$scene" "$out/render.exr"
    golden="tests/data/golden/${scene%.*}.exr"
    "$hipr" compare "$out/render.exr" "$golden" --metric flip --threshold "$threshold"
    "$hipr" compare "$out/render.exr" "$golden" --metric flip --percentile 99.9 --threshold "$worst_threshold"
    ;;
  *)
    echo "golden.sh: unknown mode $mode (check, update)" >&2
    exit 2
    ;;
esac
