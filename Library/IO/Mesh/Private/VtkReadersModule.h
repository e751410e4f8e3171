// The entry of the module proxima-vtk-mesh-readers (VtkReadersModule.cpp), which MeshIO loads on
// first use (VtkReadersOnUse.cpp): a table of VtkReaders.h's two functions, returned by a
// function with a C name that dlsym finds.
#pragma once

#include "IO/Mesh/MeshFileFormat.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace proxima::detail
{

struct VtkMeshReaders
{
  vtkSmartPointer<vtkPolyData> (*readWithVtk)(const std::string& path, MeshFileFormat format);
  vtkSmartPointer<vtkPolyData> (*readGltfWithVtk)(const std::string& vtkPath,
                                                  const std::string& userPath);
};

/// The name of `const VtkMeshReaders* entry()` in the module.
inline constexpr const char* kVtkMeshReadersEntry = "proximaVtkMeshReaders";

} // namespace proxima::detail
