#!/usr/bin/env bash
# Renders the pictures README.md shows, from the demo apps (offscreen, deterministic), into
# docs/images. Run after a change that alters what the demos draw.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out="$root/docs/images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
models=/usr/share/assimp/models
for pair in morph:MD2/sydney.md2 skin:X/Testwuson.X rigid:BVH/01_01.bvh; do
    "$build/bin/demo_character" --model "$models/${pair#*:}" --offscreen --frames 20 \
        --size 320x240 --save-dir "$tmp/${pair%%:*}" --save-frames 20
    cp "$tmp/${pair%%:*}/character_20.png" "$out/character_${pair%%:*}.png"
done
ls -l "$out"
