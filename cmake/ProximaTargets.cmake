# One registration line per library and per test target.

set(PROXIMA_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)

include(GNUInstallDirs)
# Debian's documentation folder is named for the package in lower case; GNUInstallDirs falls back
# to the project's name (share/doc/Proxima). A CMAKE_INSTALL_DOCDIR given on the command line (the
# cache entry is empty otherwise) wins.
if("$CACHE{CMAKE_INSTALL_DOCDIR}" STREQUAL "")
  set(CMAKE_INSTALL_DOCDIR "${CMAKE_INSTALL_DATAROOTDIR}/doc/proxima")
endif()

# The component of find_package(Proxima COMPONENTS ...) a layer belongs to, from its folder
# (Documentation/Library.md): the real-time kernel (Core, Geometry, Proxy, Runtime), IO, the VTK
# pipeline and the devices.
function(proxima_component_of folder result)
  if(folder MATCHES "^IO(/|$)")
    set(${result} IO PARENT_SCOPE)
  elseif(folder MATCHES "^(VTK|Devices|Dynamics|Net)(/|$)")
    set(${result} ${CMAKE_MATCH_1} PARENT_SCOPE)
  else()
    set(${result} Kernel PARENT_SCOPE)
  endif()
endfunction()

# proxima_install_library(TARGET COMPONENT HEADER_FOLDER [HEADERS...]): installs a library into
# the component's export set (ProximaCOMPONENTTargets.cmake, targets Proxima::NAME) and its public
# headers under include/proxima/HEADER_FOLDER, where `#include "HEADER_FOLDER/Name.h"` finds them
# as it does in the source tree.
function(proxima_install_library target component folder)
  install(TARGETS ${target} EXPORT Proxima${component}Targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${component}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/proxima)
  if(ARGN)
    install(FILES ${ARGN} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/proxima/${folder}
            COMPONENT ${component})
  endif()
  set_property(GLOBAL APPEND PROPERTY PROXIMA_INSTALLED_COMPONENTS ${component})
endfunction()

# proxima_add_umbrella(NAME COMPONENT TARGETS...): Proxima::NAME, an interface target that links
# every library of a component, installed with it (Proxima::Kernel, Proxima::IO).
function(proxima_add_umbrella name component)
  add_library(Proxima${name} INTERFACE)
  target_link_libraries(Proxima${name} INTERFACE ${ARGN})
  set_target_properties(Proxima${name} PROPERTIES EXPORT_NAME ${name})
  add_library(Proxima::${name} ALIAS Proxima${name})
  proxima_install_library(Proxima${name} ${component} "")
endfunction()

# proxima_add_library(NAME SOURCES ... DEPENDS ... PRIVATE_DEPENDS ...): a layer under Library/,
# target Proxima::NAME, installed with its public headers (those of its folder; Private/ and
# Testing/ stay out) into the component its folder belongs to.
function(proxima_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  set(includes "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/Library>"
               "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/proxima>")
  if(ARG_SOURCES)
    add_library(Proxima${name} STATIC ${ARG_SOURCES})
    target_include_directories(Proxima${name} PUBLIC ${includes})
    target_link_libraries(Proxima${name} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
    target_compile_options(Proxima${name} PRIVATE ${PROXIMA_WARNINGS})
  else()
    add_library(Proxima${name} INTERFACE)
    target_include_directories(Proxima${name} INTERFACE ${includes})
    target_link_libraries(Proxima${name} INTERFACE ${ARG_DEPENDS})
  endif()
  set_target_properties(Proxima${name} PROPERTIES EXPORT_NAME ${name})
  add_library(Proxima::${name} ALIAS Proxima${name})
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}/Library" "${CMAKE_CURRENT_SOURCE_DIR}")
  proxima_component_of("${folder}" component)
  file(GLOB headers CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.h")
  proxima_install_library(Proxima${name} ${component} "${folder}" ${headers})
endfunction()

# proxima_add_test(NAME SOURCES ... DEPENDS ... [LABELS label] [DEFINITIONS ...]
#                  [ENVIRONMENT VAR=value] [SHARED_DATA_CASES regex]
#                  [WHOLE_PROGRAM ctest-name [LAUNCHER command...] [TIMEOUT seconds]]):
# the one way a test program is registered. A GoogleTest program under ctest, linked with
# gtest_main; by default each of its test cases is its own ctest entry (gtest_discover_tests).
# WHOLE_PROGRAM registers the program as one entry instead, for a program whose cases share
# something costly (the image tests' X server), run through LAUNCHER when given. Test folders are
# only entered when PROXIMA_BUILD_TESTING is on; this returns early too, for tests beside a layer.
# DEPENDS goes to target_link_libraries as is, so linker flags may be among the libraries.
# PROXIMA_SHARED_MESHES is the test-data folder's meshes/ (cmake/ProximaTestData.cmake): the
# shipped third-party meshes, and the shared ones where PROXIMA_SHARED_DATA is present.
# SHARED_DATA_CASES: the discovered cases whose ctest names match the regex need files only
# PROXIMA_SHARED_DATA has (PROXIMA_SHARED_ONLY_CASES matches the cases named for its meshes) and
# get the label shared-data as well; a WHOLE_PROGRAM whose every case needs them lists
# shared-data in LABELS.
function(proxima_add_test name)
  if(NOT PROXIMA_BUILD_TESTING)
    return()
  endif()
  cmake_parse_arguments(ARG "" "WHOLE_PROGRAM;TIMEOUT;ENVIRONMENT;SHARED_DATA_CASES"
                        "SOURCES;DEPENDS;LABELS;DEFINITIONS;LAUNCHER" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    PROXIMA_SHARED_MESHES="${PROXIMA_TEST_DATA}/meshes"
    PROXIMA_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ${ARG_DEFINITIONS})
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  if(ARG_WHOLE_PROGRAM)
    add_test(NAME ${ARG_WHOLE_PROGRAM} COMMAND ${ARG_LAUNCHER} $<TARGET_FILE:${name}>)
    set_tests_properties(${ARG_WHOLE_PROGRAM} PROPERTIES LABELS "${ARG_LABELS}")
    if(ARG_ENVIRONMENT)
      set_tests_properties(${ARG_WHOLE_PROGRAM} PROPERTIES ENVIRONMENT "${ARG_ENVIRONMENT}")
    endif()
    if(ARG_TIMEOUT)
      set_tests_properties(${ARG_WHOLE_PROGRAM} PROPERTIES TIMEOUT ${ARG_TIMEOUT})
    endif()
  else()
    # PROPERTIES passes each value on as separate words, so a second label would become a
    # property name: the first label goes there, and several are set by a script ctest includes
    # after the discovered tests, on their list (TEST_LIST, <target>_TESTS by default).
    list(GET ARG_LABELS 0 firstLabel)
    if(ARG_ENVIRONMENT)
      gtest_discover_tests(${name} PROPERTIES LABELS "${firstLabel}" ENVIRONMENT
                           "${ARG_ENVIRONMENT}" DISCOVERY_TIMEOUT 60)
    else()
      gtest_discover_tests(${name} PROPERTIES LABELS "${firstLabel}" DISCOVERY_TIMEOUT 60)
    endif()
    list(LENGTH ARG_LABELS numLabels)
    if(numLabels GREATER 1 OR ARG_SHARED_DATA_CASES)
      set(labelScript "${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake")
      set(script "if(DEFINED ${name}_TESTS)\n")
      if(numLabels GREATER 1)
        string(APPEND script
               "  set_tests_properties(\${${name}_TESTS} PROPERTIES LABELS \"${ARG_LABELS}\")\n")
      endif()
      if(ARG_SHARED_DATA_CASES)
        string(APPEND script
               "  foreach(test IN LISTS ${name}_TESTS)\n"
               "    if(test MATCHES [==[${ARG_SHARED_DATA_CASES}]==])\n"
               "      set_tests_properties(\"\${test}\" PROPERTIES LABELS \"${ARG_LABELS};shared-data\")\n"
               "    endif()\n"
               "  endforeach()\n")
      endif()
      string(APPEND script "endif()\n")
      file(WRITE "${labelScript}" "${script}")
      set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${labelScript}")
    endif()
  endif()
endfunction()
