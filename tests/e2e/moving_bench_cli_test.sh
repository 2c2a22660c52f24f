#!/usr/bin/env bash
# Issue 22, "What it measures", read through the JSON (tests/data/scenes/animated_boxes.gltf playing "Spin": only the
# Spinner moves, a 90-degree turn between 0 and 1 s; the default preset's sun, a 1024² map):
# - bench --animation: with cachedStatic each moving frame redraws the one view as static + dynamic, its shadow pass
#   cheaper than the same frame re-rendered whole (everyFrame); the still frame renders no view (everyFrame: all).
# - bench --animation --cache-error: everyFrame, onChange and cachedStatic read a cache error of 0 against the frame
#   re-rendered; everyNthFrame 4 does not, and saves time; the Spinner flagged static (casters.static) has a cache
#   error and a warning naming it.
# - bench --walk: the camera walks down builtin:city's street; stable cachedStatic cascades scroll and draw a small
#   share of their texels, everyFrame all of them.
# - sweep --play: shadow.update and updateInterval as axes, each point played from its animation.time and measured at
#   its last frame: everyNthFrame 4 draws no view after the first frame and reads more wrong pixels than everyFrame.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
boxes=(--scene "$SOURCE_DIR/tests/data/scenes/animated_boxes.gltf" --set lights.0.direction=-0.3,-1,-0.2
       --set lights.0.shadow.resolution=1024)

expect_ok bench-animation "$SHADOWLAB" bench "${boxes[@]}" --width 160 --height 90 --animation Spin --frames 6 \
  --step 0.1 --set lights.0.shadow.update=cachedStatic --json animation.json
python3 - <<'PY' && pass "bench --animation: cached frames cheaper than full, a still frame renders no view" \
  || fail "bench --animation JSON (above)"
import json, sys
j = json.load(open("animation.json"))
problems = []
frames = j["perFrame"]
if len(frames) != 7 or not frames[-1]["still"]: problems.append("6 frames and a still one expected: %d" % len(frames))
for f in frames[1:-1]:
    c, u = f["cached"], f["full"]
    if c["viewsStaticPlusDynamic"] != 1 or c["viewsRendered"] != 1:
        problems.append("frame %d: cached views %s" % (f["frame"], c))
    if u["viewsFull"] != 1: problems.append("frame %d: full views %s" % (f["frame"], u))
still = frames[-1]
if still["cached"]["viewsRendered"] != 0 or still["cached"]["viewsReused"] != 1:
    problems.append("still frame, cached: %s" % still["cached"])
if still["full"]["viewsRendered"] != 1: problems.append("still frame, full: %s" % still["full"])
s = j["summary"]
if not (0 < s["cachedMedianMs"] < s["fullMedianMs"]): problems.append("cached not cheaper: %s" % s)
if s["stillFrameViewsRendered"] != 0: problems.append("summary still frame: %s" % s)
if j["cpuTimes"] != j["timingSource"].startswith("CPU"): problems.append("cpuTimes: %s" % j["timingSource"])
print("\n".join(problems) or s)
sys.exit(1 if problems else 0)
PY
grep -q "^still" bench-animation.out && pass "the still frame is in the table" || fail "no still row: $(cat bench-animation.out)"

expect_ok cache-error "$SHADOWLAB" bench "${boxes[@]}" --width 120 --height 120 --animation Spin --frames 6 \
  --step 0.15 --cache-error --intervals 4 --json cache-error.json
python3 - <<'PY' && pass "bench --cache-error: 0 for the exact policies, > 0 for everyNthFrame and a static-flagged mover" \
  || fail "bench --cache-error JSON (above)"
import json, sys
j = json.load(open("cache-error.json"))
rows = {r["policy"]: r for r in j["cacheError"]}
problems = []
for name in ("everyFrame", "onChange", "cachedStatic"):
    r = rows[name]
    if r["cacheWrongPercentMax"] != 0 or r["cacheMeanErrorMax"] != 0: problems.append("%s: %s" % (name, r))
nth = rows["everyNthFrame 4"]
if not nth["cacheWrongPercentMax"] > 0: problems.append("everyNthFrame 4 has no cache error: %s" % nth)
if not nth["wrongPercentMax"] > rows["everyFrame"]["wrongPercentMax"]: problems.append("everyNthFrame 4 vs reference")
if not nth["savedPercent"] > 0: problems.append("everyNthFrame 4 saves nothing: %s" % nth)
flagged = rows.get("cachedStatic, Spinner static")
if not flagged: problems.append("no flagged policy: %s" % list(rows))
else:
    if not flagged["cacheWrongPercentMax"] > 0: problems.append("flagged Spinner: no cache error %s" % flagged)
    if not any("casters.static: Spinner moved" in w for w in flagged["warnings"]): problems.append("no warning: %s" % flagged["warnings"])
for name, r in rows.items():
    if name != "cachedStatic, Spinner static" and r["warnings"]: problems.append("%s warns: %s" % (name, r["warnings"]))
print("\n".join(problems) or {k: (r["cacheWrongPercentMax"], r["savedPercent"]) for k, r in rows.items()})
sys.exit(1 if problems else 0)
PY
grep -q "warning: cachedStatic, Spinner static: casters.static: Spinner moved but is a static caster" cache-error.err \
  && pass "the static-flagged Spinner is named in a warning" || fail "no warning: $(cat cache-error.err)"

expect_ok sweep-play "$SHADOWLAB" sweep "${boxes[@]}" --width 120 --height 120 --set animation.play=Spin \
  --axis lights.0.shadow.update=everyFrame,everyNthFrame --axis lights.0.shadow.updateInterval=4 --play 4 --step 0.15 \
  --json sweep.json
python3 - <<'PY' && pass "sweep --play: the policy and N as axes, each point played and measured at its last frame" \
  || fail "sweep --play JSON (above)"
import json, sys
j = json.load(open("sweep.json"))
pts = {p["values"]["lights.0.shadow.update"]: p for p in j["points"]}
problems = []
if j.get("play") != {"frames": 4, "step": 0.15}: problems.append("play: %s" % j.get("play"))
full, nth = pts["everyFrame"], pts["everyNthFrame"]
for p in (full, nth):
    if abs(p["playedTime"] - 0.45) > 1e-6: problems.append("measured at %s" % p["playedTime"])
if full["viewsRenderedPerFrame"] != 1 or nth["viewsRenderedPerFrame"] != 0:
    problems.append("views per frame: %s, %s" % (full["viewsRenderedPerFrame"], nth["viewsRenderedPerFrame"]))
if not nth["shadowPassMs"] < full["shadowPassMs"]: problems.append("ms: %s vs %s" % (nth["shadowPassMs"], full["shadowPassMs"]))
if not nth["wrongPixelsPercent"] > full["wrongPixelsPercent"]:
    problems.append("wrong: %s vs %s" % (nth["wrongPixelsPercent"], full["wrongPixelsPercent"]))
print("\n".join(problems) or {k: (p["shadowPassMs"], p["wrongPixelsPercent"]) for k, p in pts.items()})
sys.exit(1 if problems else 0)
PY

# bench --cache-error on builtin:city-traffic (its sun, four cascades): the camera sees the first car that moves (from
# the default street camera every policy read 0): everyNthFrame 4 reads a cache error there, everyFrame 0.
expect_ok city-cache-error "$SHADOWLAB" bench --scene builtin:city-traffic --width 160 --height 90 --animation \
  --frames 5 --step 0.1 --cache-error --intervals 4 --set useSceneLights=true --set lights.0.projection.fit=cascades \
  --json city-cache-error.json
python3 - <<'PY' && pass "bench --cache-error on the city: its camera sees car-0, everyNthFrame 4 reads an error" \
  || fail "bench --cache-error city JSON (above)"
import json, sys
j = json.load(open("city-cache-error.json"))
rows = {r["policy"]: r for r in j["cacheError"]}
problems = []
if not j["camera"]["onMover"]: problems.append("camera: %s" % j["camera"])
for name in ("everyFrame", "cachedStatic"):
    if rows[name]["cacheWrongPercentMax"] != 0 or rows[name]["cacheMeanErrorMax"] != 0: problems.append("%s: %s" % (name, rows[name]))
nth = rows["everyNthFrame 4"]
if not (nth["cacheWrongPercentMean"] > 0 and nth["cacheMeanErrorMean"] > 0): problems.append("everyNthFrame 4: %s" % nth)
print("\n".join(problems) or {k: (r["cacheWrongPercentMean"], r["savedPercent"]) for k, r in rows.items()})
sys.exit(1 if problems else 0)
PY
grep -q "^camera: on car-0 (the first caster that moves" city-cache-error.out && pass "the camera names the car it sees" \
  || fail "no camera line: $(cat city-cache-error.out)"

# bench --walk: the camera walks down builtin:city's street (0.4 m a frame) with a cachedStatic sun in four stable
# cascades: the cached frames scroll some cascade (re-drawing a strip) and reuse others, so the texels drawn are a
# small share of the full re-render's, which draws every texel of every cascade every frame.
walk=(--scene builtin:city --width 160 --height 90 --set lights.0.projection.fit=cascades
      --set lights.0.projection.cascadeCount=4 --set lights.0.projection.cascadeFit=stable
      --set lights.0.projection.depthBounds=off --set lights.0.shadow.resolution=512
      --set lights.0.shadow.update=cachedStatic)
expect_ok walk "$SHADOWLAB" bench "${walk[@]}" --walk 0,0,-0.4 --frames 8 --json walk.json
python3 - <<'PY' && pass "bench --walk: cascades scroll, a small share of texels drawn; everyFrame draws them all" \
  || fail "bench --walk JSON (above)"
import json, sys
j = json.load(open("walk.json"))
problems = []
if j.get("walk") != [0, 0, -0.4]: problems.append("walk: %s" % j.get("walk"))
if j["played"]: problems.append("a walk alone plays no animation")
if j["device"].split(":")[0] != ("CPU" if j["cpuTimes"] else "GPU"): problems.append("device: %s" % j["device"])
frames = j["perFrame"]
if len(frames) != 9 or not frames[-1]["still"]: problems.append("8 frames and a still one expected: %d" % len(frames))
scrolled = 0
for f in frames[1:-1]:
    c, u = f["cached"], f["full"]
    scrolled += c["viewsScrolled"]
    if u["viewsFull"] != 4 or u["texelsRenderedPercent"] != 100: problems.append("frame %d full: %s" % (f["frame"], u))
    for v in c["views"]:
        if v["cache"] == "scrolled" and not (0 < v["texelsRendered"] < v["texels"] / 10):
            problems.append("frame %d %s scrolled: %s" % (f["frame"], v["view"], v))
        if v["cache"] == "reused" and v["texelsRendered"] != 0: problems.append("reused view drew texels: %s" % v)
if scrolled < 2: problems.append("only %d cascade draws scrolled" % scrolled)
s = j["summary"]
if not (0 < s["cachedTexelsRenderedPercent"] < 50): problems.append("cached texels drawn: %s" % s)
if s["fullTexelsRenderedPercent"] != 100: problems.append("full texels drawn: %s" % s)
if not (0 < s["cachedTotalMs"] < s["fullTotalMs"]): problems.append("cached not cheaper: %s" % s)
if s["stillFrameViewsRendered"] != 0 or s["stillFrameFullViewsRendered"] != 4: problems.append("still frame: %s" % s)
if sum(v["framesScrolled"] for v in j["perView"]) != scrolled: problems.append("perView: %s" % j["perView"])
print("\n".join(problems) or s)
sys.exit(1 if problems else 0)
PY
grep -q "scrolled [0-9.]*% " walk.out && pass "the per-view table shows the scrolled cascades" \
  || fail "no scrolled cell: $(cat walk.out)"
expect_error walk-zero "--walk 0,0,0: the camera's move per frame must be non-zero" "$SHADOWLAB" bench \
  --scene builtin:city --walk 0,0,0
expect_error walk-bad "--walk '1,2': expected three numbers x,y,z" "$SHADOWLAB" bench --scene builtin:city --walk 1,2

expect_error no-animation "has no animation to play" "$SHADOWLAB" bench --scene builtin:textbook --width 64 \
  --height 36 --animation --frames 2
expect_error bad-step "--step 'x': not a finite number" "$SHADOWLAB" bench "${boxes[@]}" --animation Spin --step x
expect_error cache-error-alone "cache-error requires --animation" "$SHADOWLAB" bench --scene builtin:textbook --cache-error
finish
