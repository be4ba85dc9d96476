# SPDX-License-Identifier: Apache-2.0
# Every find_package of the project, pinned to the versions Debian 12 ships
# (scripts/install-deps.sh installs them). Un-namespaced targets are aliased here.

find_package(Threads REQUIRED)
find_package(ZLIB REQUIRED)
find_package(embree 3.13 REQUIRED)
find_package(OpenImageIO 2.4 CONFIG REQUIRED)
# Debian's OpenImageIO config lists /usr/include/opencv4 (and similar) among its include
# folders although nothing we use needs them; drop the ones that do not exist so that
# libopencv-dev is not required at build time.
foreach(oiio_target OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
    if(TARGET ${oiio_target})
        get_target_property(oiio_dirs ${oiio_target} INTERFACE_INCLUDE_DIRECTORIES)
        if(oiio_dirs)
            set(oiio_existing "")
            foreach(dir IN LISTS oiio_dirs)
                if(EXISTS "${dir}" OR dir MATCHES "^\\$<")
                    list(APPEND oiio_existing "${dir}")
                endif()
            endforeach()
            set_target_properties(${oiio_target} PROPERTIES
                INTERFACE_INCLUDE_DIRECTORIES "${oiio_existing}")
        endif()
    endif()
endforeach()
find_package(CLI11 2.1 CONFIG REQUIRED)
find_package(yaml-cpp 0.7 CONFIG REQUIRED)
find_package(tinyxml2 9 CONFIG REQUIRED)
find_package(nlohmann_json 3.11 CONFIG REQUIRED)
find_package(TBB CONFIG REQUIRED)
find_package(Eigen3 3.4 CONFIG REQUIRED)

list(APPEND CMAKE_MODULE_PATH /usr/share/cmake/geographiclib)
find_package(GeographicLib REQUIRED)

if(NOT TARGET glint::embree)
    add_library(glint::embree INTERFACE IMPORTED)
    target_link_libraries(glint::embree INTERFACE embree)
endif()
if(NOT TARGET glint::yaml-cpp)
    add_library(glint::yaml-cpp INTERFACE IMPORTED)
    target_link_libraries(glint::yaml-cpp INTERFACE yaml-cpp)
endif()
if(NOT TARGET glint::geographiclib)
    add_library(glint::geographiclib INTERFACE IMPORTED)
    target_link_libraries(glint::geographiclib INTERFACE ${GeographicLib_LIBRARIES})
    target_include_directories(glint::geographiclib INTERFACE ${GeographicLib_INCLUDE_DIRS})
endif()

if(GLINT_BUILD_TESTS)
    find_package(GTest 1.12 REQUIRED)
    include(GoogleTest)
    # Debian's Python packages (GDAL, Spectral, numpy) are installed for this interpreter,
    # not for whichever python3 comes first on PATH.
    set(GLINT_ORACLE_PYTHON /usr/bin/python3 CACHE FILEPATH "Python with Debian's oracle packages")
endif()
