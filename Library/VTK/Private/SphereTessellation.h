// Sphere surfaces for drawing a sphere tree: a latitude-longitude tessellation of each sphere,
// written in parallel (vtkSMPTools) straight into the arrays of a vtkPolyData.
#pragma once

#include "Geometry/SphereTree.h"

#include <vtkType.h>

#include <vector>

namespace proxima::vtk::detail
{

/// Points and triangles of one sphere drawn with `resolution` segments around (and half as many,
/// at least 2, from pole to pole).
vtkIdType pointsPerSphere(int resolution);
vtkIdType trianglesPerSphere(int resolution);

/// Writes sphere i's points (xyz) from point i * pointsPerSphere, its triangles' point ids from
/// triangle i * trianglesPerSphere, and its radius once per triangle. The arrays must hold
/// spheres.size() times as many of each.
void tessellateSpheres(const std::vector<Sphere>& spheres, int resolution, double* points,
                       vtkIdType* connectivity, double* radii);

} // namespace proxima::vtk::detail
