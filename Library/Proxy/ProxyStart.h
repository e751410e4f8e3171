// Where the proxy starts: at the finger, unless the finger is inside a closed object of the
// scene, where a proxy would be trapped (it could never leave through the surface it collides
// with). Then it starts at the nearest free point outside that object, and the runner reports it
// (trace flag, summary) and the servo ramps the force in (ServoForce.h). Decided off the haptic
// threads, at the start of a run and when a scene is published: the inside test costs O(n) in
// the scene's triangles (WindingNumber.h; Documentation/Kernel.md, "Starting outside").
#pragma once

#include "Core/Vec3.h"
#include "Proxy/CollisionScene.h"
#include "Proxy/ProxyParameters.h"
#include "Proxy/ProxySolver.h"

namespace proxima
{

/// Where placeProxyStart() puts the proxy, and why.
struct ProxyStartPlacement
{
  /// Where the proxy starts: the requested point, or the free point it was moved to.
  Vec3 position;
  /// The requested point was inside a closed object (isInsideByWindingNumber) and the proxy
  /// starts at `position` outside it instead.
  bool movedOutside = false;
  /// The object that held the point (index in the scene), -1 when none did.
  int object = -1;
  /// That object's winding number at the requested point (0 when none held it).
  double windingNumber = 0.0;
  /// Distance from the requested point to `position`, in metres.
  double movedDistance = 0.0;
};

/// The start for a proxy of `parameters.radius` requested at `point` in `scene`. Inside a closed
/// object, the nearest surface point pushed out along the outward direction by the radius plus
/// the skin, and further (by factors of 1.25) until no triangle of any object is within the
/// radius plus half the skin and no object holds it. A point that is not finite, or a scene
/// without objects, is returned as it is. Allocates; not for the haptic threads.
ProxyStartPlacement placeProxyStart(const CollisionScene& scene, const ProxyParameters& parameters,
                                    const Vec3& point);

/// Places the solver's proxy at `placement` (resetProxyOutside when it was moved, so that the
/// next tick reports it).
inline void resetProxyTo(ProxySolver& solver, const ProxyStartPlacement& placement)
{
  if (placement.movedOutside)
  {
    solver.resetProxyOutside(placement.position);
  }
  else
  {
    solver.resetProxy(placement.position);
  }
}

} // namespace proxima
