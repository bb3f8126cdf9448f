#!/usr/bin/env bash
# The scripted run of the hostile cases: special and oversized files as configuration, log,
# preset and capture paths (scripts/hostile-files.sh), mutated captures, closed and unclosed,
# through info, dump and replay (scripts/mutate-captures.sh, COUNT of them), and every kind
# of GL context the probe makes (GLX, EGL and OSMesa; compatibility, core, ES 1/2/3) natively
# and under nprgl, for GL errors and state nprgl would leave (tests/test_contexts.cpp).
# Prints one line per part and exits 1 when any part failed.
# Usage: scripts/hostile.sh [COUNT (1000)]   (NPRGL_BUILD_DIR: build; built first)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${NPRGL_BUILD_DIR:-$root/build}
count=${1:-1000}
cmake --build "$build" -j 2 >/dev/null || { echo "hostile: the build failed" >&2; exit 2; }
failed=0
part() {
    local name=$1
    shift
    if "$@"; then
        echo "hostile: $name: ok"
    else
        echo "hostile: $name: FAILED"
        failed=1
    fi
}
part "special files" "$root/scripts/with-display.sh" "$root/scripts/hostile-files.sh" "$build"
part "$count mutated captures" env NPRGL_BUILD_DIR="$build" \
    "$root/scripts/mutate-captures.sh" "$count"
part "context kinds" "$root/scripts/with-display.sh" "$build/bin/test_contexts"
exit $failed
