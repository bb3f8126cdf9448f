#!/usr/bin/env bash
# Builds the capture reader's libFuzzer target with clang (ASan + UBSan) straight from the
# sources, generates a seed corpus and runs a fixed number of inputs. A crash, a sanitizer
# report, a leak or an oversized allocation fails the run and leaves the input in BUILD_DIR.
# Usage: scripts/fuzz.sh [RUNS] [extra libFuzzer arguments]   (NPRGL_FUZZ_DIR: build dir)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${NPRGL_FUZZ_DIR:-$root/build-fuzz}
runs=${1:-20000}
shift || true
cxx=${NPRGL_FUZZ_CXX:-clang++}
mkdir -p "$out"

sources=("$root"/capture/*.cpp)
read -r -a cflags <<<"$(pkg-config --cflags libzstd libxxhash)"
read -r -a libs <<<"$(pkg-config --libs libzstd libxxhash)"
common=(-std=c++20 -g -O1 -Wall -Wextra -I"$root" "${cflags[@]}")
needsBuild() { # target, its sources: rebuild when any source or header is newer
    local target=$1
    shift
    [ ! -x "$target" ] || [ -n "$(find "$@" "$root"/capture -newer "$target" -print -quit)" ]
}
if needsBuild "$out/fuzz_capture_reader" "$root/tests/fuzz/fuzz_capture_reader.cpp"; then
    echo "fuzz: building fuzz_capture_reader with $cxx"
    "$cxx" "${common[@]}" -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
        "${sources[@]}" "$root/tests/fuzz/fuzz_capture_reader.cpp" "${libs[@]}" \
        -o "$out/fuzz_capture_reader"
fi
if needsBuild "$out/make_seeds" "$root/tests/fuzz/make_seeds.cpp"; then
    "$cxx" "${common[@]}" "${sources[@]}" "$root/tests/fuzz/make_seeds.cpp" "${libs[@]}" \
        -o "$out/make_seeds"
fi

rm -rf "$out/seeds" "$out/corpus"
mkdir -p "$out/seeds" "$out/corpus"
"$out/make_seeds" "$out/seeds"
# Tokens of the format, so mutations can build chunks.
printf '%s\n' '"NPRGLCAP"' '"META"' '"FRAM"' '"BLOB"' '"CNTS"' '"INDX"' '"FOOT"' \
    '"\x28\xb5\x2f\xfd"' '"\x01\x00\x00\x00"' '"\xff\xff\xff\xff\xff\xff\xff\x7f"' \
    >"$out/capture.dict"

echo "fuzz: $runs runs of fuzz_capture_reader"
"$out/fuzz_capture_reader" -runs="$runs" -seed=1 -max_len=8192 -rss_limit_mb=2048 \
    -malloc_limit_mb=1100 -dict="$out/capture.dict" -artifact_prefix="$out/" \
    -print_final_stats=1 "$@" "$out/corpus" "$out/seeds"
