#!/usr/bin/env bash
# Runs one program (under the current display) until nprgl's screenshot of a frame exists, it ends, or a time limit; writes how it ended.
# Usage: corpus-run.sh STATUS_FILE LIMIT_S SHOT_DIR SHOT_PREFIX FRAME "FRAME:KEY ..." -- COMMAND [ARG...]
#   STATUS_FILE gets one line "OUTCOME STATUS SECONDS": OUTCOME is reached (the screenshot
#   SHOT_DIR/SHOT_PREFIX*_FRAME.png appeared and the program was then stopped with SIGTERM),
#   ended (it ended by itself first), hung (LIMIT_S seconds passed without either; killed) or
#   timed (FRAME 0: no screenshot is waited for; stopped after LIMIT_S seconds, a native run).
#   With RUN_TO_END=1 (a program whose native run ends by itself) it is not stopped at the
#   screenshot: reached-ended once it ends by itself after it, its own exit status to compare.
#   STATUS is the program's exit status (128+N for signal N). Each key is sent with xdotool
#   once the screenshot of its frame exists (NPRGL_SCREENSHOT must ask for those frames).
#   The program runs in a session of its own; its whole process group is killed at the end.
set -euo pipefail
status_file=$1 limit=$2 shots=$3 prefix=$4 frame=$5 keys=$6
shift 6
[ "${1:-}" = "--" ] && shift

start=$(date +%s)
setsid "$@" &
pid=$!

shot_exists() {
    compgen -G "$shots/${prefix}*_$1.png" >/dev/null
}
alive() {
    kill -0 "$pid" 2>/dev/null
}
elapsed() {
    echo $(($(date +%s) - start))
}

outcome=""
reached=0
pending=($keys)
while :; do
    if ! alive; then
        if [ "$reached" = 1 ]; then outcome=reached-ended; else outcome=ended; fi
        break
    fi
    if [ "${#pending[@]}" -gt 0 ] && shot_exists "${pending[0]%%:*}"; then
        xdotool key --delay 100 "${pending[0]#*:}" >/dev/null 2>&1 || true
        pending=("${pending[@]:1}")
        continue
    fi
    if [ "$frame" != 0 ] && [ "$reached" = 0 ] && shot_exists "$frame"; then
        reached=1
        if [ "${RUN_TO_END:-0}" != 1 ]; then
            outcome=reached
            break
        fi
    fi
    if [ "$(elapsed)" -ge "$limit" ]; then
        if [ "$frame" = 0 ]; then outcome=timed; else outcome=hung; fi
        break
    fi
    sleep 0.2
done

if [ "$outcome" != ended ] && [ "$outcome" != reached-ended ]; then
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 1 50); do
        alive || break
        sleep 0.2
    done
    if alive; then
        [ "$outcome" = hung ] || outcome="$outcome-killed"
        kill -KILL -- "-$pid" 2>/dev/null || kill -KILL "$pid" 2>/dev/null || true
    fi
fi
rc=0
wait "$pid" || rc=$?
# Whatever the program started in its session (helpers, a child that draws) goes with it.
kill -KILL -- "-$pid" 2>/dev/null || true
echo "$outcome $rc $(elapsed)" >"$status_file"
