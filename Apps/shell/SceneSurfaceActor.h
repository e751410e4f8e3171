// The surface the proxy touches, drawn from the kernel's own triangles (what the applications
// show under the proxy): sharp CAD edges (60 degrees and more) stay sharp, a scan's noisy bends
// below that stay smooth, in one warm tissue colour.
#pragma once

#include "Proxy/CollisionScene.h"

#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <vector>

class vtkAlgorithmOutput;
class vtkPolyData;

namespace proxima::shell
{

vtkSmartPointer<vtkActor> makeSceneSurfaceActor(const CollisionScene& scene);

/// The same for triangles given as vtkPolyData.
vtkSmartPointer<vtkActor> makeSurfaceActor(vtkPolyData* surface);
/// The same for a pipeline's output (vtkHapticTissue's: each update of the source redraws it).
vtkSmartPointer<vtkActor> makeSurfaceActor(vtkAlgorithmOutput* surface);

/// The same for some of the scene's objects only (a moving body's, which its own actor's
/// transform then moves; or all the others), or null when `objects` is empty.
vtkSmartPointer<vtkActor> makeSceneSurfaceActor(const CollisionScene& scene,
                                                const std::vector<std::uint32_t>& objects);

/// The objects of `scene` not among `notStill` (bodies that move, tissues that deform), in
/// order: those one still actor draws while the others get actors of their own.
std::vector<std::uint32_t> stillObjects(const CollisionScene& scene,
                                        const std::vector<std::uint32_t>& notStill);

} // namespace proxima::shell
