#include "Proxy/ProxyStart.h"

#include "Geometry/WindingNumber.h"

#include <cmath>
#include <limits>
#include <memory>

namespace proxima
{
namespace
{
/// The push grows by this factor each time a candidate is not free: small, so the point found
/// stays near the nearest free one; 200 tries reach 1e19 times the first push, past any scene.
constexpr double kPushGrowth = 1.25;
constexpr int kMaxPushes = 200;

/// The first object whose winding number at `point` says it holds the point, or -1.
int objectHolding(const CollisionScene& scene, const Vec3& point, double& winding)
{
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
  {
    const double w = windingNumber(scene.objects[i].mesh, point);
    if (isInsideByWindingNumber(w))
    {
      winding = w;
      return static_cast<int>(i);
    }
  }
  winding = 0.0;
  return -1;
}

/// No triangle of any object within `clearance` of `point`.
bool isClear(const CollisionScene& scene, const Vec3& point, double clearance,
             SphereTreeScratch& scratch)
{
  for (const CollisionObject& object : scene.objects)
  {
    if (object.tree.nearest(object.mesh, point, clearance, scratch).found)
    {
      return false;
    }
  }
  return true;
}

/// Out of the object at its surface point nearest `point`: from the point toward that surface
/// point, or, when the point is on the surface, the triangle's normal on the side the winding
/// number's sign says is outside (a positive number means outward-oriented triangles).
Vec3 outwardDirection(const TriangleMesh& mesh, const NearestTriangle& nearest, const Vec3& point,
                      double winding)
{
  const Vec3 toSurface = normalizedOrZero(nearest.closest.point - point);
  if (squaredNorm(toSurface) > 0.0)
  {
    return toSurface;
  }
  const TriangleCorners& corners = mesh.corners(nearest.triangle);
  const Vec3 normal = normalizedOrZero(cross(corners.b - corners.a, corners.c - corners.a));
  if (squaredNorm(normal) > 0.0)
  {
    return winding > 0.0 ? normal : -normal;
  }
  // A degenerate triangle under a point on the surface: any way out will do, the pushes go on
  // until the candidate is free and outside.
  return Vec3{0.0, 0.0, 1.0};
}
} // namespace

ProxyStartPlacement placeProxyStart(const CollisionScene& scene, const ProxyParameters& parameters,
                                    const Vec3& point)
{
  ProxyStartPlacement placement;
  placement.position = point;
  if (scene.objects.empty() || !isFinite(point))
  {
    return placement;
  }
  double winding = 0.0;
  const int holder = objectHolding(scene, point, winding);
  if (holder < 0)
  {
    return placement;
  }
  placement.object = holder;
  placement.windingNumber = winding;

  const double skin = resolveSkin(parameters, scene.diagonal(), scene.maxAbsCoordinate());
  const double radius = parameters.radius;
  // Free means clear of every triangle by the radius plus half the skin: a start in contact,
  // not in rounding's reach of the surface.
  const double clearance = radius + 0.5 * skin;
  // 32 KB of traversal scratch: on the heap, whatever thread publishes the scene.
  const auto scratch = std::make_unique<SphereTreeScratch>();
  const CollisionObject& object = scene.objects[static_cast<std::size_t>(holder)];
  const NearestTriangle nearest =
    object.tree.nearest(object.mesh, point, std::numeric_limits<double>::infinity(), *scratch);
  const Vec3 surface = nearest.found ? nearest.closest.point : point;
  const Vec3 outward =
    nearest.found ? outwardDirection(object.mesh, nearest, point, winding) : Vec3{0.0, 0.0, 1.0};

  double push = radius + skin;
  Vec3 candidate = surface + outward * push;
  for (int attempt = 0; attempt < kMaxPushes; ++attempt)
  {
    candidate = surface + outward * push;
    double ignored = 0.0;
    // The cheap tree query first: the O(n) winding numbers only for a candidate that is clear.
    if (isClear(scene, candidate, clearance, *scratch) &&
        objectHolding(scene, candidate, ignored) < 0)
    {
      break;
    }
    push *= kPushGrowth;
  }
  placement.position = candidate;
  placement.movedOutside = true;
  placement.movedDistance = distance(point, candidate);
  return placement;
}

} // namespace proxima
