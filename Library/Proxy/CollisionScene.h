// What the proxy collides with: one or more triangle meshes, each with its sphere tree. Built off
// the haptic thread, then only read.
#pragma once

#include "Geometry/SphereTree.h"
#include "Geometry/TriangleMesh.h"
#include "Proxy/SurfaceMaterial.h"

#include <vector>

namespace proxima
{

struct CollisionObject
{
  TriangleMesh mesh;
  SphereTree tree;
  SurfaceMaterial material;
};

struct CollisionScene
{
  std::vector<CollisionObject> objects;

  /// Adds a mesh and builds its tree. Not for the haptic thread.
  void addObject(TriangleMesh mesh, const SphereTreeOptions& options = SphereTreeOptions{},
                 const SurfaceMaterial& material = SurfaceMaterial{})
  {
    CollisionObject object;
    object.mesh = std::move(mesh);
    object.tree.build(object.mesh, options);
    object.material = material;
    objects.push_back(std::move(object));
  }

  /// Bounding-box diagonal over all objects: the scene's length scale.
  double diagonal() const
  {
    Aabb box;
    for (const CollisionObject& object : objects)
    {
      box.expand(object.mesh.bounds().lower);
      box.expand(object.mesh.bounds().upper);
    }
    return box.diagonal();
  }

  double maxAbsCoordinate() const
  {
    double largest = 0.0;
    for (const CollisionObject& object : objects)
    {
      largest = std::max(largest, object.mesh.maxAbsCoordinate());
    }
    return largest;
  }
};

} // namespace proxima
