# One place that sets warnings for every target of the project.
function(simp_set_compiler_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(SIMP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# A project library: libs/<name>/{include,src}; sources given after the name.
# Usage: simp_add_library(NAME obs TYPE SHARED SOURCES ... DEPS ...)
function(simp_add_library)
  cmake_parse_arguments(ARG "" "NAME;TYPE" "SOURCES;DEPS" ${ARGN})
  if(NOT ARG_TYPE)
    set(ARG_TYPE SHARED)
  endif()
  set(target simp_${ARG_NAME})
  add_library(${target} ${ARG_TYPE} ${ARG_SOURCES})
  add_library(simp::${ARG_NAME} ALIAS ${target})
  target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(${target} PUBLIC ${ARG_DEPS})
  simp_set_compiler_options(${target})
  set_property(GLOBAL APPEND PROPERTY SIMP_LIBRARIES ${target})
endfunction()

# A thin program over the libraries; the linker must keep plugin libraries whose
# only use is the classes they register (see doc/plugin.md).
function(simp_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  target_link_options(${name} PRIVATE -Wl,--no-as-needed)
  simp_set_compiler_options(${name})
endfunction()

# A GoogleTest executable registered with CTest. Tests find the authors' data (read-only,
# optional) through SIMP_SHARED_DATA_DIR and write under the build tree's test output dir.
function(simp_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  target_link_options(${name} PRIVATE -Wl,--no-as-needed)
  target_compile_definitions(${name} PRIVATE
    SIMP_SHARED_DATA_DIR="${CMAKE_SOURCE_DIR}/../shared/data"
    SIMP_SOURCE_DIR="${CMAKE_SOURCE_DIR}"
    SIMP_BINARY_DIR="${CMAKE_BINARY_DIR}"
    SIMP_TEST_OUTPUT_DIR="${CMAKE_BINARY_DIR}/test_output")
  simp_set_compiler_options(${name})
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600)
endfunction()
