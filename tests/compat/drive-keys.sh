#!/usr/bin/env bash
# Runs a program that needs keys to reach its 3D scene, in step with its frames: each key is
# sent (XTEST, xdotool) once nprgl has written the screenshot of its frame, and the run ends
# (SIGTERM) once the last frame's screenshot exists. Exit status: the program's own if it
# ended first or died when stopped, else 0.
# Usage: drive-keys.sh SHOT_DIR SHOT_NAME LAST_FRAME "FRAME:KEY ..." -- COMMAND [ARG...]
# (screenshots are SHOT_DIR/SHOT_NAME_FRAME.png; NPRGL_SCREENSHOT must ask for every frame named)
set -u
dir=$1 name=$2 last=$3 keys=$4
shift 4
[ "${1:-}" = "--" ] && shift
"$@" &
pid=$!
reached() {
    until [ -e "$dir/${name}_$1.png" ]; do
        kill -0 "$pid" 2>/dev/null || return 1
        sleep 0.1
    done
}
ended() {
    wait "$pid"
    local rc=$?
    echo "drive-keys: the program ended (status $rc) before frame $1" >&2
    exit "$rc"
}
for step in $keys; do
    reached "${step%%:*}" || ended "${step%%:*}"
    xdotool key --delay 100 "${step#*:}"
done
reached "$last" || ended "$last"
kill -TERM "$pid"
wait "$pid"
rc=$?
# Ended by our SIGTERM (or on its own at that moment): fine; anything else is the program's.
if [ "$rc" -eq 143 ] || [ "$rc" -eq 0 ]; then exit 0; fi
echo "drive-keys: the program ended with status $rc when stopped" >&2
exit "$rc"
