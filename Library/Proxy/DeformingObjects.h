// The deforming objects of a scene as the proxy solver uses them (issue 35: tissue): per object
// its own copy of the collision object (mesh, sphere tree, filter records), which the solver
// moves to the points a simulation last gave, and room for those points until the next tick
// applies them. Made off the haptic thread (makeDeformingObjects allocates every buffer); the
// solver then only writes into it in place.
#pragma once

#include "Core/Vec3.h"
#include "Proxy/CollisionObject.h"
#include "Proxy/CollisionScene.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace proxima
{
/// The deforming objects of one scene. Made by makeDeformingObjects(); the solver it is given to
/// updates it in place.
struct DeformingObjectSet
{
  /// One deforming object.
  struct Entry
  {
    /// Index of the object in the scene's objects.
    std::uint32_t object = 0;
    /// The object where its points are now: a copy of the scene's, whose tree is refit, never
    /// rebuilt, as the points move (SphereTree::refit).
    CollisionObject current;
    /// The points the next update moves the object to (ProxySolver::setObjectPoints).
    std::vector<Vec3> pending;
    /// True when `pending` holds points the next update has not applied yet.
    bool hasPending = false;
    /// The refit's margin (m): a tenth of the object's median edge, so that most small steps keep
    /// most spheres (SphereTree::refit).
    double refitMargin = 0.0;
  };
  /// The deforming objects, each scene object at most once.
  std::vector<Entry> entries;
  /// Per scene object: its index in `entries`, or -1 for an object that does not deform.
  std::vector<int> indexOfObject;
  /// The index in `entries` of scene object `object`; -1 for one that does not deform or is out
  /// of range.
  int indexOf(std::uint32_t object) const
  {
    return object < indexOfObject.size() ? indexOfObject[object] : -1;
  }
};

/// The set for `objects` (indices into `scene`; out of range or repeated ones are skipped), each
/// where the scene has it. Each copy's tree is built again with one sphere per triangle, the
/// shape a refit keeps tight. Allocates: not for the haptic thread.
std::unique_ptr<DeformingObjectSet> makeDeformingObjects(const CollisionScene& scene,
                                                         const std::vector<std::uint32_t>& objects);
} // namespace proxima
