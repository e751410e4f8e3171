// One thing the proxy collides with: a triangle mesh, its sphere tree and its surface material.
// Built once off the haptic thread and then never changed, so that scenes can share it: a scene
// edit makes new objects only for what changed and points at the rest (CollisionScene.h). A
// deforming object's own copy (Proxy/DeformingObjects.h) is the exception, refit in place.
#pragma once

#include "Geometry/SphereTree.h"
#include "Geometry/TriangleFilter.h"
#include "Geometry/TriangleMesh.h"
#include "Proxy/SurfaceMaterial.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace proxima
{

/// A mesh with what the proxy's queries need over it (sphere tree, filter records) and its
/// surface material. Immutable once built, and shared between scenes through CollisionObjectList.
struct CollisionObject
{
  /// The object's surface (m): in the scene's frame, or for a moving object in its own frame (where
  /// its identity pose puts it).
  TriangleMesh mesh;
  /// The sphere tree over `mesh`; buildQueries() makes it.
  SphereTree tree;
  /// Each triangle's record for the candidate cache's filters, in the mesh's order.
  std::vector<TriangleFilter> filters;
  /// How the surface feels: stiffness, friction, viscosity, textures.
  SurfaceMaterial material;

  /// Builds what the queries need over `mesh`: the sphere tree and the filter records. Not for
  /// the haptic thread.
  void buildQueries(const SphereTreeOptions& options = SphereTreeOptions{})
  {
    tree.build(mesh, options);
    filters = makeTriangleFilters(mesh);
  }
  /// After `mesh`'s points moved (TriangleMesh::movePoints): refits the tree (SphereTree::refit,
  /// with `margin`) and remakes every filter record in place. For an object one owner deforms,
  /// never one scenes share. Allocates nothing; O(triangles).
  void refitQueries(double margin)
  {
    tree.refit(mesh, margin);
    for (std::uint32_t t = 0; t < mesh.numTriangles() && t < filters.size(); ++t)
    {
      filters[t] = makeTriangleFilter(mesh.corners(t));
    }
  }
};

/// Builds the tree over `mesh` and wraps the object for sharing. Not for the haptic thread.
inline std::shared_ptr<const CollisionObject> makeCollisionObject(
  TriangleMesh mesh, const SphereTreeOptions& options = SphereTreeOptions{},
  const SurfaceMaterial& material = SurfaceMaterial{})
{
  auto object = std::make_shared<CollisionObject>();
  object->mesh = std::move(mesh);
  object->buildQueries(options);
  object->material = material;
  return object;
}

} // namespace proxima
