#!/usr/bin/env bash
# End-to-end: `shadowlab probe` (issue 13, "Why this pixel"), headless. A lit floor pixel and a shadowed one print
# their taps, bias terms and S on CPU and GPU in agreement; --json holds the same; --measure adds the exact verdict;
# a pixel outside the view, a malformed --pixel and the background are refused with a message naming the cause.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
json() { python3 -c "import json,sys; d=json.load(open('$1')); print(eval(sys.argv[1]))" "$2"; }

# Top-down view of textbook, light from -x: the floor is lit at the left edge; a box's shadow covers pixel 82,98.
view=(--scene builtin:textbook --preset default --width 200 --height 200 --set camera.autoFrame=false
      --set camera.position=[0,30,0.001] --set camera.target=[0,0,0] --set light.direction=[-1,-1,0])
expect_ok probe-lit "$SHADOWLAB" probe "${view[@]}" --pixel 30,100 --json lit.json --measure
for word in "surface: world" "light view" "texel coord" "receiver depth" "constant DepthBias" "slope-scaled" \
    "normal offset" "filter PCF 3x3: 9 taps" "agree" "exact visibility: lit"; do
  grep -q "$word" probe-lit.out && pass "probe prints '$word'" || fail "probe output lacks '$word': $(head -3 probe-lit.out)"
done
[ "$(json lit.json "d['shadow']['cpu']")" = "1.0" ] && pass "lit floor pixel: S = 1" || fail "lit S: $(json lit.json "d['shadow']")"
[ "$(json lit.json "len(d['filter']['taps'])")" = "9" ] && pass "JSON has 9 taps" || fail "JSON taps"
[ "$(json lit.json "d['shadow']['agree']")" = "True" ] && pass "JSON: CPU and GPU agree" || fail "JSON agree"
[ "$(json lit.json "d['accuracy']['exact']")" = "lit (V = 1)" ] && pass "JSON: exact visibility" || fail "JSON accuracy"

# In the shadow: S = 0, every tap's stored depth in front of the receiver.
expect_ok probe-shadow "$SHADOWLAB" probe "${view[@]}" --pixel 82,98 --json shadow.json
[ "$(json shadow.json "d['shadow']['gpu']")" = "0.0" ] && pass "pixel under the box: S = 0" \
  || fail "shadow S: $(json shadow.json "d['shadow']")"
[ "$(json shadow.json "all(t['texels'][0]['stored'] < d['receiverDepth'] for t in d['filter']['taps'])")" = "True" ] \
  && pass "every tap under the box stores a nearer caster" || fail "taps: $(grep tap probe-shadow.out | head -3)"

expect_error probe-outside "outside the 200x200 view" "$SHADOWLAB" probe "${view[@]}" --pixel 200,10
expect_error probe-malformed "expected X,Y" "$SHADOWLAB" probe "${view[@]}" --pixel 12x5
expect_error probe-background "shows no surface (background)" "$SHADOWLAB" probe --scene builtin:textbook \
  --preset default --width 200 --height 200 --pixel 0,0
expect_error probe-bad-set "shadow.depthBias" "$SHADOWLAB" probe "${view[@]}" --pixel 5,5 --set shadow.depthBias=abc
[ ! -e bad.json ] && pass "nothing written on failure" || fail "bad.json written"
finish
