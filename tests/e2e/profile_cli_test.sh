#!/usr/bin/env bash
# End-to-end: `shadowlab profile` (issue 13, "Depth profile"), headless. Across the grazing floor at zero bias the
# profile reports acne samples and the shipped preset none; the chart is a PNG of the requested size with more than a
# few colours; --json holds every sample; a line outside the view or a malformed --from/--to is refused with a message
# naming the option, and nothing is written.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
json() { python3 -c "import json,sys; d=json.load(open('$1')); print(eval(sys.argv[1]))" "$2"; }

view=(--scene builtin:grazing --preset default --width 640 --height 360)
zero=(--set shadow.depthBias=0 --set shadow.slopeScaledDepthBias=0 --set shadow.normalOffset=0
      --set shadow.receiverPlaneBias=false)  # every bias term off (the default compares the receiver's plane)
line=(--from 200,250 --to 260,250)
expect_ok profile-acne "$SHADOWLAB" profile "${view[@]}" "${zero[@]}" "${line[@]}" --out acne.png --json acne.json
grep -q "61 samples, 61 on surfaces" profile-acne.out && pass "61 samples along the line" \
  || fail "samples: $(cat profile-acne.out)"
[ "$(json acne.json "d['acneSamples'] > 30")" = "True" ] && pass "zero bias: acne samples" \
  || fail "acne: $(json acne.json "d['acneSamples']")"
[ "$(json acne.json "len(d['samples'])")" = "61" ] && pass "JSON: every sample" || fail "JSON samples"
[ "$(json acne.json "all(k in d['samples'][0] for k in ('receiverDepth','storedDepth','bias','receiverMinusBias','acne','peterPanning'))")" = "True" ] \
  && pass "JSON: each sample's numbers" || fail "JSON keys: $(json acne.json "list(d['samples'][0])")"
[ "$(png_size acne.png)" = "960 480" ] && pass "chart is 960x480" || fail "chart size $(png_size acne.png)"
read -r w h colours bright dark < <(python3 "$SOURCE_DIR/tests/e2e/png_check.py" acne.png)
[ "${colours:-0}" -gt 8 ] && pass "chart is not blank ($colours colours)" || fail "chart colours: ${colours:-none}"

expect_ok profile-default "$SHADOWLAB" profile "${view[@]}" "${line[@]}" --out default.png --json default.json \
  --plot-width 400 --plot-height 200
[ "$(json default.json "d['acneSamples']")" = "0" ] && pass "default preset: no acne" \
  || fail "default acne: $(json default.json "d['acneSamples']")"
[ "$(png_size default.png)" = "400 200" ] && pass "chart follows --plot-width/--plot-height" || fail "size $(png_size default.png)"

expect_error profile-to-outside "--to 640,10 is outside the 640x360 view" "$SHADOWLAB" profile "${view[@]}" \
  --from 0,10 --to 640,10 --out bad.png
expect_error profile-from-outside "--from -1,10 is outside" "$SHADOWLAB" profile "${view[@]}" \
  --from=-1,10 --to 5,10 --out bad.png
expect_error profile-from-malformed "--from '12x5': expected X,Y" "$SHADOWLAB" profile "${view[@]}" \
  --from 12x5 --to 5,10 --out bad.png
expect_error profile-to-malformed "--to '5,': expected X,Y" "$SHADOWLAB" profile "${view[@]}" \
  --from 1,1 --to 5, --out bad.png
expect_error profile-no-folder "--out" "$SHADOWLAB" profile "${view[@]}" "${line[@]}" --out missing/dir/p.png
[ ! -e bad.png ] && pass "nothing written on failure" || fail "bad.png written"
finish
