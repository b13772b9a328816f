#!/usr/bin/env bash
# The size rule of docs/architecture.md ("Files and functions"), checked: every C++ function of
# the production folders (app/, effects/, io/, ui/, xr/) and of tests/ longer than 80 lines, and
# every file of app/editor/ longer than 350 lines, named; exit 1 when there is one.
# A function's length is its lines from ctags' start to its end, both counted, raw strings and
# comments in it included. Universal Ctags (Debian's universal-ctags, .ci/deps.sh) is required:
# without it the check fails, never skips. VDFX_CTAGS names another ctags program.
#
# usage: function_length.sh [ROOT]   (ROOT: the repository, default this script's)
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
ctags=${VDFX_CTAGS:-ctags}
max_function_lines=80
max_editor_file_lines=350

if ! command -v "$ctags" > /dev/null 2>&1; then
  echo "vdfx: function length: '$ctags' not found: install Debian's universal-ctags (.ci/deps.sh)" >&2
  exit 1
fi
# Exuberant Ctags has no end: field, so it would pass every function.
if ! "$ctags" --version 2> /dev/null | grep -q "Universal Ctags"; then
  echo "vdfx: function length: '$ctags' is not Universal Ctags: install Debian's universal-ctags" >&2
  exit 1
fi

cd "$root"
dirs=()
for d in app effects io ui xr tests; do [ -d "$d" ] && dirs+=("$d"); done
if [ ${#dirs[@]} -eq 0 ]; then
  echo "vdfx: function length: none of app/ effects/ io/ ui/ xr/ tests/ in $root" >&2
  exit 1
fi

tags=$(mktemp)
trap 'rm -f "$tags"' EXIT
"$ctags" --fields=+neS --c++-kinds=f --languages=C++ --excmd=number --sort=no -o "$tags" \
  -R "${dirs[@]}"

# name <TAB> file <TAB> line;" <TAB> kind and fields (line:N, end:N, signature:(...) among them);
# a GoogleTest body is named by its macro's arguments, TEST(Suite,Name).
long_functions=$(awk -F'\t' -v max="$max_function_lines" '
  /^!_TAG_/ { next }
  {
    start = ""; end = ""; sig = ""
    for (i = 4; i <= NF; ++i) {
      if ($i ~ /^line:/) start = substr($i, 6)
      if ($i ~ /^end:/) end = substr($i, 5)
      if ($i ~ /^signature:/) sig = substr($i, 11)
    }
    if (start == "" || end == "") next
    name = $1
    if (name ~ /^TEST(_F|_P)?$/) name = name sig
    n = end - start + 1
    if (n > max) printf "%s:%d: %s is %d lines (over %d)\n", $2, start, name, n, max
  }' "$tags" | sort -t: -k1,1 -k2,2n)

long_files=""
if [ -d app/editor ]; then
  while IFS= read -r f; do
    n=$(wc -l < "$f")
    if [ "$n" -gt "$max_editor_file_lines" ]; then
      long_files+="$f: $n lines (over $max_editor_file_lines for a file of app/editor/)"$'\n'
    fi
  done < <(find app/editor -type f \( -name '*.cpp' -o -name '*.h' \) | sort)
fi

report="${long_functions:+$long_functions$'\n'}$long_files"
count=$(grep -c . <<< "$report" || true)
if [ "$count" -gt 0 ]; then
  printf '%s' "$report" >&2
  echo "vdfx: $count over the size rule: split a long function by meaning (parse, validate," \
    "build, run, report), not at a line count (docs/architecture.md, \"Files and functions\")" >&2
  exit 1
fi
echo "vdfx: function length ok (functions up to $max_function_lines lines in ${dirs[*]};" \
  "app/editor/ files up to $max_editor_file_lines lines)"
