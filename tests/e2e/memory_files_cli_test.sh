#!/usr/bin/env bash
# End-to-end, issue 19 section 4 ("memory and files"), one check per class:
#  - a picture whose size is known before the work is refused before it, with the figures: the PNG writer's limit
#    (render 16384x16384, measure --overlay at that size) and the picture limit (a point light's 8192² faces as one
#    cross for --shadow-map-png / --shadow-map), at once and without the memory the work would take;
#  - a sweep keeps every finished point: a point that fails is reported with its reason beside the others, and each
#    finished point is in --json / --csv as soon as its progress line is printed (a sweep stopped midway keeps them).
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"

# refused_fast NAME PATTERN CMD...: non-zero exit, PATTERN in stderr, under 5 s and (where /usr/bin/time is there)
# under 300 MB resident: the refusal comes before the rendering and its memory.
refused_fast() {
  local name=$1 pattern=$2; shift 2
  local start=$SECONDS
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -f "%M" -o "$name.rss" "$@" >"$name.out" 2>"$name.err"
  else
    "$@" >"$name.out" 2>"$name.err"
  fi
  local rc=$? took=$((SECONDS - start))
  if [ $rc -eq 0 ]; then fail "$name: exited 0"; return; fi
  grep -q -- "$pattern" "$name.err" || { fail "$name: '$pattern' not in: $(cat "$name.err")"; return; }
  [ "$took" -lt 5 ] || { fail "$name: took ${took} s"; return; }
  if [ -f "$name.rss" ]; then
    local kb; kb=$(tail -1 "$name.rss")
    [ "$kb" -lt 300000 ] || { fail "$name: $kb KB resident"; return; }
  fi
  pass "$name (exit $rc, ${took} s)"
}

refused_fast render-16384 \
  "--out big.png: a 16384x16384 PNG of 4 channels needs 1073758208 bytes of encoder rows .* more than the PNG writer's limit of 1073741823 (it counts in int); at this width at most 16383 rows fit" \
  "$SHADOWLAB" render --scene builtin:fence --width 16384 --height 16384 --out big.png
[ ! -e big.png ] && pass "nothing written" || fail "big.png written"

refused_fast cross-png \
  "--shadow-map-png cross.png: a 32768x24576 picture (light 0's six 8192² faces as one cross, float depth) needs 3221225472 bytes (4 a pixel), more than the limit of 1073741824 bytes" \
  "$SHADOWLAB" render --scene builtin:fence --set lights.0.type=point --set lights.0.shadow.resolution=8192 \
  --width 64 --height 48 --out view.png --shadow-map-png cross.png
refused_fast cross-exr "--shadow-map cross.exr: a 32768x24576 picture" \
  "$SHADOWLAB" render --scene builtin:fence --set lights.0.type=point --set lights.0.shadow.resolution=8192 \
  --width 64 --height 48 --out view.png --shadow-map cross.exr
[ ! -e view.png ] && [ ! -e cross.png ] && pass "no render before the refusal" || fail "files written"
# The same faces at 1024² make a 4096x3072 cross: written.
expect_ok cross-1024 "$SHADOWLAB" render --scene builtin:fence --set lights.0.type=point \
  --set lights.0.shadow.resolution=1024 --width 64 --height 48 --out view.png --shadow-map-png cross.png
[ "$(png_size cross.png)" = "4096 3072" ] && pass "a 1024² cube's cross is 4096x3072" || fail "cross $(png_size cross.png)"

refused_fast measure-overlay "--overlay o.png: a 16384x16384 PNG of 4 channels needs 1073758208 bytes" \
  "$SHADOWLAB" measure --scene builtin:fence --width 16384 --height 16384 --overlay o.png

# A sweep whose castsShadows=false points fail: the others are measured and written, the failed ones listed with
# their reason (not measured, not on the front), the exit status says some failed.
sweep=("$SHADOWLAB" sweep --scene builtin:fence --width 64 --height 48)
"${sweep[@]}" --frames 1 --axis lights.0.castsShadows=true,false --axis shadow.resolution=64,128 --json f.json --csv f.csv \
  >f.out 2>f.err
rc=$?
[ $rc -ne 0 ] && grep -q "error: 2 of 5 points failed" f.err && pass "sweep with failing points: exit $rc, said" \
  || fail "sweep exit $rc: $(tail -2 f.err)"
grep -q "^\[3/5\] false 64 *failed: no light casts a shadow with these values" f.err \
  && pass "a failed point's progress line gives its reason" || fail "progress: $(cat f.err)"
python3 - <<'PY' && pass "JSON: measured points kept, failed ones with their reason, off the front" || fail "f.json"
import json
d = json.load(open("f.json"))
points = {p["label"]: p for p in d["points"]}
assert set(points) == {"true 64", "true 128", "false 64", "false 128"}, points.keys()
for label in ("true 64", "true 128"):
    assert points[label]["error"] == "" and points[label]["costMs"] > 0, points[label]
for label in ("false 64", "false 128"):
    assert "no light casts a shadow" in points[label]["error"], points[label]
    assert not points[label]["paretoFront"] and points[label]["costMs"] == 0, points[label]
assert all(step["label"].startswith("true") for step in d["paretoFront"]), d["paretoFront"]
PY
[ "$(grep -c 'no light casts a shadow' f.csv)" = "2" ] && [ "$(wc -l < f.csv)" = "6" ] \
  && pass "CSV: every point, the failed two with their reason" || fail "f.csv: $(cat f.csv)"

# Each finished point is in the files when its progress line appears: stopped during its slow 8192² point, the
# sweep has already written its first two.
"${sweep[@]}" --frames 3 --axis shadow.resolution=64,128,8192 --json k.json --csv k.csv >k.out 2>k.err &
pid=$!
for _ in $(seq 600); do grep -q '^\[2/4\]' k.err && break; kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
cp k.json k-copy.json 2>/dev/null; cp k.csv k-copy.csv 2>/dev/null
kill "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
python3 - <<'PY' && pass "a sweep's finished points are on disk as they finish" || fail "k.json after 2 points: $(cat k-copy.json 2>&1 | head -5)"
import json
d = json.load(open("k-copy.json"))
labels = [p["label"] for p in d["points"]]
assert labels[:2] == ["64", "128"] and all(p["error"] == "" for p in d["points"]), labels
PY
[ "$(head -1 k-copy.csv 2>/dev/null | cut -d, -f1)" = "label" ] && [ "$(wc -l < k-copy.csv)" -ge 3 ] \
  && pass "the CSV too" || fail "k.csv: $(cat k-copy.csv 2>&1)"

finish
