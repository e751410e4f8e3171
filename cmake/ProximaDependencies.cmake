# Every third-party package is found here once, and each layer links only what DESIGN.md allows it.
# The real-time kernel (Core, Geometry, Proxy) uses none of these; VTK, OpenMesh, CGAL and
# OpenImageIO live at the edges (IO, VTK, Apps) and in tests as oracles.

find_package(Threads REQUIRED)

# VTK once, with the components of the parts switched on. IO: mesh readers and writers (STL, VTP,
# glTF; OBJ and PLY writers; the triangle filter of polyDataToSoup). The VTK layer: its filters,
# scene and representations (execution model, math, transforms, sources, rendering). The
# applications: the viewer's window, its offscreen screenshots and its text; the VTK layer's image
# tests use the same (IOImage, ImagingCore's vtkImageDifference, OpenGL2, InteractionStyle).
set(_vtkComponents)
if(PROXIMA_BUILD_IO)
  list(APPEND _vtkComponents CommonCore CommonDataModel IOGeometry IOPLY IOXML FiltersCore)
endif()
if(PROXIMA_BUILD_VTK)
  list(APPEND _vtkComponents CommonExecutionModel CommonMath CommonTransforms FiltersSources
       FiltersGeneral RenderingCore)
  if(PROXIMA_BUILD_TESTING)
    list(APPEND _vtkComponents IOImage ImagingCore RenderingOpenGL2 InteractionStyle)
  endif()
endif()
if(PROXIMA_BUILD_IO AND PROXIMA_BUILD_TESTING)
  # The mesh inspection's oracle: VTK's triangle quality (smallest angles).
  list(APPEND _vtkComponents FiltersVerdict)
endif()
if(PROXIMA_BUILD_APPS)
  list(APPEND _vtkComponents IOImage RenderingOpenGL2 InteractionStyle RenderingFreeType)
endif()
if(PROXIMA_BUILD_APPS AND PROXIMA_BUILD_QT)
  # The applications' Qt windows: VTK's Qt widget (QVTKOpenGLNativeWidget) and Qt 5's widgets,
  # with QTest for the window tests.
  list(APPEND _vtkComponents GUISupportQt)
  find_package(Qt5 5.15 REQUIRED COMPONENTS Widgets Test)
endif()
if(PROXIMA_BUILD_DYNAMICS)
  # Rigid bodies and mechanisms (Library/Dynamics), integrated at the haptic rate.
  find_package(mujoco CONFIG REQUIRED)
endif()
if(PROXIMA_BUILD_NET)
  # Remote runs (Library/Net): messages and their compiler, and the RPC framework.
  find_package(Protobuf REQUIRED)
  find_package(gRPC CONFIG REQUIRED)
endif()
if(PROXIMA_BUILD_PYTHON)
  # Debian's python3: the modules are built for it. Found before VTK, whose VTK::Python (used by
  # the wrapping of the vtkHaptic* classes, Wrapping/VTKPython) links Python3::Module.
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Debian's python3, for which the Python modules are built")
  find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module)
endif()
if(_vtkComponents)
  list(REMOVE_DUPLICATES _vtkComponents)
  find_package(VTK 9.1 REQUIRED COMPONENTS ${_vtkComponents})
endif()

if(PROXIMA_BUILD_IO)
  # OFF reading and mesh preparation (normals with a feature angle).
  find_package(OpenMesh REQUIRED)
  # Texture images (PNG, JPEG, TIFF, OpenEXR) for the scene files, and to write test images.
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
endif()

if(PROXIMA_BUILD_IO OR PROXIMA_BUILD_APPS OR PROXIMA_BUILD_BENCHMARKS)
  # Scene files and the checks of glTF documents (IO), the JSON reports of proxima and of the
  # measuring programs.
  find_package(nlohmann_json 3.10 REQUIRED)
endif()
if(PROXIMA_BUILD_APPS)
  # Command-line parsing.
  find_package(CLI11 REQUIRED)
  # The viewer asks Xlib whether a display opens before VTK's X window tries (and crashes).
  find_package(X11 REQUIRED)
endif()

if(PROXIMA_BUILD_IO OR PROXIMA_BUILD_TESTING OR PROXIMA_BUILD_BENCHMARKS)
  # Exact geometry: the self-intersections of `proxima inspect` (IO/MeshInspection), an
  # independent oracle in tests, and the AABB-tree baseline in benchmarks.
  find_package(CGAL REQUIRED)
endif()

if(PROXIMA_BUILD_TESTING)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()

if(PROXIMA_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
