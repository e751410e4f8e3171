#include "Geometry/SphereTree.h"

#include <algorithm>
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

// Rounds a double radius up to the next float that is not smaller.
float roundUpToFloat(double value)
{
  float f = static_cast<float>(value);
  if (static_cast<double>(f) < value)
  {
    f = std::nextafter(f, std::numeric_limits<float>::infinity());
  }
  return f;
}

// One coordinate rounded to the nearest float, widened back. Kept out of line on purpose: GCC 12.2
// at -O2/-O3 vectorises the three conversions of a Vec3 and then folds the narrowing-widening pair
// of the vector away, returning x and y unrounded (seen in the generated code; the tree's
// containment test caught it). A scalar call per coordinate cannot be combined that way.
[[gnu::noinline]] double roundToFloat(double value)
{
  return static_cast<double>(static_cast<float>(value));
}

Vec3 roundToFloatPrecision(const Vec3& v)
{
  return {roundToFloat(v.x), roundToFloat(v.y), roundToFloat(v.z)};
}

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
  leaf.center = roundToFloatPrecision(exact.center);
  const double reach = std::sqrt(std::max({squaredDistance(leaf.center, a),
                                           squaredDistance(leaf.center, b),
                                           squaredDistance(leaf.center, c)}));
  leaf.radius = static_cast<double>(roundUpToFloat(reach));
  leaf.triangle = triangle;
  return leaf;
}

double longestEdgeSquared(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return std::max({squaredDistance(a, b), squaredDistance(b, c), squaredDistance(c, a)});
}

// Covers one triangle with leaf spheres like scan conversion: longest-edge bisection until every
// piece's longest edge is at most `targetEdge`, or until `maxDepth` halvings.
void coverTriangle(const Vec3& a, const Vec3& b, const Vec3& c, std::uint32_t triangle,
                   double targetEdgeSquared, int maxDepth, std::vector<BuildLeaf>& leaves)
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
      leaves.push_back(makeLeaf(piece.a, piece.b, piece.c, triangle));
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

class TreeBuilder
{
public:
  TreeBuilder(std::vector<BuildLeaf>& leaves, std::uint32_t maxPerNode,
              std::vector<SphereTreeNode>& nodes)
    : m_leaves(leaves), m_maxPerNode(std::max<std::uint32_t>(1, maxPerNode)), m_nodes(nodes)
  {
  }

  // Builds the subtree over leaves [begin, end) and returns its exact (double) sphere.
  Sphere build(std::uint32_t begin, std::uint32_t end, std::uint32_t depth)
  {
    m_depth = std::max(m_depth, depth);
    Aabb box;
    for (std::uint32_t i = begin; i < end; ++i)
    {
      box.expand(m_leaves[i].center, m_leaves[i].radius);
    }
    const auto nodeIndex = static_cast<std::uint32_t>(m_nodes.size());
    m_nodes.push_back(SphereTreeNode{});
    const std::uint32_t count = end - begin;
    if (count <= m_maxPerNode)
    {
      Sphere sphere = count == 1 ? Sphere{m_leaves[begin].center, m_leaves[begin].radius}
                                 : enclosingLeaves(box.center(), begin, end);
      store(nodeIndex, sphere, begin, count, begin, end);
      return sphere;
    }

    // Paper section 5: split at the midpoint of the longest axis of the box. A split that leaves
    // one side empty (or a tree grown deep on clustered data) falls back to the median, which
    // keeps the depth logarithmic and the traversal stack bounded.
    const int axis = box.longestAxis();
    const double middle = box.center()[axis];
    auto first = m_leaves.begin() + begin;
    auto last = m_leaves.begin() + end;
    auto split = std::partition(first, last,
                                [&](const BuildLeaf& leaf) { return leaf.center[axis] < middle; });
    if (split == first || split == last || depth > kMedianSplitDepth)
    {
      split = first + count / 2;
      std::nth_element(first, split, last, [&](const BuildLeaf& x, const BuildLeaf& y) {
        return x.center[axis] < y.center[axis];
      });
    }
    const auto mid = static_cast<std::uint32_t>(split - m_leaves.begin());
    const Sphere left = build(begin, mid, depth + 1);
    const auto rightIndex = static_cast<std::uint32_t>(m_nodes.size());
    const Sphere right = build(mid, end, depth + 1);

    // The smaller of the paper's two heuristics: the sphere around both children, or the box
    // centre with a radius reaching every descendant leaf.
    const Sphere aroundChildren = enclosingTwo(left, right);
    const Sphere aroundLeaves = enclosingLeaves(box.center(), begin, end);
    const Sphere& sphere = aroundChildren.radius <= aroundLeaves.radius ? aroundChildren
                                                                         : aroundLeaves;
    store(nodeIndex, sphere, rightIndex, 0, begin, end);
    return sphere;
  }

  std::uint32_t depth() const { return m_depth; }

private:
  static constexpr std::uint32_t kMedianSplitDepth = kSphereTreeMedianSplitDepth;

  Sphere enclosingLeaves(const Vec3& center, std::uint32_t begin, std::uint32_t end) const
  {
    double radius = 0.0;
    for (std::uint32_t i = begin; i < end; ++i)
    {
      radius = std::max(radius, distance(center, m_leaves[i].center) + m_leaves[i].radius);
    }
    return Sphere{center, radius};
  }

  static Sphere enclosingTwo(const Sphere& s1, const Sphere& s2)
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

  // Stores the node in float: the centre's rounding is added to the radius, and the radius is
  // rounded up, so the stored sphere still holds every descendant leaf sphere.
  void store(std::uint32_t nodeIndex, const Sphere& sphere, std::uint32_t rightOrFirst,
             std::uint32_t numLeafSpheres, std::uint32_t begin, std::uint32_t end)
  {
    const Vec3 center = roundToFloatPrecision(sphere.center);
    double radius = 0.0;
    for (std::uint32_t i = begin; i < end && numLeafSpheres > 0; ++i)
    {
      radius = std::max(radius, distance(center, m_leaves[i].center) + m_leaves[i].radius);
    }
    if (numLeafSpheres == 0)
    {
      radius = sphere.radius + distance(center, sphere.center);
    }
    SphereTreeNode& node = m_nodes[nodeIndex];
    node.center[0] = static_cast<float>(center.x);
    node.center[1] = static_cast<float>(center.y);
    node.center[2] = static_cast<float>(center.z);
    node.radius = roundUpToFloat(radius);
    node.rightOrFirst = rightOrFirst;
    node.numLeafSpheres = numLeafSpheres;
  }

  std::vector<BuildLeaf>& m_leaves;
  std::uint32_t m_maxPerNode;
  std::vector<SphereTreeNode>& m_nodes;
  std::uint32_t m_depth = 0;
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

  double targetEdgeSquared = std::numeric_limits<double>::infinity();
  if (options.leafSizeFactor > 0.0)
  {
    std::vector<double> edges;
    edges.reserve(std::size_t{m_numTriangles} * 3);
    for (std::uint32_t t = 0; t < m_numTriangles; ++t)
    {
      const TriangleCorners& c = mesh.corners(t);
      edges.push_back(squaredDistance(c.a, c.b));
      edges.push_back(squaredDistance(c.b, c.c));
      edges.push_back(squaredDistance(c.c, c.a));
    }
    auto median = edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2);
    std::nth_element(edges.begin(), median, edges.end());
    const double target = options.leafSizeFactor * std::sqrt(*median);
    if (target > 0.0)
    {
      targetEdgeSquared = target * target;
    }
  }
  int maxDepth = 0;
  while ((2u << maxDepth) <= std::max<std::uint32_t>(1, options.maxPiecesPerTriangle) &&
         maxDepth < 30)
  {
    ++maxDepth;
  }

  std::vector<BuildLeaf> leaves;
  leaves.reserve(std::size_t{m_numTriangles} + m_numTriangles / 8);
  for (std::uint32_t t = 0; t < m_numTriangles; ++t)
  {
    const TriangleCorners& c = mesh.corners(t);
    const Vec3 a = c.a - m_origin;
    const Vec3 b = c.b - m_origin;
    const Vec3 cc = c.c - m_origin;
    if (longestEdgeSquared(a, b, cc) <= targetEdgeSquared)
    {
      leaves.push_back(makeLeaf(a, b, cc, t));
    }
    else
    {
      coverTriangle(a, b, cc, t, targetEdgeSquared, maxDepth, leaves);
    }
  }

  m_nodes.reserve(2 * leaves.size() / std::max<std::uint32_t>(1, options.maxLeafSpheresPerNode) +
                  2);
  TreeBuilder builder(leaves, options.maxLeafSpheresPerNode, m_nodes);
  builder.build(0, static_cast<std::uint32_t>(leaves.size()), 0);
  m_depth = builder.depth();
  assert(m_depth <= kSphereTreeMaxDepth); // the queries' stack is sized for this

  m_leaves.resize(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    LeafSphere& leaf = m_leaves[i];
    leaf.center[0] = static_cast<float>(leaves[i].center.x);
    leaf.center[1] = static_cast<float>(leaves[i].center.y);
    leaf.center[2] = static_cast<float>(leaves[i].center.z);
    leaf.radius = static_cast<float>(leaves[i].radius);
    leaf.triangle = leaves[i].triangle;
  }
  m_nodes.shrink_to_fit();
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
