#!/usr/bin/env bash
# The edit soak: EDITS (default 10000) random edits of every op (transform, material, light,
# emission, visibility, camera, environment intensity/rotation and switches, duplicate/delete,
# deform), one in twenty hostile (huge, tiny, degenerate transforms, zero-area emitters, values
# beyond the scene limits, NaN; those refused are counted), on the shipped cornell_sphere at
# 32x32, one scheduling step each, then converged; prints whether the image is the full-frame
# render of the final scene bit for bit and the resident memory every tenth.
# usage: [HIPR_TRAVERSAL=software] bash tools/soak.sh [EDITS] [SEED]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target hipr_soak >/dev/null
export VK_DRIVER_FILES=${VK_DRIVER_FILES:-/usr/share/vulkan/icd.d/lvp_icd.json}
build/tests/hipr_soak "${1:-10000}" "${2:-1}"
