// The one place where VTK data becomes kernel data on the way in: checks, triangulation, units.
#pragma once

#include "Geometry/TriangleSoup.h"

#include <string>

class vtkPolyData;

namespace proxima::detail
{

/// Checks `data` (finite coordinates, point ids in range, at least one polygon or strip),
/// triangulates its polygons and strips (dropping lines and vertices), and copies it into a soup
/// with every coordinate multiplied by `scale`; point normals and texture coordinates come along
/// when present for every point. Throws InputError naming `path` and the first defect found.
TriangleSoup polyDataToSoup(vtkPolyData* data, const std::string& path, double scale);

} // namespace proxima::detail
