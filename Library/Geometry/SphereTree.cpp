#include "Geometry/SphereTree.h"

#include "Geometry/Private/FloatRounding.h"
#include "Geometry/Private/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace proxima
{
namespace
{
// A leaf sphere during the build, in double, relative to the tree's origin. It already holds the
// float-rounded values that will be stored, so nodes enclose exactly what queries will test.
struct BuildLeaf
{
  Vec3 center;
  double radius;
  std::uint32_t triangle;
};

// Smallest sphere holding three points: the midpoint of the longest edge when the opposite angle
// is right or obtuse (or the points are collinear), else the circumsphere.
Sphere minimalSphere(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 corners[3] = {a, b, c};
  int longest = 0; // edge i runs from corner i to corner i+1
  double longestSquared = -1.0;
  for (int i = 0; i < 3; ++i)
  {
    const double lengthSquared = squaredDistance(corners[i], corners[(i + 1) % 3]);
    if (lengthSquared > longestSquared)
    {
      longestSquared = lengthSquared;
      longest = i;
    }
  }
  const Vec3& p = corners[longest];
  const Vec3& q = corners[(longest + 1) % 3];
  const Vec3& opposite = corners[(longest + 2) % 3];
  Sphere sphere;
  if (dot(p - opposite, q - opposite) <= 0.0)
  {
    sphere.center = (p + q) * 0.5;
  }
  else
  {
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 n = cross(ab, ac);
    const double denominator = 2.0 * dot(n, n);
    sphere.center = denominator > 0.0
                      ? a + (cross(n, ab) * dot(ac, ac) + cross(ac, n) * dot(ab, ab)) / denominator
                      : (p + q) * 0.5;
  }
  return sphere;
}

// The stored leaf sphere for one triangle piece: float centre, radius measured from that centre.
BuildLeaf makeLeaf(const Vec3& a, const Vec3& b, const Vec3& c, std::uint32_t triangle)
{
  const Sphere exact = minimalSphere(a, b, c);
  BuildLeaf leaf;
  leaf.center = detail::roundToFloatPrecision(exact.center);
  const double reach =
    std::sqrt(std::max({squaredDistance(leaf.center, a), squaredDistance(leaf.center, b),
                        squaredDistance(leaf.center, c)}));
  leaf.radius = static_cast<double>(detail::roundUpToFloat(reach));
  leaf.triangle = triangle;
  return leaf;
}

double longestEdgeSquared(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return std::max({squaredDistance(a, b), squaredDistance(b, c), squaredDistance(c, a)});
}

// Longest-edge bisection of one triangle until every piece's longest edge is at most
// `targetEdge`, or until `maxDepth` halvings; each final piece goes to `onPiece(a, b, c)`.
template <class OnPiece>
void bisectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double targetEdgeSquared,
                    int maxDepth, OnPiece&& onPiece)
{
  struct Piece
  {
    Vec3 a, b, c;
    int depth;
  };
  Piece stack[64];
  int size = 0;
  stack[size++] = Piece{a, b, c, 0};
  while (size > 0)
  {
    const Piece piece = stack[--size];
    const double ab = squaredDistance(piece.a, piece.b);
    const double bc = squaredDistance(piece.b, piece.c);
    const double ca = squaredDistance(piece.c, piece.a);
    const double longest = std::max({ab, bc, ca});
    if (piece.depth >= maxDepth || !(longest > targetEdgeSquared) || size + 2 > 64)
    {
      onPiece(piece.a, piece.b, piece.c);
      continue;
    }
    if (ab == longest)
    {
      const Vec3 m = (piece.a + piece.b) * 0.5;
      stack[size++] = Piece{piece.a, m, piece.c, piece.depth + 1};
      stack[size++] = Piece{m, piece.b, piece.c, piece.depth + 1};
    }
    else if (bc == longest)
    {
      const Vec3 m = (piece.b + piece.c) * 0.5;
      stack[size++] = Piece{piece.a, piece.b, m, piece.depth + 1};
      stack[size++] = Piece{piece.a, m, piece.c, piece.depth + 1};
    }
    else
    {
      const Vec3 m = (piece.c + piece.a) * 0.5;
      stack[size++] = Piece{piece.a, piece.b, m, piece.depth + 1};
      stack[size++] = Piece{m, piece.b, piece.c, piece.depth + 1};
    }
  }
}

// Covers one triangle with leaf spheres like scan conversion: a sphere per bisected piece.
void coverTriangle(const Vec3& a, const Vec3& b, const Vec3& c, std::uint32_t triangle,
                   double targetEdgeSquared, int maxDepth, std::vector<BuildLeaf>& leaves)
{
  bisectTriangle(a, b, c, targetEdgeSquared, maxDepth,
                 [&](const Vec3& pa, const Vec3& pb, const Vec3& pc) {
                   leaves.push_back(makeLeaf(pa, pb, pc, triangle));
                 });
}

// The most halvings that keep a triangle within `maxPieces` pieces.
int maxBisectionDepth(std::uint32_t maxPieces)
{
  int depth = 0;
  while ((2u << depth) <= std::max<std::uint32_t>(1, maxPieces) && depth < 30)
  {
    ++depth;
  }
  return depth;
}

// How many leaf spheres coverTriangle gives the triangle, without making them.
std::uint64_t countPieces(const Vec3& a, const Vec3& b, const Vec3& c, double targetEdgeSquared,
                          int maxDepth)
{
  std::uint64_t count = 0;
  bisectTriangle(a, b, c, targetEdgeSquared, maxDepth,
                 [&count](const Vec3&, const Vec3&, const Vec3&) { ++count; });
  return count;
}

// The box around leaves [begin, end) of `leaves`, each with its radius.
Aabb boundsOf(const std::vector<BuildLeaf>& leaves, std::uint32_t begin, std::uint32_t end)
{
  Aabb box;
  for (std::uint32_t i = begin; i < end; ++i)
  {
    box.expand(leaves[i].center, leaves[i].radius);
  }
  return box;
}

// Paper section 5: splits leaves [begin, end) (more than one) at the midpoint of the longest axis
// of their box and returns where the right half starts. A split that leaves one side empty (or a
// tree grown deep on clustered data) falls back to the median, which keeps the depth logarithmic
// and the traversal stack bounded.
std::uint32_t splitLeaves(std::vector<BuildLeaf>& leaves, std::uint32_t begin, std::uint32_t end,
                          std::uint32_t depth, const Aabb& box)
{
  constexpr std::uint32_t kMedianSplitDepth = kSphereTreeMedianSplitDepth;
  const int axis = box.longestAxis();
  const double middle = box.center()[axis];
  auto first = leaves.begin() + begin;
  auto last = leaves.begin() + end;
  auto split =
    std::partition(first, last, [&](const BuildLeaf& leaf) { return leaf.center[axis] < middle; });
  if (split == first || split == last || depth > kMedianSplitDepth)
  {
    split = first + (end - begin) / 2;
    std::nth_element(first, split, last, [&](const BuildLeaf& x, const BuildLeaf& y) {
      return x.center[axis] < y.center[axis];
    });
  }
  return static_cast<std::uint32_t>(split - leaves.begin());
}

// The sphere at `center` reaching every leaf sphere of [begin, end).
Sphere enclosingLeaves(const std::vector<BuildLeaf>& leaves, const Vec3& center,
                       std::uint32_t begin, std::uint32_t end)
{
  double radius = 0.0;
  for (std::uint32_t i = begin; i < end; ++i)
  {
    radius = std::max(radius, distance(center, leaves[i].center) + leaves[i].radius);
  }
  return Sphere{center, radius};
}

Sphere enclosingTwo(const Sphere& s1, const Sphere& s2)
{
  const double d = distance(s1.center, s2.center);
  if (d + s2.radius <= s1.radius)
  {
    return s1;
  }
  if (d + s1.radius <= s2.radius)
  {
    return s2;
  }
  const double radius = 0.5 * (d + s1.radius + s2.radius);
  const Vec3 center = s1.center + (s2.center - s1.center) * ((radius - s1.radius) / d);
  return Sphere{center, radius};
}

// An internal node's sphere: the smaller of the paper's two heuristics, the sphere around both
// children or the box centre with a radius reaching every descendant leaf.
Sphere parentSphere(const Sphere& left, const Sphere& right, const Sphere& aroundLeaves)
{
  const Sphere aroundChildren = enclosingTwo(left, right);
  return aroundChildren.radius <= aroundLeaves.radius ? aroundChildren : aroundLeaves;
}

// The node stored in float: the centre's rounding is added to the radius, and the radius is
// rounded up, so the stored sphere still holds every descendant leaf sphere.
SphereTreeNode storedNode(const std::vector<BuildLeaf>& leaves, const Sphere& sphere,
                          std::uint32_t rightOrFirst, std::uint32_t numLeafSpheres,
                          std::uint32_t begin, std::uint32_t end)
{
  const Vec3 center = detail::roundToFloatPrecision(sphere.center);
  double radius = 0.0;
  for (std::uint32_t i = begin; i < end && numLeafSpheres > 0; ++i)
  {
    radius = std::max(radius, distance(center, leaves[i].center) + leaves[i].radius);
  }
  if (numLeafSpheres == 0)
  {
    radius = sphere.radius + distance(center, sphere.center);
  }
  SphereTreeNode node;
  node.center[0] = static_cast<float>(center.x);
  node.center[1] = static_cast<float>(center.y);
  node.center[2] = static_cast<float>(center.z);
  node.radius = detail::roundUpToFloat(radius);
  node.rightOrFirst = rightOrFirst;
  node.numLeafSpheres = numLeafSpheres;
  return node;
}

// The serial build: one subtree, depth first, appending its nodes to `nodes` with indices
// relative to the first.
class TreeBuilder
{
public:
  TreeBuilder(std::vector<BuildLeaf>& leaves, std::uint32_t maxPerNode,
              std::vector<SphereTreeNode>& nodes)
    : m_leaves(leaves)
    , m_maxPerNode(std::max<std::uint32_t>(1, maxPerNode))
    , m_nodes(nodes)
  {}

  // Builds the subtree over leaves [begin, end), whose root is at `depth`, and returns its exact
  // (double) sphere.
  Sphere build(std::uint32_t begin, std::uint32_t end, std::uint32_t depth)
  {
    m_depth = std::max(m_depth, depth);
    const Aabb box = boundsOf(m_leaves, begin, end);
    const auto nodeIndex = static_cast<std::uint32_t>(m_nodes.size());
    m_nodes.push_back(SphereTreeNode{});
    const std::uint32_t count = end - begin;
    if (count <= m_maxPerNode)
    {
      Sphere sphere = count == 1 ? Sphere{m_leaves[begin].center, m_leaves[begin].radius}
                                 : enclosingLeaves(m_leaves, box.center(), begin, end);
      m_nodes[nodeIndex] = storedNode(m_leaves, sphere, begin, count, begin, end);
      return sphere;
    }
    const std::uint32_t mid = splitLeaves(m_leaves, begin, end, depth, box);
    const Sphere left = build(begin, mid, depth + 1);
    const auto rightIndex = static_cast<std::uint32_t>(m_nodes.size());
    const Sphere right = build(mid, end, depth + 1);
    const Sphere sphere =
      parentSphere(left, right, enclosingLeaves(m_leaves, box.center(), begin, end));
    m_nodes[nodeIndex] = storedNode(m_leaves, sphere, rightIndex, 0, begin, end);
    return sphere;
  }

  std::uint32_t depth() const { return m_depth; }

private:
  std::vector<BuildLeaf>& m_leaves;
  std::uint32_t m_maxPerNode;
  std::vector<SphereTreeNode>& m_nodes;
  std::uint32_t m_depth = 0;
};

// Triangles per chunk of the parallel passes over a mesh: enough work to be worth a thread's turn.
constexpr std::size_t kTrianglesPerChunk = 16384;
// Subtrees of at most this many leaf spheres are built whole by one thread (TreeBuilder).
constexpr std::uint32_t kLeavesPerSubtree = 8192;

// The parallel build, made to give the serial build's tree bit for bit. The top of the tree is
// split level by level, the nodes of a level in parallel, with the serial build's own split
// (splitLeaves) on the same leaf ranges, so the leaves end up in the same order; below
// kLeavesPerSubtree each subtree is one serial TreeBuilder run, the subtrees in parallel, each
// into its own node array; then the arrays are laid out depth first as the serial build lays
// them (internal nodes' right-child indices shifted by where their subtree lands) and the top
// nodes' spheres computed from their children's exactly as TreeBuilder does. Every sphere is a
// maximum over a leaf range, which does not depend on the order of the range.
class ParallelTreeBuilder
{
public:
  ParallelTreeBuilder(std::vector<BuildLeaf>& leaves, std::uint32_t maxPerNode, unsigned numThreads)
    : m_leaves(leaves)
    , m_maxPerNode(std::max<std::uint32_t>(1, maxPerNode))
    , m_numThreads(numThreads)
  {}

  // Appends the whole tree to `nodes` and returns its depth.
  std::uint32_t build(std::vector<SphereTreeNode>& nodes)
  {
    splitTop();
    buildSubtrees();
    // The top nodes' "around the leaves" spheres, each a pass over its range.
    FunctorOver finishTop{[this](std::size_t t) {
      TopNode& node = m_top[t];
      if (node.left >= 0)
      {
        node.aroundLeaves = enclosingLeaves(m_leaves, node.box.center(), node.begin, node.end);
      }
    }};
    detail::parallelFor(0, m_top.size(), 1, finishTop, m_numThreads);
    emit(0, nodes);
    std::uint32_t depth = 0;
    for (const Subtree& subtree : m_subtrees)
    {
      depth = std::max(depth, subtree.depth);
    }
    return depth;
  }

private:
  struct TopNode
  {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::uint32_t depth = 0;
    Aabb box;
    std::uint32_t mid = 0;
    // Children in m_top, or -1 when this node is the root of subtree `subtree`.
    std::int32_t left = -1;
    std::int32_t right = -1;
    std::uint32_t subtree = 0;
    Sphere aroundLeaves;
  };

  struct Subtree
  {
    std::uint32_t top = 0;
    std::vector<SphereTreeNode> nodes;
    Sphere sphere;
    std::uint32_t depth = 0;
  };

  // parallelFor over single indices, for passes whose items are few and large.
  template <typename Body>
  struct FunctorOver
  {
    Body body;
    void operator()(std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        body(i);
      }
    }
  };
  template <typename Body>
  FunctorOver(Body) -> FunctorOver<Body>;

  bool isSubtreeRoot(const TopNode& node) const
  {
    return node.end - node.begin <= std::max(kLeavesPerSubtree, m_maxPerNode);
  }

  void splitTop()
  {
    m_top.clear();
    m_top.push_back(TopNode{});
    m_top[0].end = static_cast<std::uint32_t>(m_leaves.size());
    std::vector<std::uint32_t> level{0};
    while (!level.empty())
    {
      // The nodes of one level own disjoint leaf ranges: they split in parallel.
      FunctorOver splitLevel{[&](std::size_t k) {
        TopNode& node = m_top[level[k]];
        if (!isSubtreeRoot(node))
        {
          node.box = boundsOf(m_leaves, node.begin, node.end);
          node.mid = splitLeaves(m_leaves, node.begin, node.end, node.depth, node.box);
        }
      }};
      detail::parallelFor(0, level.size(), 1, splitLevel, m_numThreads);
      std::vector<std::uint32_t> next;
      for (const std::uint32_t t : level)
      {
        if (isSubtreeRoot(m_top[t]))
        {
          m_top[t].subtree = static_cast<std::uint32_t>(m_subtrees.size());
          m_subtrees.push_back(Subtree{t, {}, {}, 0});
          continue;
        }
        const TopNode parent = m_top[t];
        TopNode left;
        left.begin = parent.begin;
        left.end = parent.mid;
        left.depth = parent.depth + 1;
        TopNode right;
        right.begin = parent.mid;
        right.end = parent.end;
        right.depth = parent.depth + 1;
        m_top[t].left = static_cast<std::int32_t>(m_top.size());
        m_top.push_back(left);
        m_top[t].right = static_cast<std::int32_t>(m_top.size());
        m_top.push_back(right);
        next.push_back(static_cast<std::uint32_t>(m_top[t].left));
        next.push_back(static_cast<std::uint32_t>(m_top[t].right));
      }
      level = std::move(next);
    }
  }

  void buildSubtrees()
  {
    FunctorOver buildOne{[this](std::size_t s) {
      Subtree& subtree = m_subtrees[s];
      const TopNode& root = m_top[subtree.top];
      subtree.nodes.reserve(2 * (root.end - root.begin) / m_maxPerNode + 2);
      TreeBuilder builder(m_leaves, m_maxPerNode, subtree.nodes);
      subtree.sphere = builder.build(root.begin, root.end, root.depth);
      subtree.depth = builder.depth();
    }};
    detail::parallelFor(0, m_subtrees.size(), 1, buildOne, m_numThreads);
  }

  // Lays out top node t and everything under it depth first; returns its exact sphere.
  Sphere emit(std::uint32_t t, std::vector<SphereTreeNode>& nodes)
  {
    const TopNode& node = m_top[t];
    if (node.left < 0)
    {
      const Subtree& subtree = m_subtrees[node.subtree];
      const auto offset = static_cast<std::uint32_t>(nodes.size());
      for (SphereTreeNode stored : subtree.nodes)
      {
        if (stored.numLeafSpheres == 0)
        {
          stored.rightOrFirst += offset;
        }
        nodes.push_back(stored);
      }
      return subtree.sphere;
    }
    const auto nodeIndex = static_cast<std::uint32_t>(nodes.size());
    nodes.push_back(SphereTreeNode{});
    const Sphere left = emit(static_cast<std::uint32_t>(node.left), nodes);
    const auto rightIndex = static_cast<std::uint32_t>(nodes.size());
    const Sphere right = emit(static_cast<std::uint32_t>(node.right), nodes);
    const Sphere sphere = parentSphere(left, right, node.aroundLeaves);
    nodes[nodeIndex] = storedNode(m_leaves, sphere, rightIndex, 0, node.begin, node.end);
    return sphere;
  }

  std::vector<BuildLeaf>& m_leaves;
  std::uint32_t m_maxPerNode;
  unsigned m_numThreads;
  std::vector<TopNode> m_top;
  std::vector<Subtree> m_subtrees;
};

// Appends the leaf spheres of triangle `triangle` (corners relative to the tree's origin).
void addLeavesOf(const Vec3& a, const Vec3& b, const Vec3& c, std::uint32_t triangle,
                 double targetEdgeSquared, int maxDepth, std::vector<BuildLeaf>& leaves)
{
  if (longestEdgeSquared(a, b, c) <= targetEdgeSquared)
  {
    leaves.push_back(makeLeaf(a, b, c, triangle));
  }
  else
  {
    coverTriangle(a, b, c, triangle, targetEdgeSquared, maxDepth, leaves);
  }
}

// The leaf spheres of a mesh's triangles, in triangle order: chunks of triangles in parallel,
// each into its own list, joined in chunk order by Reduce (so in the order of the serial loop).
class CoverTriangles
{
public:
  CoverTriangles(const TriangleMesh& mesh, const Vec3& origin, double targetEdgeSquared,
                 int maxDepth, std::vector<BuildLeaf>& leaves)
    : m_mesh(mesh)
    , m_origin(origin)
    , m_targetEdgeSquared(targetEdgeSquared)
    , m_maxDepth(maxDepth)
    , m_leaves(leaves)
    , m_chunks((mesh.numTriangles() + kTrianglesPerChunk - 1) / kTrianglesPerChunk)
  {}

  void operator()(std::size_t begin, std::size_t end)
  {
    std::vector<BuildLeaf>& out = m_chunks[begin / kTrianglesPerChunk];
    out.reserve((end - begin) + (end - begin) / 8);
    for (std::size_t t = begin; t < end; ++t)
    {
      const TriangleCorners& c = m_mesh.corners(static_cast<std::uint32_t>(t));
      addLeavesOf(c.a - m_origin, c.b - m_origin, c.c - m_origin, static_cast<std::uint32_t>(t),
                  m_targetEdgeSquared, m_maxDepth, out);
    }
  }

  void Reduce()
  {
    std::size_t total = 0;
    for (const std::vector<BuildLeaf>& chunk : m_chunks)
    {
      total += chunk.size();
    }
    m_leaves.reserve(total);
    for (std::vector<BuildLeaf>& chunk : m_chunks)
    {
      m_leaves.insert(m_leaves.end(), chunk.begin(), chunk.end());
      std::vector<BuildLeaf>().swap(chunk);
    }
  }

private:
  const TriangleMesh& m_mesh;
  Vec3 m_origin;
  double m_targetEdgeSquared;
  int m_maxDepth;
  std::vector<BuildLeaf>& m_leaves;
  std::vector<std::vector<BuildLeaf>> m_chunks;
};

} // namespace

void SphereTree::build(const TriangleMesh& mesh, const SphereTreeOptions& options)
{
  m_nodes.clear();
  m_leaves.clear();
  m_numTriangles = mesh.numTriangles();
  m_origin = mesh.bounds().center();
  m_depth = 0;
  if (m_numTriangles == 0)
  {
    return;
  }
  const unsigned threads = detail::resolveThreadCount(options.numBuildThreads);

  double targetEdgeSquared = std::numeric_limits<double>::infinity();
  if (options.leafSizeFactor > 0.0)
  {
    std::vector<double> edges(std::size_t{m_numTriangles} * 3);
    std::vector<double> shortest(m_numTriangles);
    auto squaredEdges = [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
      {
        const TriangleCorners& c = mesh.corners(static_cast<std::uint32_t>(t));
        edges[3 * t] = squaredDistance(c.a, c.b);
        edges[3 * t + 1] = squaredDistance(c.b, c.c);
        edges[3 * t + 2] = squaredDistance(c.c, c.a);
        shortest[t] = std::min({edges[3 * t], edges[3 * t + 1], edges[3 * t + 2]});
      }
    };
    detail::parallelFor(0, m_numTriangles, kTrianglesPerChunk, squaredEdges, threads);
    auto median = edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2);
    std::nth_element(edges.begin(), median, edges.end());
    auto medianShortest = shortest.begin() + static_cast<std::ptrdiff_t>(shortest.size() / 2);
    std::nth_element(shortest.begin(), medianShortest, shortest.end());
    // A CAD mesh of slivers (a cylinder's sides and its caps' fans) has long edges for most of
    // its edges, so its median edge is as long as the slivers and would leave them whole: one
    // leaf sphere as large as each sliver, met by every query beside it. The slivers' short
    // edges say how fine the surface is there; a mesh of well-shaped triangles has its median
    // shortest edge within half its median edge, and keeps the median rule.
    const double medianLength = std::sqrt(*median);
    const double scale = std::min(medianLength, kShortEdgeScaleFactor * std::sqrt(*medianShortest));
    double target = options.leafSizeFactor * scale;
    if (target > 0.0)
    {
      targetEdgeSquared = target * target;
    }
    // The short-edge rule can multiply the leaves of a mesh of slivers many times over: within
    // kLeafSphereBudget, the length grows back toward the median rule's.
    const int depth = maxBisectionDepth(options.maxPiecesPerTriangle);
    const double medianTarget = options.leafSizeFactor * medianLength;
    const std::uint64_t budget = std::max<std::uint64_t>(
      kLeafSpheresPerTriangleBudget * std::uint64_t{m_numTriangles}, kLeafSphereBudget);
    while (target > 0.0 && target < medianTarget)
    {
      std::uint64_t pieces = 0;
      for (std::uint32_t t = 0; t < m_numTriangles && pieces <= budget; ++t)
      {
        const TriangleCorners& c = mesh.corners(t);
        pieces += countPieces(c.a, c.b, c.c, targetEdgeSquared, depth);
      }
      if (pieces <= budget)
      {
        break;
      }
      target = std::min(medianTarget, target * 1.5);
      targetEdgeSquared = target * target;
    }
  }
  const int maxDepth = maxBisectionDepth(options.maxPiecesPerTriangle);

  std::vector<BuildLeaf> leaves;
  if (threads == 1)
  {
    leaves.reserve(std::size_t{m_numTriangles} + m_numTriangles / 8);
    for (std::uint32_t t = 0; t < m_numTriangles; ++t)
    {
      const TriangleCorners& c = mesh.corners(t);
      addLeavesOf(c.a - m_origin, c.b - m_origin, c.c - m_origin, t, targetEdgeSquared, maxDepth,
                  leaves);
    }
  }
  else
  {
    CoverTriangles cover(mesh, m_origin, targetEdgeSquared, maxDepth, leaves);
    detail::parallelFor(0, m_numTriangles, kTrianglesPerChunk, cover, threads);
  }

  m_nodes.reserve(2 * leaves.size() / std::max<std::uint32_t>(1, options.maxLeafSpheresPerNode) +
                  2);
  if (threads == 1)
  {
    TreeBuilder builder(leaves, options.maxLeafSpheresPerNode, m_nodes);
    builder.build(0, static_cast<std::uint32_t>(leaves.size()), 0);
    m_depth = builder.depth();
  }
  else
  {
    ParallelTreeBuilder builder(leaves, options.maxLeafSpheresPerNode, threads);
    m_depth = builder.build(m_nodes);
  }
  assert(m_depth <= kSphereTreeMaxDepth); // the queries' stack is sized for this

  m_leaves.resize(leaves.size());
  auto storeLeaves = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      LeafSphere& leaf = m_leaves[i];
      leaf.center[0] = static_cast<float>(leaves[i].center.x);
      leaf.center[1] = static_cast<float>(leaves[i].center.y);
      leaf.center[2] = static_cast<float>(leaves[i].center.z);
      leaf.radius = static_cast<float>(leaves[i].radius);
      leaf.triangle = leaves[i].triangle;
    }
  };
  detail::parallelFor(0, leaves.size(), kTrianglesPerChunk, storeLeaves, threads);
  m_nodes.shrink_to_fit();
}

namespace
{
// True when the sphere (centre, radius) holds `point` with room for rounding. Squares only, no
// square root: the radius is a float, so its square is exact in double, and the relative margin
// covers the rounding of the squared distance.
bool holdsPoint(const Vec3& center, double radius, const Vec3& point)
{
  return squaredDistance(center, point) <= radius * radius * (1.0 - 1e-14);
}

// True when the sphere (center, radius) holds the sphere (inner, innerRadius).
bool holdsSphere(const Vec3& center, double radius, const Vec3& inner, double innerRadius)
{
  const double room = radius - innerRadius;
  return room >= 0.0 && squaredDistance(center, inner) <= room * room * (1.0 - 1e-14);
}

// Stores `center` rounded to float and returns the stored centre widened back.
Vec3 storeCenter(float (&stored)[3], const Vec3& center)
{
  stored[0] = static_cast<float>(center.x);
  stored[1] = static_cast<float>(center.y);
  stored[2] = static_cast<float>(center.z);
  return {static_cast<double>(stored[0]), static_cast<double>(stored[1]),
          static_cast<double>(stored[2])};
}
} // namespace

void SphereTree::refit(const TriangleMesh& mesh, double margin)
{
  if (mesh.numTriangles() != m_numTriangles || m_nodes.empty())
  {
    return;
  }
  margin = margin > 0.0 ? margin : 0.0;
  // Leaves first. One that still holds its triangle is kept; one that does not is made again
  // around the whole triangle, from its centroid (no division: a little looser than the build's
  // smallest sphere), larger by `margin` so that the next small motions leave it be. A split
  // triangle's pieces each get the whole triangle's sphere.
  // The corners are read through the point indices rather than the mesh's corner copies: the
  // leaves visit the triangles in the tree's spatial order, and the indices and points (a third
  // of the bytes) stay in cache where the corner copies do not.
  const std::vector<Vec3>& points = mesh.points();
  bool remade = false;
  for (LeafSphere& leaf : m_leaves)
  {
    const std::array<std::uint32_t, 3>& corner = mesh.indices(leaf.triangle);
    const Vec3 a = points[corner[0]] - m_origin;
    const Vec3 b = points[corner[1]] - m_origin;
    const Vec3 c = points[corner[2]] - m_origin;
    const Vec3 center = centerOf(leaf);
    const auto radius = static_cast<double>(leaf.radius);
    if (holdsPoint(center, radius, a) && holdsPoint(center, radius, b) &&
        holdsPoint(center, radius, c))
    {
      continue;
    }
    const Vec3 stored = storeCenter(leaf.center, (a + b + c) * (1.0 / 3.0));
    const double reach = std::sqrt(std::max(
      {squaredDistance(stored, a), squaredDistance(stored, b), squaredDistance(stored, c)}));
    leaf.radius = detail::roundUpToFloatWithoutBranch(reach + margin);
    remade = true;
  }
  // Nodes depend on the leaf spheres alone: with none made again, every node still holds what it
  // held after the last build or refit, and the walk up would keep each one. A surface at rest
  // between simulation steps costs the leaf pass alone.
  if (!remade)
  {
    return;
  }
  // Then the nodes, bottom-up: in depth-first order every child comes after its parent, so a walk
  // from the last node to the first meets the children first. A node that still holds its
  // children is kept; otherwise a leaf node becomes the sphere around its leaf spheres' box
  // centre and an internal node the sphere around its two children, each larger by `margin`,
  // its radius measured from the stored float centre and rounded up.
  for (std::size_t k = m_nodes.size(); k-- > 0;)
  {
    SphereTreeNode& node = m_nodes[k];
    const Vec3 current = centerOf(node);
    const auto currentRadius = static_cast<double>(node.radius);
    if (node.numLeafSpheres > 0)
    {
      const std::uint32_t first = node.rightOrFirst;
      const std::uint32_t end = first + node.numLeafSpheres;
      bool holds = true;
      for (std::uint32_t i = first; i < end && holds; ++i)
      {
        holds = holdsSphere(current, currentRadius, centerOf(m_leaves[i]),
                            static_cast<double>(m_leaves[i].radius));
      }
      if (holds)
      {
        continue;
      }
      Aabb box;
      for (std::uint32_t i = first; i < end; ++i)
      {
        box.expand(centerOf(m_leaves[i]), static_cast<double>(m_leaves[i].radius));
      }
      const Vec3 stored = storeCenter(node.center, box.center());
      double radius = 0.0;
      for (std::uint32_t i = first; i < end; ++i)
      {
        radius = std::max(radius, distance(stored, centerOf(m_leaves[i])) +
                                    static_cast<double>(m_leaves[i].radius));
      }
      node.radius = detail::roundUpToFloatWithoutBranch(radius + margin);
      continue;
    }
    const SphereTreeNode& left = m_nodes[k + 1];
    const SphereTreeNode& right = m_nodes[node.rightOrFirst];
    const Sphere leftSphere{centerOf(left), static_cast<double>(left.radius)};
    const Sphere rightSphere{centerOf(right), static_cast<double>(right.radius)};
    if (holdsSphere(current, currentRadius, leftSphere.center, leftSphere.radius) &&
        holdsSphere(current, currentRadius, rightSphere.center, rightSphere.radius))
    {
      continue;
    }
    const Sphere around = enclosingTwo(leftSphere, rightSphere);
    const Vec3 stored = storeCenter(node.center, around.center);
    node.radius =
      detail::roundUpToFloatWithoutBranch(around.radius + distance(stored, around.center) + margin);
  }
}

std::size_t SphereTree::memoryBytes() const
{
  return m_nodes.capacity() * sizeof(SphereTreeNode) + m_leaves.capacity() * sizeof(LeafSphere);
}

std::vector<Sphere> SphereTree::spheresAtLevel(std::uint32_t level) const
{
  std::vector<Sphere> spheres;
  if (m_nodes.empty())
  {
    return spheres;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack = {{0, 0}};
  while (!stack.empty())
  {
    const auto [index, nodeLevel] = stack.back();
    stack.pop_back();
    const SphereTreeNode& node = m_nodes[index];
    if (nodeLevel == level || node.numLeafSpheres > 0)
    {
      spheres.push_back(Sphere{centerOf(node) + m_origin, static_cast<double>(node.radius)});
      continue;
    }
    stack.emplace_back(node.rightOrFirst, nodeLevel + 1);
    stack.emplace_back(index + 1, nodeLevel + 1);
  }
  return spheres;
}

std::vector<Sphere> SphereTree::leafSpheresInWorld() const
{
  std::vector<Sphere> spheres;
  spheres.reserve(m_leaves.size());
  for (const LeafSphere& leaf : m_leaves)
  {
    spheres.push_back(Sphere{centerOf(leaf) + m_origin, static_cast<double>(leaf.radius)});
  }
  return spheres;
}

} // namespace proxima
