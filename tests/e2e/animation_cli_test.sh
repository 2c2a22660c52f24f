#!/usr/bin/env bash
# Animated scenes on the command line (tests/data/scenes/animated_boxes.gltf): render --time at two times casts
# different shadows while the same time twice, or --animation none, draws the same; --animation and --time reach
# the keys; an unknown animation is refused naming the key and listing the file's; a hostile animation is skipped
# with a warning naming the file, the animation and the channel; measure --motion animation plays it; on
# builtin:city-traffic the reference follows each step by an update; bench --reference-update times it.
set -u
mkdir -p "$OUT_DIR" && cd "$OUT_DIR" || exit 1
source "$SOURCE_DIR/tests/e2e/e2e_lib.sh"
boxes="$SOURCE_DIR/tests/data/scenes/animated_boxes.gltf"
small=(--scene "$boxes" --width 160 --height 90 --set shadow.resolution=256)

# Bytes that differ between two PNGs (the writer is deterministic: the same picture is the same file).
differing() { cmp -l "$1" "$2" 2>/dev/null | wc -l; }

for t in 0 1.5; do
  expect_ok "render-$t" "$SHADOWLAB" render "${small[@]}" --time "$t" --animation Move --out "t$t.png" \
    --shadow-map-png "map$t.png"
done
expect_ok render-0-again "$SHADOWLAB" render "${small[@]}" --time 0 --animation Move --out t0-again.png \
  --shadow-map-png map0-again.png
n=$(differing map0.png map1.5.png)
[ "$n" -gt 0 ] && pass "the shadow maps at 0 s and 1.5 s differ ($n bytes)" || fail "the shadow maps at 0 s and 1.5 s are the same"
n=$(differing t0.png t1.5.png)
[ "$n" -gt 0 ] && pass "the views at 0 s and 1.5 s differ ($n bytes)" || fail "the views at 0 s and 1.5 s are the same"
n=$(differing map0.png map0-again.png)
[ "$n" -eq 0 ] && pass "0 s twice: the same map" || fail "0 s twice: $n values differ"
grep -q 'playing Move at 1.5 s' render-1.5.err && pass "the note names the animation and the time" \
  || fail "no note: $(cat render-1.5.err)"
for t in 0 1.5; do
  expect_ok "none-$t" "$SHADOWLAB" render "${small[@]}" --time "$t" --animation none --shadow-map-png "none$t.png"
done
n=$(differing none0.png none1.5.png)
[ "$n" -eq 0 ] && pass "--animation none: the file's pose at any time" || fail "--animation none: $n values differ"
# The same time through --set.
expect_ok render-set "$SHADOWLAB" render "${small[@]}" --set animation.time=1.5 --set animation.play=Move \
  --shadow-map-png map-set.png
n=$(differing map1.5.png map-set.png)
[ "$n" -eq 0 ] && pass "--time is animation.time" || fail "--time and --set animation.time differ ($n values)"

expect_error unknown-animation 'animation.play "Walk": the scene animated_boxes has no animation of that name or index (it has 0 "Move", 1 "Spin", 2 "Cubic"; or all, none)' \
  "$SHADOWLAB" render "${small[@]}" --animation Walk
# check poses each case's scene too: an animation the file lacks cannot be judged (exit 2), naming the key.
"$SHADOWLAB" check "${small[@]}" --set animation.play=Walk --max-wrong 100 >check-walk.out 2>check-walk.err
rc=$?
[ $rc -eq 2 ] && grep -q 'animation.play "Walk"' check-walk.out check-walk.err && pass "check: the case's animation is posed" \
  || fail "check --set animation.play=Walk: exit $rc, $(cat check-walk.out check-walk.err | head -5)"
expect_error negative-time "--time" "$SHADOWLAB" render "${small[@]}" --time -1
expect_ok hostile "$SHADOWLAB" render --scene "$SOURCE_DIR/tests/fuzz/regressions/gltf/anim-missing-node.gltf" \
  --width 64 --height 36 --set shadow.resolution=128
grep -q 'warning: anim-missing-node: animation 0 "Move", channel 0 (node 99 translation): it targets node 99, which does not exist' hostile.err \
  && pass "the hostile animation is named and skipped" || fail "hostile: $(cat hostile.err)"

# render --compare: each side at its own preset's animation time (B is not drawn at A's pose). A shot's PNG carries
# its preset; B's numbers beside A equal B's beside itself, and differ from A's.
expect_ok shot-a "$SHADOWLAB" render "${small[@]}" --time 0 --animation Move --out shot-a.png
expect_ok shot-b "$SHADOWLAB" render "${small[@]}" --time 1.5 --animation Move --out shot-b.png
expect_ok compare-ab "$SHADOWLAB" render --scene "$boxes" --width 160 --height 90 --preset shot-a.png --compare shot-b.png \
  --measure --out ab.png
expect_ok compare-bb "$SHADOWLAB" render --scene "$boxes" --width 160 --height 90 --preset shot-b.png --compare shot-b.png \
  --measure --out bb.png
expect_ok compare-aa "$SHADOWLAB" render --scene "$boxes" --width 160 --height 90 --preset shot-a.png --compare shot-a.png \
  --measure --out aa.png
b_ab=$(grep '^B: shot-b.png: acne' compare-ab.out); b_bb=$(grep '^B: shot-b.png: acne' compare-bb.out)
a_aa=$(grep '^B: shot-a.png: acne' compare-aa.out)
[ -n "$b_ab" ] && [ "$b_ab" = "$b_bb" ] && pass "compare: B at its own time ($b_ab)" \
  || fail "compare: B beside A reads '$b_ab', B beside itself '$b_bb'"
[ "${b_ab#B: shot-b.png: }" != "${a_aa#B: shot-a.png: }" ] && pass "compare: the two times read differently" \
  || fail "compare: A's time and B's read the same ('$a_aa'): the check cannot tell them apart"
grep -q 'note: B: .*playing Move at 1.5 s' compare-ab.err && pass "compare: B's pose is said" \
  || fail "compare: no note of B's pose: $(cat compare-ab.err)"

expect_ok motion "$SHADOWLAB" measure "${small[@]}" --animation Move --motion animation --frames 3 --step 0.5 \
  --json motion.json
grep -q "animation moved 0.5 seconds per frame, 3 frames, 2 pairs" motion.out && pass "measure --motion animation" \
  || fail "motion: $(head -5 motion.out)"
python3 -c "import json,sys; j=json.load(open('motion.json')); sys.exit(0 if j['vChangedPercent']['max']>0 else 1)" \
  && pass "the moving box changes the true shadow" || fail "no V change along the animation: $(head -c 600 motion.json)"
expect_error motion-static "has no animation to play" "$SHADOWLAB" measure --scene builtin:textbook --width 64 \
  --height 36 --motion animation --step 0.1

# builtin:city-traffic: its cars' shadows move along the animation, and the reference follows each step with an
# update of its top level (no rebuild) after the first frame.
expect_ok traffic "$SHADOWLAB" measure --scene builtin:city-traffic --set useSceneLights=true --motion animation \
  --frames 3 --step 0.2 --width 320 --height 180 --json traffic.json
python3 - <<'PY' && pass "city-traffic: the cars change the true shadow; the reference is updated, not rebuilt" \
  || fail "city-traffic motion (above)"
import json, sys
j = json.load(open("traffic.json"))
frames = j["perFrame"]
problems = []
if not j["vChangedPercent"]["max"] > 0: problems.append("no V change: %s" % j["vChangedPercent"])
if frames[0]["reference"]["bvhUpdated"]: problems.append("frame 0 updated a BVH it did not have")
for f in frames[1:]:
    c = f["reference"]
    if not (c["bvhUpdated"] and c["bvhBuildMs"] == 0 and c["instancesMoved"] == 6):
        problems.append("frame not updated: %s" % c)
print("\n".join(problems))
sys.exit(1 if problems else 0)
PY
expect_ok reference-update "$SHADOWLAB" bench --reference-update --scene builtin:city-traffic --frames 4 \
  --json reference-update.json
python3 - <<'PY' && pass "bench --reference-update: one move, a whole step and a rebuild timed" \
  || fail "bench --reference-update JSON (above)"
import json, sys
j = json.load(open("reference-update.json"))
ok = j["instancesMovedByStep"] == 6 and j["meshBvhs"] > 2000 and all(j[k] > 0 for k in ("updateOneMs", "updateStepMs", "rebuildMs"))
print(j)
sys.exit(0 if ok else 1)
PY
expect_error reference-update-static "builtin:city-traffic has one" "$SHADOWLAB" bench --reference-update \
  --scene builtin:textbook
finish
