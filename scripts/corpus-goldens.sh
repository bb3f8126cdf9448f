#!/usr/bin/env bash
# The real programs' goldens: small captures of the quick corpus kept in tests/compat/captures/ and their frames in the default style in tests/compat/golden/.
#
# Usage: scripts/corpus-goldens.sh [--record | --from DIR]
#   --record  records the quick corpus anew (scripts/corpus-captures.sh --quick, from Debian's
#             xscreensaver-gl packages, into build/corpus-goldens) and keeps the 25 smallest
#             captures (a repository stays small) in tests/compat/captures/, replacing those
#   --from DIR  the same from a quick corpus scripts/corpus-captures.sh --quick recorded
#             before (scripts/test.sh leaves one in build/corpus-quick)
#   (none)    only renders the goldens again from the kept captures, after an intended change
#             of the default style's look
# Each golden is the capture's last frame replayed in the default style (`nprgl replay`).
# Look at every picture git reports as changed before committing it: a golden made to match
# a bug hides the bug. tests/compat/test_corpus_fidelity.cpp compares (CorpusGolden).
# Writes only in build/ (BUILD_DIR) and tests/compat/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
captures=$root/tests/compat/captures
goldens=$root/tests/compat/golden
keep=25
work=""
case "${1:-}" in
    --record)
        work=$build/corpus-goldens
        rm -rf "$work"
        NPRGL_BUILD=$build "$root/scripts/corpus-captures.sh" "$work" --quick
        ;;
    --from)
        work=${2:?usage: $0 --from DIR}
        [ -f "$work/manifest.tsv" ] || { echo "$work: not a quick corpus (no manifest.tsv)" >&2; exit 1; }
        ;;
    "") ;;
    *)
        echo "usage: $0 [--record | --from DIR]" >&2
        exit 1
        ;;
esac
if [ -n "$work" ]; then
    rm -rf "$captures"
    mkdir -p "$captures"
    # The smallest, by size: no program is chosen by name.
    find "$work" -maxdepth 1 -name '*.nprgl' ! -name '*.*.nprgl' -printf '%s %p\n' | sort -n |
        head -n "$keep" | while read -r _ file; do cp "$file" "$captures/"; done
fi
mkdir -p "$goldens"
rm -f "$goldens"/*.png
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for capture in "$captures"/*.nprgl; do
    name=$(basename "$capture" .nprgl)
    last=$("$build/bin/nprgl" info "$capture" 2>/dev/null |
        awk '/^recorded_frames:/ { split($2, r, "-"); print r[2] }')
    rm -rf "$tmp/out"
    "$build/bin/nprgl" replay "$capture" -o "$tmp/out" --frames "$last" 2>/dev/null
    cp "$tmp/out/$(printf 'frame_%010d.png' "$last")" "$goldens/$name.png"
    echo "tests/compat/golden/$name.png"
done
