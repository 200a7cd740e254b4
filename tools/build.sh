#!/usr/bin/env bash
# Installs dependencies (Debian 12; needs root or sudo) and builds hipr into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup-deps.sh
cmake --preset default >/dev/null
cmake --build build -j"$(nproc)"
