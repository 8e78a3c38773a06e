# The Debian package (docs/install.md): `cpack -G DEB` in a build folder, or
# `cmake --build --preset default --target package`. It holds what `cmake --install` puts under
# /usr: the executable in /usr/bin, its data in /usr/share/springcheck, the man page and bash
# completion where Debian keeps them, the libraries, headers and CMake package config.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME springcheck)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "springcheck")
set(CPACK_PACKAGE_CONTACT "springcheck developers <springcheck@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "validation suite for mass-spring physics: your simulator against closed forms and Bullet")
set(CPACK_PACKAGE_DESCRIPTION
    "springcheck runs mass-spring scenes in its own simulator, in Bullet's soft bodies and in\n"
    "yours (any language, through a file protocol), measures how far apart they are and how far\n"
    "from closed-form answers, gates CI on tolerances and draws PDF/PNG reports.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # springcheck_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_STRIP_FILES ON)
# The shared libraries the executable links (Bullet, GLFW, libpng, libgomp, libstdc++...), read
# off the binary by dpkg-shlibdeps, so the list cannot drift from the build.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What it runs but does not link: the report draws with matplotlib and numpy, {python} engines
# need numpy, and the example engine is Python.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy, python3-matplotlib")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "bash-completion")
# Building against the libraries (find_package(springcheck)) needs their headers' dependencies.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libeigen3-dev, nlohmann-json3-dev, libbullet-dev, cmake, g++")
include(CPack)
