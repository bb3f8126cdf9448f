#!/usr/bin/env bash
# Sets everything up and runs all tests: dependencies, the build, the unit and end-to-end
# tests under Xvfb, then again under AddressSanitizer + UBSan (unit tests and end-to-end
# tests with the sanitized library preloaded), then the libFuzzer targets.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
# Warnings are errors here: the build stays warning-free.
"$root/scripts/build.sh" "$root/build" -DNPRGL_WERROR=ON
# The 32-bit library beside it, for the i386 tests (skipped where it cannot be built).
"$root/scripts/build-i386.sh" "$root/build" -DNPRGL_WERROR=ON ||
    echo "test.sh: no 32-bit library: the i386 tests will be skipped" >&2
# The tests run the programs as a new user would: the developer's own configuration files
# (~/.config/nprgl) must not change what they see.
export XDG_CONFIG_HOME="$root/build/test-config-home"
unset NPRGL_CONFIG_FILE NPRGL_STYLE NPRGL_CONFIG NPRGL_PRESET
mkdir -p "$XDG_CONFIG_HOME"
# The quick corpus of real programs (every 4th GL hack of Debian's xscreensaver-gl and
# -extra, 4 frames each) for the fidelity guard (tests/compat/test_corpus_fidelity.cpp).
rm -rf "$root/build/corpus-quick"
"$root/scripts/corpus-captures.sh" "$root/build/corpus-quick" --quick
cd "$root/build"
"$root/scripts/with-display.sh" ctest --output-on-failure -j 2

# Sanitizers on the whole pipeline. Debug (-O0): the sanitizers need no optimiser, and the
# generated sources compile far faster. First the unit and in-process tests (styles, tracker,
# capture, reconstruction); then end-to-end tests with the ASan build of libnprgl.so preloaded
# into the demo apps and glxgears (the nprgl command puts the ASan runtime first in
# LD_PRELOAD), and the recorder and replayer run through the ASan-built nprgl command.
"$root/scripts/build.sh" "$root/build-asan" -DNPRGL_SANITIZE=ON -DNPRGL_BUILD_BENCH=OFF \
    -DCMAKE_BUILD_TYPE=Debug -DNPRGL_WERROR=ON
cd "$root/build-asan"
# Mesa's llvmpipe leaks at exit by design; leaks are not what this run looks for.
export ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --output-on-failure -j 2 -L unit
# Not the trace replay test: the ASan runtime that nprgl brings into glretrace changes the
# replay's own pixels (it fills fresh allocations; the trace reads some unset memory), so its
# native side would have to run under ASan too.
"$root/scripts/with-display.sh" ctest --output-on-failure -j 2 -L e2e \
    -R 'DefaultStyle|Golden|StateUnderNprgl/(none|toon_paper_edges|strokes)_|Record|Replay|Config|Hotkeys|Overlay|StateUnderNprglOverlay|Compositor\.' \
    -E 'Traces\.'
unset ASAN_OPTIONS UBSAN_OPTIONS

# The libFuzzer targets (clang, ASan + UBSan) on generated seeds: the capture reader, and
# the replayer on fuzzed calls in valid captures.
"$root/scripts/fuzz.sh" 20000

# ThreadSanitizer: the two-thread GLX tests with a TSan build of the library preloaded (the
# sanitizer runtime first). Only what those tests need is built. Mesa is not instrumented:
# tests/tsan.supp silences races reported inside it, never in nprgl's own code.
export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
gen=()
command -v ninja >/dev/null && gen=(-G Ninja)
cmake -S "$root" -B "$root/build-tsan" "${gen[@]}" -DNPRGL_TSAN=ON -DNPRGL_BUILD_BENCH=OFF \
    -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build "$root/build-tsan" -j "$(nproc)" --target nprgl nprgl_cli probe_glx_threads \
    test_threads
cd "$root/build-tsan"
TSAN_OPTIONS="suppressions=$root/tests/tsan.supp halt_on_error=1 exitcode=66 report_mutex_bugs=0" \
    "$root/scripts/with-display.sh" bin/test_threads
