#!/usr/bin/env bash
# shadowlab export: every format writes a snippet with the preset's numbers for every light (a point light's six
# faces included); --light N exports one; a zero-light preset says nothing casts; bad input is refused naming the key.
set -u
mkdir -p "$OUT_DIR" && cd "$OUT_DIR" || exit 1
source "$SOURCE_DIR/tests/e2e/e2e_lib.sh"

for format in d3d12 d3d11 vulkan gl json; do
  rm -f "export.$format"
  expect_ok "export-$format" "$SHADOWLAB" export --preset default --set shadow.depthBias=3 --set shadow.depthFormat=d16 \
    --scene builtin:grazing --format "$format" --out "export.$format"
  [ -s "export.$format" ] && pass "export.$format written" || fail "export.$format missing"
  grep -q "builtin:grazing" "export.$format" && pass "$format names the scene" || fail "$format does not name the scene"
done
grep -q "shadowRaster.DepthBias = 3;" export.d3d12 && pass "d3d12 DepthBias" || fail "d3d12 DepthBias: $(grep DepthBias export.d3d12)"
grep -q "DXGI_FORMAT_D16_UNORM" export.d3d11 && pass "d3d11 format" || fail "d3d11 format"
grep -q "depthBiasConstantFactor = 3.0f;" export.vulkan && pass "vulkan constant" || fail "vulkan constant"
grep -q "glPolygonOffsetClamp(" export.gl && pass "gl polygon offset" || fail "gl polygon offset"
python3 -c "import json,sys; j=json.load(open('export.json')); sys.exit(0 if j['lights'][0]['rasterizer']['depthBias']==3 and j['lights'][0]['depth']['bits']==16 else 1)" \
  && pass "json numbers" || fail "json numbers: $(head -c 400 export.json)"

# Standard output without --out; the normal offset's world size follows the scene.
expect_ok export-stdout "$SHADOWLAB" export --format json --scene builtin:textbook
expect_ok export-stdout-2 "$SHADOWLAB" export --format json --scene builtin:grazing
a=$(python3 -c "import json; print(json.load(open('export-stdout.out'))['lights'][0]['normalOffset']['world'])")
b=$(python3 -c "import json; print(json.load(open('export-stdout-2.out'))['lights'][0]['normalOffset']['world'])")
[ "$a" != "$b" ] && pass "normal offset world differs per scene ($a vs $b)" || fail "normal offset world the same for two scenes"

# The shipped room preset: one point light, six cube faces, each named with its matrix; exit 0.
for format in vulkan d3d12 json; do
  expect_ok "export-room-$format" "$SHADOWLAB" export --preset room --scene builtin:room --format "$format"
done
for face in +X -X +Y -Y +Z -Z; do
  grep -q -- "// View light 0 (point) face $face: near " export-room-vulkan.out && pass "room vulkan face $face" \
    || fail "room vulkan: no face $face: $(head -c 300 export-room-vulkan.out)"
done
[ "$(grep -c 'static const float light0Face..ViewProjection\[16\]' export-room-d3d12.out)" = 6 ] \
  && pass "room d3d12: six face matrices" || fail "room d3d12: $(grep -c ViewProjection export-room-d3d12.out) matrices"
python3 -c "import json,sys; j=json.load(open('export-room-json.out')); l=j['lights'][0]; sys.exit(0 if l['type']=='point' and len(l['views'])==6 and l['views'][5]['cubeFace']=='-Z' else 1)" \
  && pass "room json: six views" || fail "room json: $(head -c 400 export-room-json.out)"
expect_ok export-room-default-scene "$SHADOWLAB" export --preset room --format gl

# --light N: that light alone; a light that does not exist is refused naming lights.N and the range.
expect_ok export-light-0 "$SHADOWLAB" export --preset room --format gl --light 0
grep -q "light 0 of" export-light-0.out && pass "--light 0 named" || fail "--light 0: $(head -c 300 export-light-0.out)"
expect_error export-light-missing "lights.1 (lights 0..0" "$SHADOWLAB" export --preset room --format gl --light 1

# A preset with no light: a clear statement that nothing casts, exit 0, every format.
python3 -c "import json; p=json.load(open('$SOURCE_DIR/presets/room.json')); p['lights']=[]; json.dump(p, open('no-lights.json','w'))"
for format in d3d12 vulkan gl json; do
  expect_ok "export-no-lights-$format" "$SHADOWLAB" export --preset no-lights.json --format "$format"
  grep -q "Nothing casts a shadow" "export-no-lights-$format.out" && pass "no lights $format says so" \
    || fail "no lights $format: $(head -c 300 "export-no-lights-$format.out")"
done
expect_error export-no-lights-light "lights.0" "$SHADOWLAB" export --preset no-lights.json --format gl --light 0

expect_error export-bad-format "--format: 'd3d9' is not one of d3d12|d3d11|vulkan|gl|json" \
  "$SHADOWLAB" export --format d3d9
expect_error export-bad-preset "no-such-preset" "$SHADOWLAB" export --preset no-such-preset --format gl
expect_error export-bad-set "shadow.depthFormat" "$SHADOWLAB" export --set shadow.depthFormat=d8 --format gl
expect_error export-bad-out "--out" "$SHADOWLAB" export --format gl --out /nonexistent-folder/x.h
expect_error export-bad-scene "unknown built-in scene 'nope'" "$SHADOWLAB" export --format gl --scene builtin:nope
finish
