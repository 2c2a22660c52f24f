#!/usr/bin/env bash
# End-to-end: `shadowlab check` (issue 23, the CI gate). A case that passes (exit 0, PASS line), one whose limit is
# below the measured figure (exit 1, FAIL line naming the light and the limit), several lights (the line says which
# light broke which limit), bad case files and flags (exit 2, the message names the file, the case and the key), the
# JUnit file parsed as XML, and the project's own check file failing when every case's bias is zeroed.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

# expect_exit NAME CODE CMD...: exit status CODE (stdout and stderr kept in NAME.out / NAME.err)
expect_exit() {
  local name=$1 code=$2; shift 2
  "$@" >"$name.out" 2>"$name.err"
  local rc=$?
  [ $rc -eq "$code" ] && pass "$name exits $code" || fail "$name: exit $rc, not $code: $(cat "$name.err") $(cat "$name.out")"
}
view=(--width 320 --height 180)

# Pass: textbook with the default preset has acne 0.014 % at 320x180.
expect_exit pass 0 "$SHADOWLAB" check --scene builtin:textbook --preset default "${view[@]}" --max-acne 0.1 --max-wrong 1
grep -q '^PASS case 1/1 "builtin:textbook default" .*lights.0 (directional): acne 0.0[0-9]* % (limit 0.100 %)' pass.out \
  && pass "PASS line with the figure beside its limit" || fail "pass line: $(cat pass.out)"

# Fail: the same case with a wrong-pixels limit below what is measured (the default preset has no acne here).
expect_exit fail 1 "$SHADOWLAB" check --scene builtin:textbook --preset default "${view[@]}" --max-acne 1 --max-wrong 0.001
grep -q '^FAIL case 1/1 .*lights.0 (directional): acne 0.0[0-9]* % (limit 1.000 %), wrong pixels 0.0[0-9]* % (limit 0.001 %: BROKEN)$' \
  fail.out && pass "FAIL line names the broken limit, the other still judged" || fail "fail line: $(cat fail.out)"

# Several lights: courtyard's spot on the hall has acne 0.013 % at 480x270, the others none.
expect_exit lights 1 "$SHADOWLAB" check --scene builtin:courtyard --preset courtyard --width 480 --height 270 --max-acne 0.005
grep -q 'lights.1 (spot): acne 0.01[0-9] % (limit 0.005 %: BROKEN)' lights.out && pass "the broken light is named" \
  || fail "lights line: $(cat lights.out)"
grep -q 'lights.0 (directional): acne 0.000 % (limit 0.005 %);' lights.out && grep -q 'lights.3 (point): acne' lights.out \
  && grep -q 'whole picture: acne 0.00[0-9] % (limit 0.005 %)$' lights.out \
  && pass "every light and the whole picture are judged" || fail "lights line: $(cat lights.out)"

# The JUnit file: a case file with a passing and a failing case whose names need escaping.
cat >cases.json <<'EOF'
{"cases": [
  {"name": "textbook <default> & \"quoted\"", "scene": "builtin:textbook", "preset": "default",
   "width": 320, "height": 180, "maxAcnePercent": 0.1, "maxEdgePixels": 10},
  {"name": "zero bias", "scene": "builtin:textbook", "preset": "default",
   "set": {"shadow.depthBias": 0, "shadow.slopeScaledDepthBias": 0, "shadow.normalOffset": 0},
   "width": 320, "height": 180, "maxAcnePercent": 0.1}
]}
EOF
mkdir -p report
expect_exit junit 1 "$SHADOWLAB" check cases.json --junit report/check.xml
python3 - <<'EOF' && pass "JUnit XML: suite counts, escaped names, failure message, figures, overlay PNGs" || fail "JUnit: $(head -c 2000 report/check.xml)"
import os, struct, xml.etree.ElementTree as ET
root = ET.parse("report/check.xml").getroot()
suite = root.find("testsuite")
assert suite.get("tests") == "2" and suite.get("failures") == "1" and suite.get("errors") == "0", suite.attrib
cases = suite.findall("testcase")
assert [c.get("name") for c in cases] == ['textbook <default> & "quoted"', "zero bias"], [c.get("name") for c in cases]
assert cases[0].find("failure") is None
failure = cases[1].find("failure")
assert failure is not None and "lights.0 (directional): acne" in failure.get("message") and "BROKEN" in failure.get("message")
for case in cases:
    props = {p.get("name"): p.get("value") for p in case.iter("property")}
    acne = float(props["lights.0 (directional) acne (%)"])
    assert float(props["lights.0 (directional) acne (%) limit"]) == 0.1
    assert (acne > 0.1) == (case.get("name") == "zero bias"), acne
    png = props["overlay"]
    assert png.startswith("report/check-overlays/") and os.path.isfile(png), png
    with open(png, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", head[16:24]) == (320, 180)
    assert png in case.find("system-out").text
EOF
grep -q '^check: 2 cases, 1 passed, 1 failed, 0 not measured' junit.out && pass "summary line" || fail "summary: $(cat junit.out)"

# Bad case files: exit 2 before any work, naming the file, the case (index and name) and the key.
bad() {  # bad NAME PATTERN JSON
  printf '%s\n' "$3" >"$1.json"
  expect_exit "$1" 2 "$SHADOWLAB" check "$1.json"
  grep -qF -- "$2" "$1.err" && pass "$1: message" || fail "$1: '$2' not in: $(cat "$1.err")"
}
ok='"scene": "builtin:textbook", "maxAcnePercent": 0.1'
bad unknown-key "unknown-key.json: case 2 (\"b\"): unknown key 'maxAcne' (a case has" \
  "{\"cases\": [{\"name\": \"a\", $ok}, {\"name\": \"b\", \"scene\": \"builtin:textbook\", \"maxAcne\": 0.1}]}"
bad wrong-type "wrong-type.json: case 1 (\"a\"): width: expected a whole number, got \"wide\"" \
  "{\"cases\": [{\"name\": \"a\", $ok, \"width\": \"wide\"}]}"
bad no-scene "no-scene.json: case 1 (\"a\"): scene: missing" '{"cases": [{"name": "a", "maxAcnePercent": 0.1}]}'
bad negative "negative.json: case 1 (\"a\"): maxLeakPercent: -1 is negative" \
  "{\"cases\": [{\"name\": \"a\", $ok, \"maxLeakPercent\": -1}]}"
bad nan "nan.json: case 1 (\"a\"): maxWrongPercent: expected a number, got string" \
  "{\"cases\": [{\"name\": \"a\", $ok, \"maxWrongPercent\": \"nan\"}]}"
bad no-limit "no-limit.json: case 1 (\"a\"): limits: no limit given" '{"cases": [{"name": "a", "scene": "builtin:textbook"}]}'
bad same-name "same-name.json: case 2 (\"a\"): name: \"a\" is used by an earlier case" \
  "{\"cases\": [{\"name\": \"a\", $ok}, {\"name\": \"a\", $ok}]}"
bad syntax "syntax.json:1:" '{"cases": [}'
bad set-key "set-key.json: case 1 (\"a\"): set shadow.depthBais=0: unknown setting 'shadow.depthBais'" \
  "{\"cases\": [{\"name\": \"a\", $ok, \"set\": [\"shadow.depthBais=0\"]}]}"
bad flicker-keys "flicker-keys.json: case 1 (\"a\"): step: describes how flicker is measured, but the case has no maxFlickerPercent" \
  "{\"cases\": [{\"name\": \"a\", $ok, \"step\": 0.1}]}"
expect_exit missing-file 2 "$SHADOWLAB" check nowhere.json
grep -q "nowhere.json: no such file" missing-file.err && pass "missing file named" || fail "missing file: $(cat missing-file.err)"
expect_exit flag-nan 2 "$SHADOWLAB" check --scene builtin:textbook --max-acne nan
grep -q -- "--max-acne nan: not a finite number" flag-nan.err && pass "flag NaN named" || fail "flag NaN: $(cat flag-nan.err)"
expect_exit flag-none 2 "$SHADOWLAB" check --scene builtin:textbook
grep -q "no limit given" flag-none.err && pass "no limit refused" || fail "no limit: $(cat flag-none.err)"
expect_exit file-and-flags 2 "$SHADOWLAB" check cases.json --max-acne 1
grep -q -- "--max-acne: a case file lists its own cases" file-and-flags.err && pass "file and flags refused" \
  || fail "file and flags: $(cat file-and-flags.err)"
# A case that cannot be measured is an error of the gate (2), not a broken limit (1).
expect_exit no-scene-file 2 "$SHADOWLAB" check --scene missing.glb --max-acne 1
grep -q '^ERROR case 1/1 .*missing.glb: scene file not found' no-scene-file.out && pass "ERROR line" \
  || fail "error line: $(cat no-scene-file.out)"

# The project's own check file passes as the CI runs it, and fails when every case's bias is zeroed.
builtin="$SOURCE_DIR/tests/checks/builtin.json"
python3 - "$builtin" <<'EOF'
import json, sys
cases = json.load(open(sys.argv[1]))
for case in cases["cases"]:
    case["set"] = {"shadow.depthBias": 0, "shadow.slopeScaledDepthBias": 0, "shadow.normalOffset": 0}
json.dump(cases, open("zero-bias.json", "w"), indent=1)
EOF
expect_exit zero-bias 1 "$SHADOWLAB" check zero-bias.json
cases=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['cases']))" "$builtin")
[ "$(grep -c '^FAIL case .*acne [0-9.]* % (limit [0-9.]* %: BROKEN)' zero-bias.out)" -eq "$cases" ] \
  && pass "zero bias breaks the acne limit of all $cases cases" || fail "zero bias: $(cat zero-bias.out)"
finish
