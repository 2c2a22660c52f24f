#!/usr/bin/env bash
# The merge-marker check must fail on a page holding a conflict (its markers written here, not stored in the tree,
# which the check itself reads) and pass once the conflict is resolved.
set -u
python=$1
check=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
{ echo "text"; echo "<<<<<<< HEAD"; echo "ours"; echo "======="; echo "theirs"; echo ">>>>>>> branch"; } > "$dir/page.md"
if out=$("$python" "$check" "$dir"); then
  echo "FAIL: the check passed a page with conflict markers"; exit 1
fi
grep -q "page.md:2" <<<"$out" || { echo "FAIL: the report does not name page.md:2"; echo "$out"; exit 1; }
printf 'text\nours\n' > "$dir/page.md"
"$python" "$check" "$dir" > /dev/null || { echo "FAIL: the check failed a resolved page"; exit 1; }
echo "merge marker check: fails on a conflict (names page.md:2), passes once resolved"
