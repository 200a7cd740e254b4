#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/: glTF/GLB scenes, edit scripts, environment images, the
# images `hipr compare` reads; clang with AddressSanitizer and UBSan) and runs each for SECONDS
# (default 60), starting from the shipped scenes and scripts, the shared scenes when ../shared is
# beside the repository, small generated images, and every input kept in tests/data/fuzz/<target>/.
# A crash, a sanitizer report or an input slower than 10 s fails the run and leaves the input in
# build-fuzz/findings/<target>/: fix it, then keep it in tests/data/fuzz/<target>/, which the
# ordinary test suite replays (tests/fuzz_regression_test.cpp). Memory is limited to 4 GB: the
# OpenEXR library takes 2 GB while refusing some malformed headers
# (tests/data/fuzz/environment/exr_huge_data_window.exr; hipr then says the file cannot be decoded).
# usage: bash tools/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j"$(nproc)"

corpus=build-fuzz/corpus
rm -rf "$corpus" build-fuzz/findings
mkdir -p "$corpus"/{gltf,edit_script,environment,image}
scenes() { find assets/scenes ../shared/scenes -maxdepth 2 -type f -size -256k \( -name '*.gltf' -o -name '*.glb' \) 2>/dev/null || true; }
for f in $(scenes); do
  cp "$f" "$corpus/gltf/$(echo "$f" | tr '/' '_')"
done
# Textures in WebP, AVIF and DDS (hipr's own decoders), in GLBs built here: no shipped scene has one.
python3 tools/fuzz_texture_seeds.py "$corpus/gltf"
for f in assets/scenes/*.edits.json tools/bench/*.json; do cp "$f" "$corpus/edit_script/$(basename "$f")"; done
oiiotool --pattern fill:top=1,0.5,0.25:bottom=0,0.1,0.2 8x4 3 -d half -o "$corpus/environment/gradient.exr"
oiiotool --pattern checker:color1=2,2,2:color2=0,0,0 8x4 3 -o "$corpus/environment/checker.hdr"
# Files of formats an environment map may not be, for the fuzzer to disguise as one.
for format in tif iff bmp tga sgi; do
  oiiotool --pattern checker:color1=2,2,2:color2=0,0,0 8x4 3 -o "$corpus/environment/other.$format"
done

# What `hipr compare` reads: PNG (RGB, grey, translucent, 16-bit), OpenEXR and Radiance.
cp "$corpus"/environment/gradient.exr "$corpus"/environment/checker.hdr "$corpus/image/"
oiiotool --pattern checker:color1=1,0.5,0:color2=0,0,0 8x4 3 -d uint8 -o "$corpus/image/rgb.png"
oiiotool --pattern constant:color=0.4 4x4 1 -d uint8 -o "$corpus/image/grey.png"
oiiotool --pattern fill:top=1,0,0,0.5:bottom=0,0,1,1 4x4 4 -d uint8 -o "$corpus/image/translucent.png"
oiiotool --pattern fill:top=0,0,0:bottom=1,1,1 4x4 3 -d uint16 -o "$corpus/image/deep.png"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
# Leaks inside Debian libraries hipr cannot free, each with its upstream report (fuzz/lsan.supp).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/fuzz/lsan.supp}
for target in gltf edit_script environment image; do
  mkdir -p "build-fuzz/findings/$target"
  seeds=("$corpus/$target")
  [ -d "tests/data/fuzz/$target" ] && seeds+=("tests/data/fuzz/$target")
  echo "== fuzz $target for ${seconds}s"
  build-fuzz/fuzz_$target -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=262144 \
    -close_fd_mask=2 -print_final_stats=1 -artifact_prefix="build-fuzz/findings/$target/" "${seeds[@]}" 2>&1 |
    grep -E "^#[0-9]+ *DONE|stat::number_of_executed_units|ERROR|SUMMARY|Test unit written" || true
  if [ -n "$(ls -A "build-fuzz/findings/$target")" ]; then
    echo "fuzz: $target found inputs that fail (build-fuzz/findings/$target)" >&2
    exit 1
  fi
done
echo "fuzz: no crash, sanitizer report or hang"
