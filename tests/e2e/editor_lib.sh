# Shared by the scripts that drive the real editor in a virtual X display (source it after e2e_lib.sh, in $OUT_DIR).
# start_editor W H ARGS... starts Xvfb (W x H) and `shadowlab edit --width W --height H ARGS...`, which writes its
# controls' rectangles to controls.json; sets $wid. control / has_control / click / wait_for work on that file.
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
click() {
  local c; c=$(control "$1") || true
  [ -n "$c" ] || { fail "control $1 not drawn"; return 1; }
  set -- $c
  xdotool mousemove --window "$wid" "$1" "$2" sleep 0.15 click 1 sleep 0.2
}
