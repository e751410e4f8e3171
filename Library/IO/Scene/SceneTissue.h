// The tissues a scene file declares (`tissue` on an object, version 3; Documentation/Tissue.md),
// made into the dynamics step that deforms them each tick: each object's tetrahedra (made when
// the scene was built, LoadedScene::tissues) with its Young's modulus and the stiffer inclusions,
// held in its fixed box. A scene without tissue makes nothing here.
#pragma once

#include "IO/Scene/SceneBuilder.h"
#include "Tissue/TissueDynamics.h"

#include <memory>

namespace proxima
{

/// The scene's tissues coupled to the proxy, or null when it has none. `kp` (N/m) and `rate`
/// (Hz) are the servo's. Each tetrahedron whose centroid lies in an inclusion takes its Young's
/// modulus (the last such inclusion's); every vertex in the fixed box is held. Throws InputError
/// naming the scene file and the object (`objects[0].tissue.fixed.box: ...`) for a box that holds
/// no vertex, or a solid the elastic model refuses.
std::unique_ptr<TissueDynamics> buildSceneTissue(const LoadedScene& loaded, double kp, double rate);

} // namespace proxima
