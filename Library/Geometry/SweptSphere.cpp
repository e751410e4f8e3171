#include "Geometry/SweptSphere.h"

#include "Geometry/ClosestPoint.h"

#include <cmath>

namespace proxima
{
namespace
{
// Smallest root of a t^2 + 2 b t + c = 0 where the path enters a round surface from outside
// (c > 0) while approaching it (b < 0); the form c / (-b + sqrt) avoids cancellation.
bool enterQuadratic(double a, double b, double c, double& t)
{
  if (!(b < 0.0) || !(a > 0.0))
  {
    return false;
  }
  if (c <= 0.0)
  {
    // Already inside, which the caller's closest point ruled out: only rounding disagrees (of
    // order epsilon times the coordinates, 1e-12 at 1e4). Moving in, the entry is now; refusing
    // it let a sphere stopped on an edge pass through the triangle on its next sweep.
    t = 0.0;
    return true;
  }
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0)
  {
    return false;
  }
  t = c / (-b + std::sqrt(discriminant));
  return true;
}

void keepEarliest(double candidate, SweepResult& best)
{
  if (candidate >= 0.0 && candidate <= best.t)
  {
    best.t = candidate;
    best.hit = true;
  }
}

// Entry of the segment into the triangle swept by a sphere of `radius`, for a start that lies
// outside it.
SweepResult sweepFromOutside(const Vec3& start, const Vec3& motion, double radius,
                             const TriangleCorners& tri)
{
  SweepResult best;
  best.t = 1.0;
  const Vec3 corners[3] = {tri.a, tri.b, tri.c};

  // Faces: the two planes offset by radius along the normal; entry counts where it projects
  // inside the triangle (the rims between faces and edges are entered through the cylinders).
  const Vec3 ab = tri.b - tri.a;
  const Vec3 ac = tri.c - tri.a;
  const Vec3 normal = cross(ab, ac);
  const double normalLength = norm(normal);
  if (normalLength > 0.0)
  {
    const Vec3 n = normal / normalLength;
    const double height = dot(start - tri.a, n);
    const double speed = dot(motion, n);
    const double side = height >= 0.0 ? 1.0 : -1.0;
    // The caller knows the start is outside the swept body; a start a rounding error inside the
    // offset plane is on it (clearance 0), or the face crossing would go unseen.
    const double clearance = std::fmax(height * side - radius, 0.0);
    const double approach = -speed * side;
    if (approach > 0.0 && clearance <= approach)
    {
      const double t = clearance / approach;
      const Vec3 onPlane = start + motion * t - n * (side * radius);
      // Inside test by edge-normal signs: robust for any winding and exact on the edges.
      const Vec3 p = onPlane;
      const bool inside = dot(cross(tri.b - tri.a, p - tri.a), normal) >= 0.0 &&
                          dot(cross(tri.c - tri.b, p - tri.b), normal) >= 0.0 &&
                          dot(cross(tri.a - tri.c, p - tri.c), normal) >= 0.0;
      if (inside)
      {
        // A point of the offset face over the triangle lies on the boundary of the swept body,
        // and a segment enters a convex body once: this is the entry, nothing can come earlier.
        best.hit = true;
        best.t = t;
        return best;
      }
    }
    // The whole segment stays more than radius from the triangle's plane on one side: no hit.
    const double endHeight = height + speed;
    if ((height > radius && endHeight > radius) || (height < -radius && endHeight < -radius))
    {
      return best;
    }
  }

  // Edges: infinite cylinders of radius about each edge line, entered between the end caps.
  for (int i = 0; i < 3; ++i)
  {
    const Vec3& from = corners[i];
    const Vec3& to = corners[(i + 1) % 3];
    const Vec3 edge = to - from;
    const double edgeSquared = dot(edge, edge);
    if (!(edgeSquared > 0.0))
    {
      continue;
    }
    const Vec3 m = start - from;
    const Vec3 mCross = cross(m, edge);
    const Vec3 dCross = cross(motion, edge);
    double t = 0.0;
    if (enterQuadratic(dot(dCross, dCross), dot(mCross, dCross),
                       dot(mCross, mCross) - radius * radius * edgeSquared, t) &&
        t <= best.t)
    {
      const double along = dot(m + motion * t, edge);
      if (along >= 0.0 && along <= edgeSquared)
      {
        keepEarliest(t, best);
      }
    }
  }

  // Corners: spheres of radius about each vertex.
  for (const Vec3& corner : corners)
  {
    const Vec3 m = start - corner;
    double t = 0.0;
    if (enterQuadratic(dot(motion, motion), dot(m, motion), dot(m, m) - radius * radius, t))
    {
      keepEarliest(t, best);
    }
  }
  if (!best.hit)
  {
    best.t = 1.0;
  }
  return best;
}

// The steepest heading (motion into the triangle over motion length) that a sweep starting in
// touching contact lets through: the goal solver's feasibility tolerance.
constexpr double kTouchingSlope = 1e-12;
} // namespace

SweepResult sweepSphereTriangle(const Vec3& start, const Vec3& motion, double radius,
                                const TriangleCorners& triangle)
{
  return sweepSphereTriangleWithSkin(start, motion, radius, 0.0, triangle);
}

namespace
{
// The contact rule of sweepSphereTriangleWithSkin; `closestToStart` gives the triangle's closest
// point to the start (closestPointOnTriangle), asked for only when the plane does not settle it.
template <typename ClosestToStart>
SweepResult sweepWithSkin(const Vec3& start, const Vec3& motion, double radius, double skin,
                          const TriangleCorners& triangle, const ClosestToStart& closestToStart)
{
  const double freshRadius = radius + skin;
  // The distance to the plane bounds the distance to the triangle from below: a start farther
  // than radius + 1.5 skin from the plane is a fresh contact, and needs no closest point.
  const Vec3 normal = cross(triangle.b - triangle.a, triangle.c - triangle.a);
  const double normalSquared = dot(normal, normal);
  if (normalSquared > 0.0)
  {
    const double height = dot(start - triangle.a, normal);
    const double limit = radius + 1.5 * skin;
    if (height * height > limit * limit * normalSquared)
    {
      return sweepFromOutside(start, motion, freshRadius, triangle);
    }
  }
  const KnownClosestPoint closest = closestToStart();
  const double startDistance = std::sqrt(closest.squaredDistance);
  double contactRadius = freshRadius;
  if (startDistance < radius + 1.5 * skin)
  {
    contactRadius = std::fmax(radius, startDistance - 0.5 * skin);
  }
  if (startDistance <= contactRadius)
  {
    // Already touching: only motion that approaches the triangle is blocked, at once. A centre
    // exactly on the triangle has no away direction, so any motion is blocked there.
    SweepResult result;
    const Vec3 away = start - closest.point;
    // A slide along the touching triangle's plane approaches it by rounding (~1e-16 of the
    // slide): with the start at the radius (or a rounding inside it, as on the crossing line of
    // two sheets at 8e-11 rad, stress seed 4009) that blocked every slide there. Only a heading
    // steeper than kTouchingSlope into the triangle counts, and only down to r - skin/2: a slide
    // that crosses by at most 1e-12 of its length, while the goal solver keeps every slide above
    // every plane to that same tolerance, cannot creep below that floor tick after tick. The exact
    // query (skin 0) keeps the strict rule.
    const double slack = skin > 0.0 && startDistance >= radius - 0.5 * skin
                           ? kTouchingSlope * std::sqrt(dot(motion, motion)) * startDistance
                           : 0.0;
    const bool approaching =
      startDistance > 0.0 ? dot(motion, away) < -slack : dot(motion, motion) > 0.0;
    result.hit = approaching;
    result.t = approaching ? 0.0 : 1.0;
    return result;
  }
  // The distance from a point moving on a line to a triangle (a convex set) is convex along
  // the line: a motion that does not approach the closest point at the start never comes nearer
  // than the start, which is outside the contact radius. Sliding past a neighbour of the surface
  // under the proxy is this case (the shortcut took 6 % of the solver's instructions off the
  // shared probe paths).
  if (dot(motion, start - closest.point) >= 0.0)
  {
    return SweepResult{};
  }
  return sweepFromOutside(start, motion, contactRadius, triangle);
}
} // namespace

SweepResult sweepSphereTriangleWithSkin(const Vec3& start, const Vec3& motion, double radius,
                                        double skin, const TriangleCorners& triangle)
{
  return sweepWithSkin(start, motion, radius, skin, triangle, [&] {
    const ClosestPointResult closest =
      closestPointOnTriangle(start, triangle.a, triangle.b, triangle.c);
    return KnownClosestPoint{closest.point, closest.squaredDistance};
  });
}

SweepResult sweepSphereTriangleWithSkin(const Vec3& start, const Vec3& motion, double radius,
                                        double skin, const TriangleCorners& triangle,
                                        const KnownClosestPoint& closestToStart)
{
  return sweepWithSkin(start, motion, radius, skin, triangle, [&] { return closestToStart; });
}

} // namespace proxima
