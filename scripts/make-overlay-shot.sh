#!/usr/bin/env bash
# The README's overlay picture: glxgears in the default style with the overlay open (overlay
# key, or NPRGL_OVERLAY=open as here), frame 60 at 640x480, into docs/gallery/overlay.png.
# Needs a display (scripts/with-display.sh gives one).   scripts/make-overlay-shot.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# A configuration folder of its own: the user's files must not change the picture.
XDG_CONFIG_HOME="$tmp/config" NPRGL_CONFIG_FILE="" NPRGL_OVERLAY=open \
    NPRGL_SCREENSHOT="frames=60;dir=$tmp" "$build/bin/nprgl" -- glxgears -geometry 640x480 \
    >/dev/null 2>&1 &
pid=$! i=0
while [ ! -f "$tmp/glxgears_60.png" ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
kill -TERM "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
mkdir -p "$root/docs/gallery"
cp "$tmp/glxgears_60.png" "$root/docs/gallery/overlay.png"
echo "docs/gallery/overlay.png"
