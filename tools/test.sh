#!/usr/bin/env bash
# Sets up, builds and runs every test (GoogleTest suites + scene generator checks) via CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --preset default
