#!/bin/sh
# Re-renders the golden replays of tests/golden/cases.txt into tests/golden/ after an
# intended change of a style's look. Look at every picture git reports as changed before
# committing it: a golden made to match a bug hides the bug.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -v '^#' "$root/tests/golden/cases.txt" | while read -r fixture style frame; do
    [ -n "$fixture" ] || continue
    name=$(echo "${fixture}_${style}" | tr '+' '-')
    rm -rf "$tmp/out"
    "$build/bin/nprgl" replay "$root/tests/fixtures/$fixture.nprgl" -o "$tmp/out" \
        --style "$style" --frames "$frame" 2>/dev/null
    cp "$tmp/out/$(printf 'frame_%010d.png' "$frame")" "$root/tests/golden/$name.png"
    echo "tests/golden/$name.png"
done
