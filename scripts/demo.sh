#!/usr/bin/env bash
# Sets everything up and runs the main job: a program rendered through nprgl in the default
# style. With a display it shows glxgears (close the window to stop); without one it renders
# the display-list demo offscreen and writes PNGs to ./nprgl-out.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build" >/dev/null
nprgl="$root/build/bin/nprgl"
out="$PWD/nprgl-out"
if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; then
    echo "nprgl: running glxgears; screenshots of frames 1, 100 and 300 go to $out" >&2
    exec "$nprgl" --screenshot "frames=1,100,300;dir=$out" -- glxgears
fi
"$nprgl" --screenshot "frames=1,60,120;dir=$out" -- \
    "$root/build/bin/demo_displaylist" --offscreen --frames 120 --size 640x480
echo "nprgl: wrote $(ls "$out"/demo_displaylist_*.png | wc -l) frames to $out:" >&2
ls "$out"/demo_displaylist_*.png >&2
