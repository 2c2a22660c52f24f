#!/usr/bin/env bash
# End-to-end: the real editor in Xvfb (1280x720) on builtin:textbook with the default preset. xdotool clicks pixels
# of the viewport (under the floating box's shadow, on the cube, on the lit floor); the Probe panel's "Save JSON"
# writes what the panel shows, and `shadowlab probe` for the same view size and pixel must say the same: the same
# texel, receiver depth and shadow factor (CPU and GPU). One of the pixels is shadowed and one lit.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
. "$SOURCE_DIR/tests/e2e/e2e_lib.sh"
. "$SOURCE_DIR/tests/e2e/editor_lib.sh"
json() { python3 -c "import json,sys; d=json.load(open('$1')); print(eval(sys.argv[1]))" "$2"; }

start_editor 1280 720 --scene builtin:textbook --preset default --screenshot-dir shots
WAIT_TRIES=1200 wait_for has_control viewport.image && WAIT_TRIES=1200 wait_for grep -q "loaded builtin:textbook" editor.out \
  || { echo "FAIL: the editor showed no scene: $(tail -3 editor.err)"; exit 1; }

# probe_at FX FY: click the view at that fraction of its size, save the probe, compare with the CLI's.
shadowed=0 lit=0
probe_at() {
  local vx vy vw vh
  read -r vx vy vw vh <<<"$(control_rect viewport.image)"
  local x=$((vx + vw * $1 / 100)) y=$((vy + vh * $2 / 100))
  move_mouse "$x" "$y" && press_button
  wait_for has_control probe.saveJson || { fail "no probe after a click at $x,$y"; return; }
  # The panel may still show the previous pixel for a frame: save until the file holds this click's pixel.
  local file="" want="[$((x - vx)), $((y - vy))]"
  for _ in $(seq 20); do
    local before; before=$(ls shots/shadowlab-probe-*.json 2>/dev/null | wc -l)
    click probe.saveJson
    wait_for bash -c "[ \$(ls shots/shadowlab-probe-*.json 2>/dev/null | wc -l) -gt $before ]" || break
    file=$(ls -t shots/shadowlab-probe-*.json | head -1)
    # xdotool's pixel is the editor's up to the view's sub-pixel origin: accept the probe's own pixel if it is
    # within one of the click.
    if [ "$(json "$file" "abs(d['pixel'][0]-$((x - vx)))<=1 and abs(d['pixel'][1]-$((y - vy)))<=1")" = True ]; then break; fi
    file=""
  done
  [ -n "$file" ] || { fail "the saved probe never showed pixel ~$want"; return; }
  grep -q "probe: $OUT_DIR/shots\|probe: shots" editor.out && pass "the status line says where the probe went" \
    || fail "no path message for the probe: $(tail -2 editor.out)"
  local px py w h
  px=$(json "$file" "d['pixel'][0]"); py=$(json "$file" "d['pixel'][1]")
  w=$(json "$file" "d['view'][0]"); h=$(json "$file" "d['view'][1]")
  [ "$(json "$file" "d['ok']")" = True ] || { fail "editor probe at $px,$py: $(json "$file" "d.get('error')")"; return; }
  expect_ok "cli-$px-$py" "$SHADOWLAB" probe --scene builtin:textbook --preset default --width "$w" --height "$h" \
    --pixel "$px,$py" --json "cli-$px-$py.json"
  python3 - "$file" "cli-$px-$py.json" <<'PY' && pass "pixel $px,$py: editor and CLI agree ($(json "$file" "d['texel']"), S $(json "$file" "d['shadow']['gpu']"))" || fail "pixel $px,$py: editor and CLI differ"
import json, sys
e, c = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
ok = True
def same(what, a, b, tol=0.0):
    global ok
    good = a == b if tol == 0.0 else abs(a - b) <= tol
    if not good: print(f"  {what}: editor {a}, CLI {b}"); ok = False
same("texel", e["texel"], c["texel"])
same("receiver depth", e["receiverDepth"], c["receiverDepth"], 1e-6)
same("S (CPU)", e["shadow"]["cpu"], c["shadow"]["cpu"], 1e-4)
same("S (GPU)", e["shadow"]["gpu"], c["shadow"]["gpu"], 1e-3)
same("taps", len(e["filter"]["taps"]), len(c["filter"]["taps"]))
same("mesh", e["surface"]["mesh"], c["surface"]["mesh"])
sys.exit(0 if ok else 1)
PY
  python3 -c "import sys; sys.exit(not $(json "$file" "d['shadow']['gpu']") < 0.5)" && shadowed=$((shadowed + 1)) || lit=$((lit + 1))
}

probe_at 49 45   # under the floating box: its shadow on the floor
probe_at 46 36   # the cube
probe_at 50 60   # the lit floor in front of the cube
[ $shadowed -ge 1 ] && pass "a shadowed pixel was compared" || fail "no clicked pixel was shadowed"
[ $lit -ge 1 ] && pass "a lit pixel was compared" || fail "no clicked pixel was lit"
cp "$(ls shots/shadowlab-probe-*.json | head -1)" first-probe.json 2>/dev/null

xdotool key ctrl+q
finish
