// The bodies a scene file declares (`body` on an object, version 2; Documentation/Dynamics.md),
// made into the coupling that moves them each tick: mass properties from each object's closed
// mesh as placed, joints in the scene's frame, and the check that each is heavy enough to touch
// stably at the run's spring and rate. A scene without bodies makes nothing here and runs no
// dynamics step.
#pragma once

#include "Dynamics/BodyCoupling.h"
#include "IO/Scene/SceneBuilder.h"

#include <memory>

namespace proxima
{

/// The bodies' coupling, or null when the scene has no bodies. `kp` (N/m) and `rate` (Hz) are
/// the servo's. Throws InputError naming the scene file and the object (`objects[2].body: ...`)
/// for a body whose mesh bounds no solid, a joint MuJoCo refuses, or a body too light for a
/// stable coupling.
std::unique_ptr<BodyCoupling> buildSceneBodies(const LoadedScene& loaded, double kp, double rate);

/// The description's joint as the Dynamics layer's.
BodyDescription bodyDescription(const SceneBody& body, const std::string& name,
                                const TriangleMesh& placedMesh);

} // namespace proxima
