# SPDX-License-Identifier: Apache-2.0
# One helper each for adding a library component, a tool and a test executable.
# Libraries and tools install themselves (cmake/GlintInstall.cmake has the rest of the
# package: config files, data, docs, examples, CPack).
include(GNUInstallDirs)
find_program(GLINT_HELP2MAN help2man DOC "help2man, for the tools' man pages (optional)")

# glint_add_library(<component> [DEPENDS <targets>...])
#   lib/<component>/src/*.cpp -> static library glint_<component> (alias glint::<component>),
#   public headers under lib/<component>/include/glint/<component>/. Installed (library,
#   headers) and exported as glint::<component> in the glintTargets export set; the compiler
#   warnings stay build-only ($<BUILD_INTERFACE:>), glint_standard and glint_sanitize are
#   exported (GlintInstall.cmake).
function(glint_add_library component)
    cmake_parse_arguments(ARG "" "" "DEPENDS;PRIVATE_DEPENDS" ${ARGN})
    file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${component}/src/*.cpp")
    if(NOT sources)
        message(WARNING "lib/${component} has no sources yet; glint_${component} not built")
        return()
    endif()
    add_library(glint_${component} STATIC ${sources})
    add_library(glint::${component} ALIAS glint_${component})
    target_include_directories(glint_${component}
        PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/${component}/include>"
               "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>"
        PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/${component}/src")
    target_link_libraries(glint_${component}
        PUBLIC glint_standard glint_sanitize ${ARG_DEPENDS}
        PRIVATE "$<BUILD_INTERFACE:glint_warnings>" ${ARG_PRIVATE_DEPENDS})
    set_target_properties(glint_${component} PROPERTIES EXPORT_NAME ${component})
    install(TARGETS glint_${component} EXPORT glintTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
    install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/${component}/include/"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" FILES_MATCHING PATTERN "*.h")
endfunction()

# glint_add_tool(<name> [DESCRIPTION <text>] DEPENDS <targets>...)
#   tools/<name>/*.cpp -> executable glint-<name>, installed to bin/, with a man page
#   (glint_add_man_page).
function(glint_add_tool name)
    cmake_parse_arguments(ARG "" "DESCRIPTION" "DEPENDS" ${ARGN})
    file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp")
    if(NOT sources)
        return()
    endif()
    add_executable(glint-${name} ${sources})
    target_link_libraries(glint-${name} PRIVATE glint_standard glint_warnings glint_sanitize
        ${ARG_DEPENDS})
    set_target_properties(glint-${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/bin")
    install(TARGETS glint-${name} RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
    glint_add_man_page(glint-${name} "${ARG_DESCRIPTION}")
endfunction()

# glint_add_man_page(<tool target> <one-line description>)
#   <build>/man/<tool>.1 from the tool's --help by help2man (target glint-man, part of the
#   default build), installed to share/man/man1. Skipped when help2man is missing
#   (cmake/GlintInstall.cmake says so once).
function(glint_add_man_page tool description)
    if(NOT GLINT_HELP2MAN)
        return()
    endif()
    if(description STREQUAL "")
        set(description "a glint tool")
    endif()
    set(page "${CMAKE_BINARY_DIR}/man/${tool}.1")
    add_custom_command(OUTPUT "${page}"
        COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_BINARY_DIR}/man"
        COMMAND "${GLINT_HELP2MAN}" --no-info --no-discard-stderr
            "--version-string=${PROJECT_VERSION}" "--name=${description}"
            "--output=${page}" "$<TARGET_FILE:${tool}>"
        DEPENDS ${tool}
        COMMENT "Generating man page ${tool}.1"
        VERBATIM)
    if(NOT TARGET glint-man)
        add_custom_target(glint-man ALL)
    endif()
    add_custom_target(${tool}-man DEPENDS "${page}")
    add_dependencies(glint-man ${tool}-man)
    install(FILES "${page}" DESTINATION "${CMAKE_INSTALL_MANDIR}/man1")
endfunction()

# glint_add_gtest_folder(<folder> <component> <label> DEPENDS <targets>...)
#   tests/<folder>/<component>/*.cpp -> one gtest executable, <folder>_<component> (test_ for
#   unit), each test registered as <folder>/<component>/<Suite.Name> with label <label>. The
#   support headers and the component's unit folder (shared fixtures) are on the include path.
function(glint_add_gtest_folder folder component label)
    cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
    file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${folder}/${component}/*.cpp")
    if(NOT sources)
        return()
    endif()
    if(folder STREQUAL "unit")
        set(target test_${component})
    else()
        set(target ${folder}_${component})
    endif()
    add_executable(${target} ${sources})
    target_link_libraries(${target} PRIVATE glint_standard glint_warnings glint_sanitize
        GTest::gtest_main GTest::gmock ${ARG_DEPENDS})
    target_include_directories(${target} PRIVATE
        "${CMAKE_CURRENT_SOURCE_DIR}/support/include"
        "${CMAKE_CURRENT_SOURCE_DIR}/unit/${component}")
    target_compile_definitions(${target} PRIVATE
        GLINT_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data"
        GLINT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tests")
    gtest_discover_tests(${target}
        TEST_PREFIX "${folder}/${component}/"
        PROPERTIES LABELS ${label}
        DISCOVERY_TIMEOUT 60)
endfunction()

# glint_add_unit_test(<component> DEPENDS <targets>...)
#   tests/unit/<component>/*.cpp -> one gtest executable, each test registered with label unit.
function(glint_add_unit_test component)
    glint_add_gtest_folder(unit ${component} unit ${ARGN})
endfunction()

# glint_add_integration_test(<component> DEPENDS <targets>...)
#   tests/integration/<component>/*.cpp -> one gtest executable whose tests run a component on
#   what the readers make of real DIRSIG files (tests/data/), so that the component's unit
#   tests link no reader; label integration.
function(glint_add_integration_test component)
    glint_add_gtest_folder(integration ${component} integration ${ARGN})
endfunction()

# glint_add_oracle_test(<component> DEPENDS <targets>...)
#   tests/oracle/<component>/*.cpp -> gtest executable whose tests compare glint with an
#   independent program (GDAL, Spectral Python, ...), label oracle. The tests skip with a
#   message when the oracle is not installed.
function(glint_add_oracle_test component)
    cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
    file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/oracle/${component}/*.cpp")
    if(NOT sources)
        return()
    endif()
    add_executable(oracle_${component} ${sources})
    target_link_libraries(oracle_${component} PRIVATE glint_standard glint_warnings glint_sanitize
        GTest::gtest_main GTest::gmock nlohmann_json::nlohmann_json ${ARG_DEPENDS})
    target_include_directories(oracle_${component} PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}/support/include")
    target_compile_definitions(oracle_${component} PRIVATE
        GLINT_TEST_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data"
        GLINT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
        GLINT_ORACLE_PYTHON="${GLINT_ORACLE_PYTHON}")
    set_target_properties(oracle_${component} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/tests")
    gtest_discover_tests(oracle_${component}
        TEST_PREFIX "oracle/${component}/"
        PROPERTIES LABELS oracle
        DISCOVERY_TIMEOUT 60)
endfunction()

# glint_add_cli_tests()
#   Every tests/cli/<tool>/<case>.toml becomes the test cli/<tool>/<case>, run by
#   tests/cli/run_case.py against the built tools (label cli; exit 77 = skipped).
function(glint_add_cli_tests)
    set(sanitized "")
    if(GLINT_SANITIZE)
        set(sanitized "--sanitized")  # cases that limit the address space are skipped
    endif()
    file(GLOB_RECURSE cases CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/cli/*.toml")
    foreach(case IN LISTS cases)
        file(RELATIVE_PATH name "${CMAKE_CURRENT_SOURCE_DIR}/cli" "${case}")
        string(REGEX REPLACE "\\.toml$" "" name "${name}")
        add_test(NAME "cli/${name}"
            COMMAND "${GLINT_ORACLE_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/cli/run_case.py"
                --bin "${CMAKE_BINARY_DIR}/bin"
                --data "${CMAKE_CURRENT_SOURCE_DIR}/data"
                --work "${CMAKE_CURRENT_BINARY_DIR}/cli-work/${name}"
                ${sanitized}
                "${case}")
        set_tests_properties("cli/${name}" PROPERTIES LABELS cli SKIP_RETURN_CODE 77 TIMEOUT 120)
    endforeach()
endfunction()
