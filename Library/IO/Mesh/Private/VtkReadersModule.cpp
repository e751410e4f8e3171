// The module proxima-vtk-mesh-readers: VtkReaders.cpp's readers behind C names for dlsym
// (VtkReadersModule.h). Exceptions (InputError) pass through to the caller as they are.
#include "IO/Mesh/Private/VtkReaders.h"
#include "IO/Mesh/Private/VtkReadersModule.h"

#include <vtkPolyData.h>

extern "C" vtkSmartPointer<vtkPolyData> proximaReadWithVtk(const std::string& path,
                                                           proxima::MeshFileFormat format)
{
  return proxima::detail::readWithVtk(path, format);
}

extern "C" vtkSmartPointer<vtkPolyData> proximaReadGltfWithVtk(const std::string& vtkPath,
                                                               const std::string& userPath)
{
  return proxima::detail::readGltfWithVtk(vtkPath, userPath);
}
