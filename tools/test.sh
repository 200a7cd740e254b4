#!/usr/bin/env bash
# Sets up, builds and runs every test (GoogleTest suites + scene generator checks) via CTest,
# then fuzzes the loaders for a bounded time (HIPR_FUZZ_SECONDS per target, default 30; 0 skips).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --preset default
seconds=${HIPR_FUZZ_SECONDS:-30}
if [ "$seconds" != 0 ]; then bash tools/fuzz.sh "$seconds"; fi
