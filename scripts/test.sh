#!/usr/bin/env bash
# Sets everything up and runs all tests: dependencies, the build, the unit and end-to-end
# tests under Xvfb, then the unit tests again under AddressSanitizer + UBSan.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build"
cd "$root/build"
"$root/scripts/with-display.sh" ctest --output-on-failure -j 2

# Sanitizers: the pure and in-process tests (the end-to-end ones preload into other programs).
# Debug (-O0): the sanitizers need no optimiser, and the generated sources compile far faster.
"$root/scripts/build.sh" "$root/build-asan" -DNPRGL_SANITIZE=ON -DNPRGL_BUILD_BENCH=OFF \
    -DCMAKE_BUILD_TYPE=Debug >/dev/null
cd "$root/build-asan"
# Mesa's llvmpipe leaks at exit by design; leaks are not what this run looks for.
ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --output-on-failure -j 2 -L unit

# The capture reader's libFuzzer target (clang, ASan + UBSan) on a generated seed corpus.
"$root/scripts/fuzz.sh" 20000
