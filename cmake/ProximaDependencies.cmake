# Every third-party package is found here once, and each layer links only what DESIGN.md allows it.
# The real-time kernel (Core, Geometry, Proxy) uses none of these; VTK, OpenMesh, CGAL and
# OpenImageIO live at the edges (IO, VTK, Apps) and in tests as oracles.

find_package(Threads REQUIRED)

if(PROXIMA_BUILD_APPS)
  # Mesh readers (STL, OBJ, PLY, VTP, glTF) and, later, the pipeline and rendering.
  find_package(VTK 9.1 REQUIRED COMPONENTS CommonCore CommonDataModel IOGeometry IOPLY IOXML
               FiltersCore)
  # OFF reading and mesh preparation (welding, normals with a feature angle).
  find_package(OpenMesh REQUIRED)
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
