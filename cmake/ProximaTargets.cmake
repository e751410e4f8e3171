# One registration line per library and per test target.

set(PROXIMA_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)

# proxima_add_library(NAME SOURCES ... DEPENDS ...): a layer under Library/, target Proxima::NAME.
function(proxima_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  if(ARG_SOURCES)
    add_library(Proxima${name} STATIC ${ARG_SOURCES})
    target_include_directories(Proxima${name} PUBLIC "${PROJECT_SOURCE_DIR}/Library")
    target_link_libraries(Proxima${name} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
    target_compile_options(Proxima${name} PRIVATE ${PROXIMA_WARNINGS})
  else()
    add_library(Proxima${name} INTERFACE)
    target_include_directories(Proxima${name} INTERFACE "${PROJECT_SOURCE_DIR}/Library")
    target_link_libraries(Proxima${name} INTERFACE ${ARG_DEPENDS})
  endif()
  add_library(Proxima::${name} ALIAS Proxima${name})
endfunction()

# proxima_add_test(NAME SOURCES ... DEPENDS ... [LABELS ...]): one GoogleTest program under ctest.
function(proxima_add_test name)
  if(NOT PROXIMA_BUILD_TESTING)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    PROXIMA_SHARED_MESHES="${PROXIMA_SHARED_DATA}/meshes"
    PROXIMA_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  gtest_discover_tests(${name} PROPERTIES LABELS "${ARG_LABELS}" DISCOVERY_TIMEOUT 60)
endfunction()
