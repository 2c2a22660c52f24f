# Shared by the end-to-end scripts (source it after `cd "$OUT_DIR"`): pass/fail bookkeeping and checks on the
# real binary's exit codes, messages and output files.
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok: $*"; }

# expect_ok NAME CMD...: exit 0
expect_ok() {
  local name=$1; shift
  if "$@" >"$name.out" 2>"$name.err"; then pass "$name"; else fail "$name (exit $?): $(cat "$name.err")"; fi
}
# expect_error NAME PATTERN CMD...: non-zero exit and PATTERN in stderr
expect_error() {
  local name=$1 pattern=$2; shift 2
  "$@" >"$name.out" 2>"$name.err"
  local rc=$?
  if [ $rc -eq 0 ]; then fail "$name: exited 0"; return; fi
  if grep -q -- "$pattern" "$name.err"; then pass "$name (exit $rc)"; else fail "$name: '$pattern' not in: $(cat "$name.err")"; fi
}
# png_size FILE -> "W H" from the IHDR chunk
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'; }
# finish: the summary line and the script's exit status
finish() { echo "$failures failure(s)"; [ "$failures" -eq 0 ]; }
