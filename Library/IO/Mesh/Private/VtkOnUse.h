// What MeshIO asks of VTK, all through the module proxima-vtk-mesh-readers (VtkReadersModule.h),
// loaded the first time one of these is called (IO/LoadOnUse/ModuleEntry.h): MeshIO itself
// references no VTK symbol, so a program that reads only OBJ, PLY and OFF files of triangles
// loads no VTK library. Each returns what polyDataToSoup makes of VTK's poly data.
#pragma once

#include "Geometry/TriangleSoup.h"
#include "IO/Mesh/MeshFileFormat.h"
#include "IO/Mesh/Private/PolygonSoup.h"

#include <string>

namespace proxima::detail
{

/// STL or VTP through VTK's reader (VtkReaders.h), then polyDataToSoup.
TriangleSoup readSoupWithVtk(const std::string& path, MeshFileFormat format, double scale);

/// glTF through VTK's reader from the checked copy `vtkPath`, errors naming `userPath`.
TriangleSoup readGltfSoupWithVtk(const std::string& vtkPath, const std::string& userPath,
                                 double scale);

/// `polygons` as a vtkPolyData (its points and faces as the readers built them before they made a
/// PolygonSoup), then polyDataToSoup, whose vtkTriangleFilter splits the polygons of more than
/// three corners.
TriangleSoup triangulateWithVtk(const PolygonSoup& polygons, const std::string& path, double scale);

} // namespace proxima::detail
