# The 32-bit library's Debian package, nprgl-i386_<version>_i386.deb, made from the i386
# library-only build (scripts/build-i386.sh, then scripts/package.sh): the library at
# /usr/lib/i386-linux-gnu/nprgl/, where the 64-bit nprgl command preloads it for 32-bit
# programs through the loader's $LIB. Its own name, not nprgl:i386: the two packages share no
# file, and CPack cannot mark them Multi-Arch: same. Its dependencies are i386 packages.
set(CPACK_PACKAGE_NAME nprgl-i386)
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE i386)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "32-bit library of nprgl, for 32-bit OpenGL programs")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "The i386 libnprgl.so, which the nprgl command (package nprgl) preloads into
 32-bit programs, such as i386 games and 32-bit Windows programs under wine32.")
set(CPACK_DEBIAN_PACKAGE_ENHANCES "nprgl")
include(${CMAKE_CURRENT_LIST_DIR}/PackageCommon.cmake)
