#!/usr/bin/env bash
# The README gallery: records a few programs once (glxgears, the gear scene, the character
# demo's two animations), replays every capture in every gallery style into docs/gallery/,
# and rewrites the table between the gallery markers in README.md. Run after a change to a
# style's look; look at the pictures before committing them.
#   scripts/make-gallery.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=scripts/gallery-lib.sh
source "$root/scripts/gallery-lib.sh"
build=${1:-$root/build}
nprgl="$build/bin/nprgl"
out="$root/docs/gallery"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
# Only this script's pictures: the compat gallery's and the overlay's are other scripts'.
rm -f "$out"/{gears,sydney,wuson,glxgears}_*.png
models=/usr/share/assimp/models
styles=(none toon+paper+edges toon textured halftone toon+edges toon+wireframe
        toon+perpixel toon+strokes halftone+paper+edges textured+paper+strokes gooch+edges
        preset:technical preset:blueprint preset:pencil xtoon+paper+edges toon+depthcue
        preset:motion)
# An entry "preset:NAME" renders with --preset NAME.
replayArgs() { case "$1" in preset:*) echo "--preset ${1#preset:}" ;; *) echo "--style $1" ;; esac; }

record() { # name frames command...
    local name=$1 frames=$2
    shift 2
    "$nprgl" record -o "$tmp/$name.nprgl" --frames "1-$frames" --style none -- "$@" \
        >/dev/null 2>&1 || true
}
record gears 5 "$build/bin/demo_displaylist" --offscreen --frames 5 --size 320x240
record sydney 20 "$build/bin/demo_character" --model "$models/MD2/sydney.md2" --offscreen \
    --frames 20 --size 320x240
record wuson 20 "$build/bin/demo_character" --model "$models/X/Testwuson.X" --offscreen \
    --frames 20 --size 320x240
"$root/scripts/with-display.sh" sh -c \
    "timeout 3 '$nprgl' record -o '$tmp/glxgears.nprgl' --frames 1-30 --style none -- \
     glxgears -geometry 300x300 >/dev/null 2>&1 || true"

scenes=()
for capture in "$tmp"/*.nprgl; do
    scene=$(basename "$capture" .nprgl)
    last=$("$nprgl" info "$capture" | awk '/^frames:/ {print $2}')
    [ -n "$last" ] || continue
    scenes+=("$scene")
    for style in "${styles[@]}"; do
        name="${scene}_$(fileName "$style")"
        rm -rf "$tmp/r"
        # shellcheck disable=SC2046 # two words: the option and its value
        "$nprgl" replay "$capture" -o "$tmp/r" $(replayArgs "$style") --frames "$last" \
            >/dev/null 2>&1
        cp "$tmp/r/$(printf 'frame_%010d.png' "$last")" "$out/$name.png"
    done
done

table="$tmp/table.md"
{
    printf '| style |'
    for scene in "${scenes[@]}"; do printf ' %s |' "$scene"; done
    printf '\n|---|'
    for _ in "${scenes[@]}"; do printf -- '---|'; done
    printf '\n'
    for style in "${styles[@]}"; do
        printf '| `%s` |' "$(label "$style")"
        for scene in "${scenes[@]}"; do
            printf ' ![%s in %s](docs/gallery/%s_%s.png) |' "$scene" "$(label "$style")" \
                "$scene" "$(fileName "$style")"
        done
        printf '\n'
    done
} > "$table"
replaceReadmeSection "$root/README.md" gallery "$table"
ls "$out" | wc -l
