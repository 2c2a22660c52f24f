# Shared by the install and package tests (source it): run an installed shadowlab with the source and build trees out
# of its reach. hide_trees DIR... sets the folders to hide; hidden CMD... runs CMD in a private mount namespace where
# each is an empty read-only tmpfs (unshare: util-linux; a user namespace when not root). Where no
# namespace can be made, `hidden` runs CMD as it is and $hidden_note says why: the tests' other proof (no path into
# the trees in the binary's read-only data) still holds. hidden_wrapper FILE BINARY writes a script that execs BINARY
# hidden (for editor_lib.sh's $SHADOWLAB: its pid is the program's).
hidden_dirs=()
hidden_note=""
# root needs no user namespace (and cannot make one in a chroot, as fresh-debian-check runs scripts/test)
_unshare=(unshare --mount)
[ "$(id -u)" -eq 0 ] || _unshare+=(--map-root-user)
# The namespace's first command: mount a tmpfs over each of the N folders that follow N, then exec the rest.
_hidden_mounts='n=$1; shift; for ((i = 0; i < n; i++)); do mount -t tmpfs -o ro,size=4k none "$1" || exit 97; shift; done; exec "$@"'
hide_trees() {
  hidden_dirs=()
  local dir kept out
  # A folder inside one already hidden is gone with it (and is no mount point any more).
  for dir in "$@"; do
    for kept in "${hidden_dirs[@]}"; do [[ "$dir/" == "$kept"/* ]] && continue 2; done
    hidden_dirs+=("$dir")
  done
  # Hidden means empty: the check looks inside the first folder from within the namespace.
  if ! out=$(hidden bash -c '[ -z "$(ls -A "$1")" ] || { echo "still has files"; exit 1; }' _ "$1" 2>&1); then
    hidden_note="cannot hide ${hidden_dirs[*]} (${_unshare[*]}: $out)"
    hidden_dirs=()
  fi
}
hidden() {
  if [ ${#hidden_dirs[@]} -eq 0 ]; then "$@"; return; fi
  "${_unshare[@]}" bash -c "$_hidden_mounts" _ "${#hidden_dirs[@]}" "${hidden_dirs[@]}" "$@"
}
hidden_wrapper() {
  local file=$1 binary=$2
  {
    echo '#!/usr/bin/env bash'
    if [ ${#hidden_dirs[@]} -eq 0 ]; then
      printf 'exec %q "$@"\n' "$binary"
    else
      printf 'exec %s bash -c %q _ %d' "${_unshare[*]}" "$_hidden_mounts" "${#hidden_dirs[@]}"
      printf ' %q' "${hidden_dirs[@]}" "$binary"
      printf ' "$@"\n'
    fi
  } >"$file"
  chmod +x "$file"
}
