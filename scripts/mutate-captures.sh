#!/usr/bin/env bash
# The deterministic mutation run (tests/mutate_captures.cpp) over the committed fixtures,
# closed and unclosed: COUNT mutated copies (bit flips, inserted and deleted bytes, cuts) from
# a fixed SEED, each through nprgl info, dump and replay with a bounded wait. Fails on a
# crash, a hang or a silent loss, and keeps those copies in BUILD_DIR/mutated-captures.
# The test suite runs 100 (MutatedCaptures.NoCrashHangOrSilentLoss).
# Usage: scripts/mutate-captures.sh [COUNT (1000)] [SEED (1)]   (NPRGL_BUILD_DIR: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${NPRGL_BUILD_DIR:-$root/build}
count=${1:-1000}
seed=${2:-1}
cmake --build "$build" -j 2 --target mutate_captures nprgl_cli >/dev/null
out=$build/mutated-captures
rm -rf "$out"
exec "$build/bin/mutate_captures" --count "$count" --seed "$seed" --out "$out" \
    "$root"/tests/fixtures/{displaylist,glxgears,immediate,textured}.nprgl
