#!/usr/bin/env bash
# Builds the 32-bit libnprgl.so for 32-bit programs: a library-only configure in BUILD_DIR/i386
# (cmake/i386-linux-gnu.cmake: gcc -m32, Debian's i386 libraries) that puts the library at
# BUILD_DIR/lib/i386-linux-gnu/nprgl/, where the main build's nprgl command preloads it through
# the loader's $LIB. Then unpacks Debian's i386 glxgears for tests/test_i386.cpp.
# Usage: scripts/build-i386.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath -m "${1:-$root/build}")
shift || true
for file in /usr/lib/i386-linux-gnu/libzstd.so /usr/lib/i386-linux-gnu/libimgui.a \
    /usr/lib/i386-linux-gnu/libOpenMeshCore.so.9.0; do
    if [ ! -e "$file" ]; then
        echo "build-i386: no $file: the i386 packages are not installed" \
            "(scripts/install-deps.sh)" >&2
        exit 1
    fi
done
export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
gen=()
command -v ninja >/dev/null && gen=(-G Ninja)
cmake -S "$root" -B "$build/i386" "${gen[@]}" \
    -DCMAKE_TOOLCHAIN_FILE="$root/cmake/i386-linux-gnu.cmake" \
    -DNPRGL_LIBRARY_ONLY=ON -DNPRGL_BUILD_TESTS=OFF -DNPRGL_BUILD_BENCH=OFF \
    -DNPRGL_LIBRARY_OUTPUT_DIR="$build/lib/i386-linux-gnu/nprgl" "$@" >/dev/null
cmake --build "$build/i386" -j "$(nproc)"

# Debian's i386 glxgears (mesa-utils-bin:i386, usr/bin/glxgears.i386-linux-gnu), unpacked
# rather than installed: it would bring i386 EGL, GLES and Wayland libraries the tests do not
# need. Its runtime libraries (libgl1:i386...) are installed by scripts/install-deps.sh.
gears=$build/i386/mesa-utils
if [ ! -x "$gears/usr/bin/glxgears.i386-linux-gnu" ]; then
    rm -rf "$gears.tmp" && mkdir -p "$gears.tmp"
    if (cd "$gears.tmp" && apt-get download mesa-utils-bin:i386 >/dev/null 2>&1 &&
        dpkg-deb -x mesa-utils-bin_*_i386.deb "$gears"); then
        echo "build-i386: unpacked $(basename "$gears.tmp"/*.deb) in $gears"
    else
        echo "build-i386: could not download mesa-utils-bin:i386; tests/test_i386 is skipped" >&2
    fi
    rm -rf "$gears.tmp"
fi
