# Every third-party package is found here once, and each layer links only what DESIGN.md allows it.
# The real-time kernel (Core, Geometry, Proxy) uses none of these; VTK, OpenMesh, CGAL and
# OpenImageIO live at the edges (IO, VTK, Apps) and in tests as oracles.

find_package(Threads REQUIRED)

if(PROXIMA_BUILD_APPS)
  # Mesh readers (STL, OBJ, PLY, VTP, glTF); the haptic pipeline of Library/VTK (filters, scene,
  # representations) and its rendering, offscreen image tests (IOImage, ImagingCore's
  # vtkImageDifference) and the viewer's window (InteractionStyle, RenderingFreeType for text).
  find_package(VTK 9.1 REQUIRED COMPONENTS CommonCore CommonDataModel CommonExecutionModel
               CommonMath CommonTransforms IOGeometry IOPLY IOXML IOImage FiltersCore
               FiltersSources FiltersGeneral ImagingCore RenderingCore RenderingOpenGL2
               InteractionStyle RenderingFreeType)
  # OFF reading and mesh preparation (welding, normals with a feature angle).
  find_package(OpenMesh REQUIRED)
  # Texture images (PNG, JPEG, TIFF, OpenEXR) for the IO layer, and to write test images.
  find_package(OpenImageIO CONFIG REQUIRED)
  # Debian 12's OpenImageIO target names /usr/include/opencv4, which exists only with
  # libopencv-dev (OIIO's headers do not need it); CMake refuses a target naming a missing folder,
  # so drop the folders that are not there.
  foreach(_property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(_folders OpenImageIO::OpenImageIO ${_property})
    if(_folders)
      set(_present)
      foreach(_folder IN LISTS _folders)
        if(EXISTS "${_folder}")
          list(APPEND _present "${_folder}")
        endif()
      endforeach()
      set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${_property} "${_present}")
    endif()
  endforeach()
  # Command-line parsing and JSON output.
  find_package(CLI11 REQUIRED)
  find_package(nlohmann_json 3.10 REQUIRED)
endif()

if(PROXIMA_BUILD_TESTING OR PROXIMA_BUILD_BENCHMARKS)
  # Exact geometry as an independent oracle in tests and as the AABB-tree baseline in benchmarks.
  find_package(CGAL REQUIRED)
endif()

if(PROXIMA_BUILD_TESTING)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()

if(PROXIMA_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
