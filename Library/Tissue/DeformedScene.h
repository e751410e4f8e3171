// A scene as its tissues are deformed now, for drawing: what a picture of a session with tissue
// must show (the trainer's --screenshot), not the rest shape the scene file gave.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Tissue/TissueDynamics.h"

namespace proxima
{

/// A copy of `scene` that shares every object but the tissues', each of which is its mesh moved to
/// the surface last handed to the solver (TissueDynamics::surface: the one the proxy touches). The
/// tissue objects have no sphere tree or filter records: for drawing, not for queries. Allocates:
/// not for the haptic thread. A tissue whose object is out of range, or whose solid has another
/// number of points than the object's mesh, is left as the scene has it.
CollisionScene deformedScene(const CollisionScene& scene, const TissueDynamics& tissue);

} // namespace proxima
