// Where a ball tool of radius R cannot touch a part (`proxima inspect --tool-radius`):
// the floors of gaps and pockets narrower than the tool, and the strips along inner corners that
// a ball rounds over. A ball-ended probe, a ball-nose cutter or the haptic proxy itself touches a
// point p of a face only with the ball tangent there, centred at p + R n on the face's free side
// (n its unit normal); so p is reachable exactly when that ball holds no part of the surface. The
// test is the sphere tree's nearest-triangle query from the centre, bounded by R.
//
// Each triangle is sampled at the centroids of a regular split into k x k smaller triangles, k the
// longest edge over R rounded up (at most ToolReachOptions::maxSplit), so a sample stands for at
// most about R across. Sides: a closed mesh with every edge consistently oriented is reached from
// outside only (its normals turned outward when its signed volume is negative); any other mesh
// from both sides, a sample reachable when either side is. Degenerate triangles have no area and
// no sample. Unreachable triangles (any sample unreachable) sharing a vertex form a region; each
// region names the deepest of its samples (the ball's centre nearest to the surface) and the
// largest radius that reaches it, found by bisection (the tangent balls at p grow nested with R,
// so reach only fails from some radius on).
#pragma once

#include "Core/Vec3.h"
#include "Geometry/SphereTree.h"
#include "Geometry/TriangleMesh.h"
#include "Geometry/TriangleSoup.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace proxima
{

/// How findToolReach() samples the surface and what it reports.
struct ToolReachOptions
{
  /// The tool's radius in metres (the soup's units), above 0.
  double toolRadius = 0.001;
  /// Regions listed with their places (the first in triangle order).
  std::size_t locationsKept = 10;
  /// The largest split per triangle edge (k above).
  int maxSplit = 8;
  /// Keep every sample (tests compare each with an independent distance).
  bool keepSamples = false;
  /// Called with the fraction done (0 to 1), for progress on long work.
  std::function<void(double)> progress;
};

/// One sample point on a triangle and whether the tool reaches it (kept only with
/// ToolReachOptions::keepSamples).
struct ReachSample
{
  /// The sampled triangle's index in the soup.
  std::uint32_t triangle = 0;
  /// The sample: the centroid of one triangle of the k x k split.
  Vec3 point;
  /// The side tested: the unit normal the tool's centre lies along.
  Vec3 side;
  /// The area the sample stands for: its triangle's area over k x k (square metres).
  double area = 0.0;
  /// True if the tool's tangent ball there holds no part of the surface (on either side, when
  /// both are tested).
  bool reachable = true;
};

/// Unreachable triangles joined through shared vertices: one place for the user to look at.
struct UnreachableRegion
{
  /// The region's first triangle in the file's order.
  std::uint32_t triangle = 0;
  /// How many unreachable triangles it holds.
  std::size_t triangles = 0;
  /// Area of the unreachable samples in it.
  double area = 0.0;
  /// The deepest sample: where the tool's ball overlaps the surface most.
  Vec3 point;
  /// The largest tool radius that touches `point` (to a relative 1e-9).
  double largestReachingRadius = 0.0;
};

/// What findToolReach() finds: how much of the surface a ball tool cannot touch, and where.
struct ToolReach
{
  /// The tool radius tested (m).
  double toolRadius = 0.0;
  /// True when only the outside was tested (a closed, consistently oriented mesh).
  bool outsideOnly = false;
  /// Samples taken; degenerate triangles have none.
  std::size_t samples = 0;
  /// Samples the tool cannot touch.
  std::size_t unreachableSamples = 0;
  /// The area all samples stand for: the mesh's surface area (square metres).
  double area = 0.0;
  /// The area the unreachable samples stand for (square metres).
  double unreachableArea = 0.0;
  /// Every triangle with an unreachable sample, in the file's order.
  std::vector<std::uint32_t> unreachableTriangles;
  /// Unreachable regions in all, however many are listed.
  std::size_t regionCount = 0;
  /// The first ToolReachOptions::locationsKept regions, in the order of their first triangle.
  std::vector<UnreachableRegion> regions;
  /// Only with ToolReachOptions::keepSamples.
  std::vector<ReachSample> sampleList;
};

/// Where a tool of options.toolRadius cannot touch `soup`. `closedAndOriented` says whether the
/// soup is closed with every edge consistently oriented (MeshInspection: closed and no
/// misoriented edge), so that only its outside is probed. Throws std::invalid_argument for a
/// radius that is not above 0 or a soup the kernel refuses (TriangleMesh::build).
ToolReach findToolReach(const TriangleSoup& soup, bool closedAndOriented,
                        const ToolReachOptions& options);

/// The same with the soup's mesh and sphere tree already built (a window's scene has them): no
/// tree is built again for another radius. `mesh` must be `soup` built, `tree` built over it.
ToolReach findToolReach(const TriangleSoup& soup, const TriangleMesh& mesh, const SphereTree& tree,
                        bool closedAndOriented, const ToolReachOptions& options);

} // namespace proxima
