#!/usr/bin/env bash
# Builds the Debian packages OUT_DIR/nprgl_<version>_<arch>.deb (default OUT_DIR: build/) and,
# where the 32-bit library builds (scripts/build-i386.sh), OUT_DIR/nprgl-i386_<version>_i386.deb
# with CPack's DEB generator from the install rules, their dependencies found by
# dpkg-shlibdeps. The builds it packages are its own (OUT_DIR/package-build and its i386/: no
# tests or benchmarks, warnings are errors). Prints each package's path. Install them with:
# sudo apt install ./build/nprgl_<version>_amd64.deb ./build/nprgl-i386_<version>_i386.deb
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mkdir -p "${1:-$root/build}" && cd "${1:-$root/build}" && pwd)
"$root/scripts/install-deps.sh"
build=$out/package-build
"$root/scripts/build.sh" "$build" -DNPRGL_BUILD_TESTS=OFF -DNPRGL_BUILD_BENCH=OFF \
    -DNPRGL_WERROR=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
rm -rf "$build/cpack"
(cd "$build" && cpack -G DEB -B "$build/cpack" >"$build/cpack.log") || {
    cat "$build/cpack.log" >&2
    exit 1
}
# The 32-bit library's package, from the library-only i386 build beside it.
if "$root/scripts/build-i386.sh" "$build" -DNPRGL_WERROR=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    >"$build/i386.log" 2>&1; then
    (cd "$build/i386" && cpack -G DEB -B "$build/cpack" >"$build/cpack-i386.log") || {
        cat "$build/cpack-i386.log" >&2
        exit 1
    }
else
    echo "package: no 32-bit library could be built (see $build/i386.log): no nprgl-i386" >&2
fi
for deb in "$build"/cpack/*.deb; do
    mv -f "$deb" "$out/"
    echo "$out/$(basename "$deb")"
done
