// The one place where VTK data becomes kernel data on the way in: checks, triangulation, units.
// Public because the mesh readers and Library/VTK's filters share it, so a poly data set is
// refused for the same defects with the same words whether it came from a file or a pipeline.
// Only a forward declaration of vtkPolyData: a caller without VTK data never needs VTK's headers.
#pragma once

#include "Geometry/TriangleSoup.h"

#include <string>

class vtkPolyData;

namespace proxima
{

/// Checks `data` (finite coordinates, point ids in range, at least one polygon or strip),
/// triangulates its polygons and strips (dropping lines and vertices), and copies it into a soup
/// with every coordinate multiplied by `scale`; point normals and texture coordinates come along
/// when present for every point. Throws InputError naming `path` and the first defect found.
TriangleSoup polyDataToSoup(vtkPolyData* data, const std::string& path, double scale);

} // namespace proxima
