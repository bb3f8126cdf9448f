# What the two Debian packages share (nprgl, and nprgl-i386 from the 32-bit build): the
# version, the maintainer, the section, dependencies found by dpkg-shlibdeps. Included by
# packaging/CMakeLists.txt and packaging/Library32.cmake after each names its package.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_CONTACT "nprgl developers <nprgl@localhost>")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Opened at run time, not linked (the library must not make every program load libGL).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libgl1")
set(CPACK_STRIP_FILES ON)
include(CPack)
