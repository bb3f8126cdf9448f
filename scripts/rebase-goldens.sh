#!/bin/sh
# Re-renders the goldens of tests/golden/cases.txt into tests/golden/ after an intended change
# of a style's look: captures replayed by `nprgl replay`, live:APP cases run under nprgl.
# Look at every picture git reports as changed before committing it: a golden made to match
# a bug hides the bug. Usage: scripts/rebase-goldens.sh [NAME-PATTERN]   (BUILD_DIR: build)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
only=${1:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -v '^#' "$root/tests/golden/cases.txt" | while read -r source style frame; do
    [ -n "$source" ] || continue
    name=$(echo "${source}_${style}" | tr '+:' '-_')
    case "$name" in *"$only"*) ;; *) continue ;; esac
    rm -rf "$tmp/out"
    mkdir -p "$tmp/out"
    case "$source" in
    live:*)
        app=${source#live:}
        "$build/bin/nprgl" --style "$style" -- "$build/bin/demo_$app" --offscreen \
            --size 256x192 --frames "$frame" --save-frames "$frame" --save-dir "$tmp/out" \
            >/dev/null 2>&1
        cp "$tmp/out/${app}_$frame.png" "$root/tests/golden/$name.png"
        ;;
    *)
        "$build/bin/nprgl" replay "$root/tests/fixtures/$source.nprgl" -o "$tmp/out" \
            --style "$style" --frames "$frame" 2>/dev/null
        cp "$tmp/out/$(printf 'frame_%010d.png' "$frame")" "$root/tests/golden/$name.png"
        ;;
    esac
    echo "tests/golden/$name.png"
done
