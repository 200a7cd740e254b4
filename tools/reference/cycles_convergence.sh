#!/usr/bin/env bash
# Error at equal samples and efficiency, hipr (both samplers) against Blender Cycles, on the
# Lambert Cornell box, all against one high-spp Cycles reference (BENCHMARKS.md, "Sampler").
# Needs `blender` (apt-get install blender) and a built hipr. The two renderers run one after
# the other on the same cores; times are each renderer's own render time (Cycles: Blender's
# render operation; hipr: render_seconds of --stats-json), wall clock, so run it on a quiet machine.
# usage: bash tools/reference/cycles_convergence.sh [OUTDIR] [SIZE] [SPP] [REF_SPP]
#        (defaults: bench-results/cycles 256 256 4096)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-bench-results/cycles}
size=${2:-256}
spp=${3:-256}
ref_spp=${4:-4096}
scene=assets/scenes/cornell_box.gltf
depth=64
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.json}
command -v blender >/dev/null || { echo "cycles_convergence.sh: needs blender (apt-get install blender)" >&2; exit 2; }
mkdir -p "$out"
cycles() {  # OUT.exr SPP SEED -> prints the render time
  blender -b --factory-startup --python tools/reference/cycles_cornell.py -- "$scene" "$1" --size "$size" \
    --spp "$2" --max-bounces "$depth" --seed "$3" 2>&1 | sed -n 's/^RENDER_TIME_S \([0-9.]*\).*/\1/p'
}
ref="$out/cycles_ref_${size}_${ref_spp}.exr"
[ -f "$ref" ] || cycles "$ref" "$ref_spp" 7 >/dev/null
rmse() {
  build/hipr compare "$1" "$ref" --metric rmse --threshold 1e30 --json "$out/compare.json" -q
  python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['value'])" "$out/compare.json"
}
rows=()
for seed in 1 2; do
  t=$(cycles "$out/cycles_$seed.exr" "$spp" "$seed")
  rows+=("cycles $seed $(rmse "$out/cycles_$seed.exr") $t")
  for sampler in sobol random; do
    img="$out/hipr_${sampler}_$seed.exr"
    build/hipr render "$scene" -o "$img" --stats-json "$img.json" -q --width "$size" --height "$size" \
      --spp "$spp" --seed "$seed" --max-depth "$depth" --sampler "$sampler"
    t=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['render_seconds'])" "$img.json")
    rows+=("hipr-$sampler $seed $(rmse "$img") $t")
  done
done
printf '%s\n' "${rows[@]}" > "$out/rows.txt"
python3 - "$out/rows.txt" "$size" "$spp" "$ref_spp" <<'EOF'
import sys
from collections import defaultdict
rows = defaultdict(list)
for line in open(sys.argv[1]):
    name, seed, err, t = line.split()
    rows[name].append((float(err), float(t)))
size, spp, ref_spp = sys.argv[2:5]
print("Lambert Cornell box, %sx%s, %s spp, max depth 64, against a %s-spp Cycles reference (two seeds):\n" %
      (size, size, spp, ref_spp))
print("| renderer | RMSE | render time (s) | efficiency 1/(RMSE^2 t) | vs Cycles |")
print("|---|---|---|---|---|")
stats = {}
for name, values in rows.items():
    mse = sum(e * e for e, _ in values) / len(values)
    t = sum(t for _, t in values) / len(values)
    stats[name] = (mse ** 0.5, t, 1.0 / (mse * t))
for name in ["cycles", "hipr-sobol", "hipr-random"]:
    r, t, eff = stats[name]
    print("| %s | %.5f | %.2f | %.0f | %.2fx |" % (name, r, t, eff, eff / stats["cycles"][2]))
print("\nhipr sobol: RMSE %.2fx Cycles'; efficiency %.2fx the random sampler's" %
      (stats["hipr-sobol"][0] / stats["cycles"][0], stats["hipr-sobol"][2] / stats["hipr-random"][2]))
EOF
