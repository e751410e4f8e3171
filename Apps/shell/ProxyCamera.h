// How the applications' camera and finger start and move with the proxy: the finger of a device
// with no path starts above the scene's top, and a following camera eases after the proxy while
// keeping the direction and distance the user gave it with the mouse.
#pragma once

#include "Core/Vec3.h"
#include "Proxy/CollisionScene.h"

class vtkCamera;

namespace proxima::shell
{

/// Two proxy radii above the scene's top (z, the default camera's up-facing side), over the
/// centre of its bounding box.
Vec3 startAboveScene(const CollisionScene& scene, double radius);

/// Between `camera` and the scene: from the centre of the scene's bounding box towards the camera,
/// two proxy radii outside the sphere around the box.
Vec3 startFacingCamera(const CollisionScene& scene, vtkCamera* camera, double radius);

/// Moves the camera a quarter of the way to the proxy, keeping its direction and distance: eased,
/// so that a jittering proxy does not shake the picture. Call once a frame.
void followProxy(vtkCamera* camera, const Vec3& proxy);

} // namespace proxima::shell
