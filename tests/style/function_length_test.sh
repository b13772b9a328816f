#!/usr/bin/env bash
# The size check (function_length.sh) on trees written here: an 80-line function and a 350-line
# file of app/editor/ pass; an 81-line function (production or test) and a 351-line editor file
# fail, each named with its place; a missing ctags fails naming the package.
#
# usage: function_length_test.sh WORK   (WORK: a scratch folder, emptied)
set -euo pipefail
check="$(cd "$(dirname "$0")" && pwd)/function_length.sh"
work=${1:?usage: function_length_test.sh WORK}
failures=0

# function_of FILE NAME LINES: a function NAME of LINES lines (its signature to its closing brace).
function_of() {
  local file=$1 name=$2 lines=$3
  mkdir -p "$(dirname "$file")"
  {
    echo "int $name(int x) {"
    for ((i = 0; i < lines - 2; ++i)); do echo "  x += $i;"; done
    echo "}"
  } >> "$file"
}

# expect CASE RC TEXT [ENV...]: the check on $work exits RC and its output contains TEXT.
expect() {
  local what=$1 want_rc=$2 text=$3
  shift 3
  local out rc=0
  out=$(env "$@" bash "$check" "$work" 2>&1) || rc=$?
  if [ "$rc" -ne "$want_rc" ] || ! grep -qF -- "$text" <<< "$out"; then
    echo "FAIL: $what: want exit $want_rc and '$text', got exit $rc:" >&2
    echo "$out" >&2
    failures=$((failures + 1))
  else
    echo "ok: $what"
  fi
}

rm -rf "$work"
mkdir -p "$work"
function_of "$work/io/short.cpp" eighty 80
mkdir -p "$work/tests" "$work/app/editor"
{
  echo "#include <gtest/gtest.h>"
  echo "TEST(Suite, Table) {"
  for ((i = 0; i < 78; ++i)); do echo "  EXPECT_EQ($i, $i);"; done
  echo "}"
} > "$work/tests/t.cpp"
seq 350 | sed 's|^|// |' > "$work/app/editor/editor.cpp"
expect "80 lines and a 350-line editor file" 0 "function length ok"

function_of "$work/xr/long.cpp" eighty_one 81
expect "an 81-line function" 1 "xr/long.cpp:1: eighty_one is 81 lines (over 80)"

rm "$work/xr/long.cpp"
echo "  EXPECT_EQ(1, 1);" > "$work/extra"
sed -i '3r '"$work/extra" "$work/tests/t.cpp"
expect "an 81-line test" 1 "tests/t.cpp:2: TEST(Suite,Table) is 81 lines (over 80)"

sed -i '4d' "$work/tests/t.cpp"
echo "// one more" >> "$work/app/editor/editor.cpp"
expect "a 351-line editor file" 1 "app/editor/editor.cpp: 351 lines (over 350"

sed -i '$d' "$work/app/editor/editor.cpp"
expect "no ctags" 1 "install Debian's universal-ctags" VDFX_CTAGS=/nonexistent/ctags

rm -rf "$work"
if [ "$failures" -gt 0 ]; then
  echo "function length check: $failures cases not as expected" >&2
  exit 1
fi
echo "function length check: 5 cases as expected"
