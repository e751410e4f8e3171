// What the rejection tests of the proxy's sweeps know of a triangle (the candidate cache,
// Proxy/CandidateCache.h, and the sphere tree's sweep, SweepQuery::filters): a sphere about its
// centroid, its plane and how far rounding puts its corners off that plane. Made once per
// triangle when an object is built, so that re-centring the cache copies records instead of
// recomputing them from the corners (square roots and cross products for a hundred triangles or
// more at each re-centring of a deep crawl).
#pragma once

#include "Geometry/TriangleMesh.h"

#include <cmath>
#include <vector>

namespace proxima
{

/// One triangle's record for the sweeps' rejection tests (the candidate cache's, the trees'): a
/// bounding sphere about its centroid and its plane, each widened against rounding so that no
/// test drops a triangle the exact test would find.
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

/// Whether a sphere of radius `reach` whose centre runs along the segment from `start` along
/// `motion` (`motionSquared` its squared length; zero motion for a point) may come within reach
/// of the triangle `filter` records: its bounding sphere, then its plane, then its bounding
/// circle in that plane at the height the segment passes. Never false for a triangle the exact
/// test would find within `reach`; a few dozen flops against a swept test's hundreds, which a
/// sphere resting on a surface of triangles much smaller than itself meets by the dozen (their
/// bounding spheres all reach it; their planes pass under it at its own radius).
inline bool mayComeWithin(const TriangleFilter& filter, const Vec3& start, const Vec3& motion,
                          double motionSquared, double reach)
{
  // Distance from the triangle's sphere centre to the segment.
  const Vec3 toCenter = filter.centroid - start;
  double s = motionSquared > 0.0 ? dot(toCenter, motion) / motionSquared : 0.0;
  s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
  const double sphereReach = filter.radius + reach;
  if (squaredDistance(toCenter, motion * s) > sphereReach * sphereReach)
  {
    return false;
  }
  // The segment's heights above the plane are linear along it: it stays beyond the reach on one
  // side, or comes no nearer than the lower end.
  const Vec3& normal = filter.normal;
  const double planeReach = reach + filter.planeSlack;
  const double startHeight = dot(normal, start) - filter.offset;
  const double endHeight = startHeight + dot(normal, motion);
  if ((startHeight > planeReach && endHeight > planeReach) ||
      (startHeight < -planeReach && endHeight < -planeReach))
  {
    return false;
  }
  const double startDepth = std::fabs(startHeight);
  const double endDepth = std::fabs(endHeight);
  const double lowest = (startHeight > 0.0) == (endHeight > 0.0)
                          ? (endDepth < startDepth ? endDepth : startDepth)
                          : 0.0;
  const double lateralSquared = planeReach * planeReach - lowest * lowest;
  const double lateral = std::sqrt(lateralSquared > 0.0 ? lateralSquared : 0.0);
  // The segment projected into the plane, against the triangle's bounding circle there.
  const Vec3 centerInPlane = toCenter - normal * dot(normal, toCenter);
  const Vec3 motionInPlane = motion - normal * dot(normal, motion);
  const double inPlaneSquared = squaredNorm(motionInPlane);
  double u = inPlaneSquared > 0.0 ? dot(centerInPlane, motionInPlane) / inPlaneSquared : 0.0;
  u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
  const double circleReach = filter.radius + lateral;
  return squaredDistance(centerInPlane, motionInPlane * u) <= circleReach * circleReach;
}

/// The record of the triangle with corners `corners`.
TriangleFilter makeTriangleFilter(const TriangleCorners& corners);

/// One record per triangle of `mesh`, in its order. Not for the haptic thread (allocates).
std::vector<TriangleFilter> makeTriangleFilters(const TriangleMesh& mesh);

} // namespace proxima
