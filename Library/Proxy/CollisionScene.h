// What the proxy collides with: one or more collision objects (CollisionObject.h), each a mesh
// with its sphere tree. The scene holds them as shared immutable objects (CollisionObjectList.h):
// a new scene after an edit reuses every object that did not change. Built off the haptic
// thread, then only read.
#pragma once

#include "Proxy/CollisionObject.h"
#include "Proxy/CollisionObjectList.h"

#include <algorithm>

namespace proxima
{

/// The objects the proxy collides with. Built off the haptic thread, then only read; objects
/// that did not change are shared with the scene it replaces.
struct CollisionScene
{
  /// The objects; their order breaks ties between contacts (the lowest index wins).
  CollisionObjectList objects;

  /// Adds a mesh and builds its tree. Not for the haptic thread.
  void addObject(TriangleMesh mesh, const SphereTreeOptions& options = SphereTreeOptions{},
                 const SurfaceMaterial& material = SurfaceMaterial{})
  {
    objects.push_back(makeCollisionObject(std::move(mesh), options, material));
  }

  /// Adds an object built elsewhere, shared with whatever else holds it.
  void addObject(CollisionObjectList::Pointer object) { objects.push_back(std::move(object)); }

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

  /// Largest absolute coordinate over all objects (m): the rounding scale of positions near
  /// them; 0 for an empty scene.
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
