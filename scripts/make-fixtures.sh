#!/usr/bin/env bash
# Regenerates the capture fixtures in tests/fixtures: three frames of every demo app
# (offscreen, 160x120) and of glxgears (under a display). Run after a change to the capture
# format or the call codec; the replay tests compare the fixtures with live runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out="$root/tests/fixtures"
nprgl="$build/bin/nprgl"
mkdir -p "$out"
for app in immediate arrays displaylist textured overlay dlopen; do
    "$nprgl" record -o "$out/$app.nprgl" -- "$build/bin/demo_$app" --offscreen --frames 3 \
        --size 160x120 2>/dev/null
done
"$nprgl" record -o "$out/arrays_vbo.nprgl" -- "$build/bin/demo_arrays" --vbo --offscreen \
    --frames 3 --size 160x120 2>/dev/null
# The character demo's three animation techniques, on Debian's assimp-testmodels.
models=/usr/share/assimp/models
for pair in morph:MD2/sydney.md2 skin:X/Testwuson.X rigid:BVH/01_01.bvh; do
    "$nprgl" record -o "$out/character_${pair%%:*}.nprgl" -- "$build/bin/demo_character" \
        --model "$models/${pair#*:}" --offscreen --frames 3 --size 160x120 2>/dev/null
done
# glxgears runs until stopped; the recording ends after frame 3 and the file is complete.
"$root/scripts/with-display.sh" timeout -s INT 4 "$nprgl" record --frames 1-3 \
    -o "$out/glxgears.nprgl" -- glxgears >/dev/null 2>&1 || true
ls -l "$out"
