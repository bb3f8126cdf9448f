#!/usr/bin/env bash
# The Debian package on this machine: its dependencies come from the libraries it links;
# `apt install ./nprgl_*.deb` gives a `nprgl` that runs glxgears styled (under a private Xvfb
# when there is no display); `apt remove nprgl` leaves none of its files. Needs root and apt.
# It installs and removes the package nprgl, and refuses to run where nprgl is already
# installed, so it never takes away a package it did not put there.
# Usage: tests/package/test-package.sh [DEB]   (default: builds one with scripts/package.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ "$(id -u)" != 0 ]; then
    echo "test-package: needs root (it installs and removes the package with apt)" >&2
    exit 1
fi
if [ "$(dpkg-query -W -f='${db:Status-Status}' nprgl 2>/dev/null)" = installed ]; then
    echo "test-package: nprgl is installed already; remove it first (apt remove nprgl)" >&2
    exit 1
fi
deb=${1:-$("$root/scripts/package.sh" | tail -n1)}
deb=$(realpath "$deb")
work=$(mktemp -d)
installed=0
cleanup() {
    if [ "$installed" = 1 ]; then
        DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq nprgl >/dev/null 2>&1 || true
    fi
    rm -rf "$work"
}
trap cleanup EXIT
failures=0
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)

# Declared dependencies: what dpkg-shlibdeps found for the linked libraries, and libGL, which
# the library opens at run time.
depends=$(dpkg-deb -f "$deb" Depends)
names=$(tr ',' '\n' <<<"$depends" | awk '{ print $1 }')
for package in libc6 libstdc++6 libosmesa6 libpng16-16 libzstd1 libgl1; do
    grep -qxF "$package" <<<"$names" || fail "Depends lacks $package: $depends"
done

DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$deb" >"$work/apt-install.log" 2>&1 || {
    cat "$work/apt-install.log" >&2
    exit 1
}
installed=1
mapfile -t files < <(dpkg -L nprgl)
for want in /usr/bin/nprgl "/usr/lib/$multiarch/nprgl/libnprgl.so" \
    /usr/share/man/man1/nprgl.1.gz /usr/share/bash-completion/completions/nprgl; do
    grep -qxF "$want" <<<"$(printf '%s\n' "${files[@]}")" || fail "the package does not hold $want"
    [ -e "$want" ] || fail "$want was not installed"
done
[ "$(command -v nprgl)" = /usr/bin/nprgl ] || fail "nprgl is not /usr/bin/nprgl"
man -w nprgl >/dev/null 2>&1 || fail "man does not find nprgl(1)"
preload=$(env -u LD_PRELOAD -u NPRGL_LIBRARY nprgl --style none -- printenv LD_PRELOAD)
[ "$preload" = "/usr/\$LIB/nprgl/libnprgl.so" ] || fail "LD_PRELOAD is '$preload'"

# glxgears from the installed command, in the default style and in none, each until its
# third frame's screenshot is written. The default style draws a page where glxgears
# clears to black: the corner pixel tells them apart.
gears() {
    local dir=$1 style=$2
    "$root/scripts/with-display.sh" bash -c '
        env -u LD_PRELOAD -u NPRGL_LIBRARY -u NPRGL_STYLE nprgl --style "$2" \
            --screenshot "frames=3;dir=$1" glxgears >/dev/null 2>"$1.err" &
        pid=$!
        # A guard against a program that never draws, not a speed check.
        for _ in $(seq 1200); do
            [ -f "$1/glxgears_3.png" ] && break
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        kill "$pid" 2>/dev/null || true
        wait "$pid" || true' sh "$dir" "$style"
    [ -f "$dir/glxgears_3.png" ] || fail "nprgl --style $style glxgears wrote no frame 3: $(cat "$dir.err")"
}
corner() {
    python3 - "$1" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
pos, idat = 8, b""
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    if kind == b"IDAT":
        idat += data[pos + 8:pos + 8 + length]
    pos += 12 + length
raw = zlib.decompress(idat)
# An 8-bit RGB(A) picture: a row starts with its filter byte, and every filter stores the
# first row's first pixel as it is (nothing lies left of it or above it).
print(" ".join(str(v) for v in raw[1:1 + 3]))
PY
}
gears "$work/styled" toon+paper+edges
gears "$work/native" none
if [ -f "$work/styled/glxgears_3.png" ] && [ -f "$work/native/glxgears_3.png" ]; then
    native=$(corner "$work/native/glxgears_3.png")
    styled=$(corner "$work/styled/glxgears_3.png")
    [ "$native" = "0 0 0" ] || fail "native glxgears corner is $native, not black"
    [ "$styled" != "$native" ] || fail "the styled glxgears corner is the native $native"
fi

DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq nprgl >"$work/apt-remove.log" 2>&1 || {
    cat "$work/apt-remove.log" >&2
    exit 1
}
installed=0
status=$(dpkg-query -W -f='${db:Status-Status}' nprgl 2>/dev/null || echo not-installed)
[ "$status" = not-installed ] || fail "after apt remove, dpkg says nprgl is $status"
for file in "${files[@]}"; do
    # Folders shared with other packages (/usr/bin...) stay; nprgl's own files and folders go.
    if [ -d "$file" ] && [ ! -L "$file" ]; then
        if dpkg -S "$file" >/dev/null 2>&1; then continue; fi
        [ ! -e "$file" ] || fail "left behind: the folder $file"
    else
        [ ! -e "$file" ] && [ ! -L "$file" ] || fail "left behind: $file"
    fi
done

if [ "$failures" -gt 0 ]; then
    echo "test-package: $failures failure(s)" >&2
    exit 1
fi
echo "package: $(basename "$deb") installs, runs glxgears styled and removes cleanly"
