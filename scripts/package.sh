#!/usr/bin/env bash
# Builds the Debian package OUT_DIR/nprgl_<version>_<arch>.deb (default OUT_DIR: build/) with
# CPack's DEB generator from the install rules, its dependencies found by dpkg-shlibdeps. The
# build it packages is its own (OUT_DIR/package-build: no tests or benchmarks, warnings are
# errors). Install it with: sudo apt install ./build/nprgl_<version>_<arch>.deb
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
for deb in "$build"/cpack/*.deb; do
    mv -f "$deb" "$out/"
    echo "$out/$(basename "$deb")"
done
