#include "Geometry/ClosestPoint.h"

#include <cmath>

namespace proxima
{
namespace
{
ClosestPointResult vertexResult(const Vec3& p, const Vec3& v, int which)
{
  ClosestPointResult r;
  r.point = v;
  r.weights[0] = which == 0 ? 1.0 : 0.0;
  r.weights[1] = which == 1 ? 1.0 : 0.0;
  r.weights[2] = which == 2 ? 1.0 : 0.0;
  r.squaredDistance = squaredDistance(p, v);
  r.feature = static_cast<TriangleFeature>(which);
  return r;
}

// Closest point on edge (from, to) whose corners are triangle corners i and j.
ClosestPointResult edgeResult(const Vec3& p, const Vec3& from, const Vec3& to, int i, int j,
                              TriangleFeature edge)
{
  const double s = closestParameterOnSegment(p, from, to);
  if (s <= 0.0)
  {
    return vertexResult(p, from, i);
  }
  if (s >= 1.0)
  {
    return vertexResult(p, to, j);
  }
  ClosestPointResult r;
  r.point = from + (to - from) * s;
  r.weights[0] = r.weights[1] = r.weights[2] = 0.0;
  r.weights[i] = 1.0 - s;
  r.weights[j] = s;
  r.squaredDistance = squaredDistance(p, r.point);
  r.feature = edge;
  return r;
}

ClosestPointResult nearestEdge(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  ClosestPointResult best = edgeResult(p, a, b, 0, 1, TriangleFeature::EdgeAB);
  const ClosestPointResult bc = edgeResult(p, b, c, 1, 2, TriangleFeature::EdgeBC);
  if (bc.squaredDistance < best.squaredDistance)
  {
    best = bc;
  }
  const ClosestPointResult ca = edgeResult(p, c, a, 2, 0, TriangleFeature::EdgeCA);
  if (ca.squaredDistance < best.squaredDistance)
  {
    best = ca;
  }
  return best;
}

// Thin and zero-area triangles. Ericson's region tests and weights cancel catastrophically when
// the triangle is thin (errors grow like epsilon / sin^2 of its smallest angle: a corner 1e-6 off
// the opposite edge gave points 1e-7 off the triangle and weights that missed the point by 1e-3),
// and with coincident corners they pick a zero-length edge. Here everything is measured in the
// frame of the longest edge: the normal is made orthogonal to that edge to working precision, so
// its remaining error only turns the plane about the edge, which moves a thin triangle by about
// epsilon times its length; the apex weight is a height ratio and the other two an abscissa along
// the edge, which reproduce the point to the same accuracy. Outside the face the nearest edge is
// the answer.
ClosestPointResult closestOnThinTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 corners[3] = {a, b, c};
  int i = 0; // the longest edge runs from corner i to corner j; k is the apex
  double longestSquared = squaredDistance(a, b);
  if (squaredDistance(b, c) > longestSquared)
  {
    longestSquared = squaredDistance(b, c);
    i = 1;
  }
  if (squaredDistance(c, a) > longestSquared)
  {
    longestSquared = squaredDistance(c, a);
    i = 2;
  }
  const int j = (i + 1) % 3;
  const int k = (i + 2) % 3;
  const Vec3& from = corners[i];
  const Vec3 edge = corners[j] - from;
  const Vec3 toApex = corners[k] - from;
  const double edgeSquared = dot(edge, edge);
  Vec3 normal = cross(edge, toApex);
  if (!(edgeSquared > 0.0))
  {
    return nearestEdge(p, a, b, c);
  }
  normal -= edge * (dot(normal, edge) / edgeSquared);
  const double normalSquared = dot(normal, normal);
  const Vec3 inPlane = cross(normal, edge); // perpendicular to the edge, toward the apex
  const double apexHeight = dot(toApex, inPlane);
  if (!(normalSquared > 0.0) || !(apexHeight > 0.0))
  {
    return nearestEdge(p, a, b, c);
  }
  const Vec3 foot = p - normal * (dot(p - from, normal) / normalSquared);
  const Vec3 fromFoot = foot - from;
  const double wk = dot(fromFoot, inPlane) / apexHeight;
  const double wj = dot(fromFoot - toApex * wk, edge) / edgeSquared;
  const double wi = 1.0 - wj - wk;
  if (!(wi >= 0.0 && wj >= 0.0 && wk >= 0.0))
  {
    return nearestEdge(p, a, b, c);
  }
  ClosestPointResult r;
  r.point = foot;
  r.weights[i] = wi;
  r.weights[j] = wj;
  r.weights[k] = wk;
  r.squaredDistance = squaredDistance(p, foot);
  r.feature = TriangleFeature::Face;
  return r;
}

// A triangle is thin when twice its area is below sqrt(kThinSquared) times its longest edge
// squared (its altitude over that edge under about 3% of the edge). Above this the region tests
// below lose at most about 1e3 epsilon of the triangle's size.
constexpr double kThinSquared = 1e-3;
} // namespace

double closestParameterOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double lengthSquared = dot(ab, ab);
  if (!(lengthSquared > 0.0))
  {
    return 0.0;
  }
  const double s = dot(p - a, ab) / lengthSquared;
  return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
}

ClosestPointResult closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c)
{
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 ap = p - a;
  const double d1 = dot(ab, ap);
  const double d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return vertexResult(p, a, 0);
  }
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp);
  const double d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return vertexResult(p, b, 1);
  }
  // The two corner tests above hold for any triangle, degenerate ones included (p is on the far
  // side of both edge directions from the corner). The edge and face tests below do not: route
  // thin and zero-area triangles to the robust routine first. Twice the area squared from the
  // Gram determinant cancels on thin triangles, which only blurs the threshold.
  const double abab = dot(ab, ab);
  const double acac = dot(ac, ac);
  const double abac = dot(ab, ac);
  const double longestSquared = std::fmax(std::fmax(abab, acac), abab + acac - 2.0 * abac);
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp);
  const double d6 = dot(ac, cp);
  if (!(abab * acac - abac * abac >= kThinSquared * longestSquared * longestSquared))
  {
    // Corner c's test holds for any triangle, like a's and b's: at the apex of a fan of CAD
    // slivers, where a proxy touches hundreds of them, most answers are a corner.
    if (d6 >= 0.0 && d5 <= d6)
    {
      return vertexResult(p, c, 2);
    }
    return closestOnThinTriangle(p, a, b, c);
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return edgeResult(p, a, b, 0, 1, TriangleFeature::EdgeAB);
  }
  if (d6 >= 0.0 && d5 <= d6)
  {
    return vertexResult(p, c, 2);
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return edgeResult(p, c, a, 2, 0, TriangleFeature::EdgeCA);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    return edgeResult(p, b, c, 1, 2, TriangleFeature::EdgeBC);
  }
  // Face region. Rounding can still send a point here that is marginally off the face; the
  // projected weights are then negative, and the nearest edge is the honest answer.
  const double denominator = va + vb + vc;
  const Vec3 normal = cross(ab, ac);
  const double normalSquared = dot(normal, normal);
  if (!(denominator > 0.0) || !(normalSquared > 0.0))
  {
    return nearestEdge(p, a, b, c);
  }
  const double v = vb / denominator;
  const double w = vc / denominator;
  const double u = 1.0 - v - w;
  if (!(u >= 0.0 && v >= 0.0 && w >= 0.0))
  {
    return nearestEdge(p, a, b, c);
  }
  // Project along the face normal for the point itself: more accurate than summing the weighted
  // corners when the triangle is large and p is close to it.
  ClosestPointResult r;
  r.point = p - normal * (dot(ap, normal) / normalSquared);
  r.weights[0] = u;
  r.weights[1] = v;
  r.weights[2] = w;
  r.squaredDistance = squaredDistance(p, r.point);
  r.feature = TriangleFeature::Face;
  return r;
}

} // namespace proxima
