// VtkOnUse.h's functions for MeshIO's users: forwarded to the module that holds them
// (VtkReadersModule.cpp, with VTK's IOGeometry and IOXML, which pull in VTK's rendering, and
// polyDataToSoup with its vtkTriangleFilter), loaded the first time an STL, VTP or glTF file, or
// a file with polygons of more than three corners, is read (IO/LoadOnUse/ModuleEntry.h).
#include "IO/Mesh/Private/VtkOnUse.h"

#include "IO/LoadOnUse/ModuleEntry.h"
#include "IO/Mesh/Private/VtkReadersModule.h"

namespace proxima::detail
{
namespace
{
const VtkMeshReaders& readers()
{
  // Loaded once, by the first caller (a function-local static is initialised thread-safely).
  static const VtkMeshReaders* const table = reinterpret_cast<const VtkMeshReaders* (*)()>(
    moduleEntry(PROXIMA_MODULE_PROXIMA_VTK_MESH_READERS, kVtkMeshReadersEntry))();
  return *table;
}
} // namespace

TriangleSoup readSoupWithVtk(const std::string& path, MeshFileFormat format, double scale)
{
  return readers().readWithVtk(path, format, scale);
}

TriangleSoup readGltfSoupWithVtk(const std::string& vtkPath, const std::string& userPath,
                                 double scale)
{
  return readers().readGltfWithVtk(vtkPath, userPath, scale);
}

TriangleSoup triangulateWithVtk(const PolygonSoup& polygons, const std::string& path, double scale)
{
  return readers().triangulateWithVtk(polygons, path, scale);
}

} // namespace proxima::detail
