#!/usr/bin/env bash
# Installs the Debian packages nprgl needs to build, test and benchmark.
set -euo pipefail
pkgs=(
    build-essential cmake ninja-build pkg-config python3 ccache
    khronos-api libgl-dev libegl-dev libx11-dev libxi-dev libosmesa6-dev libgl1-mesa-dri
    libglm-dev libopenmesh-dev libgtest-dev libgmock-dev libzstd-dev libxxhash-dev libpng-dev
    libcli11-dev nlohmann-json3-dev libassimp-dev assimp-testmodels
    libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
    mesa-utils x11-utils xvfb xauth libxtst-dev xscreensaver-gl xscreensaver-gl-extra
    freeglut3-dev libsdl2-dev libglfw3-dev
    apitrace libimgui-dev neverball openarena extremetuxracer crack-attack xdotool
    clang libclang-rt-14-dev
    wine wine64 gcc-mingw-w64-x86-64-win32   # Windows programs under Wine (tests/test_wine.cpp)
)
sudo=""
if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
# True when every package named is installed. dpkg -s refuses a name installed for two
# architectures (libzstd-dev and libzstd-dev:i386) as ambiguous; dpkg-query lists each.
installed() {
    local p
    for p in "$@"; do
        dpkg-query -W -f='${db:Status-Abbrev}\n' "$p" 2>/dev/null | grep -q '^ii' || return 1
    done
}
if ! installed "${pkgs[@]}"; then
    # An index that fails to download (a mirror in sync, another architecture's) does not
    # stop the install: apt uses what it has, and the install itself says what is missing.
    $sudo apt-get update -qq || echo "install-deps: apt-get update failed; trying anyway" >&2
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${pkgs[@]}"
fi
# 32-bit programs (scripts/build-i386.sh, tests/test_i386.cpp): g++-multilib and the i386
# libraries libnprgl.so links, and i386 Mesa for Debian's i386 glxgears. Without them the
# 32-bit library is not built and its tests are skipped, so a failure here only warns.
i386=(
    g++-multilib libzstd-dev:i386 libxxhash-dev:i386 libimgui-dev:i386 libopenmesh1:i386
    libpng16-16:i386 libgl1:i386 libglx-mesa0:i386
)
if ! installed "${i386[@]}"; then
    if ! dpkg --print-foreign-architectures | grep -qx i386; then
        $sudo dpkg --add-architecture i386
    fi
    $sudo apt-get update -qq || true
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${i386[@]}" ||
        echo "install-deps: the i386 packages could not be installed: no 32-bit library" >&2
fi
# 32-bit Windows programs under Wine (tests/test_wine.cpp, bits32): Debian's 32-bit wine
# loader and the i686 mingw-w64 compiler for tests/wine/wingl.c. Without them those tests are
# skipped, so a failure here only warns.
wine32=(wine32:i386 gcc-mingw-w64-i686-win32)
if dpkg --print-foreign-architectures | grep -qx i386 && ! installed "${wine32[@]}"; then
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${wine32[@]}" ||
        echo "install-deps: wine32 could not be installed: no 32-bit Windows program tests" >&2
fi
