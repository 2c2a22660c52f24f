#!/usr/bin/env bash
# End-to-end: `shadowlab sweep` (issue 11, "What accuracy costs"), headless. Two axes on builtin:textbook: the table
# on stdout (a row per point, the front marked, the bare draw per map size, the front in order of cost), progress on
# stderr, JSON / CSV / chart written; a bad axis key or value, or an unwritable output, is refused with exit 2 / 1
# and a message naming it before any work (no progress line, nothing written).
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
json() { python3 -c "import json,sys; d=json.load(open('$1')); print(eval(sys.argv[1]))" "$2"; }

view=(--scene builtin:textbook --preset default --width 160 --height 90 --frames 2)
expect_ok sweep "$SHADOWLAB" sweep "${view[@]}" --axis shadow.resolution=64,512 --axis filter.kind=point,pcf \
  --json s.json --csv s.csv --chart s.png --chart-width 640 --chart-height 400
rows=$(grep -cE '^(64|512) (point|pcf)' sweep.out)
[ "$rows" = "4" ] && pass "a table row per point" || fail "rows: $rows in $(cat sweep.out)"
grep -q "CPU (software rasterizer" sweep.out && pass "times labelled CPU on llvmpipe" || fail "no timing label"
grep -qE '^  64² D32F: bare draw [0-9.]+ ms' sweep.out && grep -qE '^  512² D32F: bare draw' sweep.out \
  && pass "a bare draw per map size" || fail "bare draws: $(grep bare sweep.out)"
grep -q "^Pareto front" sweep.out && pass "the front is listed" || fail "no front"
# CPU times of 2 frames are noisy: when the most accurate point also times cheapest the front holds one point and
# there is no step to describe.
front=$(sed -n '/^Pareto front/,/^reference/p' sweep.out | grep -c '^  [0-9]')
if [ "$front" -gt 1 ]; then
  [ "$(grep -c "step up +" sweep.out)" = "$((front - 1))" ] && pass "each step up says what it buys" \
    || fail "no step text for $front front points: $(cat sweep.out)"
else
  [ "$front" = 1 ] && pass "a front of one point (no step to describe)" || fail "empty front: $(cat sweep.out)"
fi
[ "$(grep -c '^\[[0-9]*/5\]' sweep.err)" = "5" ] && pass "progress on stderr (4 points + the preset)" \
  || fail "progress: $(cat sweep.err)"
[ "$(json s.json "len(d['points'])")" = "4" ] && pass "JSON: every point" || fail "JSON points"
[ "$(json s.json "all(k in d['points'][0] for k in ('shadowPassMs','mainPassMs','shadowMapBytes','bareDrawMs','shadowPassOverBareDraw','wrongPixelsPercent','meanError','acnePercent','leakPercent','edgeErrorP95World','edgeErrorP95ScreenPixels','paretoFront','settings'))")" = "True" ] \
  && pass "JSON: each point's numbers and settings" || fail "JSON keys: $(json s.json "list(d['points'][0])")"
[ "$(json s.json "d['points'][0]['wrongPixelsPercent'] > d['points'][2]['wrongPixelsPercent']")" = "True" ] \
  && pass "JSON: 512² point sampling has fewer wrong pixels than 64²" || fail "error vs resolution"
[ "$(json s.json "sum(p['paretoFront'] for p in d['points']) == len(d['paretoFront'])")" = "True" ] \
  && pass "JSON: the front is marked" || fail "front marks"
[ "$(wc -l < s.csv)" = "6" ] && pass "CSV: header, 4 points, the preset" || fail "CSV lines $(wc -l < s.csv)"
head -1 s.csv | grep -q "wrongPixelsPercent,.*shadow.resolution" && pass "CSV: numbers and every key" \
  || fail "CSV header $(head -1 s.csv)"
[ "$(png_size s.png)" = "640 400" ] && pass "chart is 640x400" || fail "chart size $(png_size s.png)"
read -r w h colours bright dark < <(python3 "$SOURCE_DIR/tests/e2e/png_check.py" s.png)
# White page, ink, grid, the points' blue, the front's red, the preset's green ring (and their blends).
[ "${colours:-0}" -ge 6 ] && pass "chart is not blank ($colours colours)" || fail "chart colours: ${colours:-none}"

# Refused before any work: no "sweep:" progress line and nothing written.
refuse() {
  local name=$1 pattern=$2 code=$3; shift 3
  "$SHADOWLAB" sweep "${view[@]}" "$@" --json bad.json >"$name.out" 2>"$name.err"
  local rc=$?
  if [ $rc -ne "$code" ]; then fail "$name: exit $rc, expected $code: $(cat "$name.err")"; return; fi
  grep -q -- "$pattern" "$name.err" || { fail "$name: '$pattern' not in: $(cat "$name.err")"; return; }
  grep -q "^sweep:" "$name.err" && { fail "$name: work started"; return; }
  pass "$name (exit $rc)"
}
refuse bad-key "shadow.resolutoin" 2 --axis shadow.resolutoin=512,1024
refuse bad-key-suggests "did you mean shadow.resolution" 2 --axis shadow.resolutoin=512,1024
refuse bad-value "filter.kind" 2 --axis filter.kind=point,gaussian
refuse bad-range "shadow.resolution" 2 --axis shadow.resolution=512,4
refuse bad-second-axis "filter.kernel" 2 --axis shadow.resolution=512 --axis filter.kernel=1,4
refuse joint-axis-parts "needs 2 parts separated by ':'" 2 --axis filter.kind,filter.kernel=pcf:3,pcf
refuse same-axis-twice "already an axis" 2 --axis filter.kind=pcf --axis filter.kind=point
refuse bad-set "shadow.depthBias" 2 --set shadow.depthBias=abc --axis filter.kind=pcf
refuse no-folder "--csv" 1 --axis filter.kind=pcf --csv missing/dir/s.csv
expect_error no-axis "axis" "$SHADOWLAB" sweep "${view[@]}"
[ ! -e bad.json ] && pass "nothing written on a refusal" || fail "bad.json written"
finish
