#!/usr/bin/env bash
# Runs programs under nprgl with hostile files: configuration, preset and log paths that are
# FIFOs, devices, a directory, 100 MB, 1 MB of random bytes, or a configuration file swapped
# for a FIFO while the program runs; and capture paths that are special files, given to the
# commands that read captures and as a recording's file (each must be refused at once: exit
# status 1 and one line, the program never started or run unrecorded). Every case runs under a bounded wait and prints one line:
# ok, HANG, CRASH, FLOOD (too many lines on stderr) or "exit status changed" (against the same
# program run without nprgl). Exits 1 when a case fails.
# Usage: scripts/hostile-files.sh [BUILD_DIR]   (default: build; it needs the bin/ and lib/
# of a build with the tests). Writes only inside a folder it makes with mktemp -d under
# BUILD_DIR (or $TMPDIR when BUILD_DIR is read-only), removed at the end unless a case failed
# or NPRGL_KEEP_TEST_FILES=1.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd) || exit 2
bin=$build/bin
lib=$build/lib/libnprgl.so
guard=${NPRGL_HOSTILE_GUARD:-60} # seconds; a case that runs longer hangs
max_lines=50                     # stderr lines a case may write
for f in "$bin/nprgl" "$lib" "$bin/demo_immediate" "$bin/probe_reload"; do
    [ -e "$f" ] || { echo "hostile-files: $f is missing; build first" >&2; exit 2; }
done
work=$(mktemp -d "$build/hostile-files.XXXXXX" 2>/dev/null ||
       mktemp -d "${TMPDIR:-/tmp}/hostile-files.XXXXXX") || exit 2
[ -n "${NPRGL_KEEP_TEST_FILES:-}" ] || trap 'rm -rf "$work"' EXIT
mkdir "$work/out"
failures=0

# run NAME [VAR=VALUE...] [-- PROGRAM ARGS...]: runs PROGRAM (default: the immediate-mode demo
# for 5 frames, offscreen) under the nprgl command with the settings over an empty
# XDG_CONFIG_HOME of its own (no file of the user's is read), or, with via=preload,
# with libnprgl.so in LD_PRELOAD; `before` names a function run before the program's plain
# run and again before its run under nprgl.
run() {
    local name=$1 settings=() program=("$bin/demo_immediate" --offscreen --frames 5)
    shift
    while [ $# -gt 0 ] && [ "$1" != "--" ]; do settings+=("$1"); shift; done
    [ $# -gt 0 ] && { shift; program=("$@"); }
    mkdir -p "$work/$name.home"
    local clean=(env -u NPRGL_CONFIG_FILE -u NPRGL_PRESET -u NPRGL_STYLE -u NPRGL_CONFIG
                 -u NPRGL_LOG_FILE -u NPRGL_RECORD XDG_CONFIG_HOME="$work/$name.home")
    "${before:-:}"
    "${clean[@]}" timeout -k 5 "$guard" "${program[@]}" >/dev/null 2>&1
    local expected=$?
    "${before:-:}"
    local log=$work/$name.log
    if [ "${via:-}" = preload ]; then
        "${clean[@]}" LD_PRELOAD="$lib" "${settings[@]}" \
            timeout -k 5 "$guard" "${program[@]}" >/dev/null 2>"$log"
    else
        "${clean[@]}" "${settings[@]}" \
            timeout -k 5 "$guard" "$bin/nprgl" -- "${program[@]}" >/dev/null 2>"$log"
    fi
    local status=$? lines result=ok
    lines=$(wc -l <"$log")
    if [ "$status" -eq 124 ] || [ "$status" -eq 137 ]; then
        result="HANG (ended after ${guard}s)"
    elif [ "$status" -gt 128 ] && [ "$status" -ne "$expected" ]; then
        result="CRASH (signal $((status - 128)))"
    elif [ "$status" -ne "$expected" ]; then
        result="exit status changed ($expected without nprgl, $status with)"
    elif [ "$lines" -gt "$max_lines" ]; then
        result="FLOOD ($lines lines on stderr)"
    fi
    [ "$result" = ok ] || failures=$((failures + 1))
    printf '%-28s %s\n' "$name" "$result"
}

# The files the cases name.
mkfifo "$work/fifo"
mkdir "$work/folder"
mkdir -p "$work/xdg/nprgl" && mkfifo "$work/xdg/nprgl/nprgl.conf" # the default paths
mkdir "$work/xdg/nprgl/demo_immediate.conf"
yes 'not a setting' | head -c 100M >"$work/100mb.conf"
head -c 1M /dev/urandom >"$work/random.conf"
printf 'preset=%s\n' "$work/fifo" >"$work/preset-line.conf"
swapped=$work/swap/nprgl/nprgl.conf
make_config() {
    mkdir -p "${swapped%/*}" && rm -f "$swapped" && echo "style=toon+edges" >"$swapped"
}

# One case a line.
run config-fifo NPRGL_CONFIG_FILE="$work/fifo"
run config-dev-zero NPRGL_CONFIG_FILE=/dev/zero
run config-dev-urandom NPRGL_CONFIG_FILE=/dev/urandom
run config-directory NPRGL_CONFIG_FILE="$work/folder"
run config-100mb NPRGL_CONFIG_FILE="$work/100mb.conf"
run config-random-1mb NPRGL_CONFIG_FILE="$work/random.conf"
run config-preset-line-fifo NPRGL_CONFIG_FILE="$work/preset-line.conf"
before=make_config run config-swapped-to-fifo XDG_CONFIG_HOME="$work/swap" -- \
    "$bin/probe_reload" --frames 4 --file "$swapped" --fifo-at 2 --save-dir "$work/out"
run xdg-config-fifo-and-folder XDG_CONFIG_HOME="$work/xdg"
via=preload run preset-fifo NPRGL_PRESET="$work/fifo"
run log-fifo NPRGL_LOG_FILE="$work/fifo"
run log-directory NPRGL_LOG_FILE="$work/folder"
run log-device NPRGL_LOG_FILE=/dev/full

# refused NAME ARGS...: `nprgl ARGS...` must end at once with status 1 and say why in at most
# a few lines (a capture path that is not a regular file is never opened for reading).
refused() {
    local name=$1 log=$work/$1.log
    shift
    env -u NPRGL_RECORD XDG_CONFIG_HOME="$work/empty.home" \
        timeout -k 5 "$guard" "$bin/nprgl" "$@" >/dev/null 2>"$log"
    local status=$? result=ok lines
    lines=$(wc -l <"$log")
    if [ "$status" -eq 124 ] || [ "$status" -eq 137 ]; then
        result="HANG (ended after ${guard}s)"
    elif [ "$status" -gt 128 ]; then
        result="CRASH (signal $((status - 128)))"
    elif [ "$status" -ne 1 ]; then
        result="exit status $status (expected 1: refused)"
    elif [ "$lines" -gt 3 ]; then
        result="FLOOD ($lines lines on stderr)"
    fi
    [ "$result" = ok ] || failures=$((failures + 1))
    printf '%-28s %s\n' "$name" "$result"
}

mkdir -p "$work/empty.home"
for target in fifo:"$work/fifo" dev-zero:/dev/zero dev-urandom:/dev/urandom \
    directory:"$work/folder"; do
    kind=${target%%:*} path=${target#*:}
    refused "info-$kind" info "$path"
    refused "dump-$kind" dump "$path"
    refused "replay-$kind" replay --stats "$path"
    refused "export-$kind" export "$path" --frame 1 -o "$work/out/x.obj"
    refused "compare-$kind" compare "$path"
    refused "record-to-$kind" record -o "$path" -- "$bin/demo_immediate" --offscreen --frames 2
done
# Through the variable the program runs, unrecorded, and its status is its own.
via=preload run record-var-fifo NPRGL_RECORD="$work/fifo"
via=preload run record-var-directory NPRGL_RECORD="$work/folder"

if [ "$failures" -gt 0 ]; then
    echo "hostile-files: $failures case(s) failed; their stderr: $work/<case>.log" >&2
    trap - EXIT
    exit 1
fi
echo "hostile-files: all cases ok"
