#!/usr/bin/env bash
# The unity check (cmake/unity_check.cmake, scripts/unity-syntax-check) on a two-file fixture: a file-local name both
# files define fails the check, and the message names both files with their lines; the second file compiled on its
# own (SKIP_UNITY_BUILD_INCLUSION) passes. Needs CMAKE (the cmake binary), GENERATOR, CXX and OUT_DIR.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="$OUT_DIR/build"
rm -rf "$OUT_DIR"
mkdir -p "$OUT_DIR"
fail() { echo "unity_check_test: $*"; exit 1; }
"$CMAKE" -S "$here" -B "$build" -G "$GENERATOR" -DCMAKE_CXX_COMPILER="$CXX" -DSECOND_ALONE=OFF >"$OUT_DIR/configure.log" ||
  { cat "$OUT_DIR/configure.log"; fail "the fixture does not configure"; }
if "$CMAKE" --build "$build" --target unity_check >"$OUT_DIR/clash.log" 2>&1; then
  cat "$OUT_DIR/clash.log"
  fail "kSide, defined by both files of one unity source, passed the check"
fi
cat "$OUT_DIR/clash.log"
grep -q "unity check: areas's unity source 0 does not compile" "$OUT_DIR/clash.log" || fail "no line naming the target"
grep -Eq "clash between (second_area.cpp:3 and first_area.cpp:3|first_area.cpp:3 and second_area.cpp:3): .*kSide" \
  "$OUT_DIR/clash.log" || fail "the clash's two files and lines are not named (clash.log above)"
"$CMAKE" -S "$here" -B "$build" -DSECOND_ALONE=ON >"$OUT_DIR/configure-alone.log"
"$CMAKE" --build "$build" --target unity_check >"$OUT_DIR/alone.log" 2>&1 ||
  { cat "$OUT_DIR/alone.log"; fail "second_area.cpp compiled on its own still fails the check"; }
echo "unity_check_test: the clash is found and named; compiled on its own, the file passes"
