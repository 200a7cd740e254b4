#!/usr/bin/env bash
# Checks the C++ format (.clang-format, Debian's clang-format): every tracked .cpp/.h outside
# shaders/ (GLSL and the host/device ABI, left as written), or with BASE (a commit) only those a
# change since BASE touches. Lists each misformatted file; exit 1 if any.
# `tools/check_format.sh --fix [BASE]` formats them in place instead.
set -euo pipefail
cd "$(dirname "$0")/.."
fix=0
if [ "${1:-}" = --fix ]; then fix=1; shift; fi
base="${1:-}"
if [ -n "$base" ]; then
  mapfile -t files < <(git diff --name-only --diff-filter=d "$base" -- '*.cpp' '*.h' | grep -v '^shaders/' || true)
else
  mapfile -t files < <(git ls-files '*.cpp' '*.h' | grep -v '^shaders/')
fi
[ "${#files[@]}" -eq 0 ] && exit 0
if [ "$fix" = 1 ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
status=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "$f: not formatted (tools/check_format.sh --fix)" >&2
    status=1
  fi
done
exit "$status"
