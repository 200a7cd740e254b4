#!/usr/bin/env bash
# The library and its CPU test suites (core, scene with the fuzz regressions, metrics, the BSDF
# compiled as C++) under AddressSanitizer and UBSan (preset `sanitize`, build-sanitize/): any
# report fails the run. The GPU suites stay in the ordinary build: lavapipe's LLVM is not
# instrumented. UBSan's vptr check is off: Debian's glslang is built without RTTI, so the
# type information it needs does not exist. Run by tools/test.sh; needs tools/setup-deps.sh's
# packages.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset sanitize >/dev/null
cmake --build build-sanitize -j"$(nproc)" --target core_test scene_test metrics_test bsdf_test
ctest --preset sanitize
