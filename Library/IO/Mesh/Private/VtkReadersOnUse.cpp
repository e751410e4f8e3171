// readWithVtk and readGltfWithVtk for MeshIO's users: forwarded to the module that holds them
// (VtkReaders.cpp, with VTK's IOGeometry and IOXML, which pull in VTK's rendering), loaded the
// first time an STL, VTP or glTF file is read (IO/LoadOnUse/ModuleEntry.h).
#include "IO/LoadOnUse/ModuleEntry.h"
#include "IO/Mesh/Private/VtkReaders.h"
#include "IO/Mesh/Private/VtkReadersModule.h"

#include <vtkPolyData.h>

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

vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, MeshFileFormat format)
{
  return readers().readWithVtk(path, format);
}

vtkSmartPointer<vtkPolyData> readGltfWithVtk(const std::string& vtkPath,
                                             const std::string& userPath)
{
  return readers().readGltfWithVtk(vtkPath, userPath);
}

} // namespace proxima::detail
