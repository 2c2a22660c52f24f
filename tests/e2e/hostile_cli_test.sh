#!/usr/bin/env bash
# End-to-end, issue 12: hostile command lines and output paths. The binary must refuse cleanly (a message naming the
# option or key and the cause, exit 1/2, never a signal) and never replace or cut a file that is not its own.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
small=(--width 64 --height 48)

# 2: a --set value that is not UTF-8, a scene path that is not UTF-8 written into --json.
expect_error set-not-utf8 "view: unknown value" "$SHADOWLAB" render --set $'view=\xff' "${small[@]}" --out v.png
mkdir -p $'scene\xff' && cp "$SOURCE_DIR"/../shared/scenes/Lantern_geometry/Lantern.* $'scene\xff'/ 2>/dev/null
if [ -f $'scene\xff/Lantern.gltf' ]; then
  expect_ok measure-not-utf8 "$SHADOWLAB" measure --scene $'scene\xff/Lantern.gltf' "${small[@]}" --json m.json
  python3 -c 'import json,sys; json.load(open("m.json"))' && pass "measure --json is valid JSON" || fail "m.json"
fi

# 1: 10,000 levels through --set.
deep=$(printf '%.0s[' {1..10000})$(printf '%.0s]' {1..10000})
expect_error set-deep "light.direction: the value nests deeper than 64 levels" \
  "$SHADOWLAB" render --set "light.direction=$deep" "${small[@]}" --out v.png

# 5: a FIFO as the preset or the scene: refused at once, not a hang.
mkfifo pipe pipe.gltf
expect_error preset-fifo "pipe: is a FIFO (named pipe), not a regular file" \
  timeout 20 "$SHADOWLAB" render --preset ./pipe "${small[@]}" --out v.png
expect_error scene-fifo "pipe.gltf: is a FIFO (named pipe), not a regular file" \
  timeout 20 "$SHADOWLAB" render --scene ./pipe.gltf "${small[@]}" --out v.png

# 6: a view too large to measure is refused with the figure, before any allocation (when memory is under 64 GiB).
avail_kb=$(awk '/MemAvailable/ {print $2}' /proc/meminfo)
if [ "$avail_kb" -lt $((64 * 1024 * 1024)) ]; then
  expect_error measure-huge "a measurement needs about 50.0 GiB of memory (200 bytes a pixel)" \
    "$SHADOWLAB" measure --scene builtin:textbook --width 16384 --height 16384
fi

# 7: outputs that are not regular files are refused before the work and left as they were.
expect_error tune-dev-null "--out /dev/null: it is a character device, not a regular file" \
  "$SHADOWLAB" tune --scene builtin:textbook "${small[@]}" --out /dev/null
[ -c /dev/null ] && pass "/dev/null is still a device" || fail "/dev/null was replaced"
expect_error render-fifo "--out pipe: it is a FIFO" "$SHADOWLAB" render "${small[@]}" --out pipe
[ -p pipe ] && pass "the FIFO is still a FIFO" || fail "the FIFO was replaced"
ln -s nowhere.json dangling.json
expect_error bench-dangling "a symbolic link to 'nowhere.json', which does not exist" \
  "$SHADOWLAB" bench --scene builtin:textbook "${small[@]}" --frames 1 --resolutions 256 --filters point \
  --json dangling.json
[ ! -e nowhere.json ] && pass "the dangling link's target was not created" || fail "nowhere.json created"
expect_error bench-no-folder "--json missing/b.json: folder 'missing' does not exist" \
  "$SHADOWLAB" bench --scene builtin:textbook "${small[@]}" --frames 1 --json missing/b.json
grep -q "bench:" bench-no-folder.out && fail "bench ran before checking --json" || pass "bench checks --json first"

# 9: bench --resolutions 0 names the key and its range, not the filter.
expect_error bench-res-zero "--resolutions: shadow.resolution: 0 is out of range (allowed integer in \[16, 32768\])" \
  "$SHADOWLAB" bench --scene builtin:textbook "${small[@]}" --frames 1 --resolutions 0 --filters point

# 8: a full disk (a 1 KiB file size limit; SIGXFSZ ignored, as a full disk raises none) keeps the old file.
expect_ok render-old "$SHADOWLAB" render "${small[@]}" --out old.png
expect_ok bench-old "$SHADOWLAB" bench --scene builtin:textbook "${small[@]}" --frames 1 --resolutions 256 \
  --filters point --json old.json
cp old.png old.png.before && cp old.json old.json.before
expect_error render-full "cannot write PNG 'old.png': .*File too large" \
  bash -c 'trap "" XFSZ; ulimit -f 1; exec "$0" render --width 640 --height 480 --out old.png' "$SHADOWLAB"
cmp -s old.png old.png.before && pass "full disk: old.png intact" || fail "full disk: old.png changed"
expect_error bench-full "--json old.json: .*File too large" \
  bash -c 'trap "" XFSZ; ulimit -f 1; exec "$0" bench --scene builtin:textbook --width 64 --height 48 --frames 1 \
    --resolutions 256 512 1024 --filters point pcf3 pcf5 poisson --json old.json' "$SHADOWLAB"
cmp -s old.json old.json.before && pass "full disk: old.json intact" || fail "full disk: old.json changed"
ls -a | grep -q '^\.old\..*tmp' && fail "a temporary file was left" || pass "no temporary left"

finish
