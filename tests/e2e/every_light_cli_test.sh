#!/usr/bin/env bash
# End-to-end, issue 19 ("every light, every number"), one check per class of defect:
#  - no light is special: on a preset whose light 0 is clean and light 1 has acne, every one-light tool describes the
#    light it was asked for and says which (probe, profile, measure --light, tune --light, render's report); on a
#    preset with no lights every command refuses or works, none crashes (bench wrote lights[0]);
#  - outputs: two outputs naming one file, an output that is an input, a read-only file: refused before the work;
#  - inputs: an overflowing motion axis, a schema-1 alias beside its key in a sweep, a range too short for a view, a
#    scenes folder that does not exist.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
small=(--scene builtin:courtyard --width 160 --height 120)

# A two-light preset on builtin:courtyard: light 0 its sun as shipped (clean), light 1 its spot with no bias (acne).
python3 - <<'EOF'
import json, os
p = json.load(open(os.environ["SOURCE_DIR"] + "/presets/courtyard.json"))
sun, spot = p["lights"][0], p["lights"][1]
spot["shadow"].update({"depthBias": 0.0, "slopeScaledDepthBias": 0.0, "normalOffset": 0.0})
p["lights"] = [sun, spot]
p["name"] = "two-lights"
json.dump(p, open("two.json", "w"), indent=2)
p["lights"] = []
p["name"] = "no-lights"
json.dump(p, open("none.json", "w"), indent=2)
EOF

# measure --light 1 reports light 1's acne, light 0's none: the numbers follow the light asked for.
expect_ok measure-light1 "$SHADOWLAB" measure --preset "$PWD/two.json" "${small[@]}" --light 1 --json m1.json
expect_ok measure-light0 "$SHADOWLAB" measure --preset "$PWD/two.json" "${small[@]}" --light 0 --json m0.json
python3 - <<'EOF' && pass "measure --light N describes light N (its own acne)" || fail "measure --light"
import json
m0, m1 = json.load(open("m0.json")), json.load(open("m1.json"))
a0 = m0["lights"][0]["acnePercent"]; a1 = m1["lights"][0]["acnePercent"]
assert m0["lights"][0]["index"] == 0 and m1["lights"][0]["index"] == 1, (m0["lights"][0], m1["lights"][0])
assert a1 > 5.0 and a0 < 1.0, (a0, a1)
EOF

# The probe: every casting light by default, each alone with its own S on CPU and GPU (they agree), labelled.
expect_ok probe-all "$SHADOWLAB" probe --preset "$PWD/two.json" "${small[@]}" --pixel 80,90 --json p.json
grep -q "^light 0 (directional)" probe-all.out && grep -q "^light 1 (spot)" probe-all.out \
  && pass "probe names each light it explains" || fail "probe labels: $(cat probe-all.out | head -5)"
python3 -c 'import json; j=json.load(open("p.json")); assert [l["light"] for l in j["lights"]]==[0,1], j.keys()' \
  && pass "probe --json: one entry per light" || fail "probe --json lights"
expect_ok probe-light1 "$SHADOWLAB" probe --preset "$PWD/two.json" "${small[@]}" --pixel 80,90 --light 1
# A point light: the CPU side follows the cube face the GPU reads (no spot cone test on faces): CPU and GPU agree.
for px in 40,60 80,90 120,100 100,40; do
  expect_ok "probe-room-$px" "$SHADOWLAB" probe --scene builtin:room --preset room --width 160 --height 120 --pixel "$px"
done

# The depth profile: several casting lights without --light are refused, --light N is followed and named.
expect_error profile-two "2 lights cast shadows: say which with --light N" \
  "$SHADOWLAB" profile --preset "$PWD/two.json" "${small[@]}" --from 10,100 --to 150,100 --out pr.png
expect_ok profile-light1 "$SHADOWLAB" profile --preset "$PWD/two.json" "${small[@]}" --from 10,100 --to 150,100 --out pr.png --light 1
grep -q "light 1 (spot)" profile-light1.out && pass "profile names its light" || fail "profile label"

# render's report lists every view with its own kind (a point light is not a "spot").
expect_ok render-room "$SHADOWLAB" render --scene builtin:room --preset room --width 160 --height 120 --out room.png
grep -q "+X: point (cube face)" render-room.out && ! grep -q "spot" render-room.out \
  && pass "render's report calls the point light's views point" || fail "render report: $(grep -i light render-room.out)"
expect_error render-two-maps "2 lights cast shadows: say which with --light N" \
  "$SHADOWLAB" render --preset "$PWD/two.json" "${small[@]}" --out t.png --shadow-map-png map.png

# No lights at all: nothing crashes; each command works or says why.
for cmd in "render --out n.png --width 160 --height 120" "bench --frames 2 --resolutions 256 --width 160 --height 120" \
           "export --format json"; do
  name="none-$(echo "$cmd" | cut -d' ' -f1)"
  "$SHADOWLAB" $cmd --preset "$PWD/none.json" >"$name.out" 2>"$name.err"
  rc=$?
  [ $rc -lt 128 ] && pass "$name exits $rc (no signal)" || fail "$name died with signal $((rc - 128))"
done
! grep -q "there is no light 0" none-render.err && pass "render without --light names no light" \
  || fail "render: $(cat none-render.err)"
grep -q "lights: none" none-bench.out && pass "bench says it ran without lights" || fail "bench: $(cat none-bench.out)"
expect_error none-profile "no light casts a shadow" \
  "$SHADOWLAB" profile --preset "$PWD/none.json" "${small[@]}" --from 10,100 --to 150,100 --out pr.png
expect_error none-measure "no" "$SHADOWLAB" measure --preset "$PWD/none.json" "${small[@]}"

# Outputs: one file named twice, an output that is an input, a read-only file, refused before any work.
expect_error sweep-same-output "both name o" "$SHADOWLAB" sweep --axis filter.kernel=1,3 "${small[@]}" \
  --json o --csv o --frames 1
cp "$PWD/two.json" "$PWD/keep.json"
expect_error measure-over-preset "is the input --preset" \
  "$SHADOWLAB" measure --preset "$PWD/keep.json" "${small[@]}" --overlay "$PWD/keep.json"
cmp -s "$PWD/two.json" "$PWD/keep.json" && pass "the preset is untouched" || fail "keep.json changed"
echo "precious" > locked.png && chmod 0444 locked.png
expect_error render-read-only "read-only (mode 0444)" "$SHADOWLAB" render "${small[@]}" --out locked.png
[ "$(cat locked.png)" = precious ] && pass "the read-only file is untouched" || fail "locked.png replaced"

# Inputs: an axis that overflows when normalized is still an axis; an alias and its key are one axis; a range too
# short for any view names the range; a scenes folder that does not exist fails.
expect_ok motion-huge-axis "$SHADOWLAB" measure --motion camera --direction 1e300,0,0 --frames 2 --step 0.01 "${small[@]}"
grep -q "texels" motion-huge-axis.out && pass "a 1e300 axis moves the camera" || fail "motion: $(cat motion-huge-axis.out)"
expect_error sweep-alias-twice "lights.0.type: this key is already an axis" \
  "$SHADOWLAB" sweep --axis light.type=directional,spot --axis lights.0.type=directional,point "${small[@]}"
expect_error range-too-short "lights.0.range: 1e-5 is too short" \
  "$SHADOWLAB" render --set lights.0.type=spot --set lights.0.range=1e-5 "${small[@]}" --out r.png
expect_error hardcases-no-scenes "--scenes /nonexistent: no such folder" \
  "$SHADOWLAB" hardcases --case 1 --quick --scenes /nonexistent

finish
