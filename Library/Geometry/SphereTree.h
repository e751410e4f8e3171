// The bounding-sphere hierarchy of paper section 5 over one triangle mesh: leaf spheres cover
// each triangle like scan conversion, internal nodes come from midpoint splits of the longest
// axis, and each node's sphere is the smaller of the paper's two heuristics. Flat depth-first
// arrays of floats (conservatively rounded) keep it compact; queries are exact in double.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/ClosestPoint.h"
#include "Geometry/TriangleMesh.h"
#include "Geometry/TriangleTestCache.h"

#include <cstdint>
#include <vector>

namespace proxima
{

/// The leaf size rule's length is the mesh's median edge, or this many times its median shortest
/// edge (each triangle's shortest) where that is less: a mesh of slivers.
inline constexpr double kShortEdgeScaleFactor = 2.0;
/// Where the short-edge rule applies, the leaf spheres it may make: this many per triangle, or
/// kLeafSphereBudget (20 bytes each) if more; past it the length grows toward the median rule's.
inline constexpr std::uint64_t kLeafSpheresPerTriangleBudget = 8;
/// The floor of that budget: any mesh may make this many leaf spheres (about 1.3 MB) under the
/// short-edge rule, however few its triangles.
inline constexpr std::uint64_t kLeafSphereBudget = std::uint64_t{1} << 16;

/// How SphereTree::build() sizes the leaf spheres, groups them and spreads the work.
struct SphereTreeOptions
{
  /// Leaf size rule: a triangle whose longest edge exceeds leafSizeFactor times the mesh's median
  /// edge length (or kShortEdgeScaleFactor times its median shortest edge, if less) is split by
  /// longest-edge bisection until every piece is that short, and each piece gets its own leaf
  /// sphere. 0 means one sphere per triangle.
  double leafSizeFactor = 2.0;
  /// A triangle is never split into more pieces than this (long slivers in a fine mesh).
  std::uint32_t maxPiecesPerTriangle = 256;
  /// Leaf spheres grouped under one leaf node (1 is the paper's tree exactly).
  std::uint32_t maxLeafSpheresPerNode = 4;
  /// Threads that build the tree (0: one per hardware thread). The tree is the same bit for bit
  /// whatever the number; 1 builds it on the calling thread alone.
  unsigned numBuildThreads = 1;
};

/// Down to this depth the build splits at the midpoint of the longest axis (or at the median when
/// that leaves a side empty); deeper, always at the median, which halves the leaf spheres.
inline constexpr std::uint32_t kSphereTreeMedianSplitDepth = 48;
/// The deepest node a build can make: below kSphereTreeMedianSplitDepth the median splits leave
/// one of at most 2^32 leaf spheres after 32 more levels. The queries' stack is sized from this.
inline constexpr std::uint32_t kSphereTreeMaxDepth = kSphereTreeMedianSplitDepth + 1 + 32;

/// A node in depth-first order: the left child is the next node; an internal node stores its
/// right child, a leaf node the range of its leaf spheres. Centres are relative to the tree's
/// origin; radii are rounded up so that a float sphere always holds what the exact one held.
struct SphereTreeNode
{
  /// Centre of the node's sphere, relative to the tree's origin (m).
  float center[3];
  /// Radius of the node's sphere (m), rounded up: it holds every leaf sphere below the node.
  float radius;
  /// Internal node: index of the right child. Leaf node: first leaf sphere.
  std::uint32_t rightOrFirst;
  /// 0 for an internal node; the number of leaf spheres for a leaf node.
  std::uint32_t numLeafSpheres;
};

/// A sphere that covers one triangle, or one piece of a split triangle: the tree's leaves.
struct LeafSphere
{
  /// Centre, relative to the tree's origin (m).
  float center[3];
  /// Radius (m), rounded up so that the sphere holds its whole triangle or piece.
  float radius;
  /// Index of the covered triangle in the mesh.
  std::uint32_t triangle;
};

/// A node's or a leaf sphere's centre in double, relative to the tree's origin.
inline Vec3 centerOf(const SphereTreeNode& node)
{
  return {static_cast<double>(node.center[0]), static_cast<double>(node.center[1]),
          static_cast<double>(node.center[2])};
}
/// A leaf sphere's centre in double, relative to the tree's origin.
inline Vec3 centerOf(const LeafSphere& leaf)
{
  return {static_cast<double>(leaf.center[0]), static_cast<double>(leaf.center[1]),
          static_cast<double>(leaf.center[2])};
}

/// A sphere in double precision: a node or leaf sphere handed out for drawing.
struct Sphere
{
  /// Centre (m), in the frame the function that returns it names.
  Vec3 center;
  /// Radius (m).
  double radius = 0.0;
};

/// Work counters of one query, for benchmarks and the trace.
struct QueryStats
{
  /// Nodes taken off the traversal stack, pruned or entered.
  std::uint32_t nodesVisited = 0;
  /// Leaf spheres of reached leaf nodes tested against the query.
  std::uint32_t leafSpheresTested = 0;
  /// Exact triangle tests run (candidatesWithin() runs none).
  std::uint32_t trianglesTested = 0;
};

/// Per-thread scratch for queries: the traversal stack and the tested-triangle cache. Make one
/// per querying thread, once; queries then never allocate.
struct SphereTreeScratch
{
  /// A depth-first walk of a tree of depth D holds at most D + 1 nodes (SphereTreeQueries.cpp),
  /// and no build is deeper than kSphereTreeMaxDepth: the stack cannot overflow.
  static constexpr int kMaxStackDepth = static_cast<int>(kSphereTreeMaxDepth) + 1;
  /// The traversal stack of node indices.
  std::uint32_t stack[kMaxStackDepth];
  /// The triangles already tested in the current query, so that each is tested once.
  TriangleTestCache tested;
};

struct TriangleFilter; // Geometry/TriangleFilter.h

/// A sphere swept along a segment, the query of SphereTree::firstContact(). Positions are in the
/// frame of the mesh the tree was built over.
struct SweepQuery
{
  /// Centre of the sphere where the sweep begins (m).
  Vec3 start;
  /// Centre of the sphere where the sweep ends (m).
  Vec3 end;
  /// Radius of the swept sphere (m); 0 sweeps a point.
  double radius = 0.0;
  /// Contact skin (see sweepSphereTriangleWithSkin); 0 for the exact geometric query.
  double skin = 0.0;
  /// Fraction of the path, from its start, that the caller knows meets no triangle of the tree
  /// (0: nothing known). The walk then enters only spheres that reach the rest of the path; the
  /// answer is the whole sweep's, bit for bit, when the caller is right. The proxy's candidate
  /// cache knows it for the part of a slide inside its ball: without it a long slide that left the
  /// ball had every triangle beside its start tested again.
  double clearBefore = 0.0;
  /// Optional: one record per triangle of the tree's mesh, in its order and frame
  /// (makeTriangleFilters). A triangle whose record shows the path cannot come within the sweep's
  /// reach is then not tested exactly; the answer is the same. Without them, every triangle under
  /// a leaf sphere the path reaches is: a sphere resting on a surface of triangles much smaller
  /// than itself reaches dozens of leaf spheres whose triangles lie under it, out of its way.
  const TriangleFilter* filters = nullptr;
};

/// The answer of SphereTree::firstContact(): where along the sweep the sphere first meets a
/// triangle, and which one.
struct SweepContact
{
  /// True when the sweep meets a triangle before its end.
  bool hit = false;
  /// Fraction of start -> end travelled at first contact (1 without a hit).
  double t = 1.0;
  /// Index of the triangle met first (the lowest index on a tie in `t`); 0 without a hit.
  std::uint32_t triangle = 0;
};

/// One triangle found by SphereTree::gatherWithin().
struct NearbyTriangle
{
  /// Index of the triangle in the mesh.
  std::uint32_t triangle = 0;
  /// Its point nearest the query point, with that point's weights, in the mesh's frame.
  ClosestPointResult closest;
};

/// The answer of SphereTree::nearest().
struct NearestTriangle
{
  /// True when a triangle lies within the query's maximum distance.
  bool found = false;
  /// Index of the nearest triangle (the lowest index on a tie); 0 when none was found.
  std::uint32_t triangle = 0;
  /// Its point nearest the query point, with that point's weights, in the mesh's frame; set only
  /// when `found`.
  ClosestPointResult closest;
};

/// The bounding-sphere hierarchy over one triangle mesh (paper section 5): build() once, then
/// query with the same mesh from any number of threads, each with its own SphereTreeScratch. The
/// tree holds no reference to the mesh.
class SphereTree
{
public:
  SphereTree() = default;

  /// Builds the tree over `mesh` in O(n log n), on options.numBuildThreads threads. The mesh
  /// must outlive nothing: queries take it again, and must be given the same mesh.
  void build(const TriangleMesh& mesh, const SphereTreeOptions& options = SphereTreeOptions{});

  /// (a) First contact of a sphere swept from query.start to query.end with any triangle.
  SweepContact firstContact(const TriangleMesh& mesh, const SweepQuery& query,
                            SphereTreeScratch& scratch, QueryStats* stats = nullptr) const;

  /// (b) Every triangle within `maxDistance` of `point` (closest point and weights included).
  /// Writes at most `capacity` of them to `out` and returns how many there are in all, so a
  /// return above `capacity` says the buffer overflowed. The stored triangles are distinct; the
  /// count is exact too unless the buffer overflowed in a query that tested more than
  /// TriangleTestCache::kMaxEntries triangles (then it may count a triangle twice).
  std::uint32_t gatherWithin(const TriangleMesh& mesh, const Vec3& point, double maxDistance,
                             NearbyTriangle* out, std::uint32_t capacity,
                             SphereTreeScratch& scratch, QueryStats* stats = nullptr) const;

  /// The triangles whose leaf spheres reach within `maxDistance` of `point`: a superset of those
  /// within that distance, without the exact test (for caches that test later). Distinct; the
  /// count is as for gatherWithin.
  std::uint32_t candidatesWithin(const Vec3& point, double maxDistance, std::uint32_t* out,
                                 std::uint32_t capacity, SphereTreeScratch& scratch,
                                 QueryStats* stats = nullptr) const;

  /// (c) The triangle nearest `point`, if one lies within `maxDistance`.
  NearestTriangle nearest(const TriangleMesh& mesh, const Vec3& point, double maxDistance,
                          SphereTreeScratch& scratch, QueryStats* stats = nullptr) const;

  /// Refits the tree to `mesh`: the mesh it was built over with its points moved (the same
  /// triangles, as TriangleMesh::movePoints leaves them), a deforming surface. The hierarchy
  /// stays. Bottom-up, a leaf sphere that still holds its triangle is kept and one that does not
  /// is made again around the whole triangle, from its centroid, larger by `margin` (m); a node
  /// that still holds its children is kept and one that does not is made again around them,
  /// larger by `margin`. A margin of a fraction of the triangles' size lets the small motions of
  /// most simulation steps pass with containment checks alone (squares, no root); the queries
  /// stay exact whatever the margin and only slow down as spheres grow or the surface strays from
  /// the shape the hierarchy was built for. A split triangle's pieces each get the whole
  /// triangle's sphere: build a tree that will be refit with one sphere per triangle
  /// (SphereTreeOptions::leafSizeFactor 0). O(leaf spheres), plus O(nodes) when a leaf sphere
  /// was made again (a surface at rest costs the leaf pass alone); allocates nothing; a mesh with
  /// another number of triangles is ignored.
  void refit(const TriangleMesh& mesh, double margin = 0.0);
  /// Number of nodes; 0 before build() or for an empty mesh.
  std::uint32_t numNodes() const { return static_cast<std::uint32_t>(m_nodes.size()); }
  /// Number of leaf spheres: at least one per triangle, more where triangles were split.
  std::uint32_t numLeafSpheres() const { return static_cast<std::uint32_t>(m_leaves.size()); }
  /// Number of triangles of the mesh the tree was built over.
  std::uint32_t numTriangles() const { return m_numTriangles; }
  /// Level of the deepest node (the root is level 0); at most kSphereTreeMaxDepth.
  std::uint32_t depth() const { return m_depth; }
  /// Bytes of the tree itself (nodes and leaf spheres), not of the mesh.
  std::size_t memoryBytes() const;
  /// The point the stored centres are relative to: the centre of the mesh's bounding box.
  const Vec3& origin() const { return m_origin; }
  /// The nodes in depth-first order, the root first.
  const std::vector<SphereTreeNode>& nodes() const { return m_nodes; }
  /// The leaf spheres, each leaf node's in one contiguous range.
  const std::vector<LeafSphere>& leafSpheres() const { return m_leaves; }

  /// The node spheres at `level` (0 is the root; leaf nodes above that level are included), in
  /// world coordinates: for drawing the tree.
  std::vector<Sphere> spheresAtLevel(std::uint32_t level) const;
  /// All leaf spheres in world coordinates.
  std::vector<Sphere> leafSpheresInWorld() const;

private:
  /// The one depth-first walk behind every query (SphereTreeQueries.cpp). The visitor says
  /// whether a node's or a leaf's sphere can still matter (reachesNode, reachesLeaf), which child
  /// to enter first (leftFirst), and takes each reached triangle once (visitTriangle).
  template <typename Visitor>
  void walk(SphereTreeScratch& scratch, QueryStats& counts, Visitor& visitor) const;

  std::vector<SphereTreeNode> m_nodes;
  std::vector<LeafSphere> m_leaves;
  Vec3 m_origin;
  std::uint32_t m_numTriangles = 0;
  std::uint32_t m_depth = 0;
};

} // namespace proxima
