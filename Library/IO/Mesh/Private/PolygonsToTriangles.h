// A reader's PolygonSoup into the kernel's TriangleSoup with exactly the checks, messages and
// output of polyDataToSoup (IO/Mesh/PolyDataToSoup.h), in plain C++. Faces that are all
// triangles are copied here; polygons of more than three corners go to VTK's vtkTriangleFilter
// in the module of VtkOnUse.h, so that their triangulation stays the one polyDataToSoup makes.
#pragma once

#include "Geometry/TriangleSoup.h"
#include "IO/Mesh/Private/PolygonSoup.h"

#include <string>

namespace proxima::detail
{

/// Throws InputError naming `path` and the first defect, as polyDataToSoup would for the same
/// polygons in a vtkPolyData.
TriangleSoup polygonsToTriangles(const PolygonSoup& polygons, const std::string& path,
                                 double scale);

} // namespace proxima::detail
