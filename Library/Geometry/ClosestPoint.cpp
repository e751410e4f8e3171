#include "Geometry/ClosestPoint.h"

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
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return edgeResult(p, a, b, 0, 1, TriangleFeature::EdgeAB);
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp);
  const double d6 = dot(ac, cp);
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
  // Face region. The region tests above use cancelling products, so on slivers and degenerate
  // triangles they can send a point here that is not over the face; the projected weights are
  // then negative or undefined, and the nearest edge is the honest answer.
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
  // On a sliver (sine of the angle at a below 1e-6) the region tests lose digits and the
  // projection can land marginally off the true face; then an edge may be nearer. Fat triangles
  // skip this check, which keeps the common case to one projection.
  if (normalSquared < 1e-12 * dot(ab, ab) * dot(ac, ac))
  {
    const ClosestPointResult edge = nearestEdge(p, a, b, c);
    if (edge.squaredDistance < r.squaredDistance)
    {
      return edge;
    }
  }
  return r;
}

} // namespace proxima
