#!/usr/bin/env bash
# End-to-end: `shadowlab hardcases` (issue 14, the suite). One cheap case writes its table, JSON and pictures; bad
# --case values are refused with a message before any work. The whole quick suite is the ctest hardcases_quick.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

expect_ok case12 "$SHADOWLAB" hardcases --quick --case 12 --json pics/c12.json --out-dir pics
grep -q "case 12  casters behind the light's near plane" case12.out && pass "table names the case" \
  || fail "no case 12 header: $(head -3 case12.out)"
grep -q "^    pass    leak, depth clamp on" case12.out && pass "a passing row" || fail "rows: $(cat case12.out)"
grep -q "1 cases, .* 0 failed" case12.out && pass "summary" || fail "summary: $(tail -2 case12.out)"
python3 -c "import json; d=json.load(open('pics/c12.json')); assert d['passed'] and d['cases'][0]['case']==12 and d['cases'][0]['rows']" \
  && pass "JSON" || fail "JSON: $(head -c 300 pics/c12.json)"
for p in case12-depth-clamp-on.png case12-depth-clamp-off.png; do
  [ -s "pics/$p" ] && pass "picture $p" || fail "no picture $p: $(ls pics)"
done
! grep -q "case  1 " case12.out && pass "--case filters" || fail "other cases ran"

expect_error case99 "--case 99: no such case (the suite has cases 1..20" "$SHADOWLAB" hardcases --case 99
"$SHADOWLAB" hardcases --case 99 >/dev/null 2>&1; [ $? -eq 2 ] && pass "bad --case exits 2" || fail "bad --case exit code"
expect_error case-word "case" "$SHADOWLAB" hardcases --case twelve
expect_error json-folder "folder 'nowhere' does not exist" "$SHADOWLAB" hardcases --case 12 --json nowhere/x.json
finish
