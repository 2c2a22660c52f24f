#!/usr/bin/env bash
# End-to-end: `shadowlab measure` and `shadowlab tune`, headless. Checks exit codes, the printed numbers (metrics
# version 2, causes, the coarse-map warning), the JSON, the overlay PNGs (the soft one of a light with a size), that a tuned preset loads back and measures
# within the acne limit (tune --light 1: light 1 measured again), that tune writes nothing when no setting reaches
# the limit, that --remeasure-bench's GPU and CPU paths agree, and that bad input is refused.
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
  --json acne.json --overlay acne.png --cause-overlay acne-cause.png
for word in "metrics version 2" "acne" "leak" "wrong pixels" "mean error" "world units" "screen pixels" \
    "self-shadowing" "Mrays/s" "BVH build"; do
  grep -q "$word" measure.out && pass "measure prints $word" || fail "measure output lacks '$word'"
done
grep -q "faint" measure.out && fail "measure still prints 'faint'" || pass "no faint acne class left"
[ "$(png_size acne.png)" = "320 180" ] && pass "overlay is 320x180" || fail "overlay size: $(png_size acne.png)"
[ "$(png_size acne-cause.png)" = "320 180" ] && pass "cause overlay is 320x180" \
  || fail "cause overlay size: $(png_size acne-cause.png)"
acne=$(json_number acne.json acnePercent)
less_than 1 "$acne" && pass "acne preset measures $acne % acne" || fail "acne preset acne = '$acne'"
[ "$(json_number acne.json metricsVersion)" = "2" ] && pass "JSON says metricsVersion 2" || fail "metricsVersion"
for key in leakPercent acneSeverity wrongPixelsPercent meanError edgeErrorP95Texels edgeErrorP95World \
    edgeErrorP95ScreenPixels kTexels mismatched causes selfShadowing casterCulled nearEdge raysPerSecond bvhBuildMs; do
  grep -q "\"$key\"" acne.json && pass "JSON has $key" || fail "JSON lacks $key"
done

# A light of size > 0: its soft numbers (version 3) after its hard ones, naming the light, in the text and the JSON;
# a hard light (the acne run above) has none.
expect_ok measure-soft "$SHADOWLAB" measure --scene builtin:textbook --preset default --width 320 --height 180 \
  --set lights.0.size=3 --set reference.softRays=64 --json soft.json --soft-overlay soft.png
grep -q "soft light lights.0 (size 3.000 degrees angular diameter, 64 rays per pixel), metrics version 3" \
  measure-soft.out && pass "measure names the soft light" || fail "no soft block: $(tail -12 measure-soft.out)"
for word in "bleeding" "over-darkening" "penumbra width error"; do
  grep -q "$word" measure-soft.out && pass "soft measure prints $word" || fail "soft output lacks '$word'"
done
python3 - <<'PY' && pass "soft JSON: version 3, light 0, widths" || fail "soft JSON: $(head -c 600 soft.json)"
import json, sys
soft = json.load(open("soft.json"))["lights"][0]["soft"]
ok = soft["metricsVersion"] == 3 and soft["light"] == 0 and soft["rays"] == 64 and soft["sizeUnit"] == "degrees"
ok = ok and soft["penumbraWidth"]["profiles"] > 0 and soft["penumbraWidth"]["referenceWorld"] > 0
sys.exit(0 if ok else 1)
PY
python3 -c "import json,sys; sys.exit('soft' in json.load(open('acne.json'))['lights'][0])" \
  && pass "a hard light has no soft numbers" || fail "acne.json has soft numbers for a hard light"
# The soft overlay: its PNG, legend and counts; a hard light has no soft reference to colour against.
[ "$(png_size soft.png)" = "320 180" ] && pass "soft overlay is 320x180" || fail "soft overlay: $(png_size soft.png)"
grep -q "wrote soft.png (lights.0 (directional): #28e6e6 = light bleeding (V = 0, lit), .*: light bleeding [0-9]* of [0-9]* umbra pixels" \
  measure-soft.out && pass "measure prints the soft overlay's legend and counts" \
  || fail "soft overlay line: $(grep soft.png measure-soft.out)"
expect_error soft-overlay-hard "has no size" "$SHADOWLAB" measure --scene builtin:textbook --preset default \
  --width 320 --height 180 --soft-overlay hard-soft.png

# Issue 9, observation 3: the roof's leak is named as a culled caster, with its remedy.
expect_ok measure-roof "$SHADOWLAB" measure --scene builtin:roof --preset default --width 320 --height 180 \
  --set shadow.cullMode=back --json roof.json
grep -q "caster culled in the shadow pass .*shadow.cullMode=none" measure-roof.out && pass "roof: cause and remedy" \
  || fail "roof causes: $(grep -A4 'causes of' measure-roof.out)"
culled=$(python3 -c "import json; print(json.load(open('roof.json'))['lights'][0]['causes']['casterCulled']['percentOfWrong'])")
less_than 90 "$culled" && pass "roof: culled casters explain $culled % of wrong pixels" || fail "roof culled = $culled"

# Issue 19: each cause's share of what it explains. Faint acne (too little slope bias, no receiver plane) is all
# self-shadowing, though hardly a pixel of it is "wrong" (|S-V| >= 0.5): its share is of acne, not of wrong.
expect_ok measure-faint "$SHADOWLAB" measure --scene builtin:textbook --preset default --width 320 --height 180 \
  --set lights.0.shadow.slopeScaledDepthBias=1.5 --set lights.0.shadow.normalOffset=0 \
  --set lights.0.shadow.receiverPlaneBias=false --json faint.json
grep -q "self-shadowing  *[0-9.]* % of acne" measure-faint.out && pass "faint acne: self-shadowing as a share of acne" \
  || fail "faint acne causes: $(grep -A3 'causes of' measure-faint.out)"
ofacne=$(python3 -c "import json; print(json.load(open('faint.json'))['lights'][0]['causes']['selfShadowing']['percentOfAcne'])")
less_than 90 "$ofacne" && pass "faint acne: self-shadowing explains $ofacne % of acne" || fail "faint acne: $ofacne % of acne"

# Issue 9, observation 2: a 16² map says that acne and leak cannot judge it.
expect_ok measure-coarse "$SHADOWLAB" measure --scene builtin:textbook --preset default --set shadow.resolution=16 \
  --width 320 --height 180 --json coarse.json
grep -q "WARNING: coarse map.*cannot judge.*wrong pixels" measure-coarse.out && pass "coarse map warning printed" \
  || fail "no coarse-map warning: $(sed -n 2,9p measure-coarse.out)"
grep -q '"coarseMap": true' coarse.json && pass "JSON marks the coarse map" || fail "JSON coarseMap"

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
grep -q '"scene": "builtin:textbook"' tuned.json && pass "the tuned preset records its scene" \
  || fail "no scene in tuned.json"
expect_ok measure-tuned "$SHADOWLAB" measure --scene builtin:textbook --preset ./tuned.json --width 320 --height 180 \
  --json tuned-measure.json
tuned_acne=$(json_number tuned-measure.json acnePercent)
awk -v a="$tuned_acne" 'BEGIN { exit !(a <= 0.1) }' && pass "tuned preset measures $tuned_acne % acne" \
  || fail "tuned preset acne = '$tuned_acne'"
expect_ok render-tuned "$SHADOWLAB" render --scene builtin:textbook --preset ./tuned.json --width 64 --height 36 \
  --out tuned.png

# No setting can reach the limit: said so with the cause that stops it, no preset written, exit 3.
"$SHADOWLAB" tune --scene builtin:textbook --preset default --set projection.autoFit=false \
  --set projection.orthoSize=8 --set projection.near=0.01 --set projection.far=40 --set sampler.addressMode=wrap \
  --width 160 --height 90 --out hopeless.json >tune-hopeless.out 2>&1
rc=$?
[ $rc -eq 3 ] && pass "hopeless tune exits 3" || fail "hopeless tune exit $rc"
grep -q "NO setting reached.*stopped by outside the light's volume" tune-hopeless.out && [ ! -f hopeless.json ] \
  && pass "tune says when nothing reaches the limit, names the cause, writes no preset" \
  || fail "hopeless tune: $(grep -A1 'NO setting' tune-hopeless.out)"

# The roof: tune searches the cull mode and the result fixes the leak.
expect_ok tune-roof "$SHADOWLAB" tune --scene builtin:roof --preset default --width 320 --height 180 \
  --set shadow.cullMode=back --out roof-tuned.json
grep -q "^result:.*cullMode \(none\|front\)" tune-roof.out && pass "tune picks a cull mode for the roof" \
  || fail "roof tune: $(grep '^result' tune-roof.out)"

# Issue 21: a VSM preset tunes VSM's own keys (declared in vsm_filter.cpp) with a soft light: the preset gets them,
# the JSON has each candidate's values, soft numbers and cost.
expect_ok tune-vsm "$SHADOWLAB" tune --scene builtin:textbook --preset default --set filter.kind=vsm \
  --set filter.bleedReduction=0 --set lights.0.size=2 --set reference.softRays=64 --set lights.0.shadow.resolution=512 \
  --width 160 --height 90 --out vsm-tuned.json --json vsm-tune.json
grep -q "^result (vsm): .*filter.bleedReduction.*soft mean |S-V|" tune-vsm.out && pass "tune names VSM's chosen keys" \
  || fail "vsm tune: $(grep -A1 '^result' tune-vsm.out)"
python3 -c "
import json
light = json.load(open('vsm-tune.json'))['lights'][0]
assert light['tradeOffKeys'] == ['filter.minVariance', 'filter.bleedReduction'], light['tradeOffKeys']
assert all(s['tradeOffStep'] and s['costMs'] > 0 and s['soft'] for s in light['path']), light['path'][0]
tuned = json.load(open('vsm-tuned.json'))['filter']
assert tuned['bleedReduction'] == light['tradeOffChosen']['filter.bleedReduction'], tuned
" && pass "tune's JSON and preset hold the technique's values" || fail "vsm tune JSON / preset"

# Many lights (issue 10): a 2-light preset (the tuned sun plus a spot light) measured light by light, then the whole
# picture; --light N measures and tunes one light; a light that does not exist or does not cast is refused by key.
python3 - <<'PY'
import copy, json
p = json.load(open("tuned.json"))
spot = copy.deepcopy(p["lights"][0])
spot.update({"type": "spot", "position": [2, 6, 3], "direction": [-0.3, -1, -0.5]})
spot["shadow"].update({"depthBias": 0, "slopeScaledDepthBias": 0, "normalOffset": 0})
p["lights"].append(spot)
json.dump(p, open("two-lights.json", "w"), indent=2)
PY
expect_ok measure-two "$SHADOWLAB" measure --scene builtin:textbook --preset ./two-lights.json --width 320 \
  --height 180 --json two.json --overlay two.png --cause-overlay two-cause.png
grep -q "^lights.0 (directional)" measure-two.out && grep -q "^lights.1 (spot)" measure-two.out \
  && grep -q "^whole picture (2 lights measured" measure-two.out && pass "measure prints each light and the whole" \
  || fail "two lights: $(grep -E '^(lights|whole)' measure-two.out)"
python3 - <<'PY' && pass "JSON: lights[2] + whole, max(light wrong) <= whole wrong <= sum" || fail "two-light JSON"
import json, sys
d = json.load(open("two.json"))
wrong = [l["counts"]["wrong"] for l in d["lights"]]
w = d["whole"]["counts"]["wrong"]
ok = [l["index"] for l in d["lights"]] == [0, 1] and d["lights"][1]["type"] == "spot" and max(wrong) <= w <= sum(wrong)
ok = ok and wrong[1] > 0 and d["whole"]["lightsMeasured"] == 2
print("per light wrong", wrong, "whole", w)
sys.exit(0 if ok else 1)
PY
[ "$(png_size two.png)" = "320 180" ] && pass "union overlay written" || fail "union overlay: $(png_size two.png)"
expect_ok measure-light1 "$SHADOWLAB" measure --scene builtin:textbook --preset ./two-lights.json --width 320 \
  --height 180 --light 1 --json light1.json
python3 -c "
import json; a = json.load(open('light1.json')); b = json.load(open('two.json'))
assert [l['index'] for l in a['lights']] == [1] and a['lights'][0]['counts'] == b['lights'][1]['counts']" \
  && pass "--light 1 measures light 1 alone, with the numbers it has among two" || fail "--light 1: $(head -3 measure-light1.out)"
expect_ok measure-point "$SHADOWLAB" measure --scene builtin:textbook --preset ./two-lights.json \
  --set lights.2.type=point --set 'lights.2.position=[1,4,1]' --set lights.2.range=7 --light 2 --width 320 \
  --height 180 --json point.json --overlay point.png
python3 -c "
import json; l = json.load(open('point.json'))['lights'][0]
assert l['index'] == 2 and l['type'] == 'point', l['type']
assert l['counts']['outOfRange'] > 1000 and l['counts']['outsideCone'] == 0, l['counts']
assert l['wrongPixelsPercent'] < 5, l['wrongPixelsPercent']" \
  && pass "a point light is measured through its cube map; beyond its range is not counted" \
  || fail "point light: $(grep -E 'wrong pixels|pixels [0-9]' measure-point.out | head -2)"
expect_error light-5 "lights.5: no such light (the settings have 2 lights" "$SHADOWLAB" measure \
  --scene builtin:textbook --preset ./two-lights.json --light 5 --width 32 --height 32
expect_error tune-light-5 "lights.5: no such light" "$SHADOWLAB" tune --scene builtin:textbook \
  --preset ./two-lights.json --light 5 --width 32 --height 32 --out never.json
[ ! -f never.json ] && pass "a refused tune writes nothing" || fail "tune --light 5 wrote never.json"
expect_error light-no-shadow "lights.1.castsShadows is false" "$SHADOWLAB" measure --scene builtin:textbook \
  --preset ./two-lights.json --set lights.1.castsShadows=false --light 1 --width 32 --height 32
expect_ok tune-light1 "$SHADOWLAB" tune --scene builtin:textbook --preset ./two-lights.json --light 1 --width 320 \
  --height 180 --max-acne 0.1 --out two-tuned.json
python3 -c "
import json; a = json.load(open('two-lights.json')); b = json.load(open('two-tuned.json'))
assert b['lights'][0]['shadow'] == a['lights'][0]['shadow'], 'light 0 must stay'" \
  && pass "tune --light 1 keeps light 0's bias" || fail "tune --light 1 changed light 0: $(grep '^result' tune-light1.out)"
# What tune wrote is what it promised: light 1 measured again with the tuned preset (same view) is within the limit,
# where it started far above it.
expect_ok measure-tuned-light1 "$SHADOWLAB" measure --scene builtin:textbook --preset ./two-tuned.json --light 1 \
  --width 320 --height 180 --json light1-tuned.json
python3 -c "
import json; before = json.load(open('light1.json'))['lights'][0]; after = json.load(open('light1-tuned.json'))['lights'][0]
assert after['index'] == 1, after['index']
print('light 1 acne', before['acnePercent'], '% before tune,', after['acnePercent'], '% after (limit 0.1 %)')
assert before['acnePercent'] > 0.1, 'light 1 must start above the limit for the check to mean anything'
assert after['acnePercent'] <= 0.1, after['acnePercent']" \
  && pass "tune --light 1: light 1 measured again is within the limit it was given" \
  || fail "tune --light 1 re-measured: $(grep -A2 '^lights.1' measure-tuned-light1.out | head -3)"

# Live accuracy: --remeasure-bench times re-measures after a bias change on the GPU path and the CPU path, and both
# count the same frame alike.
expect_ok remeasure "$SHADOWLAB" measure --scene builtin:textbook --preset acne --width 320 --height 180 \
  --remeasure-bench 4
grep -q "^REMEASURE 320x180: [0-9.]* ms GPU (live) vs [0-9.]* ms CPU" remeasure.out && pass "remeasure-bench prints the figure" \
  || fail "remeasure-bench: $(tail -3 remeasure.out)"
grep -q "counts: GPU == CPU" remeasure.out && pass "GPU and CPU paths count alike" \
  || fail "remeasure counts: $(grep counts: remeasure.out)"
expect_error bad-remeasure "remeasure-bench" "$SHADOWLAB" measure --width 32 --height 32 --remeasure-bench 0

expect_error bad-key "no.such" "$SHADOWLAB" measure --set no.such=1
expect_error bad-scene "nope.gltf" "$SHADOWLAB" measure --scene /nonexistent/nope.gltf
expect_error bad-size "width" "$SHADOWLAB" measure --width 0
expect_error bad-json-dir "no-such-dir" "$SHADOWLAB" measure --width 32 --height 32 --json no-such-dir/x.json
expect_error bad-overlay-dir "no-such-dir" "$SHADOWLAB" measure --width 32 --height 32 --overlay no-such-dir/x.png
expect_error bad-max-acne "max-acne" "$SHADOWLAB" tune --max-acne -1 --width 32 --height 32
expect_error bad-tune-out "no-such-dir" "$SHADOWLAB" tune --width 32 --height 32 --out no-such-dir/t.json
expect_error bad-tune-range "shadow.resolution" "$SHADOWLAB" tune --set shadow.resolution=0

finish
