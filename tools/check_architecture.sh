#!/usr/bin/env bash
# Two rules of docs/architecture.md that a change can break without noticing.
# 1. No source file under src/ is longer than 500 lines (a file has one job).
# 2. The engine (src/render) never includes the method (src/hipr): HiPR attaches its passes to the
# engine's render state, not the other way round (docs/architecture.md). Both folders are
# reached as "hipr/..." (include/hipr is the public API), so a header counts as the method's
# when it exists under src/hipr and not under include/hipr. Exit 1 names each offending line.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
status=0
while IFS=: read -r file line text; do
  header="$(sed -E 's/.*#include "hipr\/([^"]+)".*/\1/' <<<"$text")"
  if [[ -f "$root/src/hipr/$header" && ! -f "$root/include/hipr/$header" ]]; then
    echo "${file#"$root/"}:$line: the engine includes the method's hipr/$header" >&2
    status=1
  fi
done < <(grep -Hn '#include "hipr/' "$root"/src/render/*.h "$root"/src/render/*.cpp || true)
while read -r lines file; do
  [[ "$file" == total ]] && continue
  if ((lines > 500)); then
    echo "${file#"$root/"}: $lines lines (at most 500: split it by job)" >&2
    status=1
  fi
done < <(find "$root/src" -name '*.cpp' -o -name '*.h' | xargs wc -l)
exit "$status"
