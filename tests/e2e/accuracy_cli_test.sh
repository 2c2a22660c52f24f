#!/usr/bin/env bash
# End-to-end: `shadowlab measure` and `shadowlab tune`, headless. Checks exit codes, the printed numbers, the JSON,
# the overlay PNG, that a tuned preset loads back and measures within the acne limit, and that bad input is refused.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
# json_number FILE KEY -> the first "KEY": number in the file
json_number() { grep -o "\"$2\": *[-0-9.eE+]*" "$1" | head -1 | sed 's/.*: *//'; }
# less_than A B: A < B as numbers
less_than() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

expect_ok measure "$SHADOWLAB" measure --scene builtin:textbook --preset acne --width 320 --height 180 \
  --json acne.json --overlay acne.png
for word in "acne" "leak" "edge error" "Mrays/s" "BVH build"; do
  grep -q "$word" measure.out && pass "measure prints $word" || fail "measure output lacks '$word'"
done
[ "$(png_size acne.png)" = "320 180" ] && pass "overlay is 320x180" || fail "overlay size: $(png_size acne.png)"
acne=$(json_number acne.json acnePercent)
less_than 1 "$acne" && pass "acne preset measures $acne % acne" || fail "acne preset acne = '$acne'"
for key in leakPercent edgeErrorP95Texels kTexels mismatched raysPerSecond bvhBuildMs; do
  grep -q "\"$key\"" acne.json && pass "JSON has $key" || fail "JSON lacks $key"
done

expect_ok measure-spot "$SHADOWLAB" measure --scene builtin:fence --preset default --set light.type=spot \
  --set light.position=[0,6,4] --set light.direction=[0,-1,-0.6] --width 160 --height 90 --json spot.json
less_than 0 "$(json_number spot.json outsideCone)" && pass "spot light: pixels outside the cone counted" \
  || fail "spot: outsideCone = $(json_number spot.json outsideCone)"

expect_ok tune "$SHADOWLAB" tune --scene builtin:textbook --preset default --set shadow.depthBias=0 \
  --set shadow.slopeScaledDepthBias=0 --set shadow.normalOffset=0 --width 320 --height 180 --out tuned.json \
  --json path.json
grep -q "zero bias" tune.out && pass "tune prints its path" || fail "tune path missing"
grep -q "^result" tune.out && pass "tune prints the result" || fail "tune result missing: $(tail -5 tune.out)"
grep -q "wrote tuned.json" tune.out && [ -f tuned.json ] && pass "tune writes the preset" || fail "no tuned.json"
expect_ok measure-tuned "$SHADOWLAB" measure --scene builtin:textbook --preset ./tuned.json --width 320 --height 180 \
  --json tuned-measure.json
tuned_acne=$(json_number tuned-measure.json acnePercent)
awk -v a="$tuned_acne" 'BEGIN { exit !(a <= 0.1) }' && pass "tuned preset measures $tuned_acne % acne" \
  || fail "tuned preset acne = '$tuned_acne'"
expect_ok render-tuned "$SHADOWLAB" render --scene builtin:textbook --preset ./tuned.json --width 64 --height 36 \
  --out tuned.png

# No setting can reach the limit: said so, still a preset and exit 0.
expect_ok tune-hopeless "$SHADOWLAB" tune --scene builtin:textbook --preset default --set projection.autoFit=false \
  --set projection.orthoSize=8 --set projection.near=0.01 --set projection.far=40 --set sampler.addressMode=wrap \
  --width 160 --height 90 --out hopeless.json
grep -q "NO setting reached" tune-hopeless.out && [ -f hopeless.json ] && pass "tune says when nothing reaches the limit" \
  || fail "hopeless tune: $(tail -3 tune-hopeless.out)"

expect_error bad-key "no.such" "$SHADOWLAB" measure --set no.such=1
expect_error bad-scene "nope.gltf" "$SHADOWLAB" measure --scene /nonexistent/nope.gltf
expect_error bad-size "width" "$SHADOWLAB" measure --width 0
expect_error bad-json-dir "no-such-dir" "$SHADOWLAB" measure --width 32 --height 32 --json no-such-dir/x.json
expect_error bad-overlay-dir "no-such-dir" "$SHADOWLAB" measure --width 32 --height 32 --overlay no-such-dir/x.png
expect_error bad-max-acne "max-acne" "$SHADOWLAB" tune --max-acne -1 --width 32 --height 32
expect_error bad-tune-out "no-such-dir" "$SHADOWLAB" tune --width 32 --height 32 --out no-such-dir/t.json
expect_error bad-tune-range "shadow.resolution" "$SHADOWLAB" tune --set shadow.resolution=0

finish
