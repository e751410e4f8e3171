#include "ProxyOracle.h"

#include <CGAL/AABB_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace proxima::oracle
{
namespace
{
using Kernel = CGAL::Epick;
using Point = Kernel::Point_3;
using Cuboid = Kernel::Iso_cuboid_3;

// 128-bit binary floating point (113-bit significand): the difference of two nearby doubles is
// exact in it and the product of two such differences nearly so, which is what makes a normal of a
// sliver, or a distance 1 mm from a point 1 km from the origin, trustworthy.
__extension__ typedef __float128 Quad;

struct Q3
{
  Quad x = 0;
  Quad y = 0;
  Quad z = 0;
};

Q3 operator+(const Q3& a, const Q3& b)
{
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Q3 operator-(const Q3& a, const Q3& b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Q3 operator*(const Q3& a, Quad s)
{
  return {a.x * s, a.y * s, a.z * s};
}
Quad dotQ(const Q3& a, const Q3& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Q3 crossQ(const Q3& a, const Q3& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// `p` in the frame whose origin is `origin`, subtracted in 128 bits.
Q3 local(const Vec3& p, const Vec3& origin)
{
  return {Quad(p.x) - Quad(origin.x), Quad(p.y) - Quad(origin.y), Quad(p.z) - Quad(origin.z)};
}
Vec3 toVec(const Q3& q)
{
  return {static_cast<double>(q.x), static_cast<double>(q.y), static_cast<double>(q.z)};
}
Vec3 toWorld(const Q3& q, const Vec3& origin)
{
  return {static_cast<double>(Quad(origin.x) + q.x), static_cast<double>(Quad(origin.y) + q.y),
          static_cast<double>(Quad(origin.z) + q.z)};
}

// Squared distance from p to segment [a, b], and the closest point.
Quad pointSegmentSquared(const Q3& p, const Q3& a, const Q3& b, Q3& closest)
{
  const Q3 e = b - a;
  const Quad ee = dotQ(e, e);
  Quad t = 0;
  if (ee > 0)
  {
    t = dotQ(p - a, e) / ee;
    t = t < 0 ? Quad(0) : (t > 1 ? Quad(1) : t);
  }
  closest = a + e * t;
  const Q3 d = p - closest;
  return dotQ(d, d);
}

// Squared distance from p to triangle (a, b, c): the projection onto the plane when it falls
// inside (signs of the edge triple products against the explicit normal), else the nearest of the
// three edges. A zero-area triangle (normal exactly 0 in 128 bits) is its three edges.
Quad pointTriangleSquared(const Q3& p, const Q3& a, const Q3& b, const Q3& c, Q3& closest)
{
  const Q3 n = crossQ(b - a, c - a);
  const Quad nn = dotQ(n, n);
  if (nn > 0)
  {
    const bool inside = dotQ(crossQ(b - a, p - a), n) >= 0 && dotQ(crossQ(c - b, p - b), n) >= 0 &&
                        dotQ(crossQ(a - c, p - c), n) >= 0;
    if (inside)
    {
      const Quad h = dotQ(p - a, n);
      closest = p - n * (h / nn);
      return h * h / nn;
    }
  }
  Q3 best;
  Quad bestSquared = pointSegmentSquared(p, a, b, best);
  Q3 candidate;
  Quad squared = pointSegmentSquared(p, b, c, candidate);
  if (squared < bestSquared)
  {
    bestSquared = squared;
    best = candidate;
  }
  squared = pointSegmentSquared(p, c, a, candidate);
  if (squared < bestSquared)
  {
    bestSquared = squared;
    best = candidate;
  }
  closest = best;
  return bestSquared;
}

// Squared distance between segments [p1, q1] and [p2, q2]: the stationary point of the convex
// quadratic when it lies inside the unit square, else the best of the four sides (each an
// endpoint against the other segment).
Quad segmentSegmentSquared(const Q3& p1, const Q3& q1, const Q3& p2, const Q3& q2)
{
  Q3 unused;
  Quad best = pointSegmentSquared(p1, p2, q2, unused);
  best = std::min(best, pointSegmentSquared(q1, p2, q2, unused));
  best = std::min(best, pointSegmentSquared(p2, p1, q1, unused));
  best = std::min(best, pointSegmentSquared(q2, p1, q1, unused));
  const Q3 d1 = q1 - p1;
  const Q3 d2 = q2 - p2;
  const Q3 r = p1 - p2;
  const Quad a = dotQ(d1, d1);
  const Quad e = dotQ(d2, d2);
  const Quad b = dotQ(d1, d2);
  const Quad c = dotQ(d1, r);
  const Quad f = dotQ(d2, r);
  const Quad denominator = a * e - b * b;
  if (denominator > 0)
  {
    const Quad s = (b * f - c * e) / denominator;
    const Quad t = (a * f - b * c) / denominator;
    if (s > 0 && s < 1 && t > 0 && t < 1)
    {
      const Q3 d = (p1 + d1 * s) - (p2 + d2 * t);
      best = std::min(best, dotQ(d, d));
    }
  }
  return best;
}

Point toPoint(const Vec3& v)
{
  return Point(v.x, v.y, v.z);
}

// Bounding boxes as the AABB tree's primitives: overlap of two boxes of doubles is decided
// exactly, so a box query never misses a triangle, zero-area ones included.
struct BoxMap
{
  using key_type = std::uint32_t;
  using value_type = Cuboid;
  using reference = const Cuboid&;
  using category = boost::readable_property_map_tag;
  const std::vector<Cuboid>* boxes = nullptr;
  friend reference get(const BoxMap& map, key_type id) { return (*map.boxes)[id]; }
};

struct ReferencePointMap
{
  using key_type = std::uint32_t;
  using value_type = Point;
  using reference = Point;
  using category = boost::readable_property_map_tag;
  const std::vector<Cuboid>* boxes = nullptr;
  friend reference get(const ReferencePointMap& map, key_type id) { return (*map.boxes)[id].min(); }
};

using Primitive =
  CGAL::AABB_primitive<std::uint32_t, BoxMap, ReferencePointMap, CGAL::Tag_false, CGAL::Tag_false>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;

CGAL::Bbox_3 paddedBox(const Vec3& lower, const Vec3& upper, double pad)
{
  // The pad covers the rounding of lower - pad and upper + pad themselves.
  const double slack = pad * 1e-12 + 1e-15 * (maxAbsComponent(lower) + maxAbsComponent(upper));
  const double p = pad + slack;
  return CGAL::Bbox_3(lower.x - p, lower.y - p, lower.z - p, upper.x + p, upper.y + p, upper.z + p);
}
} // namespace

std::string str(double value)
{
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string str(const Vec3& v)
{
  // One snprintf, not "{" + std::string: GCC 12 warns falsely (-Wrestrict) on that concatenation.
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "{%.17g, %.17g, %.17g}", v.x, v.y, v.z);
  return buffer;
}

Vec3 projectOntoCone(const Vec3& v, const Vec3* normals, int count)
{
  // min |x - v|^2 = x.x - 2 v.x + const; CGAL takes 2D (here 2I) and c = -2v.
  CGAL::Quadratic_program<double> program(CGAL::LARGER, false, 0.0, false, 0.0);
  for (int i = 0; i < count; ++i)
  {
    program.set_a(0, i, normals[i].x);
    program.set_a(1, i, normals[i].y);
    program.set_a(2, i, normals[i].z);
    program.set_b(i, 0.0);
  }
  for (int j = 0; j < 3; ++j)
  {
    program.set_d(j, j, 2.0);
    program.set_c(j, -2.0 * v[j]);
  }
  // Full exact Dantzig pricing: CGAL 5.5's default (partial filtered) pricing fails a
  // precondition (and crashes with NDEBUG) on some one-constraint programs, e.g. v nearly
  // opposite to n: v = {-0.013689695822515193, 0.013689695822515195, 0.013689695822515193},
  // n = {0.57735026918962573, -0.57735026918962573, -0.57735026918962573}.
  CGAL::Quadratic_program_options options;
  options.set_pricing_strategy(CGAL::QP_DANTZIG);
  const auto solution = CGAL::solve_quadratic_program(program, CGAL::Gmpzf(), options);
  if (!solution.is_optimal())
  {
    // The cone always holds 0 and the objective is strictly convex: this cannot happen.
    return Vec3{std::nan(""), std::nan(""), std::nan("")};
  }
  Vec3 x;
  auto value = solution.variable_values_begin();
  for (int j = 0; j < 3; ++j, ++value)
  {
    x[j] = CGAL::to_double(*value);
  }
  return x;
}

struct MeshOracle::Impl
{
  std::vector<TriangleCorners> triangles;
  std::vector<Cuboid> boxes;
  Tree tree;
  Vec3 lower;
  Vec3 upper;
  double diagonal = 0.0;

  void build()
  {
    boxes.reserve(triangles.size());
    Aabb all;
    for (const TriangleCorners& t : triangles)
    {
      const Vec3 lo = componentMin(componentMin(t.a, t.b), t.c);
      const Vec3 hi = componentMax(componentMax(t.a, t.b), t.c);
      boxes.emplace_back(Point(lo.x, lo.y, lo.z), Point(hi.x, hi.y, hi.z));
      all.expand(lo);
      all.expand(hi);
    }
    lower = all.lower;
    upper = all.upper;
    diagonal = all.diagonal();
    BoxMap boxMap{&boxes};
    ReferencePointMap pointMap{&boxes};
    tree.insert(
      boost::counting_iterator<std::uint32_t>(0),
      boost::counting_iterator<std::uint32_t>(static_cast<std::uint32_t>(triangles.size())), boxMap,
      pointMap);
    tree.build();
  }

  void candidates(const CGAL::Bbox_3& box, std::vector<std::uint32_t>& out) const
  {
    out.clear();
    tree.all_intersected_primitives(box, std::back_inserter(out));
  }
};

MeshOracle::MeshOracle(const TriangleMesh& mesh)
  : MeshOracle([&mesh] {
    std::vector<TriangleCorners> corners;
    corners.reserve(mesh.numTriangles());
    for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
    {
      corners.push_back(mesh.corners(t));
    }
    return corners;
  }())
{}

MeshOracle::MeshOracle(std::vector<TriangleCorners> triangles)
  : m_impl(std::make_unique<Impl>())
{
  m_impl->triangles = std::move(triangles);
  m_impl->build();
}

MeshOracle::MeshOracle(const CollisionScene& scene)
  : m_impl(std::make_unique<Impl>())
{
  for (const CollisionObject& object : scene.objects)
  {
    for (std::uint32_t t = 0; t < object.mesh.numTriangles(); ++t)
    {
      m_impl->triangles.push_back(object.mesh.corners(t));
    }
  }
  m_impl->build();
}

MeshOracle::~MeshOracle() = default;

std::size_t MeshOracle::numTriangles() const
{
  return m_impl->triangles.size();
}
Aabb MeshOracle::bounds() const
{
  Aabb box;
  box.expand(m_impl->lower);
  box.expand(m_impl->upper);
  return box;
}
double MeshOracle::diagonal() const
{
  return m_impl->diagonal;
}

double MeshOracle::pointTriangleDistance(const Vec3& p, const TriangleCorners& t, Vec3* closest,
                                         Vec3* away)
{
  Q3 nearest;
  const Quad squared =
    pointTriangleSquared(Q3{}, local(t.a, p), local(t.b, p), local(t.c, p), nearest);
  if (closest != nullptr)
  {
    *closest = toWorld(nearest, p);
  }
  if (away != nullptr)
  {
    *away = toVec(Q3{} - nearest);
  }
  return std::sqrt(static_cast<double>(squared));
}

bool MeshOracle::segmentTouchesTriangle(const Vec3& a, const Vec3& b, const TriangleCorners& t)
{
  const Point pa = toPoint(a);
  const Point pb = toPoint(b);
  const Point p0 = toPoint(t.a);
  const Point p1 = toPoint(t.b);
  const Point p2 = toPoint(t.c);
  const Kernel::Segment_3 path(pa, pb);
  auto pathTouchesEdge = [&](const Point& e0, const Point& e1) {
    if (e0 == e1)
    {
      return pa == pb ? pa == e0 : path.has_on(e0);
    }
    const Kernel::Segment_3 edge(e0, e1);
    return pa == pb ? edge.has_on(pa) : CGAL::do_intersect(path, edge);
  };
  if (CGAL::collinear(p0, p1, p2))
  {
    // Zero area: the triangle is its edges (CGAL's triangle tests require a proper triangle).
    return pathTouchesEdge(p0, p1) || pathTouchesEdge(p1, p2) || pathTouchesEdge(p2, p0);
  }
  const Kernel::Triangle_3 triangle(p0, p1, p2);
  if (pa == pb)
  {
    return triangle.has_on(pa);
  }
  return CGAL::do_intersect(path, triangle);
}

double MeshOracle::segmentTriangleDistance(const Vec3& a, const Vec3& b, const TriangleCorners& t)
{
  if (segmentTouchesTriangle(a, b, t))
  {
    return 0.0;
  }
  // Apart, the nearest pair has a segment end point or a point of a triangle edge in it: with
  // both inside, the segment would be parallel to the plane and could slide to one of those.
  const Q3 qa{};
  const Q3 qb = local(b, a);
  const Q3 c0 = local(t.a, a);
  const Q3 c1 = local(t.b, a);
  const Q3 c2 = local(t.c, a);
  Q3 unused;
  Quad best = pointTriangleSquared(qa, c0, c1, c2, unused);
  best = std::min(best, pointTriangleSquared(qb, c0, c1, c2, unused));
  best = std::min(best, segmentSegmentSquared(qa, qb, c0, c1));
  best = std::min(best, segmentSegmentSquared(qa, qb, c1, c2));
  best = std::min(best, segmentSegmentSquared(qa, qb, c2, c0));
  return std::sqrt(static_cast<double>(best));
}

double MeshOracle::distance(const Vec3& p, double cap) const
{
  const Impl& m = *m_impl;
  std::vector<std::uint32_t> ids;
  // Grow the search box until a triangle inside it is nearer than its half-size (any nearer
  // triangle would have had to overlap the box), or until it holds the whole scene.
  const double sceneReach = norm(componentMax(m.upper - p, p - m.lower)) + m.diagonal;
  double reach = std::isfinite(cap) ? cap : std::max(m.diagonal / 64.0, 1e-6);
  for (;;)
  {
    m.candidates(paddedBox(p, p, reach), ids);
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t id : ids)
    {
      best = std::min(best, pointTriangleDistance(p, m.triangles[id], nullptr));
    }
    if (best <= reach)
    {
      return std::min(best, cap);
    }
    if (reach >= cap || reach > sceneReach)
    {
      return cap;
    }
    reach = std::min(reach * 4.0, cap);
  }
}

namespace
{
// Pieces of [a, b] no longer than `piece` (at least one): a long segment is searched box by box,
// so that only triangles near it are ever tested, not every triangle in its bounding box.
int numPieces(const Vec3& a, const Vec3& b, double piece)
{
  const double length = distance(a, b);
  if (!(piece > 0.0) || !(length > piece))
  {
    return 1;
  }
  return static_cast<int>(std::min(std::ceil(length / piece), 1e6));
}
Vec3 along(const Vec3& a, const Vec3& b, int i, int n)
{
  return i == n ? b : a + (b - a) * (static_cast<double>(i) / n);
}
// More than the rounding of along(): the pieces' boxes, padded by it, cover the segment exactly.
double splitSlack(const Vec3& a, const Vec3& b)
{
  return 1e-15 * (maxAbsComponent(a) + maxAbsComponent(b) + distance(a, b));
}
} // namespace

double MeshOracle::segmentDistance(const Vec3& a, const Vec3& b, double cap) const
{
  const Impl& m = *m_impl;
  std::vector<std::uint32_t> ids;
  if (std::isfinite(cap))
  {
    // Every triangle within cap of the segment overlaps the padded box of some piece; each one
    // found is measured against the whole segment.
    const int n = numPieces(a, b, 4.0 * cap);
    double best = cap;
    for (int i = 0; i < n; ++i)
    {
      const Vec3 p = along(a, b, i, n);
      const Vec3 q = along(a, b, i + 1, n);
      m.candidates(paddedBox(componentMin(p, q), componentMax(p, q), cap + splitSlack(a, b)), ids);
      for (std::uint32_t id : ids)
      {
        best = std::min(best, segmentTriangleDistance(a, b, m.triangles[id]));
        if (best == 0.0)
        {
          return 0.0;
        }
      }
    }
    return best;
  }
  const double sceneReach =
    norm(componentMax(m.upper - componentMin(a, b), componentMax(a, b) - m.lower)) + m.diagonal;
  double reach = std::max(m.diagonal / 64.0, 1e-6);
  for (;;)
  {
    const double found = segmentDistance(a, b, reach);
    if (found < reach || reach > sceneReach)
    {
      return found;
    }
    reach *= 4.0;
  }
}

bool MeshOracle::segmentClearOf(const Vec3& a, const Vec3& b, double reach) const
{
  // The end points first: cheap, and usually decisive (a finger inside the object).
  if (distance(a, reach) < reach || distance(b, reach) < reach)
  {
    return false;
  }
  const Impl& m = *m_impl;
  std::vector<std::uint32_t> ids;
  const int n = numPieces(a, b, 4.0 * reach);
  for (int i = 0; i < n; ++i)
  {
    const Vec3 p = along(a, b, i, n);
    const Vec3 q = along(a, b, i + 1, n);
    m.candidates(paddedBox(componentMin(p, q), componentMax(p, q), reach + splitSlack(a, b)), ids);
    for (std::uint32_t id : ids)
    {
      if (segmentTriangleDistance(a, b, m.triangles[id]) < reach)
      {
        return false;
      }
    }
  }
  return true;
}

bool MeshOracle::segmentTouchesAny(const Vec3& a, const Vec3& b) const
{
  const Impl& m = *m_impl;
  std::vector<std::uint32_t> ids;
  // Pieces of about a thousandth of the scene; the padding of each box covers the rounding of the
  // split points, and each candidate is tested exactly against the whole segment.
  const int n = numPieces(a, b, std::max(m.diagonal * 1e-3, 1e-9));
  for (int i = 0; i < n; ++i)
  {
    const Vec3 p = along(a, b, i, n);
    const Vec3 q = along(a, b, i + 1, n);
    m.candidates(paddedBox(componentMin(p, q), componentMax(p, q), splitSlack(a, b)), ids);
    for (std::uint32_t id : ids)
    {
      if (segmentTouchesTriangle(a, b, m.triangles[id]))
      {
        return true;
      }
    }
  }
  return false;
}

std::vector<MeshOracle::Near> MeshOracle::within(const Vec3& p, double radius) const
{
  const Impl& m = *m_impl;
  std::vector<std::uint32_t> ids;
  m.candidates(paddedBox(p, p, radius), ids);
  std::vector<Near> found;
  for (std::uint32_t id : ids)
  {
    Near near;
    near.triangle = id;
    near.distance = pointTriangleDistance(p, m.triangles[id], &near.closest, &near.away);
    if (near.distance <= radius)
    {
      found.push_back(near);
    }
  }
  return found;
}

OracleSettings OracleSettings::forScene(double diagonal, double skin)
{
  OracleSettings settings;
  settings.penetrationTolerance = std::max(1e-9, 1e-9 * diagonal);
  settings.gatherTolerance = settings.penetrationTolerance;
  // The solver's contacts reach radius + 2 skins; beyond 4 skins a triangle is not touching.
  settings.freePathMargin = 4.0 * skin;
  return settings;
}

void InvariantStats::fail(std::uint64_t& counter, const std::string& message)
{
  ++counter;
  if (messages.size() < 12)
  {
    messages.push_back(message);
  }
}

std::string InvariantStats::summary(const std::string& name) const
{
  std::ostringstream out;
  out.precision(3);
  out << "[oracle] " << name << ": ticks " << ticks << ", contact ticks " << contactTicks
      << ", move segments " << moveSegments << ", residual checks " << residualChecks
      << ", free-path checks " << freePathChecks << "\n"
      << "[oracle] " << name << ": min clearance (d - r) " << minClearance
      << " m, min sweep clearance " << minSweepClearance << " m, max residual " << maxResidual
      << " m (remaining slide " << maxSlide << " m), max gap " << maxGap
      << " m, max free-path error " << maxFreePathError << " m, max force error " << maxForceError
      << " (relative), max replay discrepancy " << maxReplayDiscrepancy << " m\n"
      << "[oracle] " << name << ": max iterations " << maxIterations << ", iteration-cap ticks "
      << capTicks << ", budget-limited ticks " << budgetLimitedTicks << ", overflow ticks "
      << overflowTicks << ", refused ticks " << refusedTicks
      << " (uncapped they converge in <= " << maxUncappedIterations << " iterations, ending up to "
      << maxCapLag << " m from the capped end; non-terminating " << nonTerminating << ")"
      << ", failures " << failures() << " (penetration " << penetrations << ", crossing "
      << crossings << ", tunnel " << tunnels << ", free path " << freePathFailures << ", residual "
      << residualFailures << ", gap " << gapFailures << ", force " << forceFailures << ", coverage "
      << coverageFailures << ", refusal " << refusalFailures << ", replay " << replayFailures
      << ", approach " << approachFailures << ", non-terminating " << nonTerminating << ", settle "
      << settleFailures << "; limited up to " << maxRestingLimitedTick << " ticks into a rest)\n";
  // One row per case for the tables of the closing note: grep '^\[table\]'.
  out << "[table] | " << name << " | " << ticks << " | " << minClearance << " | "
      << minSweepClearance << " | " << maxResidual << " | " << maxGap << " | " << maxFreePathError
      << " | " << maxIterations << " | " << capTicks << " | " << maxCapLag << " | " << failures()
      << " |\n";
  for (const std::string& message : messages)
  {
    out << "[oracle] " << name << ": FAIL " << message << "\n";
  }
  for (const std::string& note : notes)
  {
    out << "[oracle] " << name << ": note " << note << "\n";
  }
  return out.str();
}

void checkServoForce(InvariantStats& stats, const std::string& where, const ForceTick& tick,
                     double stiffness, double maxForce)
{
  const Vec3& force = tick.force;
  if (!std::isfinite(force.x) || !std::isfinite(force.y) || !std::isfinite(force.z))
  {
    stats.fail(stats.forceFailures, where + ": force is not finite");
    return;
  }
  if (tick.refused)
  {
    if (force != tick.previousForce)
    {
      stats.fail(stats.forceFailures, where + ": refused tick did not hold the force");
    }
    return;
  }
  // In long double, whose exponent reaches 1e4932: the spring and its magnitude for a finger
  // 1e300 m away are exact enough there, where in double |F|^2 overflows.
  const long double k = stiffness;
  const long double fx = (static_cast<long double>(tick.proxy.x) - tick.finger.x) * k;
  const long double fy = (static_cast<long double>(tick.proxy.y) - tick.finger.y) * k;
  const long double fz = (static_cast<long double>(tick.proxy.z) - tick.finger.z) * k;
  const long double longMagnitude = std::sqrt(fx * fx + fy * fy + fz * fz);
  const double limit = maxForce * (1.0 + 1e-12);
  if (tick.ramped || (tick.inContact && !tick.knownStiffness))
  {
    // Bounded by the clamp, and (unramped) along the spring.
    const long double along = fx * force.x + fy * force.y + fz * force.z;
    if (norm(force) > limit || (!tick.ramped && along < 0.0L))
    {
      stats.fail(stats.forceFailures, where + ": force " + str(force) + " is beyond the clamp " +
                                        str(maxForce) + " N or against kp (proxy - finger)");
    }
    return;
  }
  const bool clamp = longMagnitude > maxForce;
  const long double gain = clamp ? maxForce / longMagnitude : 1.0L;
  const Vec3 expected{static_cast<double>(fx * gain), static_cast<double>(fy * gain),
                      static_cast<double>(fz * gain)};
  const double magnitude = static_cast<double>(longMagnitude);
  const double error = norm(force - expected) / std::max(norm(expected), 1e-300);
  stats.maxForceError = std::max(stats.maxForceError, magnitude > 0.0 ? error : 0.0);
  if (clamp != tick.clamped || (magnitude > 0.0 && error > 1e-12) ||
      (magnitude == 0.0 && force != Vec3{}))
  {
    stats.fail(stats.forceFailures,
               where + ": force " + str(force) + (tick.clamped ? " (clamped)" : "") +
                 " but kp (proxy - finger) gives " + str(expected) + (clamp ? " (clamped)" : ""));
  }
}

TickChecker::TickChecker(const MeshOracle& oracle, const CollisionScene& scene,
                         const ProxyParameters& parameters, const OracleSettings& settings)
  : m_oracle(oracle)
  , m_scene(scene)
  , m_parameters(parameters)
  , m_settings(settings)
  , m_replay(std::make_unique<ProxySolver>())
  , m_moveRecord(std::make_unique<MoveRecord>(kMaxRecordedPoints))
{}

void TickChecker::reset(const Vec3& proxy)
{
  m_proxy = proxy;
  m_restingTicks = 0;
  m_hasRestingFinger = false;
}

void TickChecker::check(std::uint64_t tick, const Vec3& finger, const ProxyTickResult& result)
{
  check(tick, finger, result.proxy, result.iterations, result.numContacts,
        result.conditions.has(TickCondition::fingerRefused),
        result.conditions.has(TickCondition::hitIterationCap),
        result.conditions.has(TickCondition::contactOverflow),
        result.conditions.has(TickCondition::budgetLimited));
}

double TickChecker::residual(const Vec3& proxy, const Vec3& finger, double* slide) const
{
  const Vec3 v = finger - proxy;
  const double length = norm(v);
  const std::vector<MeshOracle::Near> near =
    m_oracle.within(proxy, m_parameters.radius + m_settings.gatherTolerance);
  std::vector<Vec3> normals;
  for (const MeshOracle::Near& n : near)
  {
    // The oracle's own normal: from its closest point to the proxy (in 128 bits, then rounded).
    const Vec3 away = n.away;
    const Vec3 unit = normalizedOrZero(away);
    if (unit == Vec3{})
    {
      continue; // the centre on a triangle: the penetration check reports it
    }
    if (std::find(normals.begin(), normals.end(), unit) == normals.end())
    {
      normals.push_back(unit);
    }
  }
  bool inside = true;
  for (const Vec3& n : normals)
  {
    inside = inside && dot(n, v) >= 0.0;
  }
  if (inside)
  {
    if (slide != nullptr)
    {
      *slide = length;
    }
    return length; // nothing blocks the straight step: the whole distance could be gained
  }
  const Vec3 x = projectOntoCone(v, normals.data(), static_cast<int>(normals.size()));
  if (slide != nullptr)
  {
    *slide = norm(x);
  }
  return length - norm(v - x);
}

Vec3 TickChecker::sought(const Vec3& finger) const
{
  // The solver's documented reach (ProxySolver::reachRadius): 16 (M + max(diagonal, r)) about the
  // centre of the scene's box, computed here from the oracle's own triangles, in long double.
  const Aabb box = m_oracle.bounds();
  const long double largest = std::max(maxAbsComponent(box.lower), maxAbsComponent(box.upper));
  const long double reach =
    16.0L * (largest + std::max<long double>(m_oracle.diagonal(), m_parameters.radius));
  const Vec3 center = box.center();
  long double d[3];
  long double scale = 0.0L;
  for (int i = 0; i < 3; ++i)
  {
    d[i] = static_cast<long double>(finger[i]) - center[i];
    scale = std::max(scale, std::fabs(d[i]));
  }
  if (!(scale > 0.0L) || !std::isfinite(static_cast<double>(scale)))
  {
    return finger;
  }
  long double squared = 0.0L;
  for (long double& c : d)
  {
    c /= scale;
    squared += c * c;
  }
  const long double length = scale * std::sqrt(squared);
  if (length <= reach)
  {
    return finger;
  }
  Vec3 at;
  for (int i = 0; i < 3; ++i)
  {
    at[i] = static_cast<double>(center[i] + d[i] * (reach / std::sqrt(squared)));
  }
  return at;
}

void TickChecker::check(std::uint64_t tick, const Vec3& requestedFinger, const Vec3& proxy,
                        int iterations, int contacts, bool refused, bool hitCap, bool overflow,
                        bool budgetLimited)
{
  InvariantStats& s = m_stats;
  const double radius = m_parameters.radius;
  const Vec3 before = m_proxy;
  auto where = [&]() {
    return "tick " + std::to_string(tick) + " (reproduce: resetProxy(" + str(before) +
           "), update(" + str(requestedFinger) + "))";
  };
  // A finger beyond the solver's reach is sought at the reach, in its direction; the invariants
  // are about that point.
  const Vec3 finger = refused ? requestedFinger : sought(requestedFinger);
  ++s.ticks;
  s.contactTicks += contacts > 0 ? 1 : 0;
  s.capTicks += hitCap ? 1 : 0;
  s.budgetLimitedTicks += budgetLimited ? 1 : 0;
  // (h) Budgeted ticks settle: a finger at rest is reached within maxRestingLimitedTicks ticks.
  m_restingTicks =
    (m_hasRestingFinger && requestedFinger == m_restingFinger) ? m_restingTicks + 1 : 0;
  m_restingFinger = requestedFinger;
  m_hasRestingFinger = true;
  if (budgetLimited && m_restingTicks > 0)
  {
    s.maxRestingLimitedTick = std::max(s.maxRestingLimitedTick, m_restingTicks);
    if (m_restingTicks > static_cast<std::uint64_t>(m_settings.maxRestingLimitedTicks))
    {
      s.fail(s.settleFailures, "tick " + std::to_string(tick) + ": still budget-limited " +
                                 std::to_string(m_restingTicks) +
                                 " ticks after the finger came to rest at " + str(requestedFinger));
    }
  }
  s.overflowTicks += overflow ? 1 : 0;
  s.maxIterations = std::max(s.maxIterations, iterations);
  m_proxy = proxy;
  if (refused)
  {
    ++s.refusedTicks;
    if (proxy != before)
    {
      s.fail(s.refusalFailures, where() + ": finger refused but the proxy moved to " + str(proxy));
    }
    return;
  }

  // The chain of the tick's segments, as the solver recorded it replaying the tick from the
  // previous proxy: stopped by the cap where the live tick stopped (by the cap or its iteration
  // budget), with the live tick's iteration budget (its second half allows no stretched slides:
  // TickBudget::secondHalf) and without its time budget, which could stop the replay elsewhere.
  std::vector<MovePoint> points{MovePoint{before, MovePointKind::Accepted}};
  if (iterations >= 1)
  {
    ProxyParameters capped = m_parameters;
    capped.tickBudgetSeconds = 0.0;
    capped.maxIterations = iterations;
    m_replay->setScene(&m_scene, capped);
    m_replay->resetProxy(before);
    m_replay->recordMoves(m_moveRecord.get());
    const ProxyTickResult step = m_replay->update(requestedFinger);
    m_replay->recordMoves(nullptr);
    if (m_moveRecord->overflowed)
    {
      s.fail(s.replayFailures,
             where() + ": the tick moved along more segments than the record holds");
    }
    points.assign(m_moveRecord->points.begin() + 1,
                  m_moveRecord->points.begin() + static_cast<std::ptrdiff_t>(m_moveRecord->count));
    points.insert(points.begin(), MovePoint{before, MovePointKind::Accepted});
    // The replay starts cold; the live solver may answer from its temporal-coherence cache,
    // which agrees with the trees as a set but not to the bit: allow section 4's accuracy.
    const double discrepancy = distance(step.proxy, proxy);
    s.maxReplayDiscrepancy = std::max(s.maxReplayDiscrepancy, discrepancy);
    if (iterations >= 2 && discrepancy > m_settings.penetrationTolerance)
    {
      s.fail(s.replayFailures, where() + ": replayed from a fresh solver the tick ends at " +
                                 str(step.proxy) + " instead of " + str(proxy));
    }
    // The chain ends where the live tick ended (a replay that made no move, from a start the live
    // tick left, ends on a segment of its own: the oracle must see that jump too).
    if (points.size() == 1)
    {
      points.push_back(MovePoint{proxy, MovePointKind::Accepted});
    }
    else
    {
      points.back().position = proxy;
    }
  }
  else
  {
    points.push_back(MovePoint{proxy, MovePointKind::Accepted});
  }
  if (iterations == 0 && proxy != before)
  {
    s.fail(s.replayFailures, where() + ": no move stage but the proxy moved");
  }

  // (g') The approach along the chain: at every accepted point (the tick's start, the end of a
  // plain slide, the end of a retrace) the finger is no farther than at the accepted point before
  // it; only a curvature-stretched trial, or the move that judged it and the walk back from it,
  // may leave the finger for a moment. The tick ends on an accepted point.
  double acceptedDistance = distance(before, finger);
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    if (points[k].kind != MovePointKind::Accepted)
    {
      continue;
    }
    const double d = distance(points[k].position, finger);
    if (d > acceptedDistance + m_settings.residualTolerance)
    {
      s.fail(s.approachFailures, where() + ": segment " + std::to_string(k) + " ends " +
                                   str(d - acceptedDistance) +
                                   " m farther from the finger than the accepted point before it");
    }
    acceptedDistance = std::min(acceptedDistance, d);
  }
  if (points.back().kind != MovePointKind::Accepted)
  {
    s.fail(s.approachFailures,
           where() + ": the tick ended on a stretched trial, not an accepted point");
  }

  // (b) No tunnelling: each move segment crosses no triangle and keeps its distance.
  const double cap = 2.0 * radius;
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    const Vec3& a = points[k - 1].position;
    const Vec3& b = points[k].position;
    if (a == b)
    {
      continue;
    }
    ++s.moveSegments;
    if (m_oracle.segmentTouchesAny(a, b))
    {
      s.fail(s.crossings, where() + ": move " + std::to_string(k) + " from " + str(a) + " to " +
                            str(b) + " crosses a triangle");
    }
    const double clearance = m_oracle.segmentDistance(a, b, cap) - radius;
    s.minSweepClearance = std::min(s.minSweepClearance, clearance);
    if (clearance < -m_settings.penetrationTolerance)
    {
      s.fail(s.tunnels, where() + ": move " + std::to_string(k) + " from " + str(a) + " to " +
                          str(b) + " passes " + str(-clearance) + " m inside the radius");
    }
  }

  // (g) Energy (paper section 8): without shading or texture a tick ends no farther from the
  // finger than it began. Per tick, not per move: the device only ever sees a tick's end, and a
  // slide stretched over a curved edge may leave the finger briefly before falling nearer.
  if (distance(proxy, finger) > distance(before, finger) + m_settings.residualTolerance)
  {
    s.fail(s.approachFailures, where() + ": the tick ended " +
                                 str(distance(proxy, finger) - distance(before, finger)) +
                                 " m farther from the finger than it began");
  }

  // (a) No penetration at the end of the tick.
  const double clearance = m_oracle.distance(proxy, cap) - radius;
  s.minClearance = std::min(s.minClearance, clearance);
  if (clearance < -m_settings.penetrationTolerance)
  {
    s.fail(s.penetrations,
           where() + ": proxy " + str(proxy) + " is " + str(-clearance) + " m inside the radius");
  }

  // (f) Contact gap: an active plane means a triangle at the radius, not beyond it.
  if (contacts > 0)
  {
    s.maxGap = std::max(s.maxGap, clearance);
    if (clearance > m_settings.gapTolerance)
    {
      s.fail(s.gapFailures, where() + ": " + std::to_string(contacts) +
                              " contacts reported but the nearest triangle is " + str(clearance) +
                              " m beyond the radius");
    }
  }

  if (!budgetLimited)
  {
    checkEnd(where(), proxy, finger, iterations);
  }
  if (hitCap)
  {
    // Why the cap was hit: too few iterations for a slow (zig-zag) convergence, or a loop that
    // never settles. Replayed without the cap from the same start.
    ProxyParameters uncapped = m_parameters;
    uncapped.maxIterations = m_settings.uncappedIterations;
    uncapped.tickBudgetIterations = 0;
    uncapped.tickBudgetSeconds = 0.0;
    m_replay->setScene(&m_scene, uncapped);
    m_replay->resetProxy(before);
    const ProxyTickResult converged = m_replay->update(requestedFinger);
    const double lag = distance(converged.proxy, proxy);
    s.maxCapLag = std::max(s.maxCapLag, lag);
    if (converged.conditions.has(TickCondition::hitIterationCap))
    {
      s.fail(s.nonTerminating,
             where() + ": the move/update loop does not terminate (still moving " + "after " +
               std::to_string(converged.iterations) + " iterations; the capped tick ended " +
               str(lag) + " m from where the long run stopped)");
    }
    else
    {
      s.maxUncappedIterations = std::max(s.maxUncappedIterations, converged.iterations);
      if (s.notes.size() < 4)
      {
        s.notes.push_back(where() + ": iteration cap hit; converges in " +
                          std::to_string(converged.iterations) + " iterations, " + str(lag) +
                          " m from where the capped tick ended");
      }
    }
  }
}

void TickChecker::checkEnd(const std::string& where, const Vec3& proxy, const Vec3& finger,
                           int iterations)
{
  InvariantStats& s = m_stats;
  const double radius = m_parameters.radius;
  if (proxy == finger)
  {
    return;
  }
  // (c) Free path: where the straight sweep from proxy to finger touches nothing, the proxy
  // should have gone all the way.
  const double freeReach = radius + m_settings.freePathMargin;
  if (m_oracle.segmentClearOf(proxy, finger, freeReach))
  {
    ++s.freePathChecks;
    const double error = distance(proxy, finger);
    s.maxFreePathError = std::max(s.maxFreePathError, error);
    if (error > m_settings.freePathTolerance)
    {
      s.fail(s.freePathFailures, where + ": the path to the finger is free but the proxy " +
                                   "stopped " + str(error) + " m short at " + str(proxy));
    }
  }

  // (d) Local minimum: no feasible step along the oracle's own constraint planes gets nearer.
  if (distance(proxy, finger) > m_settings.residualTolerance)
  {
    ++s.residualChecks;
    double slide = 0.0;
    const double r = residual(proxy, finger, &slide);
    s.maxResidual = std::max(s.maxResidual, r);
    s.maxSlide = std::max(s.maxSlide, slide);
    if (!(r <= m_settings.residualTolerance))
    {
      const double gap = m_oracle.distance(proxy, 2.0 * radius) - radius;
      s.fail(s.residualFailures, where + ": not a local minimum: a feasible step gets " + str(r) +
                                   " m nearer the finger (proxy " + str(proxy) + " is " + str(gap) +
                                   " m beyond the radius from the mesh, iterations " +
                                   std::to_string(iterations) + ")");
    }
  }
}

} // namespace proxima::oracle
