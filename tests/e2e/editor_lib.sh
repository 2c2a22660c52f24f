# Shared by the scripts that drive the real editor in a virtual X display (source it after e2e_lib.sh, in $OUT_DIR).
# start_editor W H ARGS... starts Xvfb (W x H) and `shadowlab edit --width W --height H ARGS...`, which writes its
# controls' rectangles to controls.json, with "input": the mouse position and the mouse-button and key events its
# newest frame has seen; sets $wid. control / has_control / click / move_mouse / send_keys / wait_for work on that
# file: each input helper waits until the editor has seen its input (no fixed sleeps).
# Xvfb and the editor are always killed on exit. Needs: SHADOWLAB, OUT_DIR.
for tool in Xvfb xdotool python3; do
  command -v $tool >/dev/null || { echo "FAIL: $tool is not installed (scripts/install-deps)"; exit 1; }
done

xvfb_pid="" app_pid="" wid=""
cleanup() {
  [ -n "$app_pid" ] && kill "$app_pid" 2>/dev/null
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
  wait 2>/dev/null
}
trap cleanup EXIT
trap "exit 1" TERM INT  # so the EXIT trap runs when the timeout stops us

start_editor() {
  local width=$1 height=$2
  shift 2
  # Xvfb picks a free display number and writes it to fd 3.
  Xvfb -displayfd 3 -screen 0 "${width}x${height}x24" -nolisten tcp 3>display.txt 2>xvfb.err &
  xvfb_pid=$!
  for _ in $(seq 100); do [ -s display.txt ] && break; sleep 0.1; done
  [ -s display.txt ] || { echo "FAIL: Xvfb did not start: $(cat xvfb.err)"; exit 1; }
  export DISPLAY=":$(cat display.txt)"
  export SHADOWLAB_CONFIG_DIR="$OUT_DIR/config" SHADOWLAB_USER_PRESETS="$OUT_DIR/user-presets"
  export SHADOWLAB_EDITOR_CONTROLS="$OUT_DIR/controls.json"
  "$SHADOWLAB" edit --width "$width" --height "$height" "$@" >editor.out 2>editor.err &
  app_pid=$!
  wid=$(timeout 30 xdotool search --sync --name "ShadowLab" | head -1)
  [ -n "$wid" ] || { echo "FAIL: no editor window: $(cat editor.err)"; exit 1; }
  xdotool windowfocus --sync "$wid" 2>/dev/null || xdotool windowfocus "$wid"
}

# control NAME -> "cx cy w h" (centre and size, window pixels) from the controls file; empty if not drawn.
control() {
  python3 - "$1" <<'PY' 2>/dev/null
import json, sys
r = json.load(open("controls.json")).get(sys.argv[1])
if r: print(int(r[0] + r[2] / 2), int(r[1] + r[3] / 2), int(r[2]), int(r[3]))
PY
}
# control_rect NAME -> "x y w h" (top-left corner and size).
control_rect() {
  python3 - "$1" <<'PY' 2>/dev/null
import json, sys
r = json.load(open("controls.json")).get(sys.argv[1])
if r: print(int(r[0]), int(r[1]), int(r[2]), int(r[3]))
PY
}
# wait_for CONDITION-COMMAND... (up to ~30 s; WAIT_TRIES=N for N tenths of a second)
wait_for() { for _ in $(seq "${WAIT_TRIES:-300}"); do "$@" && return 0; kill -0 "$app_pid" 2>/dev/null || return 1; sleep 0.1; done; return 1; }
has_control() { [ -f controls.json ] && [ -n "$(control "$1")" ]; }
# input_seen mouse|buttons|keys -> what the editor's newest frame has seen ("x y" or a count).
input_seen() {
  python3 - "$1" <<'PY' 2>/dev/null
import json, sys
v = json.load(open("controls.json"))["input"][sys.argv[1]]
print(*v) if isinstance(v, list) else print(v)
PY
}
mouse_seen_at() { [ "$(input_seen mouse)" = "$1 $2" ]; }
seen_at_least() { local n; n=$(input_seen "$1") && [ "$n" -ge "$2" ]; }
# move_mouse X Y (window pixels): until a frame has seen the pointer there.
move_mouse() {
  xdotool mousemove --window "$wid" "$1" "$2"
  wait_for mouse_seen_at "$1" "$2" || { fail "the editor never saw the pointer at $1,$2 (controls.json: $(input_seen mouse))"; return 1; }
}
# press_button: a left click where the pointer is, until the editor has seen its press and release.
press_button() {
  local before; before=$(input_seen buttons) || before=0
  xdotool click 1
  wait_for seen_at_least buttons $((before + 2)) || { fail "the editor never saw the click (buttons seen: $(input_seen buttons), wanted $((before + 2)))"; return 1; }
}
# send_keys COMBO...: xdotool key COMBO... (e.g. ctrl+s Return), until the editor has handled every press and release.
send_keys() {
  local before events=0 combo plus
  before=$(input_seen keys) || before=0
  for combo in "$@"; do plus=${combo//[^+]/}; events=$((events + 2 * (${#plus} + 1))); done
  xdotool key "$@"
  wait_for seen_at_least keys $((before + events)) || { fail "the editor never handled the keys $* (keys seen: $(input_seen keys), wanted $((before + events)))"; return 1; }
}
click() {
  local c; c=$(control "$1") || true
  [ -n "$c" ] || { fail "control $1 not drawn"; return 1; }
  set -- $c
  move_mouse "$1" "$2" && press_button
}
