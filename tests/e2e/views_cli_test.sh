#!/usr/bin/env bash
# End-to-end, issue 20: the per-light tools take a view as well as a light. probe, profile, export and render's bias
# report work on light 1 (a spot: one view) and on a cascaded light (each cascade listed, or the one --view names);
# a point light's face by name; a bad --view names the light, its view count and the allowed values.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
json() { python3 -c "import json,sys; d=json.load(open('$1')); print(eval(sys.argv[1]))" "$2"; }

# Light 1: the courtyard's spot (one view): every tool describes it; --view has nothing to choose.
court=(--scene builtin:courtyard --preset courtyard --width 160 --height 120)
expect_ok probe-light1 "$SHADOWLAB" probe "${court[@]}" --pixel 80,90 --light 1
grep -q "^light 1 (spot), alone" probe-light1.out && pass "probe on light 1" || fail "probe light 1: $(sed -n 2p probe-light1.out)"
expect_ok profile-light1 "$SHADOWLAB" profile "${court[@]}" --from 10,100 --to 150,100 --out p1.png --light 1
expect_ok export-light1 "$SHADOWLAB" export --preset courtyard --scene builtin:courtyard --format json --light 1
expect_error probe-light1-view "--view cascade:1: light 1 has one view" \
  "$SHADOWLAB" probe "${court[@]}" --pixel 80,90 --light 1 --view cascade:1

# A cascaded sun on the textbook, seen from near the floor: 3 cascades.
casc=(--scene builtin:textbook --preset default --width 240 --height 135 --set lights.0.projection.fit=cascades
      --set lights.0.projection.cascadeCount=3 --set lights.0.projection.shadowDistance=30
      --set lights.0.projection.splitLambda=0.6 --set lights.0.projection.blendBand=0.2 --set camera.autoFrame=false
      --set camera.position=[-4,1.2,9] --set camera.target=[1,0.3,-3])
# render's bias report: one block per cascade, each texel-relative term in that cascade's texel.
expect_ok render-casc "$SHADOWLAB" render "${casc[@]}" --out casc.png
python3 - <<'PY' && pass "render: a bias block per cascade, normal offset = 0.5 x its texel" || fail "render bias: $(grep -A1 '^bias of' render-casc.out)"
import re
text = open("render-casc.out").read()
texels = [float(t) for t in re.findall(r"light 0 cascade:\d: directional.*?texel ([0-9.e+-]+) world units", text)]
blocks = re.findall(r"bias of light 0 cascade:(\d).*?normal offset ([0-9.e+-]+) world units \(texel ([0-9.e+-]+) world units\)", text, re.S)
assert len(texels) == 3 and [int(b[0]) for b in blocks] == [0, 1, 2], (texels, blocks)
for (c, offset, texel), t in zip(blocks, texels):
    assert abs(float(texel) - t) <= 5e-3 * t, (c, texel, t)  # printed to 3 digits
    assert abs(float(offset) - 0.5 * t) <= 5e-3 * t, (c, offset, t)  # the default preset's 0.5 texels
assert texels[0] < texels[1] < texels[2], texels
PY
# probe: without --view the cascade holding the point, said so; --view cascade:2 looks it up there, not compared.
expect_ok probe-casc "$SHADOWLAB" probe "${casc[@]}" --pixel 120,130 --json pc.json
grep -q "cascade:0 (of 3 views: the one holding this point" probe-casc.out && pass "probe names the holding cascade" \
  || fail "probe cascade: $(sed -n 2p probe-casc.out)"
expect_ok probe-casc-view "$SHADOWLAB" probe "${casc[@]}" --pixel 120,130 --view cascade:2 --json pv.json
grep -q "the GPU reads cascade:0 here; cascade:2's lookup is shown, not compared" probe-casc-view.out \
  && pass "probe --view cascade:2 says what it shows" || fail "probe --view: $(head -4 probe-casc-view.out)"
[ "$(json pv.json "d['cascade'], d['shadow']['compared']")" = "('cascade:2', False)" ] && pass "probe --view JSON" \
  || fail "probe --view JSON: $(json pv.json "d.get('cascade'), d['shadow']")"
expect_error probe-bad-view "--view cascade:5: light 0 has no such view: it has 3 views (allowed: cascade:0, cascade:1, cascade:2)" \
  "$SHADOWLAB" probe "${casc[@]}" --pixel 120,130 --view cascade:5
# profile: each point in its cascade, or the one --view names.
expect_ok profile-casc "$SHADOWLAB" profile "${casc[@]}" --from 20,120 --to 220,60 --out pc.png
grep -q "each point in the view holding it (of 3; --view chooses one)" profile-casc.out && pass "profile says which views" \
  || fail "profile: $(head -2 profile-casc.out)"
expect_ok profile-casc-view "$SHADOWLAB" profile "${casc[@]}" --from 20,120 --to 220,60 --out pv.png --view cascade:1
expect_error profile-bad-view "it has 3 views (allowed: cascade:0, cascade:1, cascade:2)" \
  "$SHADOWLAB" profile "${casc[@]}" --from 20,120 --to 220,60 --out pv.png --view +X
# export: every cascade, or one with --light 0 --view.
expect_ok export-casc "$SHADOWLAB" export "${casc[@]}" --format json --out casc.json
[ "$(json casc.json "[v['cascade'] for v in d['lights'][0]['views']]")" = "[0, 1, 2]" ] && pass "export: 3 cascades" \
  || fail "export cascades: $(head -c 300 casc.json)"
expect_ok export-casc-gl "$SHADOWLAB" export "${casc[@]}" --format gl
grep -q "CascadeChoice light0Cascade(vec3 worldPos)" export-casc-gl.out && pass "export gl: the selection" \
  || fail "export gl selection"
expect_ok export-casc-view "$SHADOWLAB" export "${casc[@]}" --format json --light 0 --view cascade:2 --out one.json
[ "$(json one.json "[v['cascade'] for v in d['lights'][0]['views']]")" = "[2]" ] && pass "export --view cascade:2" \
  || fail "export --view: $(head -c 300 one.json)"
expect_error export-view-no-light "say which light with --light N" "$SHADOWLAB" export "${casc[@]}" --format gl --view cascade:1
expect_error export-bad-view "light 0 has no such view: it has 3 views" \
  "$SHADOWLAB" export "${casc[@]}" --format gl --light 0 --view cascade:9

# A point light's face by name.
expect_ok export-room-face "$SHADOWLAB" export --preset room --scene builtin:room --format json --light 0 --view -Y --out face.json
[ "$(json face.json "[v['cubeFace'] for v in d['lights'][0]['views']]")" = "['-Y']" ] && pass "export --view -Y" \
  || fail "export face: $(head -c 300 face.json)"
expect_error probe-room-bad-view "allowed: +X, -X, +Y, -Y, +Z, -Z" \
  "$SHADOWLAB" probe --scene builtin:room --preset room --width 160 --height 120 --pixel 80,90 --view cascade:0

# tune on a cascaded light where one cascade stops every candidate: the preset's DepthBiasClamp (1e-4, kept as given)
# caps constant + slope bias, and normal offset alone leaves the sphere's terminator in cascade 1 in steps. The message
# and the JSON name the light, the cascade, its pixels and the least acne it reached; no preset is written.
tuneCasc=(--scene builtin:textbook --preset default --width 240 --height 135 --set lights.0.projection.fit=cascades
          --set lights.0.projection.cascadeCount=3 --set lights.0.projection.shadowDistance=30
          --set lights.0.projection.splitLambda=0.6 --set camera.autoFrame=false --set camera.position=[-4,1.2,9]
          --set camera.target=[1,0.3,-3] --set shadow.resolution=256 --set shadow.depthBiasClamp=0.0001
          --set shadow.depthBias=0 --set shadow.slopeScaledDepthBias=0 --set shadow.normalOffset=0)
"$SHADOWLAB" tune "${tuneCasc[@]}" --json tune-casc.json --out tune-casc-preset.json >tune-casc.out 2>tune-casc.err
rc=$?
[ $rc -eq 3 ] && [ ! -e tune-casc-preset.json ] && pass "tune: no setting holds in every cascade (exit 3, no preset)" \
  || fail "tune cascades: exit $rc, $(tail -3 tune-casc.err)"
grep -Eq "cascade:1 of lights.0 \(directional\) stops it: its [0-9]+ measured pixels keep acne above the limit with every candidate \(least [0-9.]+ %;.*shadow.depthBiasClamp 0.0001" tune-casc.out \
  && pass "tune names the light, the cascade, its pixels, its least acne and the clamp" \
  || fail "tune message: $(grep 'NO setting' tune-casc.out)"
python3 - <<'PY' && pass "tune JSON: blockingCascade 1, its pixels and least acne" || fail "tune JSON: $(head -c 400 tune-casc.json)"
import json
l = json.load(open("tune-casc.json"))["lights"][0]
c = l["report"]["cascaded"]["cascades"][1]
least = min(s["cascadeAcnePercent"][1] for s in l["path"])
others = [min(s["cascadeAcnePercent"][i] for s in l["path"]) for i in (0, 2)]
assert not l["reachedLimit"] and l["blockingCascade"] == 1, l["blockingCascade"]
assert l["blockingCascadePixels"] == c["pixels"] >= 200, (l["blockingCascadePixels"], c["pixels"])
assert abs(l["blockingCascadeLeastAcnePercent"] - least) < 1e-12 and least > 0.1, least
assert l["blockingCascadeAcnePercent"] == c["acnePercent"] and l["blockingCascadeTexelWorldSize"] == c["texelWorldSize"]
assert max(others) <= 0.1, others
PY
finish
