// The module proxima-vtk-mesh-readers: VtkReaders.cpp's readers followed by polyDataToSoup, and
// VtkTriangulation.cpp's triangulation, in the table of VtkReadersModule.h. Exceptions
// (InputError) pass through to the caller as they are.
#include "IO/Mesh/Private/VtkReadersModule.h"

#include "IO/Mesh/PolyDataToSoup.h"
#include "IO/Mesh/Private/VtkReaders.h"
#include "IO/Mesh/Private/VtkTriangulation.h"

#include <vtkPolyData.h>

namespace
{
using proxima::MeshFileFormat;
using proxima::TriangleSoup;

TriangleSoup readSoup(const std::string& path, MeshFileFormat format, double scale)
{
  return proxima::polyDataToSoup(proxima::detail::readWithVtk(path, format), path, scale);
}

TriangleSoup readGltfSoup(const std::string& vtkPath, const std::string& userPath, double scale)
{
  return proxima::polyDataToSoup(proxima::detail::readGltfWithVtk(vtkPath, userPath), userPath,
                                 scale);
}
} // namespace

extern "C" const proxima::detail::VtkMeshReaders* proximaVtkMeshReaders()
{
  static const proxima::detail::VtkMeshReaders readers{
    &readSoup, &readGltfSoup, &proxima::detail::triangulatePolygonsWithVtk};
  return &readers;
}
