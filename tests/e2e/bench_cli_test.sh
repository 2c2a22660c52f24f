#!/usr/bin/env bash
# End-to-end: `bench`, `bench --lights` and `bench --planner` read through their JSON (issue 19: no test read it). Tiny and quick (a 64x36
# view, 2 frames a row, small maps). Every time is present, finite and positive; the JSON describes the lights it
# timed: their count, index and type from the preset, a point light's six views, each view's light; map memory is
# every light's maps at the row's resolution; bench --lights moves the spot it says and renders only its view, and the
# main-pass rows count 1, 2, 4 shadowed lights; a scene's own lights (useSceneLights) are the ones listed and sized; a
# preset without lights has no light and no shadow time.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
tiny=(--scene builtin:courtyard --preset courtyard --width 64 --height 36 --frames 2)
# The courtyard's maps made small; light 2 off (enabled false) so that the JSON must tell a light that casts nothing.
small=(--set lights.0.shadow.resolution=128 --set lights.1.shadow.resolution=64 --set lights.2.enabled=false
       --set lights.3.shadow.resolution=32)

expect_ok bench "$SHADOWLAB" bench "${tiny[@]}" "${small[@]}" --resolutions 64 128 --filters point pcf3 --json bench.json
expect_ok bench-lights "$SHADOWLAB" bench --lights "${tiny[@]}" "${small[@]}" --json lights.json
python3 - "$SOURCE_DIR/presets/courtyard.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1])); p["lights"] = []; json.dump(p, open("none.json", "w"))
PY
# The scene's own lights (useSceneLights): the JSON lists them and every row's resolution applies to their maps.
expect_ok bench-scene "$SHADOWLAB" bench --scene builtin:courtyard --preset default --set useSceneLights=true \
  --width 64 --height 36 --frames 2 --resolutions 32 64 --filters point --json scene-lights.json
expect_ok bench-none "$SHADOWLAB" bench --scene builtin:courtyard --preset ./none.json --width 64 --height 36 \
  --frames 2 --resolutions 64 --filters point --json no-lights.json

python3 - "$SOURCE_DIR/presets/courtyard.json" <<'PY' && pass "bench and bench --lights JSON: fields, times and lights" \
  || fail "bench JSON (above)"
import json, math, sys
preset = json.load(open(sys.argv[1]))
problems = []
def check(ok, what):
    if not ok: problems.append(what)
def positive(doc, key, where):
    v = doc.get(key)
    check(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0,
          f"{where}.{key} = {v!r}: not a finite positive number")

types = [l["type"] for l in preset["lights"]]
formats = [l["shadow"]["depthFormat"] for l in preset["lights"]]
check(types == ["directional", "spot", "spot", "point"] and formats == ["d32f"] * 4, f"courtyard preset changed: {types} {formats}")
enabled = [True, True, False, True]
want_lights = [{"index": i, "type": t, "enabled": e, "castsShadows": e, "views": (6 if t == "point" else 1) if e else 0}
               for i, (t, e) in enumerate(zip(types, enabled))]

b = json.load(open("bench.json"))
for key in ("width", "height", "frames", "triangles"):
    positive(b, key, "bench")
check(b["scene"] == "courtyard" and b["width"] == 64 and b["height"] == 36 and b["frames"] == 2, "bench: view/scene")
check(b.get("lights") == want_lights, f"bench.lights = {b.get('lights')}, expected {want_lights}")
check([(r["resolution"], r["filter"]) for r in b["rows"]] == [(64, "point"), (64, "pcf3"), (128, "point"), (128, "pcf3")],
      f"bench rows: {[(r['resolution'], r['filter']) for r in b['rows']]}")
layers = sum(l["views"] for l in want_lights)  # every casting light's views, one map layer each
for r in b["rows"]:
    for key in ("shadowMapMiB", "shadowPassMs", "mainPassMs", "wallMsPerFrame"):
        positive(r, key, f"bench.rows[{r['resolution']} {r['filter']}]")
    want = layers * r["resolution"] ** 2 * 4 / 2**20
    check(abs(r["shadowMapMiB"] - want) < 1e-9, f"bench row {r['resolution']}: shadowMapMiB {r['shadowMapMiB']}, "
          f"every light's maps are {layers} x {r['resolution']}^2 x 4 bytes = {want} MiB")

l = json.load(open("lights.json"))
for key in ("width", "height", "frames", "allViewsMs", "movedLightShadowMs"):
    positive(l, key, "bench --lights")
check(l.get("lights") == want_lights, f"bench --lights .lights = {l.get('lights')}")
resolution = {0: 128, 1: 64, 3: 32}
want_views = [(i, -1 if t != "point" else f) for i, t in enumerate(types) if enabled[i]
              for f in (range(6) if t == "point" else [-1])]
check([(v.get("light"), v.get("face")) for v in l["views"]] == want_views,
      f"views (light, face): {[(v.get('light'), v.get('face')) for v in l['views']]}, expected {want_views}")
for v in l["views"] if not problems else []:
    where = f"view {v['view']}"
    positive(v, "ms", where)
    check(v["kind"] == types[v["light"]] and v["view"].startswith(f"light {v['light']}"), f"{where}: light {v['light']} kind {v['kind']}")
    check(v["resolution"] == resolution[v["light"]], f"{where}: resolution {v['resolution']}")
    check(isinstance(v["castersDrawn"], int) and v["castersDrawn"] > 0, f"{where}: castersDrawn {v['castersDrawn']}")
check(abs(l["allViewsMs"] - sum(v["ms"] for v in l["views"])) < 1e-6 * l["allViewsMs"], "allViewsMs is not the views' sum")
check(l["staticFrameViews"] == 0, f"a static frame rendered {l['staticFrameViews']} views")
check(types[l["movedLight"]] == "spot" and l["movedLightViews"] == 1, f"moved light {l['movedLight']}: {l['movedLightViews']} views")
rows = l["mainPassByShadowedLights"]
check([r["lights"] for r in rows] == [1, 2, 4], f"main pass rows: {[r['lights'] for r in rows]}")
for r in rows:
    for key in ("shadowedMainMs", "unshadowedMainMs"):
        positive(r, key, f"mainPassByShadowedLights[{r['lights']}]")
    check(math.isfinite(r["shadowTapsMs"]) and abs(r["shadowTapsMs"] - (r["shadowedMainMs"] - r["unshadowedMainMs"])) < 1e-9,
          f"shadowTapsMs {r['shadowTapsMs']} is not shadowed - unshadowed")

sl = json.load(open("scene-lights.json"))
check([(x.get("index"), x.get("type"), x.get("views")) for x in sl.get("lights") or []] ==
      [(0, "directional", 1), (1, "spot", 1), (2, "spot", 1), (3, "point", 6)], f"scene lights: {sl.get('lights')}")
for r in sl["rows"]:
    want = 9 * r["resolution"] ** 2 * 4 / 2**20
    check(abs(r["shadowMapMiB"] - want) < 1e-9, f"scene-light row {r['resolution']}: shadowMapMiB {r['shadowMapMiB']}, "
          f"the scene's 9 views at {r['resolution']}^2 are {want} MiB")

n = json.load(open("no-lights.json"))
check(n.get("lights") == [], f"no-light bench: lights {n.get('lights')}")
for r in n["rows"]:
    positive(r, "mainPassMs", "no-light row")
    check(r["shadowMapMiB"] == 0 and r["shadowPassMs"] == 0, f"no-light row has a shadow pass: {r}")
for p in problems: print("  ", p)
sys.exit(1 if problems else 0)
PY

# bench --planner: the planner's CPU time with 8 lights and each cascade against a bare draw of what it holds, each
# line labelled (scene, lights, cascade). The courtyard's sun made cascaded (3 cascades of 64²).
expect_ok bench-planner "$SHADOWLAB" bench --planner --scene builtin:courtyard --preset courtyard --width 64 \
  --height 36 --frames 2 --set lights.0.projection.fit=cascades --set lights.0.projection.cascadeCount=3 \
  --set lights.0.shadow.resolution=64 --json planner.json
grep -q "^planner CPU time per frame, scene courtyard, 8 lights (2 directional cascaded, 3 spot, 3 point; 28 views), this thread's CPU time" \
  bench-planner.out && grep -Eq "^  camera moving: [0-9.]+ ms \([1-7] of 7 cascades re-rendered per frame\)" bench-planner.out \
  && grep -Eq "^  camera still:  [0-9.]+ ms \(0 views re-rendered\)" bench-planner.out \
  && pass "bench --planner: the planner's labelled lines" || fail "bench --planner: $(cat bench-planner.out)"
grep -q "^cascade shadow pass vs a bare depth draw of the casters it holds, scene courtyard, the settings' cascaded" \
  bench-planner.out && [ "$(grep -Ec '^  light 0 cascade:[0-2] +64² D32F +([0-9]+ casters .* shadow +[0-9.]+ ms  bare +[0-9.]+ ms  ratio [0-9.]+|skipped: no caster)' bench-planner.out)" = 3 ] \
  && grep -Eq ' ms  ratio [0-9.]+' bench-planner.out \
  && pass "bench --planner: one labelled line per cascade" || fail "bench --planner cascades: $(cat bench-planner.out)"
python3 - <<'PY' && pass "bench --planner JSON" || fail "bench --planner JSON (above)"
import json, math, sys
d = json.load(open("planner.json"))
ok = d["planner"]["lights"] == 8 and d["planner"]["views"] == 28 and d["planner"]["movingMeanMs"] > 0 \
     and [c["view"] for c in d["cascades"]] == ["light 0 cascade:0", "light 0 cascade:1", "light 0 cascade:2"] \
     and any(c["ran"] for c in d["cascades"]) \
     and all(c["shadowMs"] > 0 and c["bareMs"] > 0 and math.isfinite(c["ratio"]) for c in d["cascades"] if c["ran"])
print(json.dumps(d, indent=1)[:2000]) if not ok else None
sys.exit(0 if ok else 1)
PY
# A moments technique's cost split: the mips pass is its own column, nonzero with filter.momentMips, zero without.
mips=(--scene builtin:textbook --preset default --width 64 --height 36 --frames 2 --resolutions 64 --filters vsm)
expect_ok bench-mips "$SHADOWLAB" bench "${mips[@]}" --set filter.momentMips=true --json mips.json
expect_ok bench-no-mips "$SHADOWLAB" bench "${mips[@]}" --json no-mips.json
grep -Eq "^resolution +filter +map MiB +shadow ms +moments ms +blur ms +mips ms +main ms" bench-mips.out \
  && python3 - <<'PY' && pass "bench: the mips pass's column" || fail "bench mips column: $(cat bench-mips.out)"
import json, sys
on, off = json.load(open("mips.json"))["rows"][0], json.load(open("no-mips.json"))["rows"][0]
ok = on["mipsPassMs"] > 0 and on["blurPassMs"] > 0 and off["mipsPassMs"] == 0 and off["blurPassMs"] > 0
print(on, off) if not ok else None
sys.exit(0 if ok else 1)
PY
finish
