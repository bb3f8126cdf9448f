#!/usr/bin/env bash
# The Debian packages on this machine: their dependencies come from the libraries they link;
# `apt install ./nprgl_*.deb` gives a `nprgl` that runs glxgears styled (under a private Xvfb
# when there is no display), and with ./nprgl-i386_*_i386.deb beside it the same command
# styles Debian's i386 glxgears; `apt remove` leaves none of their files. Needs root and apt.
# It installs and removes the packages nprgl and nprgl-i386, and refuses to run where either
# is already installed, so it never takes away a package it did not put there.
# Usage: tests/package/test-package.sh [DEB...]   (default: builds them with scripts/package.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ "$(id -u)" != 0 ]; then
    echo "test-package: needs root (it installs and removes the package with apt)" >&2
    exit 1
fi
for package in nprgl nprgl-i386; do
    if [ "$(dpkg-query -W -f='${db:Status-Status}' $package 2>/dev/null)" = installed ]; then
        echo "test-package: $package is installed already; remove it first" \
            "(apt remove $package)" >&2
        exit 1
    fi
done
if [ $# -gt 0 ]; then debs=("$@"); else mapfile -t debs < <("$root/scripts/package.sh" | grep "\.deb$"); fi
deb="" deb32=""
for d in "${debs[@]}"; do
    case $(dpkg-deb -f "$d" Package) in
        nprgl) deb=$(realpath "$d") ;;
        nprgl-i386) deb32=$(realpath "$d") ;;
        *) echo "test-package: $d is neither nprgl nor nprgl-i386" >&2 && exit 1 ;;
    esac
done
[ -n "$deb" ] || { echo "test-package: no nprgl package among ${debs[*]}" >&2 && exit 1; }
packages=(nprgl)
[ -z "$deb32" ] || packages+=(nprgl-i386)
work=$(mktemp -d)
installed=0
cleanup() {
    if [ "$installed" = 1 ]; then
        DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq "${packages[@]}" >/dev/null 2>&1 ||
            true
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

if [ -n "$deb32" ]; then
    depends32=$(dpkg-deb -f "$deb32" Depends)
    names32=$(tr ',' '\n' <<<"$depends32" | awk '{ print $1 }')
    for package in libc6 libstdc++6 libpng16-16 libzstd1 libgl1; do
        grep -qxF "$package" <<<"$names32" || fail "nprgl-i386's Depends lacks $package: $depends32"
    done
    [ "$(dpkg-deb -f "$deb32" Architecture)" = i386 ] || fail "nprgl-i386 is not an i386 package"
fi

debs=("$deb")
[ -z "$deb32" ] || debs+=("$deb32")
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${debs[@]}" >"$work/apt-install.log" 2>&1 || {
    cat "$work/apt-install.log" >&2
    exit 1
}
installed=1
mapfile -t files < <(dpkg -L "${packages[@]}")
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
# clears to black: the corner pixel tells them apart. GEARS: another glxgears (i386).
gears() {
    local dir=$1 style=$2 program=${3:-glxgears}
    local shot=$dir/$(basename "$program")_3.png
    "$root/scripts/with-display.sh" bash -c '
        env -u LD_PRELOAD -u NPRGL_LIBRARY -u NPRGL_STYLE nprgl --style "$2" \
            --screenshot "frames=3;dir=$1" "$3" >/dev/null 2>"$1.err" &
        pid=$!
        # A guard against a program that never draws, not a speed check.
        for _ in $(seq 1200); do
            [ -f "$4" ] && break
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        kill "$pid" 2>/dev/null || true
        wait "$pid" || true' sh "$dir" "$style" "$program" "$shot"
    [ -f "$shot" ] || fail "nprgl --style $style $program wrote no frame 3: $(cat "$dir.err")"
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
if [ -n "$deb32" ]; then
    [ -e "/usr/lib/i386-linux-gnu/nprgl/libnprgl.so" ] || fail "nprgl-i386 installed no library"
    # Debian's i386 glxgears, as scripts/build-i386.sh unpacks it (mesa-utils-bin:i386).
    gears32=$(ls "$root"/build*/i386/mesa-utils/usr/bin/glxgears.i386-linux-gnu \
        "$root"/build*/package-build/i386/mesa-utils/usr/bin/glxgears.i386-linux-gnu \
        2>/dev/null | head -n1 || true)
    if [ -n "$gears32" ]; then
        gears "$work/styled32" toon+paper+edges "$gears32"
        shot32=$work/styled32/glxgears.i386-linux-gnu_3.png
        if [ -f "$shot32" ]; then
            [ "$(corner "$shot32")" != "0 0 0" ] || fail "the i386 glxgears was not styled"
            grep -q "cannot be preloaded" "$work/styled32.err" &&
                fail "the i386 library was not preloaded: $(cat "$work/styled32.err")"
        fi
    else
        echo "test-package: no i386 glxgears unpacked (scripts/build-i386.sh): the 32-bit" \
            "library is installed but not run" >&2
    fi
fi

DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq "${packages[@]}" >"$work/apt-remove.log" 2>&1 || {
    cat "$work/apt-remove.log" >&2
    exit 1
}
installed=0
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' $package 2>/dev/null || echo not-installed)
    [ "$status" = not-installed ] || fail "after apt remove, dpkg says $package is $status"
done
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
echo "package: $(basename "$deb")${deb32:+ and $(basename "$deb32")} install, run glxgears" \
    "styled and remove cleanly"
