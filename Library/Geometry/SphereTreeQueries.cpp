// The sphere tree's queries (paper section 5): one depth-first walk, and one visitor per query
// that says which spheres can still matter, which child to enter first, and what to do with a
// triangle. The build is in SphereTree.cpp.
#include "Geometry/SphereTree.h"

#include "Geometry/SweptSphere.h"
#include "Geometry/TriangleFilter.h"

#include <cassert>
#include <cmath>

namespace proxima
{
namespace
{
// The walk keeps, at any time, at most one pending sibling per level above the node it is in plus
// the two children it just pushed: a tree of depth D needs D + 1 slots. The build bounds D.
static_assert(SphereTreeScratch::kMaxStackDepth >= kSphereTreeMaxDepth + 1,
              "the traversal stack must hold a walk of the deepest tree the build can make");

// Pruning compares in double against float spheres that were rounded up by at least one float
// ulp; this slack keeps exact tangencies of zero-radius spheres from being pruned by rounding.
constexpr double kPruneSlack = 1.0 + 1e-9;

// Squared distance from c to the segment start + [0, 1] * motion.
double segmentDistanceSquared(const Vec3& start, const Vec3& motion, double motionSquared,
                              const Vec3& c)
{
  const Vec3 toCenter = c - start;
  double s = motionSquared > 0.0 ? dot(toCenter, motion) / motionSquared : 0.0;
  s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
  return squaredDistance(toCenter, motion * s);
}

void addStats(const QueryStats& counts, QueryStats* stats)
{
  if (stats != nullptr)
  {
    stats->nodesVisited += counts.nodesVisited;
    stats->leafSpheresTested += counts.leafSpheresTested;
    stats->trianglesTested += counts.trianglesTested;
  }
}

// (a) The first contact of a swept sphere. The path is cut at the best contact so far, so only
// spheres near the part before it are entered, and the child the path meets first goes first.
// Ties in t go to the lowest triangle index, whatever the order of the walk.
class FirstContactVisitor
{
public:
  FirstContactVisitor(const TriangleMesh& mesh, const SweepQuery& query, const Vec3& origin,
                      QueryStats& counts)
    : m_mesh(mesh)
    , m_query(query)
    , m_start(query.start - origin)
    , m_motion(query.end - query.start)
    , m_reachBeyondSphere(query.radius + query.skin)
    , m_clearBefore(query.clearBefore > 0.0 ? query.clearBefore : 0.0)
    , m_counts(counts)
  {}

  bool reachesNode(const SphereTreeNode& node)
  {
    // The path from where it is not known clear up to the best contact at this node; its leaf
    // spheres are tested against the same.
    const double from = unclearFrom();
    m_from = m_start + m_motion * from;
    m_reachable = m_motion * (m_best.t - from);
    m_reachableSquared = dot(m_reachable, m_reachable);
    return reachesPath(centerOf(node), node.radius);
  }

  bool leftFirst(const SphereTreeNode& left, const SphereTreeNode& right) const
  {
    return dot(centerOf(left) - m_start, m_motion) <= dot(centerOf(right) - m_start, m_motion);
  }

  bool reachesLeaf(const LeafSphere& leaf) const
  {
    return reachesPath(centerOf(leaf), leaf.radius);
  }

  void visitTriangle(std::uint32_t triangle)
  {
    if (m_query.filters != nullptr && !mayReachFiltered(m_query.filters[triangle]))
    {
      return;
    }
    ++m_counts.trianglesTested;
    const SweepResult hit = sweepSphereTriangleWithSkin(m_query.start, m_motion, m_query.radius,
                                                        m_query.skin, m_mesh.corners(triangle));
    if (hit.hit &&
        (!m_best.hit || hit.t < m_best.t || (hit.t == m_best.t && triangle < m_best.triangle)))
    {
      m_best.hit = true;
      m_best.t = hit.t;
      m_best.triangle = triangle;
    }
  }

  const SweepContact& best() const { return m_best; }

private:
  // Where the part of the path that can still give the first contact begins: where the caller
  // no longer knows it clear, or the best contact so far if that is sooner.
  double unclearFrom() const { return m_clearBefore < m_best.t ? m_clearBefore : m_best.t; }

  // The record's test on the part of the path that can still give the first contact (in the
  // mesh's frame, where the records are): from where it is not known clear to the best contact
  // so far, ends included, so a tie in t passes.
  bool mayReachFiltered(const TriangleFilter& filter) const
  {
    const double from = unclearFrom();
    const Vec3 motion = m_motion * (m_best.t - from);
    return mayComeWithin(filter, m_query.start + m_motion * from, motion, dot(motion, motion),
                         m_reachBeyondSphere);
  }

  bool reachesPath(const Vec3& center, float radius) const
  {
    const double reach = (static_cast<double>(radius) + m_reachBeyondSphere) * kPruneSlack;
    return !(segmentDistanceSquared(m_from, m_reachable, m_reachableSquared, center) >
             reach * reach);
  }

  const TriangleMesh& m_mesh;
  const SweepQuery& m_query;
  const Vec3 m_start; // in the tree's frame
  const Vec3 m_motion;
  const double m_reachBeyondSphere;
  const double m_clearBefore;
  QueryStats& m_counts;
  Vec3 m_from;
  Vec3 m_reachable;
  double m_reachableSquared = 0.0;
  SweepContact m_best;
};

// (b) Every triangle with a leaf sphere within `maxDistance` of a point (in the tree's frame),
// handed to `Found`; the order of the children does not matter, left goes first.
template <typename Found>
class NearPointVisitor
{
public:
  NearPointVisitor(const Vec3& point, double maxDistance, Found& found)
    : m_point(point)
    , m_maxDistance(maxDistance)
    , m_found(found)
  {}

  bool reachesNode(const SphereTreeNode& node) const
  {
    return reaches(centerOf(node), node.radius);
  }
  bool leftFirst(const SphereTreeNode&, const SphereTreeNode&) const { return true; }
  bool reachesLeaf(const LeafSphere& leaf) const { return reaches(centerOf(leaf), leaf.radius); }
  void visitTriangle(std::uint32_t triangle) { m_found(triangle); }

private:
  bool reaches(const Vec3& center, float radius) const
  {
    const double reach = (static_cast<double>(radius) + m_maxDistance) * kPruneSlack;
    return !(squaredDistance(center, m_point) > reach * reach);
  }

  const Vec3 m_point;
  const double m_maxDistance;
  Found& m_found;
};

// (c) The nearest triangle: branch and bound, the nearer child first so that a good early answer
// prunes the rest. Ties in squared distance go to the lowest triangle index.
class NearestVisitor
{
public:
  NearestVisitor(const TriangleMesh& mesh, const Vec3& point, double maxDistance,
                 const Vec3& origin, QueryStats& counts)
    : m_mesh(mesh)
    , m_point(point)
    , m_inTree(point - origin)
    , m_bestDistance(maxDistance)
    , m_bestSquared(maxDistance * maxDistance)
    , m_counts(counts)
  {}

  bool reachesNode(const SphereTreeNode& node) const
  {
    return !(gap(centerOf(node), node.radius) > m_bestDistance * kPruneSlack);
  }

  bool leftFirst(const SphereTreeNode& left, const SphereTreeNode& right) const
  {
    return gap(centerOf(left), left.radius) <= gap(centerOf(right), right.radius);
  }

  bool reachesLeaf(const LeafSphere& leaf) const
  {
    return !(gap(centerOf(leaf), leaf.radius) > m_bestDistance * kPruneSlack);
  }

  void visitTriangle(std::uint32_t triangle)
  {
    ++m_counts.trianglesTested;
    const TriangleCorners& c = m_mesh.corners(triangle);
    const ClosestPointResult closest = closestPointOnTriangle(m_point, c.a, c.b, c.c);
    // Compare squared distances, as computed: square roots would merge values that differ in
    // the last bit, and the answer must be the same triangle a brute-force scan picks.
    const double d2 = closest.squaredDistance;
    if ((!m_best.found && d2 <= m_bestSquared) || d2 < m_bestSquared ||
        (d2 == m_bestSquared && triangle < m_best.triangle))
    {
      m_best.found = true;
      m_best.triangle = triangle;
      m_best.closest = closest;
      m_bestSquared = d2;
      m_bestDistance = std::sqrt(d2);
    }
  }

  const NearestTriangle& best() const { return m_best; }

private:
  double gap(const Vec3& center, float radius) const
  {
    return distance(center, m_inTree) - static_cast<double>(radius);
  }

  const TriangleMesh& m_mesh;
  const Vec3 m_point;
  const Vec3 m_inTree;
  double m_bestDistance;
  double m_bestSquared;
  QueryStats& m_counts;
  NearestTriangle m_best;
};

// Once the per-query cache is full a triangle reached through a second leaf sphere is tested
// again; a gather then looks through what it already stored so that no triangle is listed twice.
bool isStored(const NearbyTriangle* out, std::uint32_t count, std::uint32_t triangle)
{
  for (std::uint32_t i = 0; i < count; ++i)
  {
    if (out[i].triangle == triangle)
    {
      return true;
    }
  }
  return false;
}

bool isStored(const std::uint32_t* out, std::uint32_t count, std::uint32_t triangle)
{
  for (std::uint32_t i = 0; i < count; ++i)
  {
    if (out[i] == triangle)
    {
      return true;
    }
  }
  return false;
}
} // namespace

template <typename Visitor>
void SphereTree::walk(SphereTreeScratch& scratch, QueryStats& counts, Visitor& visitor) const
{
  scratch.tested.clear();
  std::uint32_t* stack = scratch.stack;
  int size = 0;
  stack[size++] = 0;
  while (size > 0)
  {
    const std::uint32_t nodeIndex = stack[--size];
    const SphereTreeNode& node = m_nodes[nodeIndex];
    ++counts.nodesVisited;
    if (!visitor.reachesNode(node))
    {
      continue;
    }
    if (node.numLeafSpheres == 0)
    {
      const std::uint32_t left = nodeIndex + 1;
      const std::uint32_t right = node.rightOrFirst;
      assert(size + 2 <= SphereTreeScratch::kMaxStackDepth); // see the static_assert above
      const bool leftFirst = visitor.leftFirst(m_nodes[left], m_nodes[right]);
      stack[size++] = leftFirst ? right : left;
      stack[size++] = leftFirst ? left : right;
      continue;
    }
    for (std::uint32_t i = 0; i < node.numLeafSpheres; ++i)
    {
      const LeafSphere& leaf = m_leaves[node.rightOrFirst + i];
      ++counts.leafSpheresTested;
      // The per-query cache: a triangle under several reached leaf spheres is visited once.
      if (!visitor.reachesLeaf(leaf) || !scratch.tested.insert(leaf.triangle))
      {
        continue;
      }
      visitor.visitTriangle(leaf.triangle);
    }
  }
}

SweepContact SphereTree::firstContact(const TriangleMesh& mesh, const SweepQuery& query,
                                      SphereTreeScratch& scratch, QueryStats* stats) const
{
  if (m_nodes.empty())
  {
    return SweepContact{};
  }
  QueryStats counts;
  FirstContactVisitor visitor(mesh, query, m_origin, counts);
  walk(scratch, counts, visitor);
  addStats(counts, stats);
  return visitor.best();
}

std::uint32_t SphereTree::gatherWithin(const TriangleMesh& mesh, const Vec3& point,
                                       double maxDistance, NearbyTriangle* out,
                                       std::uint32_t capacity, SphereTreeScratch& scratch,
                                       QueryStats* stats) const
{
  std::uint32_t found = 0;
  if (m_nodes.empty() || !(maxDistance >= 0.0))
  {
    return 0;
  }
  QueryStats counts;
  const double maxDistanceSquared = maxDistance * maxDistance;
  auto gather = [&](std::uint32_t triangle) {
    ++counts.trianglesTested;
    const TriangleCorners& c = mesh.corners(triangle);
    const ClosestPointResult closest = closestPointOnTriangle(point, c.a, c.b, c.c);
    if (closest.squaredDistance <= maxDistanceSquared &&
        !(scratch.tested.full() && isStored(out, found < capacity ? found : capacity, triangle)))
    {
      if (found < capacity)
      {
        out[found] = NearbyTriangle{triangle, closest};
      }
      ++found;
    }
  };
  NearPointVisitor visitor(point - m_origin, maxDistance, gather);
  walk(scratch, counts, visitor);
  addStats(counts, stats);
  return found;
}

std::uint32_t SphereTree::candidatesWithin(const Vec3& point, double maxDistance,
                                           std::uint32_t* out, std::uint32_t capacity,
                                           SphereTreeScratch& scratch, QueryStats* stats) const
{
  std::uint32_t found = 0;
  if (m_nodes.empty() || !(maxDistance >= 0.0))
  {
    return 0;
  }
  QueryStats counts;
  auto collect = [&](std::uint32_t triangle) {
    if (scratch.tested.full() && isStored(out, found < capacity ? found : capacity, triangle))
    {
      return;
    }
    if (found < capacity)
    {
      out[found] = triangle;
    }
    ++found;
  };
  NearPointVisitor visitor(point - m_origin, maxDistance, collect);
  walk(scratch, counts, visitor);
  addStats(counts, stats);
  return found;
}

NearestTriangle SphereTree::nearest(const TriangleMesh& mesh, const Vec3& point, double maxDistance,
                                    SphereTreeScratch& scratch, QueryStats* stats) const
{
  if (m_nodes.empty() || !(maxDistance >= 0.0))
  {
    return NearestTriangle{};
  }
  QueryStats counts;
  NearestVisitor visitor(mesh, point, maxDistance, m_origin, counts);
  walk(scratch, counts, visitor);
  addStats(counts, stats);
  return visitor.best();
}

} // namespace proxima
