#!/usr/bin/env bash
# End-to-end: `shadowlab measure --motion`, headless. A camera moved by sub-texel steps flickers 0 % and re-renders no
# shadow view; a light turned by sub-texel steps on a point-filtered 256² map flickers (> 0 %) and prints it beside the
# V-changed share and the step in texels; the JSON, the overlay (flickering pixels in their colour) and the worst pair's
# two frames are written; bad options are refused naming the option.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
# json_get FILE PYTHON-EXPRESSION-ON-j -> its value
json_get() { python3 -c "import json; j = json.load(open('$1')); print($2)"; }
less_than() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }
coarse=(--scene builtin:textbook --preset default --set filter.kind=point --set shadow.resolution=256
        --width 480 --height 270)

expect_ok camera "$SHADOWLAB" measure "${coarse[@]}" --motion camera --frames 4 --step 0.02 --json camera.json
grep -q "camera moved 0.02 world units per frame = 0.17.* texels .*sub-texel" camera.out && pass "step in texels" \
  || fail "camera step line: $(sed -n 2p camera.out)"
[ "$(json_get camera.json "j['flickerPercent']['max']")" = "0.0" ] && pass "camera motion: flicker 0" \
  || fail "camera flicker = $(json_get camera.json "j['flickerPercent']")"
[ "$(json_get camera.json "sum(p['shadowViewsRendered'] for p in j['pairs'])")" = "0" ] \
  && pass "camera motion re-renders no shadow view" || fail "camera motion re-rendered a view"
[ "$(json_get camera.json "len(j['pairs'])")" = "3" ] && pass "4 frames = 3 pairs" || fail "pairs"
expect_ok turn "$SHADOWLAB" measure "${coarse[@]}" --motion camera-turn --frames 3 --step 0.1 --json turn.json
[ "$(json_get turn.json "(j['flickerPercent']['max'], j['motion'], j['stepUnit'])")" = "(0.0, 'camera-turn', 'degrees')" ] \
  && pass "camera turn: flicker 0" || fail "camera turn: $(json_get turn.json "j['flickerPercent']")"

expect_ok light "$SHADOWLAB" measure "${coarse[@]}" --motion light --frames 4 --step 0.4 --json light.json \
  --overlay light.png --frames-out pair
for word in "flicker " "V changed" "mean |dS|" "sub-texel" "<- worst"; do
  grep -q -- "$word" light.out && pass "light motion prints '$word'" || fail "output lacks '$word'"
done
flicker=$(json_get light.json "j['flickerPercent']['max']")
less_than 0 "$flicker" && pass "sub-texel light turn flickers ($flicker %)" || fail "light flicker = $flicker"
less_than "$(json_get light.json "j['stepTexels']")" 1 && pass "the light's step is sub-texel" || fail "stepTexels"
[ "$(png_size light.png)" = "480 270" ] && pass "overlay is 480x270" || fail "overlay size: $(png_size light.png)"
worst=$(json_get light.json "j['worstPair']")
for f in "$worst" "$((worst + 1))"; do
  [ "$(png_size "pair/frame-$f.png")" = "480 270" ] && pass "frame $f of the worst pair written" \
    || fail "pair/frame-$f.png missing"
done
# The flicker colour (#ff28e6) is in the overlay, about as often as the JSON counts flickering pixels.
magenta=$(python3 - <<'PY'
import zlib, struct
data = open("light.png", "rb").read()
pos, idat, w, h = 8, b"", 0, 0
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8]); body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR": w, h = struct.unpack(">II", body[:8])
    if kind == b"IDAT": idat += body
    pos += 12 + n
raw, stride, prev, count, i = zlib.decompress(idat), w * 4, bytearray(w * 4), 0, 0
for _ in range(h):
    f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride]); i += 1 + stride
    for x in range(stride):
        a = line[x - 4] if x >= 4 else 0; b = prev[x]; c = prev[x - 4] if x >= 4 else 0
        p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
        line[x] = (line[x] + [0, a, b, (a + b) // 2, a if pa <= pb and pa <= pc else b if pb <= pc else c][f]) & 255
    count += sum(1 for x in range(0, stride, 4) if tuple(line[x:x + 3]) == (255, 40, 230)); prev = line
print(count)
PY
)
less_than 0 "$magenta" && pass "overlay marks $magenta flickering pixels" || fail "no flicker colour in the overlay"

expect_error frames-one "--frames 1" "$SHADOWLAB" measure "${coarse[@]}" --motion light --frames 1 --step 0.1
expect_error step-nan "--step 'nan'" "$SHADOWLAB" measure "${coarse[@]}" --motion light --step nan
expect_error step-absurd "--step 720" "$SHADOWLAB" measure "${coarse[@]}" --motion light --step 720
expect_error step-missing "needs --step" "$SHADOWLAB" measure "${coarse[@]}" --motion camera
expect_error motion-unknown "--motion 'sideways': unknown motion (camera, camera-turn, light or animation)" "$SHADOWLAB" measure "${coarse[@]}" --motion sideways --step 1
expect_error motion-missing "need --motion" "$SHADOWLAB" measure "${coarse[@]}" --frames 3 --step 1
expect_error direction-bad "--direction" "$SHADOWLAB" measure "${coarse[@]}" --motion light --step 0.1 \
  --direction 0,0
expect_error light-missing "--light 3" "$SHADOWLAB" measure "${coarse[@]}" --motion light --step 0.1 --light 3

# Issue 20: stale depth bounds (HARD_CASES 20) from the CLI: the frame after a 90 degree turn loses more shadows with
# the frame before's bounds than with its own.
expect_ok stale-bounds "$SHADOWLAB" measure --scene builtin:city --preset default --set useSceneLights=true \
  --set lights.0.projection.fit=cascades --width 240 --height 135 --stale-bounds 90 --json stale.json
python3 - stale.json <<'PY' && pass "stale bounds: one frame late loses more shadows" || fail "stale bounds JSON: $(cat stale.json)"
import json, sys
d = json.load(open(sys.argv[1]))
same, prev = d["sameFrame"], d["previousFrame"]
assert d["turnDegrees"] == 90 and same["shadowedPixels"] == prev["shadowedPixels"] > 0
assert prev["missingShadows"] > same["missingShadows"], (same, prev)
PY
grep -q "bounds of the frame before (previousFrame, 1 late): *missing shadows" stale-bounds.out \
  && pass "stale bounds: both latencies printed" || fail "stale bounds text: $(cat stale-bounds.out)"
expect_error stale-bounds-light "needs a directional light with projection.fit cascades" "$SHADOWLAB" measure \
  --scene builtin:textbook --width 64 --height 36 --stale-bounds 90
expect_error stale-bounds-nan "--stale-bounds 'nan': not a finite number" "$SHADOWLAB" measure --stale-bounds nan
expect_error stale-bounds-range "must lie in (0, 180]" "$SHADOWLAB" measure --stale-bounds 270
expect_error stale-bounds-motion "not with --motion" "$SHADOWLAB" measure --stale-bounds 90 --motion camera --step 1
finish
