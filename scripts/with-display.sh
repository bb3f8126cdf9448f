#!/usr/bin/env bash
# Runs a command with an X display: the current one, or a private Xvfb started for it.
# WITH_DISPLAY_SIZE=WxH always starts a private one of that size (a program that takes the
# whole screen draws fewer pixels on a small one).
set -euo pipefail
size=${WITH_DISPLAY_SIZE:-1280x1024}
if [ -z "${WITH_DISPLAY_SIZE:-}" ] && [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; then
    exec "$@"
fi
if ! command -v Xvfb >/dev/null; then
    echo "with-display: no DISPLAY and no Xvfb (run scripts/install-deps.sh)" >&2
    exit 1
fi
# -noreset: by default Xvfb resets itself whenever its last client leaves, and a program that
# connects during the reset is refused (glxgears then exits 255 with no message on stderr).
# -displayfd: Xvfb picks a free display itself and writes its number once it accepts
# clients, so two runs side by side never race for one number.
numfile=$(mktemp)
Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp -noreset 3>"$numfile" >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true; rm -f "$numfile"' EXIT
until [ -s "$numfile" ]; do
    if ! kill -0 "$xvfb" 2>/dev/null; then
        echo "with-display: Xvfb did not start" >&2
        exit 1
    fi
    sleep 0.1
done
export DISPLAY=":$(head -n1 "$numfile")"
"$@"
