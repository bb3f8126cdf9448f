#!/usr/bin/env bash
# Builds and runs the libFuzzer targets with clang (ASan + UBSan), each on generated seeds for
# a fixed number of inputs and a fixed seed:
#   fuzz_capture_reader  the capture container (chunks, checksums, zstd, index), built
#                        straight from the sources;
#   fuzz_replay          hostile calls in a valid container, decoded and replayed on OSMesa
#                        through the shim (CMake, NPRGL_FUZZ=ON, in BUILD_DIR/cmake), with
#                        style none and then, for fewer inputs, the default style.
# A crash, a sanitizer report, a leak (reader), an oversized allocation or a timeout fails
# the run and leaves the input in BUILD_DIR.
# Usage: scripts/fuzz.sh [RUNS] [extra libFuzzer arguments]   (RUNS: of the reader; the
# replay target, some 1000 times slower (a context per input), runs RUNS/20 inputs with style
# none and RUNS/80 with the default style, or NPRGL_FUZZ_REPLAY_RUNS and a quarter of it;
# NPRGL_FUZZ_DIR: build dir)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${NPRGL_FUZZ_DIR:-$root/build-fuzz}
runs=${1:-20000}
shift || true
replayRuns=${NPRGL_FUZZ_REPLAY_RUNS:-$((runs / 20))}
cc=${NPRGL_FUZZ_CC:-clang}
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

# The replay target links the shim: CMake builds it and what it needs (ccache helps; Debug
# compiles fastest, and the time goes into Mesa, which is not instrumented anyway).
echo "fuzz: building fuzz_replay with $cxx"
export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
gen=()
command -v ninja >/dev/null && gen=(-G Ninja)
if [ ! -f "$out/cmake/CMakeCache.txt" ]; then
    CC=$cc CXX=$cxx cmake -S "$root" -B "$out/cmake" "${gen[@]}" -DNPRGL_FUZZ=ON \
        -DNPRGL_BUILD_TESTS=OFF -DNPRGL_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug >/dev/null
fi
cmake --build "$out/cmake" -j "$(nproc)" --target fuzz_replay make_replay_seeds >/dev/null

rm -rf "$out/seeds" "$out/corpus" "$out/replay-seeds" "$out/replay-corpus"
mkdir -p "$out/seeds" "$out/corpus" "$out/replay-seeds" "$out/replay-corpus"
"$out/make_seeds" "$out/seeds"
"$out/cmake/bin/make_replay_seeds" "$out/replay-seeds" "$root"/tests/fixtures/*.nprgl
# Tokens of the format, so mutations can build chunks.
printf '%s\n' '"NPRGLCAP"' '"META"' '"FRAM"' '"BLOB"' '"CNTS"' '"INDX"' '"FOOT"' \
    '"\x28\xb5\x2f\xfd"' '"\x01\x00\x00\x00"' '"\xff\xff\xff\xff\xff\xff\xff\x7f"' \
    >"$out/capture.dict"
# Tokens of the Stream: pseudo-ops, a blob reference (see fuzz_replay.cpp), the null and
# blob array markers, image modes with an offset, large counts.
printf '%s\n' '"\x00\xff"' '"\x01\xff"' '"\x02\xff"' '"\xb1\x0b\xb1\x0b\xb1\x0b\xb1\x00"' \
    '"\xfe\xff\xff\xff"' '"\xff\xff\xff\xff"' '"\x02\x00\x00\x00\x00\x00\x00\x00\x00"' \
    '"\xff\xff\xff\x7f"' '"\x00\x00\x01\x00"' >"$out/replay.dict"

echo "fuzz: $runs runs of fuzz_capture_reader"
"$out/fuzz_capture_reader" -runs="$runs" -seed=1 -max_len=8192 -rss_limit_mb=2048 \
    -malloc_limit_mb=1100 -dict="$out/capture.dict" -artifact_prefix="$out/" \
    -print_final_stats=1 "$@" "$out/corpus" "$out/seeds"

# Mesa (llvmpipe) keeps allocations past a context's end and at exit by design, so leak
# detection would only report the driver: it is off for this target, per input and at exit
# (the reader's keeps it).
export ASAN_OPTIONS=detect_leaks=0
# One context per input: the per-context "style ..." line would flood the log.
export NPRGL_LOG_LEVEL=warn
replay=("$out/cmake/bin/fuzz_replay" -seed=1 -max_len=65536 -timeout=60 -rss_limit_mb=2048
    -malloc_limit_mb=1100 -detect_leaks=0 -dict="$out/replay.dict" -artifact_prefix="$out/"
    -print_final_stats=1 "$@" "$out/replay-corpus" "$out/replay-seeds")
echo "fuzz: $replayRuns runs of fuzz_replay (style none)"
NPRGL_STYLE=none "${replay[@]}" -runs="$replayRuns"
echo "fuzz: $((replayRuns / 4)) runs of fuzz_replay (default style)"
env -u NPRGL_STYLE "${replay[@]}" -runs="$((replayRuns / 4))"
