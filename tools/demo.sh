#!/usr/bin/env bash
# Sets up, builds hipr (the binary alone: the test suites build in tools/test.sh) and renders
# the shipped Cornell box to out/cornell_box.png (+ .exr).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh hipr
mkdir -p out
./build/hipr render assets/scenes/cornell_box.gltf -o out/cornell_box.exr -o out/cornell_box.png \
  --width 512 --height 512 --spp 64 \
  --stats-json out/cornell_box.stats.json
echo "demo: wrote out/cornell_box.png, out/cornell_box.exr and out/cornell_box.stats.json"
