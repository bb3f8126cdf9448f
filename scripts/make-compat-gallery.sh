#!/usr/bin/env bash
# The README's real-programs gallery: a few of Debian's xscreensaver GL hacks (package
# xscreensaver-gl) natively and in three chains, frame 40 of each run at 480x270, into
# docs/gallery/compat_<hack>_<style>.png, and the table between the compat-gallery markers in
# README.md. The hacks animate by the clock, so each run shows another moment: look at the
# pictures before committing them.   scripts/make-compat-gallery.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=scripts/gallery-lib.sh
source "$root/scripts/gallery-lib.sh"
build=${1:-$root/build}
hacks=(engine molecule superquadrics glknots)
styles=(none toon+paper+edges preset:pencil halftone+paper+edges)
out="$root/docs/gallery"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

shoot() { # hack style -> $tmp/<hack>_40.png, run until frame 40 is written
    local hack=$1 style=$2 dir="$tmp/$1-$(fileName "$2")"
    mkdir -p "$dir"
    # shellcheck disable=SC2046 # two words: the option and its value
    NPRGL_SCREENSHOT="frames=40;dir=$dir" "$build/bin/nprgl" $(styleArgs "$style") -- \
        "/usr/libexec/xscreensaver/$hack" -window -geometry 480x270 >/dev/null 2>&1 &
    local pid=$! i=0
    while [ ! -f "$dir/${hack}_40.png" ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
    kill -TERM "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    [ -f "$dir/${hack}_40.png" ] && cp "$dir/${hack}_40.png" "$out/compat_${hack}_$(fileName "$style").png"
}
for hack in "${hacks[@]}"; do
    for style in "${styles[@]}"; do shoot "$hack" "$style"; done
done

table="$tmp/table.md"
{
    printf '| program |'
    for style in "${styles[@]}"; do printf ' `%s` |' "$(label "$style")"; done
    printf '\n|---|'
    for _ in "${styles[@]}"; do printf -- '---|'; done
    printf '\n'
    for hack in "${hacks[@]}"; do
        printf '| %s |' "$hack"
        for style in "${styles[@]}"; do
            printf ' ![%s in %s](docs/gallery/compat_%s_%s.png) |' "$hack" "$(label "$style")" \
                "$hack" "$(fileName "$style")"
        done
        printf '\n'
    done
} > "$table"
replaceReadmeSection "$root/README.md" compat-gallery "$table"
