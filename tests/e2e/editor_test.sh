#!/usr/bin/env bash
# End-to-end: the real `shadowlab edit` in a virtual X display (Xvfb) with real X input from xdotool. The editor
# writes its controls' rectangles to $SHADOWLAB_EDITOR_CONTROLS so clicks land on real widgets. Checks: F12 writes a
# PNG of the viewport's size that decodes and is not blank; a click on "1K", Ctrl+S and Enter save a preset that
# `render` loads and that equals the state; a bad scene path leaves the editor running with a message; Ctrl+F12
# writes the whole window; Ctrl+Q quits cleanly. Xvfb and the editor are always killed on exit.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
. "$SOURCE_DIR/tests/e2e/e2e_lib.sh"
png_check() { python3 "$SOURCE_DIR/tests/e2e/png_check.py" "$1"; }

# Without a display: a clear message and a non-zero exit.
env -u DISPLAY -u WAYLAND_DISPLAY "$SHADOWLAB" edit >nodisplay.out 2>&1
rc=$?
if [ $rc -ne 0 ] && grep -q "needs a display" nodisplay.out; then pass "no display: exit $rc with a message"
else fail "no display: exit $rc: $(cat nodisplay.out)"; fi

. "$SOURCE_DIR/tests/e2e/editor_lib.sh"
start_editor 1600 900 --scene builtin:textbook --screenshot-dir shots
# The panels live in the sidebars' tabs: Stats shows once its tab is clicked. The first frame compiles shaders and
# loads the scene: on a loaded 2-core machine that can take over 30 s, so these two waits allow 2 minutes.
WAIT_TRIES=1200 wait_for has_control tab:Stats && click tab:Stats
WAIT_TRIES=1200 wait_for has_control stats.frames && pass "editor window up, a frame rendered" || fail "no frame: $(cat editor.err)"
move_mouse 800 450

# F12: the viewport as PNG (the editor says where once it is written).
send_keys F12
wait_for grep -q "^shadowlab: screenshot: " editor.out
shot=$(ls shots/shadowlab-*.png 2>/dev/null | head -1)
if [ -z "$shot" ]; then fail "F12 wrote no screenshot: $(tail -3 editor.err)"; else
  read -r _ _ vw vh <<<"$(control viewport.image)"
  if info=$(png_check "$shot"); then
    read -r w h colours bright dark <<<"$info"
    [ "$w $h" = "$vw $vh" ] && pass "F12 screenshot is the viewport's size ($w x $h)" || fail "screenshot $w x $h, viewport $vw x $vh"
    [ "$colours" -gt 20 ] && python3 -c "import sys; sys.exit(not ($bright > 0.05 and $dark > 0.01))" \
      && pass "screenshot is not blank ($colours colours, lit $bright, dark $dark)" || fail "screenshot looks blank: $info"
  else fail "$info"; fi
  grep -q "screenshot: $shot" editor.out && pass "the editor says where the screenshot went" || fail "no path message"
fi

# "1K", then Ctrl+S on the shipped default preset: Save As opens with "default-tuned"; Enter saves it.
click "tab:Shadow map" && wait_for has_control shadow.resolution=1K
click shadow.resolution=1K
send_keys ctrl+s
wait_for has_control saveAs.name && pass "Ctrl+S on a shipped preset asks for a name" || fail "no Save As dialog"
send_keys Return
saved="$OUT_DIR/user-presets/default-tuned.json"
if wait_for test -f "$saved"; then
  pass "preset saved to the user folder"
  "$SHADOWLAB" render --scene builtin:textbook --preset "$saved" --width 64 --height 48 --out loaded.png \
    >render.out 2>render.err && pass "render loads the saved preset" || fail "render refuses it: $(cat render.err)"
  python3 - "$saved" "$SOURCE_DIR/presets/default.json" <<'PY' && pass "saved preset = default with resolution 1024" || fail "saved preset differs"
import json, sys
saved, shipped = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
for meta in ("name", "description"): saved.pop(meta, None); shipped.pop(meta, None)
# The shipped preset is schema 1 (one light); the editor saves schema 2: the same values, as light 0.
light = shipped.pop("light")
ambient, scene_lights = light.pop("ambient"), light.pop("useSceneLight")
light.update(range=0.0, color=[1.0, 1.0, 1.0], enabled=True, castsShadows=True,
             shadow=shipped.pop("shadow"), projection=shipped.pop("projection"))
shipped.update(schemaVersion=2, ambient=ambient, useSceneLights=scene_lights, lights=[light])
shipped["lights"][0]["shadow"]["resolution"] = 1024
shipped["lights"][0]["shadow"].update(update="onChange", updateInterval=4)
# Keys newer than the schema-1 file, at their defaults: the editor saves every key.
shipped["camera"]["sceneCamera"] = -1
shipped["casters"] = {"excluded": [], "static": [], "dynamic": []}
shipped["animation"] = {"play": "all", "time": 0.0}
shipped["reference"] = {"softRays": 256}
light["size"] = 0.0
shipped["filter"].update(momentBits=32, blurWidth=5.0, blurUnit="texels", momentMips=False, minVariance=1e-06, bleedReduction=0.2,
                         positiveExponent=40.0, negativeExponent=5.0, momentBias=3e-05, blockerSearchTexels=16.0,
                         penumbraMaxTexels=16.0)
light["projection"].update(fit="scene", cascadeCount=4, splitLambda=0.75, splits=[0.0, 0.0, 0.0],
                           shadowDistance=0.0, blendBand=0.1, cascadeFit="stable", depthBounds="off")
# The save records the scene and the camera as shown; nobody moved it, so it stays auto-framed.
if saved.pop("scene", None) != "builtin:textbook": print("no scene recorded"); sys.exit(1)
for key in ("position", "target"): saved["camera"].pop(key); shipped["camera"].pop(key)
if saved != shipped:
    print("saved:  ", json.dumps(saved, sort_keys=True)); print("expected:", json.dumps(shipped, sort_keys=True)); sys.exit(1)
PY
else fail "no preset at $saved: $(tail -3 editor.err)"; fi

# A bad scene path: a message, the editor keeps running on its scene.
click tab:Scene && wait_for has_control scene.path
click scene.path
send_keys ctrl+a
# Typed at full speed: printable keys reach a text field without a frame each, and every character arrives in order.
xdotool type --delay 0 "/nonexistent/Missing_Scene-2 (copy).gltf"
xdotool key Return
if wait_for grep -qF "/nonexistent/Missing_Scene-2 (copy).gltf: " editor.err; then
  # Still drawing frames after the message: it sees the pointer move.
  move_mouse 790 440 && kill -0 "$app_pid" 2>/dev/null && pass "bad scene path: message, editor still running" || fail "editor died"
else fail "no message for a bad scene path: $(tail -3 editor.err)"; fi

# Measure in the Accuracy panel: the worker's numbers arrive while the window keeps running.
click tab:Accuracy && wait_for has_control accuracy.measure
click accuracy.measure
if wait_for grep -q "accuracy of light [0-9]*: acne" editor.out; then
  pass "Accuracy: Measure printed $(grep -m1 -o 'acne [0-9.]* %' editor.out)"
else fail "no accuracy numbers: $(tail -3 editor.err)"; fi

# Ctrl+F12: the whole window (the editor says where once it is written).
move_mouse 800 450
send_keys ctrl+F12
wait_for grep -q "^shadowlab: window screenshot: " editor.out
window_shot=$(ls shots/shadowlab-window-*.png 2>/dev/null | head -1)
if [ -n "$window_shot" ] && info=$(png_check "$window_shot"); then
  read -r w h _ <<<"$info"
  [ "$w $h" = "1600 900" ] && pass "Ctrl+F12 wrote the whole window" || fail "window shot is $w x $h"
  cp "$window_shot" editor-window.png
else fail "no whole-window screenshot"; fi

# Ctrl+Q: quits (no unsaved changes after the save) and remembers the layout.
xdotool key ctrl+q
for _ in $(seq 100); do kill -0 "$app_pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$app_pid" 2>/dev/null; then fail "Ctrl+Q did not quit"; else
  wait "$app_pid"; rc=$?; app_pid=""
  [ $rc -eq 0 ] && pass "Ctrl+Q quits with exit 0" || fail "exit $rc"
  [ -f config/imgui.ini ] && pass "panel layout saved in imgui.ini" || fail "no imgui.ini"
fi

finish
