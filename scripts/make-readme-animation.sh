#!/usr/bin/env bash
# The animated picture README.md shows: Debian's glxgears recorded once (under Xvfb when there
# is no display), replayed natively and in the default style with `nprgl replay --video`, the
# two side by side as an animated GIF in docs/gallery/. Run after a change to the default
# style's look; look at it before committing it.
#   scripts/make-readme-animation.sh [BUILD_DIR]
# Needs FFmpeg's command (Debian's ffmpeg package) for the side by side and the GIF, and
# glxgears (mesa-utils); nprgl itself encodes the videos. Writes only a temporary folder and
# docs/gallery/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
nprgl="$build/bin/nprgl"
out="$root/docs/gallery/glxgears-animated.gif"
frames=40
fps=20
for need in "$nprgl" "$(command -v glxgears || echo glxgears)"; do
    [ -e "$need" ] || { echo "make-readme-animation: $need is missing (build first)" >&2; exit 1; }
done
command -v ffmpeg >/dev/null || {
    echo "make-readme-animation: needs the ffmpeg command (apt-get install ffmpeg)" >&2
    exit 1
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# A fixed number of frames; glxgears runs until it is stopped (the timeout only ends it).
"$root/scripts/with-display.sh" sh -c \
    "timeout 10 '$nprgl' record -o '$tmp/walk.nprgl' --frames 1-$frames --style none -- \
     glxgears -geometry 300x300 >/dev/null 2>&1 || true"
[ -s "$tmp/walk.nprgl" ] || { echo "make-readme-animation: glxgears was not recorded" >&2; exit 1; }
for look in none default; do
    args=(--style none)
    [ "$look" = default ] && args=()
    "$nprgl" replay "$tmp/walk.nprgl" "${args[@]}" --video "$tmp/$look.mp4" --fps "$fps" \
        >/dev/null
done
# Native on the left, the default style on the right; a looping GIF (every viewer plays it)
# with a palette made for these frames.
side="[0:v][1:v]hstack=inputs=2,scale=480:-2,split[a][b]"
palette="[a]palettegen=stats_mode=diff[p];[b][p]paletteuse"
ffmpeg -loglevel error -y -i "$tmp/none.mp4" -i "$tmp/default.mp4" \
    -filter_complex "$side;$palette" -loop 0 -an "$out"
ls -l "$out"
