#!/usr/bin/env bash
# Installs dependencies (Debian 12; needs root or sudo) and builds hipr into build/: every
# target, or only those named (tools/demo.sh builds `hipr` alone, not the test suites).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup-deps.sh
cmake --preset default >/dev/null
if [ "$#" -gt 0 ]; then
  cmake --build build -j"$(nproc)" --target "$@"
else
  cmake --build build -j"$(nproc)"
fi
