#!/usr/bin/env bash
# Sets up, checks the C++ format (tools/check_format.sh), builds and runs every test
# (GoogleTest suites + scene generator checks) via CTest,
# then the CPU suites again under AddressSanitizer and UBSan (tools/sanitize.sh;
# HIPR_SANITIZE=0 skips), then fuzzes the loaders for a bounded time (HIPR_FUZZ_SECONDS per
# target, default 30; 0 skips).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
bash tools/check_format.sh
# The set-up installed the glTF validator: its tests fail, rather than skip, without it.
export HIPR_REQUIRE_GLTF_VALIDATOR=1
ctest --preset default
if [ "${HIPR_SANITIZE:-1}" != 0 ]; then bash tools/sanitize.sh; fi
seconds=${HIPR_FUZZ_SECONDS:-30}
if [ "$seconds" != 0 ]; then bash tools/fuzz.sh "$seconds"; fi
