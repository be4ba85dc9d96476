# SPDX-License-Identifier: Apache-2.0
# Compiler settings as INTERFACE targets (never global CMAKE_CXX_FLAGS):
#   glint_standard  - C++20
#   glint_warnings  - warnings on, -Werror when GLINT_WERROR
#   glint_sanitize  - ASan + UBSan when GLINT_SANITIZE

add_library(glint_standard INTERFACE)
target_compile_features(glint_standard INTERFACE cxx_std_20)
set(CMAKE_CXX_EXTENSIONS OFF)
# Release is -O2 (CMake's default -O3 is replaced); never -ffast-math: results must be IEEE.
set(CMAKE_CXX_FLAGS_RELEASE "-O2 -DNDEBUG" CACHE STRING "" FORCE)

add_library(glint_warnings INTERFACE)
target_compile_options(glint_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual
    -Wimplicit-fallthrough)
if(GLINT_WERROR)
    target_compile_options(glint_warnings INTERFACE -Werror)
endif()

add_library(glint_sanitize INTERFACE)
if(GLINT_SANITIZE)
    target_compile_options(glint_sanitize INTERFACE -fsanitize=address,undefined
        -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
    target_link_options(glint_sanitize INTERFACE -fsanitize=address,undefined)
endif()
