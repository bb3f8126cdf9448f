#!/usr/bin/env bash
# The README's real-programs gallery: a few of Debian's xscreensaver GL hacks (package
# xscreensaver-gl) and games (neverball, openarena, extremetuxracer, crack-attack) natively
# and in three chains, one frame of each run (the hacks' 40th at 480x270, the games' in their
# level at 640x480; etr and crack-attack driven by keys, tests/compat/drive-keys.sh), into
# docs/gallery/compat_<program>_<style>.png, and the table between the compat-gallery markers
# in README.md. The hacks animate by the clock and openarena spawns where it likes, so each run
# shows another moment: look at the pictures before committing them.
#   scripts/make-compat-gallery.sh [BUILD_DIR [PROGRAM...]]  (PROGRAMs: shoot only those; the
#   table always lists all)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=scripts/gallery-lib.sh
source "$root/scripts/gallery-lib.sh"
build=${1:-$root/build}
shift || true
hacks=(engine molecule superquadrics glknots)
games=(neverball openarena etr crack-attack)
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
    etr) echo "500 etr_ctx2" ;;
    crack-attack) echo "600 crack-attack" ;;
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
    etr) echo "/usr/games/etr" ;;
    *) echo "/usr/libexec/xscreensaver/$1 -window -geometry 480x270" ;;
    esac
}

shoot() { # program style -> docs/gallery/compat_<program>_<style>.png, run until it is written
    local program=$1 style=$2 dir="$tmp/$1-$(fileName "$2")" frame name
    read -r frame name <<< "$(shotOf "$program")"
    mkdir -p "$dir" "$tmp/home"
    local shot="$dir/${name}_$frame.png"
    if [ "$program" = etr ]; then
        # Into its race by five Returns, on a 640x480 display of its own (it takes the whole
        # screen), with OpenAL's null sound device (see tests/compat/test_compat.cpp).
        # shellcheck disable=SC2046 # words: the style options
        HOME="$tmp/home" ALSOFT_DRIVERS=null WITH_DISPLAY_SIZE=640x480 \
            NPRGL_SCREENSHOT="frames=50,100,150,200,250,$frame;dir=$dir" \
            "$root/scripts/with-display.sh" "$root/tests/compat/drive-keys.sh" "$dir" "$name" \
            "$frame" "50:Return 100:Return 150:Return 200:Return 250:Return" -- \
            "$build/bin/nprgl" $(styleArgs "$style") -- /usr/games/etr >/dev/null 2>&1 || true
        [ -f "$shot" ] && cp "$shot" "$out/compat_${program}_$(fileName "$style").png"
        return 0
    fi
    if [ "$program" = crack-attack ]; then
        # A solo game, started by Return; its board of blocks has risen by the frame kept.
        # shellcheck disable=SC2046 # words: the style options
        HOME="$tmp/home" SDL_AUDIODRIVER=dummy NPRGL_SCREENSHOT="frames=100,$frame;dir=$dir" \
            "$root/scripts/with-display.sh" "$root/tests/compat/drive-keys.sh" "$dir" "$name" \
            "$frame" "100:Return" -- "$build/bin/nprgl" $(styleArgs "$style") -- \
            /usr/games/crack-attack --solo >/dev/null 2>&1 || true
        [ -f "$shot" ] && cp "$shot" "$out/compat_${program}_$(fileName "$style").png"
        return 0
    fi
    # shellcheck disable=SC2046 # words: the options and the program's command line
    HOME="$tmp/home" NPRGL_SCREENSHOT="frames=$frame;dir=$dir" "$build/bin/nprgl" \
        $(styleArgs "$style") -- $(commandOf "$program") >/dev/null 2>&1 &
    local pid=$! i=0
    while [ ! -f "$shot" ] && [ $i -lt 1200 ]; do sleep 0.1; i=$((i + 1)); done
    kill -TERM "$pid" 2>/dev/null || true
    # A game may hang in its own SIGTERM handler (seen once with ioquake3, inside the driver):
    # ten seconds, then SIGKILL.
    i=0
    while kill -0 "$pid" 2>/dev/null && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    [ -f "$shot" ] && cp "$shot" "$out/compat_${program}_$(fileName "$style").png"
}
chosen=("$@")
[ ${#chosen[@]} -gt 0 ] || chosen=("${hacks[@]}" "${games[@]}")
for program in "${chosen[@]}"; do
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
