// SphereTree against brute force over every triangle, with the same per-triangle routines the
// tree calls (sweepSphereTriangleWithSkin, closestPointOnTriangle), so answers must agree to the
// last bit: same hit, same t and same triangle for firstContact; same triangle and squared
// distance for nearest; the same set for gatherWithin (only triangles whose distance is within
// 1e-12 relative of the threshold may differ). Also the tree's invariants: every point of every
// triangle lies in one of its leaf spheres, every node sphere holds its descendant leaf spheres,
// the leaf ranges partition the leaf spheres, and the depth is bounded.
//
// The brute force scans all triangles but skips the exact test where a triangle's bounding box is
// provably out of reach (farther than the query's reach, with a 1e-6 relative margin): that
// keeps 2,000 queries on a 70k-triangle scan to a second and changes no answer.
#include "Geometry/SphereTree.h"

#include "Geometry/ProceduralMeshes.h"
#include "Geometry/SweptSphere.h"
#include "Geometry/TriangleFilter.h"

#include "GeometryTestSupport.h"

#if PROXIMA_WITH_MESH_IO
#include "IO/Mesh/MeshReader.h"
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace proxima::test
{
namespace
{

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Failures by kind, printed at the end of each test so one noisy kind cannot hide another.
struct FailureTally
{
  std::map<std::string, int> counts;
  int total() const
  {
    int sum = 0;
    for (const auto& [kind, count] : counts)
    {
      sum += count;
    }
    return sum;
  }
  void print() const
  {
    for (const auto& [kind, count] : counts)
    {
      std::printf("[ failures ] %-28s %d\n", kind.c_str(), count);
    }
  }
};

class BruteForce
{
public:
  explicit BruteForce(const TriangleMesh& mesh)
    : m_mesh(mesh)
  {
    m_boxes.resize(mesh.numTriangles());
    for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
    {
      const TriangleCorners& c = mesh.corners(t);
      m_boxes[t].expand(c.a);
      m_boxes[t].expand(c.b);
      m_boxes[t].expand(c.c);
    }
  }

  SweepContact firstContact(const SweepQuery& q) const
  {
    Aabb reach;
    reach.expand(q.start);
    reach.expand(q.end);
    const double margin = (q.radius + q.skin) * (1.0 + 1e-6) + 1e-12 * m_mesh.maxAbsCoordinate();
    reach.expand(reach.lower, margin);
    reach.expand(reach.upper, margin);
    SweepContact best;
    const Vec3 motion = q.end - q.start;
    for (std::uint32_t t = 0; t < m_mesh.numTriangles(); ++t)
    {
      if (disjoint(m_boxes[t], reach))
      {
        continue;
      }
      const SweepResult r =
        sweepSphereTriangleWithSkin(q.start, motion, q.radius, q.skin, m_mesh.corners(t));
      if (r.hit && (!best.hit || r.t < best.t))
      {
        best.hit = true;
        best.t = r.t;
        best.triangle = t;
      }
    }
    return best;
  }

  NearestTriangle nearest(const Vec3& p, double maxDistance) const
  {
    NearestTriangle best;
    double bestSquared = maxDistance * maxDistance;
    for (std::uint32_t t = 0; t < m_mesh.numTriangles(); ++t)
    {
      if (boxDistanceSquared(m_boxes[t], p) > bestSquared * (1.0 + 1e-6))
      {
        continue;
      }
      const TriangleCorners& c = m_mesh.corners(t);
      const ClosestPointResult r = closestPointOnTriangle(p, c.a, c.b, c.c);
      if ((!best.found && r.squaredDistance <= bestSquared) || r.squaredDistance < bestSquared)
      {
        best.found = true;
        best.triangle = t;
        best.closest = r;
        bestSquared = r.squaredDistance;
      }
    }
    return best;
  }

  /// Triangle -> squared distance, for every triangle within maxDistance.
  std::vector<std::pair<std::uint32_t, double>> within(const Vec3& p, double maxDistance) const
  {
    std::vector<std::pair<std::uint32_t, double>> found;
    const double limit = maxDistance * maxDistance;
    for (std::uint32_t t = 0; t < m_mesh.numTriangles(); ++t)
    {
      if (boxDistanceSquared(m_boxes[t], p) > limit * (1.0 + 1e-6))
      {
        continue;
      }
      const TriangleCorners& c = m_mesh.corners(t);
      const double d2 = closestPointOnTriangle(p, c.a, c.b, c.c).squaredDistance;
      if (d2 <= limit)
      {
        found.emplace_back(t, d2);
      }
    }
    return found;
  }

  /// Squared distance of triangle t to p (for judging boundary cases).
  double squaredDistance(std::uint32_t t, const Vec3& p) const
  {
    const TriangleCorners& c = m_mesh.corners(t);
    return closestPointOnTriangle(p, c.a, c.b, c.c).squaredDistance;
  }

private:
  static bool disjoint(const Aabb& x, const Aabb& y)
  {
    return x.lower.x > y.upper.x || x.upper.x < y.lower.x || x.lower.y > y.upper.y ||
           x.upper.y < y.lower.y || x.lower.z > y.upper.z || x.upper.z < y.lower.z;
  }
  static double boxDistanceSquared(const Aabb& box, const Vec3& p)
  {
    const Vec3 below = componentMax(box.lower - p, Vec3{});
    const Vec3 above = componentMax(p - box.upper, Vec3{});
    return squaredNorm(below + above);
  }

  const TriangleMesh& m_mesh;
  std::vector<Aabb> m_boxes;
};

double medianEdgeLength(const TriangleMesh& mesh)
{
  std::vector<double> edges;
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    const TriangleCorners& c = mesh.corners(t);
    edges.push_back(distance(c.a, c.b));
    edges.push_back(distance(c.b, c.c));
    edges.push_back(distance(c.c, c.a));
  }
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  return edges[edges.size() / 2];
}

/// A point near the surface: on a random triangle, moved up to `spreadDistance` off it; one in
/// ten anywhere in the padded bounding box.
Vec3 pointNearSurface(Random& random, const TriangleMesh& mesh, double spreadDistance)
{
  if (random.chance(0.1))
  {
    const Aabb& b = mesh.bounds();
    const Vec3 pad{spreadDistance, spreadDistance, spreadDistance};
    const Vec3 lower = b.lower - pad;
    const Vec3 upper = b.upper + pad;
    return {random.uniform(lower.x, upper.x), random.uniform(lower.y, upper.y),
            random.uniform(lower.z, upper.z)};
  }
  const auto t = static_cast<std::uint32_t>(random.integer(0, int(mesh.numTriangles()) - 1));
  return pointOnTriangle(random, mesh.corners(t)) +
         random.direction() * (spreadDistance * random.uniform(0.0, 1.0));
}

struct AgreementStats
{
  int numSweeps = 0;
  int numSweepHits = 0;
  int numNearest = 0;
  int numNearestFound = 0;
  int numGathers = 0;
  long numGathered = 0;
  int numBoundaryExcused = 0;
  QueryStats work;
};

/// Runs `numQueries` of each query against the tree and the brute force; returns the failures.
void compareWithBruteForce(const TriangleMesh& mesh, const SphereTree& tree, Random& random,
                           int numQueries, const std::string& label, AgreementStats& stats,
                           FailureTally& tally)
{
  const BruteForce brute(mesh);
  const std::vector<TriangleFilter> filters = makeTriangleFilters(mesh);
  auto scratch = std::make_unique<SphereTreeScratch>();
  const double edge = std::fmax(medianEdgeLength(mesh), 1e-9 * mesh.diagonal());
  FailureBudget budget(6);
  auto fail = [&](int query, const std::string& what) {
    ++tally.counts[what.substr(0, what.find(' '))];
    if (budget.spend())
    {
      ADD_FAILURE() << label << " query " << query << ": " << what;
    }
  };
  std::vector<NearbyTriangle> out(1 << 16);
  for (int i = 0; i < numQueries; ++i)
  {
    const double radius = edge * std::array<double, 3>{0.3, 1.0, 3.0}[i % 3];

    // (a) firstContact
    SweepQuery q;
    q.start = pointNearSurface(random, mesh, 3.0 * radius);
    q.end = q.start + random.direction() * (radius * random.uniform(0.0, 3.0));
    q.radius = radius;
    q.skin = i % 2 == 0 ? 0.0 : radius * 0.01;
    const SweepContact fromTree = tree.firstContact(mesh, q, *scratch, &stats.work);
    const SweepContact fromBrute = brute.firstContact(q);
    ++stats.numSweeps;
    stats.numSweepHits += fromBrute.hit ? 1 : 0;
    if (fromTree.hit != fromBrute.hit || fromTree.t != fromBrute.t ||
        (fromBrute.hit && fromTree.triangle != fromBrute.triangle))
    {
      fail(i, "firstContact from " + str(q.start) + " to " + str(q.end) + " radius " + str(radius) +
                " skin " + str(q.skin) + ": tree hit " + std::to_string(fromTree.hit) + " t " +
                str(fromTree.t) + " triangle " + std::to_string(fromTree.triangle) +
                ", brute force hit " + std::to_string(fromBrute.hit) + " t " + str(fromBrute.t) +
                " triangle " + std::to_string(fromBrute.triangle));
    }
    // The same sweep with a part of the path known clear (as the proxy's candidate cache knows
    // it: any fraction up to the first contact, the whole path without one), with the triangles'
    // filter records, and with both: the brute force's answer each time, from no more exact
    // tests than the plain sweep.
    SweepQuery knownClear = q;
    knownClear.clearBefore = random.uniform(0.0, 1.0) * (fromBrute.hit ? fromBrute.t : 1.0);
    QueryStats wholeWork;
    tree.firstContact(mesh, q, *scratch, &wholeWork);
    for (int variant = 0; variant < 3; ++variant)
    {
      SweepQuery shortcut = variant == 1 ? q : knownClear;
      shortcut.filters = variant >= 1 ? filters.data() : nullptr;
      QueryStats work;
      const SweepContact answer = tree.firstContact(mesh, shortcut, *scratch, &work);
      if (answer.hit != fromBrute.hit || answer.t != fromBrute.t ||
          (fromBrute.hit && answer.triangle != fromBrute.triangle) ||
          work.trianglesTested > wholeWork.trianglesTested)
      {
        fail(i, "firstContact(clear before " + str(shortcut.clearBefore) + ", records " +
                  std::to_string(variant >= 1) + ") from " + str(q.start) + " to " + str(q.end) +
                  ": hit " + std::to_string(answer.hit) + " t " + str(answer.t) + " triangle " +
                  std::to_string(answer.triangle) + " after " +
                  std::to_string(work.trianglesTested) + " tests (" +
                  std::to_string(wholeWork.trianglesTested) + " without)");
      }
    }

    // (c) nearest, with an unlimited, a generous and a tight search radius
    const Vec3 p = pointNearSurface(random, mesh, 3.0 * radius);
    const double maxDistance = std::array<double, 3>{kInfinity, 2.0 * radius, 0.5 * radius}[i % 3];
    const NearestTriangle nearTree = tree.nearest(mesh, p, maxDistance, *scratch, &stats.work);
    const NearestTriangle nearBrute = brute.nearest(p, maxDistance);
    ++stats.numNearest;
    stats.numNearestFound += nearBrute.found ? 1 : 0;
    if (nearTree.found != nearBrute.found ||
        (nearBrute.found &&
         (nearTree.triangle != nearBrute.triangle ||
          nearTree.closest.squaredDistance != nearBrute.closest.squaredDistance)))
    {
      fail(i, "nearest to " + str(p) + " within " + str(maxDistance) + ": tree found " +
                std::to_string(nearTree.found) + " triangle " + std::to_string(nearTree.triangle) +
                " d2 " + str(nearTree.closest.squaredDistance) + ", brute force found " +
                std::to_string(nearBrute.found) + " triangle " +
                std::to_string(nearBrute.triangle) + " d2 " +
                str(nearBrute.closest.squaredDistance));
    }

    // (b) gatherWithin, the same set
    const double gatherDistance = radius * random.uniform(0.5, 2.0);
    const std::uint32_t count =
      tree.gatherWithin(mesh, p, gatherDistance, out.data(), static_cast<std::uint32_t>(out.size()),
                        *scratch, &stats.work);
    const auto expected = brute.within(p, gatherDistance);
    ++stats.numGathers;
    stats.numGathered += static_cast<long>(expected.size());
    std::set<std::uint32_t> fromTreeSet;
    for (std::uint32_t k = 0; k < std::min<std::uint32_t>(count, std::uint32_t(out.size())); ++k)
    {
      if (!fromTreeSet.insert(out[k].triangle).second)
      {
        fail(i, "gatherWithin(duplicate) returned triangle " + std::to_string(out[k].triangle) +
                  " twice");
      }
      if (out[k].closest.squaredDistance != brute.squaredDistance(out[k].triangle, p))
      {
        fail(i, "gatherWithin(closest) closest point of triangle " +
                  std::to_string(out[k].triangle) + " differs from closestPointOnTriangle's");
      }
    }
    std::set<std::uint32_t> fromBruteSet;
    for (const auto& [t, d2] : expected)
    {
      fromBruteSet.insert(t);
    }
    if (count != fromTreeSet.size())
    {
      fail(i, "gatherWithin(count) counted " + std::to_string(count) + " but returned " +
                std::to_string(fromTreeSet.size()));
    }
    std::vector<std::uint32_t> differing;
    std::set_symmetric_difference(fromTreeSet.begin(), fromTreeSet.end(), fromBruteSet.begin(),
                                  fromBruteSet.end(), std::back_inserter(differing));
    for (std::uint32_t t : differing)
    {
      const double d = std::sqrt(brute.squaredDistance(t, p));
      if (std::fabs(d - gatherDistance) <= 1e-12 * gatherDistance)
      {
        ++stats.numBoundaryExcused;
        continue;
      }
      fail(i, "gatherWithin(set) around " + str(p) + " within " + str(gatherDistance) +
                (fromTreeSet.count(t) ? ": tree has, brute force lacks, triangle "
                                      : ": brute force has, tree lacks, triangle ") +
                std::to_string(t) + " at distance " + str(d));
    }
    // A buffer too small: the overflow is reported, the count is the full count while the
    // per-query cache held every tested triangle (beyond that a triangle reached through two leaf
    // spheres may be counted twice, never stored twice), and what fits is a subset.
    if (expected.size() >= 2)
    {
      const auto capacity = static_cast<std::uint32_t>(expected.size() / 2);
      std::vector<NearbyTriangle> small(capacity);
      QueryStats smallStats;
      const std::uint32_t total =
        tree.gatherWithin(mesh, p, gatherDistance, small.data(), capacity, *scratch, &smallStats);
      const bool cacheHeldAll = smallStats.trianglesTested <= TriangleTestCache::kMaxEntries;
      if (cacheHeldAll ? total != count : total < count)
      {
        fail(i, "gatherWithin(capacity) with capacity " + std::to_string(capacity) + " counted " +
                  std::to_string(total) + " instead of " + std::to_string(count));
      }
      for (const NearbyTriangle& n : small)
      {
        if (fromTreeSet.count(n.triangle) == 0)
        {
          fail(i, "gatherWithin(capacity) with a small buffer returned triangle " +
                    std::to_string(n.triangle) + " not in the full answer");
        }
      }
    }
  }
}

/// Structural invariants, checked in long double from the stored float values.
void checkInvariants(const TriangleMesh& mesh, const SphereTree& tree,
                     const SphereTreeOptions& options, Random& random, const std::string& label,
                     FailureTally& tally)
{
  FailureBudget budget(6);
  std::string kind = "invariant(structure)";
  auto fail = [&](const std::string& what) {
    ++tally.counts[kind];
    if (budget.spend())
    {
      ADD_FAILURE() << label << ": " << what;
    }
  };
  const auto& nodes = tree.nodes();
  const auto& leaves = tree.leafSpheres();
  if (tree.numTriangles() != mesh.numTriangles() || nodes.empty() ||
      leaves.size() < mesh.numTriangles())
  {
    fail("sizes: " + std::to_string(nodes.size()) + " nodes, " + std::to_string(leaves.size()) +
         " leaf spheres for " + std::to_string(mesh.numTriangles()) + " triangles");
    return;
  }
  if (!(tree.depth() < 64))
  {
    fail("depth " + std::to_string(tree.depth()));
  }
  // Walk the tree: each leaf sphere is in exactly one leaf node; each node holds its leaves.
  std::vector<int> owner(leaves.size(), 0);
  struct Frame
  {
    std::uint32_t node;
    std::uint32_t depth;
  };
  std::vector<Frame> stack = {{0, 0}};
  std::vector<std::uint32_t> path; // node indices from the root, for containment checks
  std::vector<std::vector<std::uint32_t>> leavesUnder(nodes.size());
  std::uint32_t deepest = 0;
  // Depth-first order: the subtree of node i is a contiguous range starting at i; collect for
  // each node the leaf spheres under it by a post-order accumulation.
  std::vector<std::uint32_t> subtreeEnd(nodes.size(), 0);
  std::function<std::uint32_t(std::uint32_t, std::uint32_t)> visit =
    [&](std::uint32_t index, std::uint32_t depth) -> std::uint32_t {
    deepest = std::max(deepest, depth);
    const SphereTreeNode& node = nodes[index];
    if (node.numLeafSpheres > 0)
    {
      if (node.numLeafSpheres > std::max<std::uint32_t>(1, options.maxLeafSpheresPerNode) ||
          node.rightOrFirst + node.numLeafSpheres > leaves.size())
      {
        fail("leaf node " + std::to_string(index) + " holds " +
             std::to_string(node.numLeafSpheres) + " leaf spheres from " +
             std::to_string(node.rightOrFirst));
        return index + 1;
      }
      for (std::uint32_t k = 0; k < node.numLeafSpheres; ++k)
      {
        ++owner[node.rightOrFirst + k];
        leavesUnder[index].push_back(node.rightOrFirst + k);
      }
      return index + 1;
    }
    if (!(node.rightOrFirst > index + 1 && node.rightOrFirst < nodes.size()) || depth > 200)
    {
      fail("internal node " + std::to_string(index) + " has right child " +
           std::to_string(node.rightOrFirst));
      return index + 1;
    }
    const std::uint32_t leftEnd = visit(index + 1, depth + 1);
    if (leftEnd != node.rightOrFirst)
    {
      fail("node " + std::to_string(index) + ": left subtree ends at " + std::to_string(leftEnd) +
           " but the right child is " + std::to_string(node.rightOrFirst));
    }
    const std::uint32_t end = visit(node.rightOrFirst, depth + 1);
    for (std::uint32_t child : {index + 1, node.rightOrFirst})
    {
      leavesUnder[index].insert(leavesUnder[index].end(), leavesUnder[child].begin(),
                                leavesUnder[child].end());
    }
    return end;
  };
  const std::uint32_t end = visit(0, 0);
  if (end != nodes.size())
  {
    fail("the tree spans " + std::to_string(end) + " of " + std::to_string(nodes.size()) +
         " nodes");
  }
  if (deepest != tree.depth())
  {
    fail("depth() says " + std::to_string(tree.depth()) + " but the deepest node is at " +
         std::to_string(deepest));
  }
  for (std::size_t k = 0; k < leaves.size(); ++k)
  {
    if (owner[k] != 1)
    {
      fail("leaf sphere " + std::to_string(k) + " is in " + std::to_string(owner[k]) +
           " leaf nodes");
      break;
    }
  }
  kind = "invariant(containment)";
  // Every node sphere contains every descendant leaf sphere (float values, compared exactly
  // in long double with 1e-12 relative slack, far inside the queries' 1e-9 pruning slack).
  for (std::uint32_t index = 0; index < nodes.size(); ++index)
  {
    const SphereTreeNode& node = nodes[index];
    for (std::uint32_t k : leavesUnder[index])
    {
      const LeafSphere& leaf = leaves[k];
      long double d2 = 0;
      for (int axis = 0; axis < 3; ++axis)
      {
        const long double delta =
          static_cast<long double>(node.center[axis]) - static_cast<long double>(leaf.center[axis]);
        d2 += delta * delta;
      }
      const long double reach = std::sqrt(d2) + static_cast<long double>(leaf.radius);
      if (!(reach <= static_cast<long double>(node.radius) * (1.0L + 1e-12L)))
      {
        fail("node " + std::to_string(index) + " (radius " + str(double(node.radius)) +
             ") does not hold leaf sphere " + std::to_string(k) + " (reaches " +
             str(double(reach)) + ")");
        break;
      }
    }
  }
  kind = "invariant(coverage)";
  // Coverage: corners, edge midpoints, the centroid and random points of each triangle lie in
  // one of that triangle's leaf spheres (world = origin + stored centre). Rounding the corners
  // into the tree's frame costs up to epsilon times the coordinates.
  std::vector<std::vector<std::uint32_t>> leavesOf(mesh.numTriangles());
  for (std::uint32_t k = 0; k < leaves.size(); ++k)
  {
    if (leaves[k].triangle >= mesh.numTriangles())
    {
      fail("leaf sphere " + std::to_string(k) + " names triangle " +
           std::to_string(leaves[k].triangle));
      return;
    }
    leavesOf[leaves[k].triangle].push_back(k);
  }
  const Vec3 origin = tree.origin();
  const long double slack = 4.0L * kEpsilon * (mesh.maxAbsCoordinate() + maxAbsComponent(origin));
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    if (leavesOf[t].empty())
    {
      fail("triangle " + std::to_string(t) + " has no leaf sphere");
      continue;
    }
    if (options.leafSizeFactor == 0.0 && leavesOf[t].size() != 1)
    {
      fail("with leafSizeFactor 0 triangle " + std::to_string(t) + " has " +
           std::to_string(leavesOf[t].size()) + " leaf spheres");
    }
    if (leavesOf[t].size() > std::max<std::uint32_t>(1, options.maxPiecesPerTriangle))
    {
      fail("triangle " + std::to_string(t) + " has " + std::to_string(leavesOf[t].size()) +
           " leaf spheres, more than maxPiecesPerTriangle");
    }
    const TriangleCorners& c = mesh.corners(t);
    std::vector<Vec3> samples = {c.a,
                                 c.b,
                                 c.c,
                                 (c.a + c.b) * 0.5,
                                 (c.b + c.c) * 0.5,
                                 (c.c + c.a) * 0.5,
                                 (c.a + c.b + c.c) * (1.0 / 3.0)};
    for (int s = 0; s < 4; ++s)
    {
      samples.push_back(pointOnTriangle(random, c));
    }
    for (const Vec3& sample : samples)
    {
      bool covered = false;
      for (std::uint32_t k : leavesOf[t])
      {
        long double d2 = 0;
        for (int axis = 0; axis < 3; ++axis)
        {
          const long double delta = static_cast<long double>(origin[axis]) +
                                    static_cast<long double>(leaves[k].center[axis]) -
                                    static_cast<long double>(sample[axis]);
          d2 += delta * delta;
        }
        covered = covered || std::sqrt(d2) <=
                               static_cast<long double>(leaves[k].radius) * (1.0L + 1e-12L) + slack;
      }
      if (!covered)
      {
        fail("point " + str(sample) + " of triangle " + std::to_string(t) +
             " lies in none of its " + std::to_string(leavesOf[t].size()) + " leaf spheres");
        break;
      }
    }
  }
}

TriangleMesh buildMesh(TriangleSoup soup)
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(std::move(soup), error)) << error.message;
  return mesh;
}

/// A hostile soup: triangles of sizes over four decades, slivers, zero-area triangles, exact
/// duplicates (ties for every query) and a far cluster (a split with an empty side).
TriangleSoup makeRandomSoup(Random& random, int numTriangles, const Vec3& offset)
{
  TriangleSoup soup;
  const TriangleShape shapes[] = {TriangleShape::Fat,       TriangleShape::Fat,
                                  TriangleShape::Needle,    TriangleShape::Cap,
                                  TriangleShape::Collinear, TriangleShape::Coincident};
  for (int t = 0; t < numTriangles; ++t)
  {
    TriangleCorners c;
    if (t > 0 && random.chance(0.05))
    {
      c = TriangleCorners{soup.points[soup.points.size() - 3], soup.points[soup.points.size() - 2],
                          soup.points[soup.points.size() - 1]};
    }
    else
    {
      const Vec3 center =
        random.chance(0.02) ? offset + Vec3{50, 0, 0} : offset + random.inCube(1.0);
      c = makeTriangle(random, shapes[random.integer(0, 5)], 0.1 * random.logUniform(-2.0, 1.0),
                       center, random.logUniform(0.0, 8.0));
    }
    const auto first = static_cast<std::uint32_t>(soup.points.size());
    soup.points.push_back(c.a);
    soup.points.push_back(c.b);
    soup.points.push_back(c.c);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  return soup;
}

/// Two coincident copies of a grid: every query near it has exact ties to break.
TriangleSoup makeDoubledGrid()
{
  TriangleSoup grid = makeGrid(1.0, 30);
  const auto numPoints = static_cast<std::uint32_t>(grid.points.size());
  const auto numTriangles = grid.triangles.size();
  grid.points.insert(grid.points.end(), grid.points.begin(), grid.points.end());
  grid.pointNormals.insert(grid.pointNormals.end(), grid.pointNormals.begin(),
                           grid.pointNormals.end());
  for (std::size_t t = 0; t < numTriangles; ++t)
  {
    const auto& tri = grid.triangles[t];
    grid.triangles.push_back({tri[0] + numPoints, tri[1] + numPoints, tri[2] + numPoints});
  }
  return grid;
}

struct NamedMesh
{
  std::string name;
  TriangleMesh mesh;
};

std::vector<NamedMesh> proceduralMeshes()
{
  Random random(0x7ee00001);
  std::vector<NamedMesh> meshes;
  meshes.push_back({"random soup", buildMesh(makeRandomSoup(random, 1500, Vec3{}))});
  meshes.push_back(
    {"random soup at 1e4", buildMesh(makeRandomSoup(random, 800, Vec3{1e4, -1e4, 5e3}))});
  meshes.push_back({"icosphere 3", buildMesh(makeIcosphere(3, 0.05))});
  meshes.push_back({"icosphere 4 off centre", buildMesh(makeIcosphere(4, 1.0, Vec3{3, -2, 1}))});
  meshes.push_back({"grid 40", buildMesh(makeGrid(2.0, 40, 0.5))});
  meshes.push_back({"doubled grid", buildMesh(makeDoubledGrid())});
  meshes.push_back({"box", buildMesh(makeBox(Vec3{1.0, 0.01, 3.0}))});
  return meshes;
}

void printStats(const std::string& label, const SphereTree& tree, const TriangleMesh& mesh,
                const AgreementStats& s)
{
  std::printf("[ %s ] %u triangles, %u leaf spheres, %u nodes, depth %u, %.1f bytes/triangle; "
              "%d sweeps (%d hits), %d nearest (%d found), %d gathers (%ld triangles), "
              "%d boundary cases; %.1f nodes and %.1f triangles tested per query\n",
              label.c_str(), mesh.numTriangles(), tree.numLeafSpheres(), tree.numNodes(),
              tree.depth(), double(tree.memoryBytes()) / mesh.numTriangles(), s.numSweeps,
              s.numSweepHits, s.numNearest, s.numNearestFound, s.numGathers, s.numGathered,
              s.numBoundaryExcused,
              double(s.work.nodesVisited) / (s.numSweeps + s.numNearest + s.numGathers),
              double(s.work.trianglesTested) / (s.numSweeps + s.numNearest + s.numGathers));
}

TEST(SphereTree, AgreesWithBruteForceOnProceduralMeshes)
{
  Random random(0x7ee00002);
  FailureTally tally;
  for (const NamedMesh& m : proceduralMeshes())
  {
    SphereTree tree;
    tree.build(m.mesh);
    const SphereTreeOptions defaults;
    checkInvariants(m.mesh, tree, defaults, random, m.name, tally);
    AgreementStats stats;
    compareWithBruteForce(m.mesh, tree, random, 2000, m.name, stats, tally);
    printStats(m.name, tree, m.mesh, stats);
    EXPECT_GT(stats.numSweepHits, stats.numSweeps / 10) << m.name << ": too few hits to judge";
    EXPECT_GT(stats.numGathered, stats.numGathers / 2) << m.name << ": too few gathered to judge";
  }
  tally.print();
  EXPECT_EQ(tally.total(), 0) << "seed 0x7ee00002";
}

TEST(SphereTree, EveryOptionAgreesWithBruteForce)
{
  Random random(0x7ee00003);
  FailureTally tally;
  const std::vector<NamedMesh> meshes = proceduralMeshes();
  for (double leafSizeFactor : {0.0, 1.0, 2.0, 4.0})
  {
    for (std::uint32_t perNode : {1u, 2u, 4u, 8u})
    {
      for (std::size_t m : {std::size_t{0}, std::size_t{3}, std::size_t{5}})
      {
        SphereTreeOptions options;
        options.leafSizeFactor = leafSizeFactor;
        options.maxLeafSpheresPerNode = perNode;
        // Few pieces per triangle in one configuration: the cap must hold.
        options.maxPiecesPerTriangle = leafSizeFactor == 1.0 ? 4 : 256;
        SphereTree tree;
        tree.build(meshes[m].mesh, options);
        const std::string label = meshes[m].name + " (leafSizeFactor " +
                                  std::to_string(leafSizeFactor) + ", " + std::to_string(perNode) +
                                  " per node)";
        checkInvariants(meshes[m].mesh, tree, options, random, label, tally);
        AgreementStats stats;
        compareWithBruteForce(meshes[m].mesh, tree, random, 150, label, stats, tally);
      }
    }
  }
  tally.print();
  EXPECT_EQ(tally.total(), 0) << "seed 0x7ee00003";
}

// The real meshes of the test data (PROXIMA_SHARED_MESHES) against brute force, read through the
// IO layer's readers when that layer is built (PROXIMA_BUILD_IO; without it the tests skip).
// `shipped`: the files are in Data/Meshes, so a missing one fails; else they are in
// PROXIMA_SHARED_DATA only, and the test skips, saying so, without them.
void agreeWithBruteForceOnRealMeshes(const std::vector<const char*>& files, bool shipped,
                                     std::uint64_t seed)
{
#if PROXIMA_WITH_MESH_IO
  const std::string folder = PROXIMA_SHARED_MESHES;
  Random random(seed);
  FailureTally tally;
  std::vector<std::pair<const char*, TriangleSoup>> soups;
  for (const char* file : files)
  {
    try
    {
      soups.emplace_back(file, readMeshFile(folder + "/" + file));
    }
    catch (const InputError& error)
    {
      if (shipped)
      {
        ADD_FAILURE() << file << " is shipped in Data/Meshes: " << error.what();
        continue;
      }
      GTEST_SKIP() << error.what() << " (the shared meshes, PROXIMA_SHARED_DATA)";
    }
  }
  for (const auto& [file, soup] : soups)
  {
    const TriangleMesh mesh = buildMesh(soup);
    SphereTree tree;
    tree.build(mesh);
    checkInvariants(mesh, tree, SphereTreeOptions{}, random, file, tally);
    AgreementStats stats;
    // 2,000 of each query on the smaller meshes; fewer on the bunny to keep the scan short.
    const int numQueries = mesh.numTriangles() > 50000 ? 700 : 2000;
    compareWithBruteForce(mesh, tree, random, numQueries, file, stats, tally);
    printStats(file, tree, mesh, stats);
  }
  tally.print();
  EXPECT_EQ(tally.total(), 0) << "seed " << std::hex << seed;
#else
  (void)files;
  (void)shipped;
  (void)seed;
  GTEST_SKIP() << "the IO layer is not built";
#endif
}

TEST(SphereTree, AgreesWithBruteForceOnShippedMeshes)
{
  agreeWithBruteForceOnRealMeshes(
    {"teapot.obj", "spot_triangulated.obj", "stanford-bunny.obj", "fandisk.off", "featuretype.STL"},
    true, 0x7ee00004);
}

// The CAD parts that may not ship (label shared-data).
TEST(SphereTree, AgreesWithBruteForceOnSharedOnlyMeshes)
{
  agreeWithBruteForceOnRealMeshes({"abc_00000050_trimesh_000.stl", "M3x10_screw.stl"}, false,
                                  0x7ee00005);
}

// A CAD cylinder of slivers (sides one facet wide and the whole height long, caps fanned from one
// rim point): most of its edges are long, so a leaf size taken from the median edge alone left
// every sliver whole, and every query beside the cylinder met all 384 side slivers. The leaves
// must be tight: a query ball meets few more triangles' leaf spheres than triangles the ball
// reaches. Only by a fan's apex, where all of a cap's 190 slivers meet, do the pieces of slivers
// it does not reach crowd in, within about a piece of the apex.
TEST(SphereTree, SliverCylinderLeavesAreTight)
{
  const TriangleMesh mesh = buildMesh(makeSliverCylinder(192, 0.02, 0.1));
  SphereTree tree;
  tree.build(mesh);
  auto scratch = std::make_unique<SphereTreeScratch>();
  Random random(0x7ee00005);
  const double reach = 0.003;
  // The fans' apexes (rim point 0 of each cap) and how near them the crowding is allowed.
  const Vec3 apexes[2] = {{0.02, 0.0, -0.05}, {0.02, 0.0, 0.05}};
  const double apexRegion = 0.008;
  std::vector<std::uint32_t> found(mesh.numTriangles());
  int worstExcess = 0;
  std::uint64_t allCandidates = 0;
  std::uint64_t allReached = 0;
  for (int trial = 0; trial < 400; ++trial)
  {
    // A point 0-2 mm off the side or a cap, anywhere along it.
    const double angle = random.uniform(0.0, 6.283185307179586);
    Vec3 point;
    if (random.chance(0.7))
    {
      const double out = 0.02 + random.uniform(0.0, 0.002);
      point = {out * std::cos(angle), out * std::sin(angle), random.uniform(-0.05, 0.05)};
    }
    else
    {
      const double at = random.uniform(0.0, 0.02);
      point = {at * std::cos(angle), at * std::sin(angle),
               (random.chance(0.5) ? 1.0 : -1.0) * (0.05 + random.uniform(0.0, 0.002))};
    }
    const std::uint32_t candidates = tree.candidatesWithin(
      point, reach, found.data(), static_cast<std::uint32_t>(found.size()), *scratch);
    int reached = 0;
    for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
    {
      const auto closest = oracleClosestOnTriangle(extend<Quad>(point), mesh.corners(t));
      reached += closest.squaredDistance <= Quad(reach) * Quad(reach) ? 1 : 0;
    }
    ASSERT_GE(static_cast<int>(candidates), reached) << "seed 0x7ee00005, point " << str(point);
    if (distance(point, apexes[0]) > apexRegion && distance(point, apexes[1]) > apexRegion)
    {
      worstExcess = std::max(worstExcess, static_cast<int>(candidates) - 4 * reached);
      allCandidates += candidates;
      allReached += static_cast<std::uint64_t>(reached);
    }
  }
  // Leaf pieces about twice the facet width: a ball of 3 mm meets each nearby sliver's pieces
  // a little beyond what it reaches, never the whole side.
  EXPECT_LE(worstExcess, 16) << "seed 0x7ee00005";
  EXPECT_LE(allCandidates, 3 * allReached) << "seed 0x7ee00005";
  std::printf("[ slivers ] %zu leaf spheres for %u triangles; candidates %.2f per triangle "
              "reached\n",
              static_cast<std::size_t>(tree.numLeafSpheres()), mesh.numTriangles(),
              static_cast<double>(allCandidates) / static_cast<double>(allReached));
}

// A tree refit after its mesh deformed (SphereTree::refit, TriangleMesh::movePoints) answers as
// brute force over the deformed triangles does, and keeps every invariant: every point of every
// triangle in one of its leaf spheres, every node holding its leaves. The deformation is large
// against the triangles (a twist, a bulge and a per-point jitter, several triangle sizes in all),
// so the hierarchy no longer fits the surface well; only speed may suffer, never an answer. Each
// mesh is deformed twice in a row, refitting each time (the second time with a margin, so that
// the spheres that still hold their triangles are kept), with one sphere per triangle (how a
// deforming surface is built) and with the default split leaves. Then it is moved back a little
// (less than the margin) and refit: the spheres that still hold are kept, the answers the same.
TEST(SphereTree, RefitAfterDeformingAgreesWithBruteForce)
{
  Random random(0x7ee00006);
  FailureTally tally;
  std::vector<NamedMesh> meshes;
  meshes.push_back({"icosphere 4", buildMesh(makeIcosphere(4, 0.05))});
  meshes.push_back({"grid 40", buildMesh(makeGrid(2.0, 40, 0.5))});
  meshes.push_back({"random soup", buildMesh(makeRandomSoup(random, 1500, Vec3{}))});
  for (double leafSizeFactor : {0.0, 2.0})
  {
    for (const NamedMesh& original : meshes)
    {
      TriangleMesh mesh = original.mesh;
      SphereTreeOptions options;
      options.leafSizeFactor = leafSizeFactor;
      SphereTree tree;
      tree.build(mesh, options);
      const double size = mesh.diagonal();
      const double edge = medianEdgeLength(mesh);
      for (int round = 1; round <= 2; ++round)
      {
        std::vector<Vec3> points = mesh.points();
        for (Vec3& p : points)
        {
          const double angle = 0.4 * round * p.z / size;
          const double c = std::cos(angle);
          const double s = std::sin(angle);
          p = Vec3{c * p.x - s * p.y, s * p.x + c * p.y, p.z};
          p = p + Vec3{0.0, 0.0, 0.1 * size * std::exp(-squaredNorm(p) / (size * size))};
          p = p + random.inCube(0.5 * edge);
        }
        ASSERT_TRUE(mesh.movePoints(points.data(), points.size()));
        tree.refit(mesh, round == 1 ? 0.0 : 0.1 * edge);
        const std::string label = original.name + " deformed " + std::to_string(round) +
                                  "x (leafSizeFactor " + std::to_string(leafSizeFactor) + ")";
        checkInvariants(mesh, tree, options, random, label, tally);
        AgreementStats stats;
        compareWithBruteForce(mesh, tree, random, 400, label, stats, tally);
        printStats(label, tree, mesh, stats);
        EXPECT_GT(stats.numSweepHits, stats.numSweeps / 10) << label << ": too few hits to judge";
      }
      std::vector<Vec3> nudged = mesh.points();
      for (Vec3& p : nudged)
      {
        p = p + random.inCube(0.02 * edge);
      }
      ASSERT_TRUE(mesh.movePoints(nudged.data(), nudged.size()));
      tree.refit(mesh, 0.1 * edge);
      const std::string label =
        original.name + " nudged (leafSizeFactor " + std::to_string(leafSizeFactor) + ")";
      checkInvariants(mesh, tree, options, random, label, tally);
      AgreementStats stats;
      compareWithBruteForce(mesh, tree, random, 200, label, stats, tally);
    }
  }
  tally.print();
  EXPECT_EQ(tally.total(), 0) << "seed 0x7ee00006";
}

// A refit whose surface did not move keeps every sphere, nodes and leaves, byte for byte (it
// skips the walk up the nodes when no leaf sphere was made again); one that moves a single point
// far still remakes the spheres above it, up to the root, so that the invariants and the answers
// hold.
TEST(SphereTree, RefitRemakesTheNodesAboveOneMovedPointAndNothingWhenNothingMoved)
{
  Random random(0x7ee00007);
  FailureTally tally;
  TriangleMesh mesh = buildMesh(makeIcosphere(4, 0.05));
  SphereTreeOptions options;
  options.leafSizeFactor = 0.0;
  SphereTree tree;
  tree.build(mesh, options);
  const double edge = medianEdgeLength(mesh);
  const auto sameBytes = [](const auto& a, const auto& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(a.front())) == 0;
  };
  for (int round = 0; round < 2; ++round)
  {
    const std::vector<SphereTreeNode> nodes = tree.nodes();
    const std::vector<LeafSphere> leaves = tree.leafSpheres();
    tree.refit(mesh, 0.1 * edge);
    EXPECT_TRUE(sameBytes(nodes, tree.nodes())) << "round " << round;
    EXPECT_TRUE(sameBytes(leaves, tree.leafSpheres())) << "round " << round;

    std::vector<Vec3> points = mesh.points();
    const auto moved = static_cast<std::size_t>(random.integer(0, int(points.size()) - 1));
    points[moved] = points[moved] * 1.5;
    ASSERT_TRUE(mesh.movePoints(points.data(), points.size()));
    tree.refit(mesh, 0.1 * edge);
    EXPECT_NE(tree.nodes().front().radius, nodes.front().radius)
      << "the root must grow to hold a point moved half the sphere's radius out";
    const std::string label = "one point moved out, round " + std::to_string(round);
    checkInvariants(mesh, tree, options, random, label, tally);
    AgreementStats stats;
    compareWithBruteForce(mesh, tree, random, 200, label, stats, tally);
  }
  tally.print();
  EXPECT_EQ(tally.total(), 0) << "seed 0x7ee00007";
}

TEST(SphereTree, EmptyTreeAnswersNothing)
{
  TriangleMesh empty;
  SphereTree tree;
  tree.build(empty);
  auto scratch = std::make_unique<SphereTreeScratch>();
  EXPECT_EQ(tree.numNodes(), 0u);
  SweepQuery q;
  q.end = Vec3{1, 0, 0};
  q.radius = 1.0;
  EXPECT_FALSE(tree.firstContact(empty, q, *scratch).hit);
  EXPECT_FALSE(tree.nearest(empty, Vec3{}, kInfinity, *scratch).found);
  NearbyTriangle out[1];
  EXPECT_EQ(tree.gatherWithin(empty, Vec3{}, 1.0, out, 1, *scratch), 0u);
}

TEST(SphereTree, DrawingHelpersCoverTheTree)
{
  const TriangleMesh mesh = buildMesh(makeIcosphere(2, 1.0, Vec3{5, 5, 5}));
  SphereTree tree;
  tree.build(mesh);
  EXPECT_EQ(tree.leafSpheresInWorld().size(), tree.numLeafSpheres());
  const auto root = tree.spheresAtLevel(0);
  ASSERT_EQ(root.size(), 1u);
  // The root sphere, in world coordinates, holds every corner of the mesh.
  for (const Vec3& p : mesh.points())
  {
    EXPECT_LE(distance(p, root[0].center), root[0].radius * (1.0 + 1e-9));
  }
  // Going down a level never loses coverage: the deepest level is all the leaf nodes.
  EXPECT_GE(tree.spheresAtLevel(tree.depth()).size(), tree.spheresAtLevel(1).size());
}

} // namespace
} // namespace proxima::test
