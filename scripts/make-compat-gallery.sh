#!/usr/bin/env bash
# The README's real-programs gallery: a few of Debian's xscreensaver GL hacks (package
# xscreensaver-gl) and games (neverball, openarena) natively and in three chains, one frame of
# each run (the hacks' 40th at 480x270, the games' in their level at 640x480), into
# docs/gallery/compat_<program>_<style>.png, and the table between the compat-gallery markers
# in README.md. The hacks animate by the clock and openarena spawns where it likes, so each run
# shows another moment: look at the pictures before committing them.
#   scripts/make-compat-gallery.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=scripts/gallery-lib.sh
source "$root/scripts/gallery-lib.sh"
build=${1:-$root/build}
hacks=(engine molecule superquadrics glknots)
games=(neverball openarena)
styles=(none toon+paper+edges preset:pencil halftone+paper+edges)
out="$root/docs/gallery"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

# program -> the frame to keep, the name nprgl gives its screenshots, and its command line.
shotOf() {
    case "$1" in
    neverball) echo "100 neverball_ctx2" ;;
    openarena) echo "250 ioquake3_ctx2" ;;
    *) echo "40 $1" ;;
    esac
}
commandOf() {
    case "$1" in
    neverball) echo "/usr/games/neverball -l map-easy/coins.sol" ;;
    openarena)
        echo "/usr/games/openarena +set r_mode -1 +set r_customwidth 640" \
            "+set r_customheight 480 +set r_fullscreen 0 +set cl_renderer opengl1" \
            "+set s_initsound 0 +devmap oa_dm1 +wait 800 +quit" ;;
    *) echo "/usr/libexec/xscreensaver/$1 -window -geometry 480x270" ;;
    esac
}

shoot() { # program style -> docs/gallery/compat_<program>_<style>.png, run until it is written
    local program=$1 style=$2 dir="$tmp/$1-$(fileName "$2")" frame name
    read -r frame name <<< "$(shotOf "$program")"
    mkdir -p "$dir" "$tmp/home"
    # shellcheck disable=SC2046 # words: the options and the program's command line
    HOME="$tmp/home" NPRGL_SCREENSHOT="frames=$frame;dir=$dir" "$build/bin/nprgl" \
        $(styleArgs "$style") -- $(commandOf "$program") >/dev/null 2>&1 &
    local pid=$! i=0 shot="$dir/${name}_$frame.png"
    while [ ! -f "$shot" ] && [ $i -lt 1200 ]; do sleep 0.1; i=$((i + 1)); done
    kill -TERM "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    [ -f "$shot" ] && cp "$shot" "$out/compat_${program}_$(fileName "$style").png"
}
for program in "${hacks[@]}" "${games[@]}"; do
    for style in "${styles[@]}"; do shoot "$program" "$style"; done
done

table="$tmp/table.md"
{
    printf '| program |'
    for style in "${styles[@]}"; do printf ' `%s` |' "$(label "$style")"; done
    printf '\n|---|'
    for _ in "${styles[@]}"; do printf -- '---|'; done
    printf '\n'
    for hack in "${hacks[@]}" "${games[@]}"; do
        printf '| %s |' "$hack"
        for style in "${styles[@]}"; do
            printf ' ![%s in %s](docs/gallery/compat_%s_%s.png) |' "$hack" "$(label "$style")" \
                "$hack" "$(fileName "$style")"
        done
        printf '\n'
    done
} > "$table"
replaceReadmeSection "$root/README.md" compat-gallery "$table"
