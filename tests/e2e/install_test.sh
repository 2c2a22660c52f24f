#!/usr/bin/env bash
# End-to-end: `cmake --install` into a prefix, the prefix moved elsewhere, and the moved shadowlab run with the source
# and build trees hidden (hidden_tree_lib.sh): info names the moved prefix's data folder, render and measure load
# shipped presets by name, and the editor (Xvfb) starts on one and lists them all. The binary's read-only data holds
# no path into either tree, so nothing there can be what it reads.
# Needs: SOURCE_DIR, BUILD_DIR, OUT_DIR, CMAKE (the cmake that configured BUILD_DIR).
set -uo pipefail
: "${SOURCE_DIR:?}" "${BUILD_DIR:?}" "${OUT_DIR:?}" "${CMAKE:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
. "$SOURCE_DIR/tests/e2e/e2e_lib.sh"
. "$SOURCE_DIR/tests/e2e/hidden_tree_lib.sh"
presets=$(cd "$SOURCE_DIR/presets" && ls *.json)

"$CMAKE" --install "$BUILD_DIR" --prefix "$OUT_DIR/stage" >install.out 2>&1 || { cat install.out; fail "cmake --install"; finish; exit; }
[ -x stage/bin/shadowlab ] && pass "installed bin/shadowlab" || fail "no stage/bin/shadowlab: $(cat install.out)"
installed=$(cd stage/share/shadowlab/presets 2>/dev/null && ls *.json)
[ "$installed" = "$presets" ] && pass "installed share/shadowlab/presets: every shipped preset" \
  || fail "share/shadowlab/presets has [$installed], presets/ has [$presets]"

# Moved out of the build tree (and so out of the source tree, where the build folder usually is).
work=$(cd "$(mktemp -d "${TMPDIR:-/tmp}/shadowlab-moved.XXXXXX")" && pwd -P)  # as /proc/self/exe will name it
out=$OUT_DIR
# The logs come back to OUT_DIR; the moved prefix goes.
keep_logs() { cp "$work"/*.out "$work"/*.err "$work"/*.json "$out" 2>/dev/null; rm -rf "$work"; }
trap keep_logs EXIT
case "$work/" in "$SOURCE_DIR"/*|"$BUILD_DIR"/*) fail "the temporary folder $work is inside the trees"; finish; exit;; esac
mv stage "$work/prefix"
bin="$work/prefix/bin/shadowlab"

# No path into the trees among the binary's constants: the lookup can only be relative to the binary.
objcopy -O binary --only-section=.rodata "$bin" rodata.bin
for tree in "$SOURCE_DIR" "$BUILD_DIR"; do
  if grep -qaF "$tree" rodata.bin; then fail "the installed binary's .rodata holds $tree: $(grep -aoF "$tree" rodata.bin | head -1)"
  else pass "no path into $tree in the binary's .rodata"; fi
done

hide_trees "$SOURCE_DIR" "$BUILD_DIR"
[ -z "$hidden_note" ] && pass "source and build trees hidden from the moved binary" || echo "note: $hidden_note"
cd "$work"  # the commands' files go here: OUT_DIR is inside the hidden build tree
expect_ok info hidden "$bin" info
grep -qxF "shipped data: $work/prefix/share/shadowlab" info.out && pass "info: the moved prefix's data folder" \
  || fail "info does not name $work/prefix/share/shadowlab: $(cat info.out info.err)"
expect_ok render hidden "$bin" render --scene builtin:grazing --preset default --width 64 --height 48 --out render.png
[ "$(png_size render.png 2>/dev/null)" = "64 48" ] && pass "render --preset default wrote a 64x48 PNG" || fail "render.png"
expect_ok measure hidden "$bin" measure --scene builtin:grazing --preset acne --width 64 --height 48 --json measure.json
python3 -c "import json,sys; m=json.load(open('measure.json')); sys.exit(not (m['whole']['acnePercent'] > 0))" 2>measure.py.err \
  && pass "measure --preset acne: acne measured" || fail "measure.json: $(cat measure.py.err)"

# The editor, from the moved prefix and hidden, on a shipped preset by name; its list is the moved prefix's presets.
hidden_wrapper shadowlab-hidden "$bin"
SHADOWLAB="$work/shadowlab-hidden" OUT_DIR="$work"
. "$SOURCE_DIR/tests/e2e/editor_lib.sh"
trap 'cleanup; keep_logs' EXIT  # editor_lib.sh's trap, and ours
start_editor 1024 640 --scene builtin:grazing --preset acne
# The first frame compiles the shaders: on a loaded 2-core machine that can take a minute.
WAIT_TRIES=1200 wait_for has_control tab:Scene && click tab:Scene || fail "no Scene tab: $(tail -3 editor.err)"
WAIT_TRIES=100 wait_for has_control "preset.shipped=${presets%%.json*}"  # the list, drawn once, has them all
missing=""
for p in $presets; do has_control "preset.shipped=${p%.json}" || missing+=" ${p%.json}"; done
[ -z "$missing" ] && pass "the editor lists every shipped preset" || fail "the editor's list lacks:$missing ($(cat editor.err))"
if grep -q "not loaded\|no shipped data" editor.err; then fail "editor: $(cat editor.err)"; else pass "the editor loaded preset acne"; fi
xdotool key ctrl+q
for _ in $(seq 100); do kill -0 "$app_pid" 2>/dev/null || break; sleep 0.1; done
wait "$app_pid"; rc=$?; app_pid=""
[ $rc -eq 0 ] && pass "Ctrl+Q: exit 0" || fail "the editor exited $rc: $(tail -3 editor.err)"
finish
