#!/usr/bin/env bash
# shadowlab export: every format writes a snippet with the preset's numbers; bad input is refused naming the key.
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
python3 -c "import json,sys; j=json.load(open('export.json')); sys.exit(0 if j['rasterizer']['depthBias']==3 and j['depth']['bits']==16 else 1)" \
  && pass "json numbers" || fail "json numbers: $(head -c 400 export.json)"

# Standard output without --out; the normal offset's world size follows the scene.
expect_ok export-stdout "$SHADOWLAB" export --format json --scene builtin:textbook
expect_ok export-stdout-2 "$SHADOWLAB" export --format json --scene builtin:grazing
a=$(python3 -c "import json; print(json.load(open('export-stdout.out'))['normalOffset']['world'])")
b=$(python3 -c "import json; print(json.load(open('export-stdout-2.out'))['normalOffset']['world'])")
[ "$a" != "$b" ] && pass "normal offset world differs per scene ($a vs $b)" || fail "normal offset world the same for two scenes"

expect_error export-bad-format "--format: 'd3d9' is not one of d3d12|d3d11|vulkan|gl|json" \
  "$SHADOWLAB" export --format d3d9
expect_error export-bad-preset "no-such-preset" "$SHADOWLAB" export --preset no-such-preset --format gl
expect_error export-bad-set "shadow.depthFormat" "$SHADOWLAB" export --set shadow.depthFormat=d8 --format gl
expect_error export-bad-out "--out" "$SHADOWLAB" export --format gl --out /nonexistent-folder/x.h
expect_error export-bad-scene "unknown built-in scene 'nope'" "$SHADOWLAB" export --format gl --scene builtin:nope
finish
