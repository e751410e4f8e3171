// readWithVtk and readGltfWithVtk for MeshIO's users: forwarded to the module that holds them
// (VtkReaders.cpp, with VTK's IOGeometry and IOXML, which pull in VTK's rendering), loaded the
// first time an STL, VTP or glTF file is read (IO/LoadOnUse/ModuleEntry.h).
#include "IO/LoadOnUse/ModuleEntry.h"
#include "IO/Mesh/Private/VtkReaders.h"
#include "IO/Mesh/Private/VtkReadersModule.h"

#include <vtkPolyData.h>

namespace proxima::detail
{

vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, MeshFileFormat format)
{
  static const auto read = reinterpret_cast<ReadWithVtkEntry>(
    moduleEntry(PROXIMA_MODULE_PROXIMA_VTK_MESH_READERS, kReadWithVtkEntry));
  return read(path, format);
}

vtkSmartPointer<vtkPolyData> readGltfWithVtk(const std::string& vtkPath, const std::string& userPath)
{
  static const auto read = reinterpret_cast<ReadGltfWithVtkEntry>(
    moduleEntry(PROXIMA_MODULE_PROXIMA_VTK_MESH_READERS, kReadGltfWithVtkEntry));
  return read(vtkPath, userPath);
}

} // namespace proxima::detail
