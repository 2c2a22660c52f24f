#!/usr/bin/env bash
# End-to-end: `cpack -G DEB` on the build. The .deb's fields (name, version, maintainer, description); its Depends
# name the Debian package of every shared library the binary links (dpkg-shlibdeps' versioned list, not a hand-written
# one); it holds usr/bin/shadowlab and usr/share/shadowlab/presets; extracted elsewhere with dpkg-deb -x, its
# shadowlab renders a shipped preset by name with the source and build trees hidden (hidden_tree_lib.sh).
# The install into a fresh Debian 12 root is scripts/package-check (minutes: not here).
# Needs: SOURCE_DIR, BUILD_DIR, OUT_DIR, CPACK (the cpack of the cmake that configured BUILD_DIR), VERSION.
set -uo pipefail
: "${SOURCE_DIR:?}" "${BUILD_DIR:?}" "${OUT_DIR:?}" "${CPACK:?}" "${VERSION:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
. "$SOURCE_DIR/tests/e2e/e2e_lib.sh"
. "$SOURCE_DIR/tests/e2e/hidden_tree_lib.sh"
for tool in dpkg-deb dpkg-shlibdeps file objdump; do
  command -v $tool >/dev/null || { echo "FAIL: $tool is not installed (scripts/install-deps)"; exit 1; }
done

"$CPACK" -G DEB --config "$BUILD_DIR/CPackConfig.cmake" -B "$OUT_DIR/pkg" >cpack.out 2>&1 || { cat cpack.out; fail "cpack -G DEB"; finish; exit; }
deb=$(ls pkg/*.deb 2>/dev/null)
[ "$(basename "$deb")" = "shadowlab_${VERSION}_$(dpkg --print-architecture).deb" ] && pass "cpack wrote $(basename "$deb")" \
  || { fail "no shadowlab_${VERSION}_*.deb: $(ls pkg) $(tail -5 cpack.out)"; finish; exit; }

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = shadowlab ] && [ "$(field Version)" = "$VERSION" ] && pass "Package shadowlab, Version $VERSION" \
  || fail "Package '$(field Package)', Version '$(field Version)'"
[[ "$(field Maintainer)" =~ ^[^\<]+\ \<[^@\>]+@[^\>]+\>$ ]] && pass "Maintainer: $(field Maintainer)" || fail "Maintainer '$(field Maintainer)'"
[ "$(field Description | wc -l)" -ge 3 ] && pass "Description: a summary and a long description" || fail "Description: $(field Description)"

root=$(cd "$(mktemp -d "${TMPDIR:-/tmp}/shadowlab-deb.XXXXXX")" && pwd -P)
trap 'cp "$root"/*.out "$root"/*.err "$OUT_DIR" 2>/dev/null; rm -rf "$root"' EXIT
dpkg-deb -x "$deb" "$root" || fail "dpkg-deb -x"

# Every linked library's package is in Depends, with dpkg-shlibdeps' minimum version (a hand list has none).
depends=$(field Depends)
echo "Depends: $depends"
objdump -p "$root/usr/bin/shadowlab" | awk '$1 == "NEEDED" {print $2}' >needed.txt
[ -s needed.txt ] || fail "no NEEDED libraries read from the packaged binary"
while read -r soname; do
  path=$(ldconfig -p | awk -v s="$soname" '$1 == s {print $NF; exit}')
  pkg=$(dpkg -S "$(readlink -f "$path")" 2>/dev/null | head -1 | cut -d: -f1)
  [ -n "$pkg" ] || pkg=$(dpkg -S "$path" 2>/dev/null | head -1 | cut -d: -f1)
  if [ -z "$pkg" ]; then fail "$soname: no Debian package owns $path"
  elif [[ ", $depends" == *", $pkg (>= "* ]]; then pass "Depends: $pkg (>= ...) for $soname"
  else fail "Depends lacks '$pkg (>= version)' for $soname: $depends"; fi
done <needed.txt

dpkg-deb -c "$deb" >contents.txt
for f in ./usr/bin/shadowlab ./usr/share/shadowlab/presets/default.json; do
  grep -q " $f\$" contents.txt && pass "the .deb holds $f" || fail "the .deb lacks $f: $(cat contents.txt)"
done

# Extracted outside the trees (above) and run with them hidden.
hide_trees "$SOURCE_DIR" "$BUILD_DIR"
[ -z "$hidden_note" ] && pass "source and build trees hidden from the extracted binary" || echo "note: $hidden_note"
cd "$root"
expect_ok deb-render hidden "$root/usr/bin/shadowlab" render --scene builtin:grazing --preset soft --width 64 --height 48 \
  --out render.png
[ "$(png_size render.png 2>/dev/null)" = "64 48" ] && pass "the extracted .deb renders preset soft" || fail "render.png"
finish
