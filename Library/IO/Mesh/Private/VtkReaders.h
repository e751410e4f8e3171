// Runs the VTK reader for one format and turns whatever VTK complains about into an InputError.
#pragma once

#include "IO/Mesh/MeshFileFormat.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace proxima::detail
{

/// STL or VTP. Throws InputError when the reader reports an error, or reports a warning and
/// produces nothing.
vtkSmartPointer<vtkPolyData> readWithVtk(const std::string& path, MeshFileFormat format);

/// glTF: every mesh of the default scene, node transforms applied, appended into one poly data,
/// read from `vtkPath` (the checked copy of GltfGeometryFile.h, never the user's file), with the
/// errors as readWithVtk's but naming `userPath`, the file the user gave.
vtkSmartPointer<vtkPolyData> readGltfWithVtk(const std::string& vtkPath,
                                             const std::string& userPath);

} // namespace proxima::detail
