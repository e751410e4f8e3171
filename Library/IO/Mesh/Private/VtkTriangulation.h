// Inside the module proxima-vtk-mesh-readers: a PolygonSoup with polygons of more than three
// corners triangulated by polyDataToSoup (vtkTriangleFilter), so that the triangles are the ones
// VTK makes, as they were before the readers produced plain C++.
#pragma once

#include "Geometry/TriangleSoup.h"
#include "IO/Mesh/Private/PolygonSoup.h"

#include <string>

namespace proxima::detail
{

/// The polygons as a vtkPolyData (double points, normals and texture coordinates when present;
/// lines and vertex cells left out, which vtkTriangleFilter drops anyway), then polyDataToSoup.
TriangleSoup triangulatePolygonsWithVtk(const PolygonSoup& polygons, const std::string& path,
                                        double scale);

} // namespace proxima::detail
