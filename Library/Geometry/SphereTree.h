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
inline constexpr std::uint64_t kLeafSphereBudget = std::uint64_t{1} << 16;

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
  float center[3];
  float radius;
  /// Internal node: index of the right child. Leaf node: first leaf sphere.
  std::uint32_t rightOrFirst;
  /// 0 for an internal node; the number of leaf spheres for a leaf node.
  std::uint32_t numLeafSpheres;
};

struct LeafSphere
{
  float center[3];
  float radius;
  std::uint32_t triangle;
};

/// A node's or a leaf sphere's centre in double, relative to the tree's origin.
inline Vec3 centerOf(const SphereTreeNode& node)
{
  return {static_cast<double>(node.center[0]), static_cast<double>(node.center[1]),
          static_cast<double>(node.center[2])};
}
inline Vec3 centerOf(const LeafSphere& leaf)
{
  return {static_cast<double>(leaf.center[0]), static_cast<double>(leaf.center[1]),
          static_cast<double>(leaf.center[2])};
}

struct Sphere
{
  Vec3 center;
  double radius = 0.0;
};

/// Work counters of one query, for benchmarks and the trace.
struct QueryStats
{
  std::uint32_t nodesVisited = 0;
  std::uint32_t leafSpheresTested = 0;
  std::uint32_t trianglesTested = 0;
};

/// Per-thread scratch for queries: the traversal stack and the tested-triangle cache. Make one
/// per querying thread, once; queries then never allocate.
struct SphereTreeScratch
{
  /// A depth-first walk of a tree of depth D holds at most D + 1 nodes (SphereTreeQueries.cpp),
  /// and no build is deeper than kSphereTreeMaxDepth: the stack cannot overflow.
  static constexpr int kMaxStackDepth = static_cast<int>(kSphereTreeMaxDepth) + 1;
  std::uint32_t stack[kMaxStackDepth];
  TriangleTestCache tested;
};

struct SweepQuery
{
  Vec3 start;
  Vec3 end;
  double radius = 0.0;
  /// Contact skin (see sweepSphereTriangleWithSkin); 0 for the exact geometric query.
  double skin = 0.0;
};

struct SweepContact
{
  bool hit = false;
  /// Fraction of start -> end travelled at first contact (1 without a hit).
  double t = 1.0;
  std::uint32_t triangle = 0;
};

struct NearbyTriangle
{
  std::uint32_t triangle = 0;
  ClosestPointResult closest;
};

struct NearestTriangle
{
  bool found = false;
  std::uint32_t triangle = 0;
  ClosestPointResult closest;
};

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

  std::uint32_t numNodes() const { return static_cast<std::uint32_t>(m_nodes.size()); }
  std::uint32_t numLeafSpheres() const { return static_cast<std::uint32_t>(m_leaves.size()); }
  std::uint32_t numTriangles() const { return m_numTriangles; }
  std::uint32_t depth() const { return m_depth; }
  /// Bytes of the tree itself (nodes and leaf spheres), not of the mesh.
  std::size_t memoryBytes() const;
  const Vec3& origin() const { return m_origin; }
  const std::vector<SphereTreeNode>& nodes() const { return m_nodes; }
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
