# The folder the tests, benchmarks and test scripts read real meshes and person-like paths from:
# PROXIMA_TEST_DATA (build/TestData), laid out as PROXIMA_SHARED_DATA is, with meshes/ and paths/
# holding symbolic links. meshes/ links every file of Data/Meshes (the third-party meshes that
# ship, Data/README.md) and, where PROXIMA_SHARED_DATA is present, its files that are not
# shipped (the screw, the ABC part, the cranium); paths/ links the shared person-like paths. So a
# clone without the shared folder finds every shipped mesh under the same names, and the tests
# that need a file only PROXIMA_SHARED_DATA has carry the label shared-data and skip, saying so.
# Remade at every configure, so that a changed PROXIMA_SHARED_DATA leaves no stale link.
set(PROXIMA_TEST_DATA "${PROJECT_BINARY_DIR}/TestData")
# The test cases named for a mesh that may not ship (parameter names have `_` for `.` and `-`):
# for proxima_add_test's SHARED_DATA_CASES.
set(PROXIMA_SHARED_ONLY_CASES "M3x10_screw|abc_00000050_trimesh_000|cranium_bone_iso075mm")
if(EXISTS "${PROXIMA_SHARED_DATA}/meshes")
  set(PROXIMA_HAVE_SHARED_DATA TRUE)
else()
  set(PROXIMA_HAVE_SHARED_DATA FALSE)
  message(STATUS "Proxima: no shared data in PROXIMA_SHARED_DATA (${PROXIMA_SHARED_DATA}); "
                 "the tests labelled shared-data will skip")
endif()

file(REMOVE_RECURSE "${PROXIMA_TEST_DATA}")
file(MAKE_DIRECTORY "${PROXIMA_TEST_DATA}/meshes" "${PROXIMA_TEST_DATA}/paths")

# proxima_link_test_data(SUBFOLDER FILE...): links each file into TestData/SUBFOLDER unless a file
# of its name is there already (the shipped copy comes first).
function(proxima_link_test_data subfolder)
  foreach(file IN LISTS ARGN)
    get_filename_component(name "${file}" NAME)
    set(link "${PROXIMA_TEST_DATA}/${subfolder}/${name}")
    if(NOT EXISTS "${link}" AND NOT IS_SYMLINK "${link}")
      file(CREATE_LINK "${file}" "${link}" SYMBOLIC)
    endif()
  endforeach()
endfunction()

# CONFIGURE_DEPENDS: a file added to either folder, or the shared folder appearing, configures
# again at the next build.
file(GLOB _shippedMeshes CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/Data/Meshes/*")
proxima_link_test_data(meshes ${_shippedMeshes})
file(GLOB _sharedMeshes CONFIGURE_DEPENDS "${PROXIMA_SHARED_DATA}/meshes/*")
file(GLOB _sharedPaths CONFIGURE_DEPENDS "${PROXIMA_SHARED_DATA}/paths/*")
proxima_link_test_data(meshes ${_sharedMeshes})
proxima_link_test_data(paths ${_sharedPaths})
