// What the candidate cache's filters know of a triangle (CandidateCache.h): a sphere about its
// centroid, its plane and how far rounding puts its corners off that plane. Made once per
// triangle when an object is built, so that re-centring the cache copies records instead of
// recomputing them from the corners (square roots and cross products for a hundred triangles or
// more at each re-centring of a deep crawl).
#pragma once

#include "Geometry/TriangleMesh.h"

#include <vector>

namespace proxima
{

/// One triangle's record for the candidate cache's rejection tests: a bounding sphere about its
/// centroid and its plane, each widened against rounding so that no test drops a triangle the
/// exact test would find.
struct TriangleFilter
{
  /// The centroid of the corners, the centre of the bounding sphere (m).
  Vec3 centroid;
  /// The centroid's distance to the farthest corner, a hair larger (see makeTriangleFilter).
  double radius = 0.0;
  /// The unit normal (zero for a triangle without area).
  Vec3 normal;
  /// The plane's offset (m): n . x = offset on the plane.
  double offset = 0.0;
  /// How far rounding may put a corner, or a height measured near the triangle, off the plane.
  double planeSlack = 0.0;
};

/// The record of the triangle with corners `corners`.
TriangleFilter makeTriangleFilter(const TriangleCorners& corners);

/// One record per triangle of `mesh`, in its order. Not for the haptic thread (allocates).
std::vector<TriangleFilter> makeTriangleFilters(const TriangleMesh& mesh);

} // namespace proxima
