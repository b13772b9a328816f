#!/usr/bin/env bash
# Formatting check: every tracked C++ file must be as clang-format 14 writes it with the committed
# .clang-format (fix with: git ls-files '*.cpp' '*.h' | xargs clang-format-14 -i).
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h')
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! clang-format-14 --dry-run --Werror "${files[@]}" 2> "$log"; then
  head -40 "$log" >&2
  echo "vdfx: $(grep -c 'clang-format-violations' "$log") places are not formatted; run clang-format-14 -i on them" >&2
  exit 1
fi
echo "vdfx: formatting ok (${#files[@]} files)"
