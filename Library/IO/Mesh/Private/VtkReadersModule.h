// The entry of the module proxima-vtk-mesh-readers (VtkReadersModule.cpp), which MeshIO loads on
// first use (VtkReadersOnUse.cpp): a table of the functions of VtkOnUse.h, returned by a function
// with a C name that dlsym finds. Only kernel types cross: MeshIO never sees a VTK object.
#pragma once

#include "Geometry/TriangleSoup.h"
#include "IO/Mesh/MeshFileFormat.h"
#include "IO/Mesh/Private/PolygonSoup.h"

#include <string>

namespace proxima::detail
{

struct VtkMeshReaders
{
  TriangleSoup (*readWithVtk)(const std::string& path, MeshFileFormat format, double scale);
  TriangleSoup (*readGltfWithVtk)(const std::string& vtkPath, const std::string& userPath,
                                  double scale);
  TriangleSoup (*triangulateWithVtk)(const PolygonSoup& polygons, const std::string& path,
                                     double scale);
};

/// The name of `const VtkMeshReaders* entry()` in the module.
inline constexpr const char* kVtkMeshReadersEntry = "proximaVtkMeshReaders";

} // namespace proxima::detail
