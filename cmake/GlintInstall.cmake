# SPDX-License-Identifier: Apache-2.0
# The install tree and the .deb (docs/install.md). glint_add_library and glint_add_tool
# (GlintHelpers.cmake) install every component and tool themselves; this file adds the rest:
#   <prefix>/bin/glint-*                       the tools
#   <prefix>/share/glint/                      data/ (found next to the executable at run time)
#   <prefix>/share/glint/examples/{demo,optics,plugin}
#   <prefix>/share/doc/glint/                  README.md, docs/
#   <prefix>/share/man/man1/glint-*.1          man pages (help2man, when installed)
#   <prefix>/include/glint/<component>/*.h, <prefix>/lib/libglint_<component>.a
#   <prefix>/lib/cmake/glint/                  glintConfig.cmake: find_package(glint CONFIG)
include(CMakePackageConfigHelpers)

set(GLINT_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/glint" CACHE STRING
    "Where glintConfig.cmake is installed, relative to the prefix")

# C++20 for users of the installed libraries (glint::standard), and the sanitizer flags an
# ASan build's libraries need at link time (glint::sanitize: empty unless GLINT_SANITIZE).
# The warning flags (-Werror in CI) are build-only and not exported.
set_target_properties(glint_standard PROPERTIES EXPORT_NAME standard)
set_target_properties(glint_sanitize PROPERTIES EXPORT_NAME sanitize)
install(TARGETS glint_standard glint_sanitize EXPORT glintTargets)
install(EXPORT glintTargets NAMESPACE glint:: FILE glintTargets.cmake
    DESTINATION "${GLINT_INSTALL_CMAKEDIR}")
# glint_DATA_DIR in the config: the installed data folder (solar spectrum).
set(GLINT_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/glint")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/glintConfig.cmake.in"
    "${CMAKE_CURRENT_BINARY_DIR}/glintConfig.cmake"
    INSTALL_DESTINATION "${GLINT_INSTALL_CMAKEDIR}"
    PATH_VARS GLINT_INSTALL_DATADIR)
# 0.x: a minor version may break the API.
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/glintConfigVersion.cmake"
    VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/glintConfig.cmake"
    "${CMAKE_CURRENT_BINARY_DIR}/glintConfigVersion.cmake"
    DESTINATION "${GLINT_INSTALL_CMAKEDIR}")

# Data: glint-render looks for <exe dir>/../share/glint/solar/astm_g173.csv
# (glint::data_dir_lookup, lib/core/include/glint/core/install_paths.h).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/data/" DESTINATION "${CMAKE_INSTALL_DATADIR}/glint")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/examples/demo" "${PROJECT_SOURCE_DIR}/examples/optics"
    "${PROJECT_SOURCE_DIR}/examples/plugin"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/glint/examples" USE_SOURCE_PERMISSIONS
    PATTERN "build" EXCLUDE)
install(FILES "${PROJECT_SOURCE_DIR}/README.md" DESTINATION "${CMAKE_INSTALL_DOCDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/" DESTINATION "${CMAKE_INSTALL_DOCDIR}/docs")

if(NOT GLINT_HELP2MAN)
    message(STATUS "help2man not found: the tools' man pages are not generated "
                   "(scripts/install-deps.sh installs it)")
endif()

# cpack -G DEB (from the build folder, or `make package`): one package, installed under /usr.
set(CPACK_PACKAGE_NAME glint)
set(CPACK_PACKAGE_VENDOR "glint")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
    "glint reads DIRSIG4 .sim/.platform/.ppd/.tasks and DIRSIG5 .jsim simulations and renders "
    "ENVI images by spectral path tracing (glint-render), with tools for schedules, detection, "
    "demosaicing and ENVI files. Also ships the static libraries, headers and CMake package "
    "(find_package(glint CONFIG)) for writing custom sensors.")
set(CPACK_PACKAGE_CONTACT "glint maintainers <glint-maintainers@example.org>")
set(CPACK_RESOURCE_FILE_README "${PROJECT_SOURCE_DIR}/README.md")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/glint")
# The shared libraries the tools link (Debian 12 names; `ldd build/<preset>/bin/glint-*`).
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libc6, libstdc++6, libgcc-s1, libembree3-3 (>= 3.13), libopenimageio2.4, libyaml-cpp0.7, libtinyxml2-9, libtbb12, libgeographiclib23")
# glint-envi encode runs ffmpeg.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "ffmpeg")
# Building against the installed CMake package (examples/plugin) needs the -dev packages
# glintConfig.cmake finds.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "cmake, g++, libembree-dev, libopenimageio-dev, libcli11-dev, libyaml-cpp-dev, libtinyxml2-dev, nlohmann-json3-dev, libtbb-dev, libgeographiclib-dev")
include(CPack)
