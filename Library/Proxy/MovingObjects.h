// The moving objects of a scene as the proxy solver uses them (paper section 6): per object the
// pose it was given, the pose its queries use now, and a copy of its mesh placed by that pose.
// Made off the haptic thread (makeMovingObjects allocates the copies); the solver then only
// writes into it in place, so a runner can build one beside a scene and hand it to the solver
// on the haptic thread (ProxySolver::useMovingObjects) without allocating or freeing there.
#pragma once

#include "Core/RigidTransform.h"
#include "Geometry/TriangleMesh.h"
#include "Proxy/CollisionScene.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace proxima
{

/// The moving objects of one scene, with each one's pose and placed mesh copy. Made off the
/// haptic thread by makeMovingObjects(); the solver it is given to then updates it in place.
struct MovingObjectSet
{
  /// One moving object.
  struct Entry
  {
    /// Index of the object in the scene's objects.
    std::uint32_t object = 0;
    /// The pose as last set (ProxySolver::setObjectPose); the next update moves the object there.
    RigidTransform pose;
    /// The pose the mesh copy and the queries use now.
    RigidTransform applied;
    /// The object's mesh placed by `applied`, in the scene's frame.
    TriangleMesh mesh;
  };
  /// The moving objects, each scene object at most once.
  std::vector<Entry> entries;
  /// Per scene object: its index in `entries`, or -1 for a static object.
  std::vector<int> indexOfObject;

  /// The index in `entries` of scene object `object`; -1 for a static object or one out of range.
  int indexOf(std::uint32_t object) const
  {
    return object < indexOfObject.size() ? indexOfObject[object] : -1;
  }
};

/// The set for `objects` (indices into `scene`; out of range or repeated ones are skipped), each
/// at the identity pose. Allocates: not for the haptic thread.
inline std::unique_ptr<MovingObjectSet> makeMovingObjects(const CollisionScene& scene,
                                                          const std::vector<std::uint32_t>& objects)
{
  auto set = std::make_unique<MovingObjectSet>();
  set->indexOfObject.assign(scene.objects.size(), -1);
  for (const std::uint32_t object : objects)
  {
    if (object >= scene.objects.size() || set->indexOfObject[object] >= 0)
    {
      continue;
    }
    set->indexOfObject[object] = static_cast<int>(set->entries.size());
    MovingObjectSet::Entry entry;
    entry.object = object;
    entry.mesh = scene.objects[object].mesh;
    set->entries.push_back(std::move(entry));
  }
  return set;
}

} // namespace proxima
