#!/usr/bin/env bash
# `cmake --install` into a prefix inside the build tree, then what was installed: the nprgl
# command preloads the installed library (through the loader's $LIB), styles, records and
# reads back a demo program; the man page renders and documents every command, option, variable
# and exit status of the help; the bash completion offers commands, options, styles and captures.
# Usage: test-install.sh BUILD_DIR MULTIARCH DEMO_APP
set -euo pipefail
build=$1 multiarch=$2 demo=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
prefix=$build/install-test/prefix
work=$build/install-test/work
rm -rf "$build/install-test"
mkdir -p "$work"
failures=0
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
nprgl=$prefix/bin/nprgl
library=$prefix/lib/$multiarch/nprgl/libnprgl.so
for file in "$nprgl" "$library" "$prefix/share/man/man1/nprgl.1.gz" \
    "$prefix/share/bash-completion/completions/nprgl"; do
    [ -f "$file" ] || fail "not installed: ${file#"$prefix"/}"
done
[ -x "$nprgl" ] || { echo "FAIL: no installed nprgl command" >&2; exit 1; }

# The installed command, away from the build tree's library and settings.
run() { env -u NPRGL_LIBRARY -u LD_PRELOAD -u NPRGL_STYLE -u NPRGL_CONFIG -u NPRGL_PRESET "$@"; }

# LD_PRELOAD names the installed library through $LIB, and the loader maps that file.
preload=$(run "$nprgl" --style none -- printenv LD_PRELOAD)
case $preload in
*"$prefix/\$LIB/nprgl/libnprgl.so"*) ;;
*) fail "LD_PRELOAD is '$preload', not $prefix/\$LIB/nprgl/libnprgl.so" ;;
esac
maps=$(run "$nprgl" --style none -- cat /proc/self/maps)
real=$(realpath "$library")
grep -qF "$real" <<<"$maps" || fail "the program did not load $real"
if grep -q "$build/lib/libnprgl.so" <<<"$maps"; then
    fail "the installed command loaded the build tree's library"
fi

# A styled run with a screenshot, and a recording read back by the installed command.
run "$nprgl" --screenshot "frames=2;dir=$work/shots" -- "$demo" --offscreen --frames 2 \
    >"$work/run.out" 2>"$work/run.err" || fail "styled run failed: $(cat "$work/run.err")"
[ -s "$work/shots/$(basename "$demo")_2.png" ] || fail "no screenshot of frame 2 from the run"
run "$nprgl" record -o "$work/demo.nprgl" -- "$demo" --offscreen --frames 2 \
    >"$work/record.out" 2>"$work/record.err" || fail "record failed: $(cat "$work/record.err")"
run "$nprgl" info "$work/demo.nprgl" >"$work/info.out" 2>&1 || fail "info failed"
grep -qE "^frames: +2 " "$work/info.out" || fail "the capture has not 2 frames: $(head -5 "$work/info.out")"

# The man page renders, and names everything the help does.
page=$prefix/share/man/man1/nprgl.1.gz
if command -v man >/dev/null; then
    text=$(LC_ALL=C MANWIDTH=200 man --warnings -l "$page" 2>"$work/man.err" | col -b)
    [ ! -s "$work/man.err" ] || fail "man warns: $(cat "$work/man.err")"
else
    # The source without its requests and escapes: what man would show, roughly.
    text=$(zcat "$page" | sed -E 's/^\.[A-Z]+ ?//; s/\\f[BIRP]//g; s/\\-/-/g; s/"//g')
fi
grep -q "^NAME" <<<"$text" || fail "the man page has no NAME section"
help=$("$nprgl" help)
names=$(sed -n '/^Commands:/,/^$/p' <<<"$help" | awk '/^  [a-z]/ { print $1 }')
for command in $names; do
    grep -qw -- "$command" <<<"$text" || fail "the man page does not name the command $command"
    for option in $("$nprgl" help "$command" | sed -n '/^Options:/,/^$/p' |
        grep -oE -- '(^| |,)--?[a-zA-Z][a-z-]*' | tr -d ' ,'); do
        grep -qF -- "$option" <<<"$text" || fail "the man page does not name $command $option"
    done
done
for variable in $(grep -oE 'NPRGL_[A-Z_]+' <<<"$help" | sort -u); do
    grep -qF "$variable" <<<"$text" || fail "the man page does not name $variable"
done
for status in $(grep -oE '\b(1|2|126|127)\b' <<<"$(grep -A3 'Exit status' <<<"$help")"); do
    grep -qE "^ *$status\b|, +$status\b" <<<"$text" || fail "the man page has no exit status $status"
done

# Bash completion, as bash calls it for a word under the cursor.
complete_words() {
    bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1));
             _nprgl 2>/dev/null; printf "%s\n" "${COMPREPLY[@]}"' \
        sh "$prefix/share/bash-completion/completions/nprgl" "$nprgl" "$@"
}
expect_completion() {
    local want=$1
    shift
    # Not a pipe into grep -q: under pipefail, its early exit would fail the writer.
    local offered
    offered=$(complete_words "$@")
    grep -qxF -- "$want" <<<"$offered" || fail "completing '$*' does not offer $want"
}
expect_completion replay rep
expect_completion --style --st
expect_completion --screenshot record --scr
expect_completion toon+paper --style toon+pa
expect_completion toon.diffuse_threshold= --set toon.diffuse_th
expect_completion pencil --preset pen
expect_completion --stats replay x.nprgl --st
expect_completion "$root/tests/fixtures/glxgears.nprgl" replay "$root/tests/fixtures/glx"

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s); the installed tree is in $prefix" >&2
    exit 1
fi
echo "install: nprgl, $multiarch/nprgl/libnprgl.so, nprgl(1) and the completion work from $prefix"
