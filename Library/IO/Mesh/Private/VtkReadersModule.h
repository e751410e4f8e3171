// The entries of the module proxima-vtk-mesh-readers (VtkReadersModule.cpp), which MeshIO loads
// on first use (VtkReadersOnUse.cpp): VtkReaders.h's two functions under C names that dlsym finds.
#pragma once

#include "IO/Mesh/MeshFileFormat.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace proxima::detail
{

using ReadWithVtkEntry = vtkSmartPointer<vtkPolyData> (*)(const std::string&, MeshFileFormat);
using ReadGltfWithVtkEntry = vtkSmartPointer<vtkPolyData> (*)(const std::string&,
                                                               const std::string&);
inline constexpr const char* kReadWithVtkEntry = "proximaReadWithVtk";
inline constexpr const char* kReadGltfWithVtkEntry = "proximaReadGltfWithVtk";

} // namespace proxima::detail
