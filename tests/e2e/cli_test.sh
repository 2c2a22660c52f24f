#!/usr/bin/env bash
# End-to-end: the real `shadowlab` binary, headless. Checks outputs exist and decode, and that every kind of bad
# input exits non-zero with a message naming what is wrong. Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

expect_ok render "$SHADOWLAB" render --scene builtin:textbook --preset default --width 320 --height 200 \
  --out view.png --shadow-map map.exr --shadow-map-png map.png
[ "$(png_size view.png)" = "320 200" ] && pass "view.png is 320x200" || fail "view.png size: $(png_size view.png)"
[ "$(png_size map.png)" = "2048 2048" ] && pass "map.png is 2048x2048" || fail "map.png size: $(png_size map.png)"
head -c 4 map.exr | od -An -tx1 | grep -q "76 2f 31 01" && pass "map.exr is an OpenEXR file" || fail "map.exr magic"
grep -q "wrote view.png" render.out && pass "says where it wrote" || fail "no 'wrote view.png' in output"

expect_ok render-set "$SHADOWLAB" render --scene builtin:fence --preset soft --set shadow.resolution=512 \
  --set filter.kind=pcf --set filter.kernel=5 --set light.direction=[0,-1,-0.8] --view shadow \
  --width 160 --height 100 --out fence.png --shadow-map-png fence-map.png
[ "$(png_size fence-map.png)" = "512 512" ] && pass "--set shadow.resolution applies" || fail "fence-map size"
grep -q "PCF_KERNEL 5" render-set.out && pass "--set filter.kernel reaches the shader" || fail "kernel not in variants"

# Issue 9, observation 5: with a far plane of 1e6 the bias report gives D32F's step at the receivers' real depth
# (2^-40, not 2^-24), the slope-scaled term and the clamp, and says the clip space's precision exceeds the bias.
expect_ok render-far "$SHADOWLAB" render --scene builtin:textbook --set projection.autoFit=false \
  --set projection.far=1e6 --width 64 --height 64 --out far.png
grep -q "nearest receivers (depth 1.27e-05, r = 2^-40)" render-far.out && pass "DepthBias step at the receivers" \
  || fail "no receiver-depth step in: $(cat render-far.out)"
grep -q "SlopeScaledDepthBias 1 x median depth slope" render-far.out && grep -q "DepthBiasClamp: none" render-far.out \
  && pass "slope term and clamp reported" || fail "slope / clamp missing in: $(cat render-far.out)"
grep -q "more than the total bias: expect acne" render-far.out && pass "clip-space precision warns" \
  || fail "no precision warning in: $(cat render-far.out)"
# Observation 6: the camera keeps a millimetre at a million units through --set.
expect_ok render-camera "$SHADOWLAB" render --scene builtin:textbook --set camera.autoFrame=false \
  --set camera.position=[1000000.001,5,5] --set camera.target=[1000000,0,0] --width 32 --height 32 --out cam.png

for view in lit shadow light-depth; do
  expect_ok "view-$view" "$SHADOWLAB" render --scene builtin:thin-walls --view "$view" --width 64 --height 64 --out "v-$view.png"
done
for preset in "$SOURCE_DIR"/presets/*.json; do
  expect_ok "preset-$(basename "$preset" .json)" "$SHADOWLAB" render --preset "$preset" --width 64 --height 64 --out p.png
done
for scene in "$SOURCE_DIR"/../shared/scenes/*/*.gltf; do
  [ -f "$scene" ] || continue
  expect_ok "scene-$(basename "$scene" .gltf)" "$SHADOWLAB" render --scene "$scene" --width 96 --height 64 \
    --set shadow.resolution=512 --out s.png
done

expect_ok scenes "$SHADOWLAB" scenes
for name in textbook grazing thin-walls fence room courtyard; do
  grep -q "builtin:$name" scenes.out && pass "scenes lists $name" || fail "scenes does not list $name"
done
expect_ok info "$SHADOWLAB" info
grep -q "GL_RENDERER" info.out && grep -q "GL_MAX_TEXTURE_SIZE" info.out && pass "info prints renderer and limits" || fail "info output"
expect_ok keys "$SHADOWLAB" keys
grep -q "shadow.slopeScaledDepthBias" keys.out && pass "keys lists the bias" || fail "keys output"

# Bad input: a clear message naming what is wrong, and a non-zero exit.
# A render carries its preset: rendering from the picture gives the same picture (same settings, scene and camera).
expect_ok shot "$SHADOWLAB" render --scene builtin:fence --preset soft --set shadow.depthBias=3.5 --view shadow \
  --width 96 --height 64 --out shot.png
expect_ok shot-again "$SHADOWLAB" render --scene builtin:fence --preset shot.png --width 96 --height 64 --out again.png
cmp -s shot.png again.png && pass "render --preset shot.png reproduces shot.png" || fail "shot.png and again.png differ"
expect_error shot-other-scene "tuned on builtin:fence" "$SHADOWLAB" render --scene builtin:textbook --preset shot.png \
  --set no.such=1 --out other.png
expect_error png-without-preset "carries no ShadowLab preset" "$SHADOWLAB" render --preset fence-map.png --out x.png

expect_error bad-key "no.such" "$SHADOWLAB" render --set no.such=1 --out x.png
expect_error bad-range "shadow.resolution" "$SHADOWLAB" render --set shadow.resolution=0 --out x.png
expect_error bad-nan "shadow.depthBias" "$SHADOWLAB" render --set shadow.depthBias=nan --out x.png
expect_error bad-enum "filter.kind" "$SHADOWLAB" render --set filter.kind=gaussian --out x.png
expect_error bad-kernel "filter.kernel" "$SHADOWLAB" render --set filter.kernel=4 --out x.png
expect_error zero-light "light.direction" "$SHADOWLAB" render --set light.direction=[0,0,0] --out x.png
expect_error missing-scene "nope.gltf" "$SHADOWLAB" render --scene /nonexistent/nope.gltf --out x.png
expect_error unknown-builtin "textbook" "$SHADOWLAB" render --scene builtin:nope --out x.png
expect_error missing-preset "missing.json" "$SHADOWLAB" render --preset /nonexistent/missing.json --out x.png
printf '{"schema":"shadowlab-preset","schemaVersion":1,"shadow":{"depthBias":"a lot"}}' >bad-type.json
expect_error bad-preset-type "shadow.depthBias" "$SHADOWLAB" render --preset bad-type.json --out x.png
printf '{"schema":"shadowlab-preset", "schemaVersion":1, "shadow": {' >truncated.json
expect_error bad-preset-syntax "truncated.json" "$SHADOWLAB" render --preset truncated.json --out x.png
expect_error bad-out-dir "no-such-dir" "$SHADOWLAB" render --width 32 --height 32 --out no-such-dir/x.png
expect_error bad-size "width" "$SHADOWLAB" render --width 0 --out x.png
expect_error bad-view "view" "$SHADOWLAB" render --view sideways --out x.png
expect_error bad-command "" "$SHADOWLAB" frobnicate
printf 'not a gltf' >broken.gltf
expect_error broken-gltf "broken.gltf" "$SHADOWLAB" render --scene broken.gltf --out x.png

# Issue 13, A/B: preset B right of the divider, from the same camera, each side labelled (with --measure, accuracy).
expect_ok render-compare "$SHADOWLAB" render --scene builtin:grazing --preset acne --compare default --measure \
  --split 0.5 --width 320 --height 180 --out ab.png
[ "$(png_size ab.png)" = "320 180" ] && pass "the A/B picture is the view's size" || fail "ab.png size: $(png_size ab.png)"
# The acne side is striped (many colours), the default side flat: the halves must differ in distinct colours.
python3 "$SOURCE_DIR/tests/e2e/split_check.py" ab.png && pass "left half striped, right half clean" \
  || fail "split picture: $(python3 "$SOURCE_DIR/tests/e2e/split_check.py" ab.png 2>&1)"
expect_error compare-split "--split 2" "$SHADOWLAB" render --scene builtin:textbook --compare default --split 2 \
  --width 64 --height 64 --out x.png
expect_error measure-alone "--measure goes with --compare" "$SHADOWLAB" render --scene builtin:textbook --measure \
  --width 64 --height 64 --out x.png
expect_error compare-missing "nope.json" "$SHADOWLAB" render --scene builtin:textbook --compare nope.json \
  --width 64 --height 64 --out x.png
expect_ok render-point-cross "$SHADOWLAB" render --scene builtin:textbook --set lights.1.type=point \
  --set lights.1.position=1,4,3 --set lights.1.shadow.resolution=64 --light 1 --shadow-map-png cross.png \
  --width 64 --height 64 --out x.png
[ "$(png_size cross.png)" = "256 192" ] && pass "a point light's map is a 4x3 cross of faces" \
  || fail "cross.png size: $(png_size cross.png)"
expect_error no-light-3 "there is no light 3" "$SHADOWLAB" render --scene builtin:textbook --light 3 \
  --shadow-map-png m.png --width 64 --height 64 --out x.png

# Issue 20: a file's cameras and what casts, through --set.
CITY="$SOURCE_DIR/tests/data/scenes/sky_box_city.gltf"
expect_ok render-scene-camera "$SHADOWLAB" render --scene "$CITY" --set camera.sceneCamera=0 \
  --set 'casters.excluded=["Root/City/SkyBox","Root/City/Gone"]' --width 64 --height 48 --out street.png
grep -q "camera 0: Street (perspective)" render-scene-camera.out && pass "render lists the file's cameras" \
  || fail "no camera list in: $(cat render-scene-camera.out)"
grep -q "camera 3 ('zero fov') refused" render-scene-camera.err && pass "a hostile camera is refused alone" \
  || fail "no refusal in: $(cat render-scene-camera.err)"
grep -q "no node 'Root/City/Gone'" render-scene-camera.err && pass "an unknown caster path is a warning" \
  || fail "no unknown-path warning in: $(cat render-scene-camera.err)"
expect_error scene-camera-range "camera.sceneCamera: 9 is not a camera of scene sky_box_city" "$SHADOWLAB" render \
  --scene "$CITY" --set camera.sceneCamera=9 --width 32 --height 32 --out x.png

# A user preset by its name, as the editor finds it: every command resolves --preset alike (preset_catalog).
mkdir -p user-presets
cp "$SOURCE_DIR/presets/acne.json" user-presets/street-test.json
SHADOWLAB_USER_PRESETS="$PWD/user-presets" expect_ok user-preset-by-name "$SHADOWLAB" render --scene builtin:grazing \
  --preset street-test --width 32 --height 32 --out user.png
expect_error user-preset-unknown "nonesuch-preset" "$SHADOWLAB" render --preset nonesuch-preset --out x.png

# No command opens the editor; without a display it says so and exits non-zero (tests/e2e/editor_test.sh opens it).
expect_error noargs "needs a display" "$SHADOWLAB"

finish
