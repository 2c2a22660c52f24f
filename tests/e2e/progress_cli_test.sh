#!/usr/bin/env bash
# End-to-end: the progress line of long CLI work (issue 23). On a terminal (stderr on a pseudo-terminal, pty_run.py)
# check, sweep, tune, hardcases and measure draw "WHAT done/total UNIT, mm:ss elapsed, ..." and erase it at the end;
# piped, or with CI set, not a byte of it reaches the output; stdout never holds it.
# Needs: SHADOWLAB, SOURCE_DIR, OUT_DIR.
set -uo pipefail
: "${SHADOWLAB:?}" "${SOURCE_DIR:?}" "${OUT_DIR:?}"
rm -rf "$OUT_DIR" && mkdir -p "$OUT_DIR" && cd "$OUT_DIR"
unset DISPLAY WAYLAND_DISPLAY
. "$(dirname "${BASH_SOURCE[0]}")/e2e_lib.sh"
pty_run="$(dirname "${BASH_SOURCE[0]}")/pty_run.py"

# progress NAME LINE-PATTERN CMD...: drawn on a terminal outside CI, absent when piped or under CI.
progress() {
  local name=$1 pattern=$2; shift 2
  env -u CI python3 "$pty_run" "$name.tty.err" "$@" >"$name.tty.out" || fail "$name on a terminal: exit $?"
  grep -qaE "$pattern" "$name.tty.err" && pass "$name: progress drawn on a terminal" \
    || fail "$name: no '$pattern' on the terminal: $(head -c 400 "$name.tty.err" | cat -v)"
  # The last thing on the terminal erases the line: nothing of it is left once the work ends.
  tail -c 4 "$name.tty.err" | od -An -c | grep -q '\\r 033   \[   K' && pass "$name: the line is erased at the end" \
    || fail "$name: the terminal ends with: $(tail -c 80 "$name.tty.err" | cat -v)"
  env -u CI "$@" >"$name.pipe.out" 2>"$name.pipe.err" || fail "$name piped: exit $?"
  CI=true python3 "$pty_run" "$name.ci.err" "$@" >"$name.ci.out" || fail "$name under CI: exit $?"
  # Never on stdout, not even at a terminal; nothing on stderr when piped or under CI.
  for f in "$name.tty.out" "$name.pipe.out" "$name.pipe.err" "$name.ci.err" "$name.ci.out"; do
    if grep -qaE 'elapsed|estimating time left' "$f" || grep -qa $'\033\[K' "$f"; then
      fail "$name: progress text in $f: $(head -c 300 "$f" | cat -v)"
    else
      pass "$name: quiet in $f"
    fi
  done
}

view=(--width 320 --height 180)
progress check 'check [0-9]+/1 cases, [0-9]{2}:[0-9]{2} elapsed' \
  "$SHADOWLAB" check --scene builtin:textbook --preset default "${view[@]}" --max-acne 1 --out-dir check-overlays
progress sweep 'sweep [0-9]+/2 points, [0-9]{2}:[0-9]{2} elapsed' \
  "$SHADOWLAB" sweep --scene builtin:textbook --preset default "${view[@]}" --frames 2 --axis shadow.resolution=512,1024
progress tune 'tune 0/1 lights, [0-9]{2}:[0-9]{2} elapsed' \
  "$SHADOWLAB" tune --scene builtin:textbook --preset default "${view[@]}" --out tuned.json
progress hardcases 'hardcases [0-9]+/1 cases, [0-9]{2}:[0-9]{2} elapsed' "$SHADOWLAB" hardcases --quick --case 12
progress measure 'measure [0-9]+ %, [0-9]{2}:[0-9]{2} elapsed' \
  "$SHADOWLAB" measure --scene builtin:textbook --preset default "${view[@]}"
finish
