// The scene's bounding spheres at one level of its trees (paper section 5), drawn as translucent
// wireframe balls over the part: how the tree the proxy queries covers it. Level 0 is each tree's
// root; leaves above the level are drawn too, so the whole surface stays covered.
#pragma once

#include "Proxy/CollisionScene.h"

#include <vtkSmartPointer.h>

#include <cstdint>

class vtkActor;

namespace proxima::inspector
{

/// The spheres of every object's tree at `level`, and how many were drawn.
vtkSmartPointer<vtkActor> makeSphereTreeLevelActor(const CollisionScene& scene, std::uint32_t level,
                                                   std::size_t& spheres);

/// The deepest level of the scene's trees.
std::uint32_t sphereTreeDepth(const CollisionScene& scene);

} // namespace proxima::inspector
