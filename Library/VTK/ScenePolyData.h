// The kernel's scene back as vtkPolyData, for drawing exactly what the proxy touches: every
// object's triangles in world coordinates, cell data "ObjectId" saying which object each came
// from.
#pragma once

#include "Proxy/CollisionScene.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace proxima::vtk
{

/// Fills `output` with the triangles of every object of `scene`.
void scenePolyData(const CollisionScene& scene, vtkPolyData* output);
/// The same, into a new vtkPolyData.
vtkSmartPointer<vtkPolyData> scenePolyData(const CollisionScene& scene);

} // namespace proxima::vtk
