// The surface the proxy touches, drawn from the kernel's own triangles (what the applications
// show under the proxy): sharp CAD edges (60 degrees and more) stay sharp, a scan's noisy bends
// below that stay smooth, in one warm tissue colour.
#pragma once

#include "Proxy/CollisionScene.h"

#include <vtkActor.h>
#include <vtkSmartPointer.h>

namespace proxima::shell
{

vtkSmartPointer<vtkActor> makeSceneSurfaceActor(const CollisionScene& scene);

} // namespace proxima::shell
