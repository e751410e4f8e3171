// Where the proxy starts (ProxyStart.h): outside every closed object, clear of every triangle by
// the radius, near the surface point nearest the finger; checked with brute-force distances and
// winding numbers over all triangles, apart from the sphere trees the placement uses.
#include "Proxy/ProxyStart.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/ProceduralMeshes.h"
#include "Geometry/WindingNumber.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

namespace proxima
{
namespace
{
constexpr double kSphereRadius = 0.05;

TriangleMesh meshOf(TriangleSoup soup)
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(std::move(soup), error)) << error.message;
  return mesh;
}

double bruteForceDistance(const CollisionScene& scene, const Vec3& point)
{
  double best = 1e300;
  for (const CollisionObject& object : scene.objects)
  {
    for (std::uint32_t t = 0; t < object.mesh.numTriangles(); ++t)
    {
      const TriangleCorners& c = object.mesh.corners(t);
      best =
        std::min(best, std::sqrt(closestPointOnTriangle(point, c.a, c.b, c.c).squaredDistance));
    }
  }
  return best;
}

bool insideAny(const CollisionScene& scene, const Vec3& point)
{
  for (const CollisionObject& object : scene.objects)
  {
    if (isInsideByWindingNumber(windingNumber(object.mesh, point)))
    {
      return true;
    }
  }
  return false;
}

std::unique_ptr<CollisionScene> sphereScene()
{
  auto scene = std::make_unique<CollisionScene>();
  scene->addObject(meshOf(makeIcosphere(4, kSphereRadius)));
  return scene;
}

ProxyParameters parameters()
{
  ProxyParameters p;
  p.radius = 0.001;
  return p;
}

TEST(ProxyStart, FingerOutsideStartsAtTheFinger)
{
  const auto scene = sphereScene();
  const Vec3 finger{0.0, 0.0, 0.08};
  const ProxyStartPlacement placement = placeProxyStart(*scene, parameters(), finger);
  EXPECT_FALSE(placement.movedOutside);
  EXPECT_EQ(placement.object, -1);
  EXPECT_EQ(placement.position, finger);
  EXPECT_EQ(placement.movedDistance, 0.0);
}

TEST(ProxyStart, FingerAtTheCentreStartsJustOutsideTheNearestFace)
{
  const auto scene = sphereScene();
  const ProxyParameters p = parameters();
  const double skin = resolveSkin(p, scene->diagonal(), scene->maxAbsCoordinate());
  const ProxyStartPlacement placement = placeProxyStart(*scene, p, {});
  ASSERT_TRUE(placement.movedOutside);
  EXPECT_EQ(placement.object, 0);
  EXPECT_NEAR(placement.windingNumber, 1.0, 1e-9);
  EXPECT_FALSE(insideAny(*scene, placement.position));
  const double clearance = bruteForceDistance(*scene, placement.position);
  EXPECT_GE(clearance, p.radius);
  // The nearest free point: the nearest face's distance plus the radius and the skin (a convex
  // surface frees the first candidate).
  const double toSurface = bruteForceDistance(*scene, {});
  EXPECT_NEAR(placement.movedDistance, toSurface + p.radius + skin, 1e-12);
  EXPECT_NEAR(clearance, p.radius + skin, 1e-12);
}

TEST(ProxyStart, RandomPointsInsideASphereEndFreeAndNear)
{
  const auto scene = sphereScene();
  const ProxyParameters p = parameters();
  const double skin = resolveSkin(p, scene->diagonal(), scene->maxAbsCoordinate());
  std::mt19937 random(13u);
  std::uniform_real_distribution<double> coordinate(-kSphereRadius, kSphereRadius);
  int placed = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    const Vec3 finger{coordinate(random), coordinate(random), coordinate(random)};
    const bool inside = insideAny(*scene, finger);
    const ProxyStartPlacement placement = placeProxyStart(*scene, p, finger);
    EXPECT_EQ(placement.movedOutside, inside);
    if (!inside)
    {
      continue;
    }
    ++placed;
    EXPECT_FALSE(insideAny(*scene, placement.position));
    EXPECT_GE(bruteForceDistance(*scene, placement.position), p.radius);
    EXPECT_NEAR(placement.movedDistance, bruteForceDistance(*scene, finger) + p.radius + skin,
                1e-12);
  }
  EXPECT_GT(placed, 20);
}

TEST(ProxyStart, InsideOutOrientationMakesNoDifference)
{
  TriangleSoup soup = makeIcosphere(3, kSphereRadius);
  for (auto& t : soup.triangles)
  {
    std::swap(t[1], t[2]);
  }
  CollisionScene scene;
  scene.addObject(meshOf(std::move(soup)));
  const ProxyStartPlacement placement = placeProxyStart(scene, parameters(), {0.0, 0.01, 0.0});
  ASSERT_TRUE(placement.movedOutside);
  EXPECT_NEAR(placement.windingNumber, -1.0, 1e-9);
  EXPECT_FALSE(insideAny(scene, placement.position));
  EXPECT_GT(placement.position.y, kSphereRadius);
}

TEST(ProxyStart, PushesPastAnObjectJustOutsideTheSurface)
{
  // A slab right outside the sphere where the finger leaves it: the first candidate (surface plus
  // radius plus skin) is inside the slab, so the push goes on through it and out the other side.
  auto scene = sphereScene();
  scene->addObject(meshOf(makeBox({0.01, 0.03, 0.03}, {kSphereRadius + 0.0105, 0.0, 0.0})));
  const ProxyParameters p = parameters();
  const Vec3 finger{0.045, 0.0, 0.0};
  const ProxyStartPlacement placement = placeProxyStart(*scene, p, finger);
  ASSERT_TRUE(placement.movedOutside);
  EXPECT_EQ(placement.object, 0);
  EXPECT_FALSE(insideAny(*scene, placement.position));
  EXPECT_GE(bruteForceDistance(*scene, placement.position), p.radius);
  EXPECT_GT(placement.position.x, kSphereRadius + 0.0205 + p.radius);
  // Along the way out, not somewhere else: the slab's far side is 0.021 m past the surface, and
  // each push is 1.25 times the last.
  EXPECT_LT(placement.position.x, kSphereRadius + 1.25 * (0.0205 + p.radius) + 0.001);
  // The nearest face's normal is a few degrees off the x axis.
  EXPECT_LT(std::abs(placement.position.y), 0.1 * placement.position.x);
  EXPECT_LT(std::abs(placement.position.z), 0.1 * placement.position.x);
}

TEST(ProxyStart, HollowShellsAndNestedObjects)
{
  // A finger between two concentric spheres (a hollow ball made of two outward meshes): the
  // outer one holds it and its surface is the way out, although the inner one is nearer.
  CollisionScene scene;
  scene.addObject(meshOf(makeIcosphere(4, kSphereRadius)));
  scene.addObject(meshOf(makeIcosphere(3, 0.03)));
  const ProxyParameters p = parameters();
  const Vec3 finger{0.0, 0.0, 0.032};
  const ProxyStartPlacement placement = placeProxyStart(scene, p, finger);
  ASSERT_TRUE(placement.movedOutside);
  EXPECT_EQ(placement.object, 0);
  EXPECT_FALSE(insideAny(scene, placement.position));
  EXPECT_GE(bruteForceDistance(scene, placement.position), p.radius);
  EXPECT_GT(placement.position.z, kSphereRadius);
  // Inside the inner sphere too (winding 2 in all): the same way out.
  const ProxyStartPlacement deeper = placeProxyStart(scene, p, {0.0, 0.0, 0.01});
  ASSERT_TRUE(deeper.movedOutside);
  EXPECT_FALSE(insideAny(scene, deeper.position));
  EXPECT_GE(bruteForceDistance(scene, deeper.position), p.radius);
}

TEST(ProxyStart, AFingerInAnOpenCornerIsNotMoved)
{
  // A floor and two walls facing the free octant: a finger in front of them is in free space,
  // though the walls wind most of a turn around it (backwards).
  const double s = 0.02;
  TriangleSoup corner;
  corner.points = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}, {s, 0, s}};
  corner.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 6}, {0, 6, 1}};
  CollisionScene scene;
  scene.addObject(meshOf(std::move(corner)));
  const ProxyStartPlacement placement = placeProxyStart(scene, parameters(), {0.008, 0.008, 0.008});
  EXPECT_FALSE(placement.movedOutside);
  EXPECT_EQ(placement.position, (Vec3{0.008, 0.008, 0.008}));
}

TEST(ProxyStart, NotFiniteOrEmptyIsLeftAlone)
{
  const auto scene = sphereScene();
  const Vec3 nan{std::nan(""), 0.0, 0.0};
  EXPECT_FALSE(placeProxyStart(*scene, parameters(), nan).movedOutside);
  const CollisionScene empty;
  EXPECT_FALSE(placeProxyStart(empty, parameters(), {}).movedOutside);
}

TEST(ProxyStart, TheSolverReportsTheMovedStartOnItsNextUpdateOnly)
{
  const auto scene = sphereScene();
  ProxySolver solver;
  solver.setScene(scene.get(), parameters());
  const ProxyStartPlacement placement = placeProxyStart(*scene, parameters(), {});
  resetProxyTo(solver, placement);
  EXPECT_EQ(solver.proxy(), placement.position);
  EXPECT_TRUE(solver.update({}).conditions.has(TickCondition::startedOutside));
  EXPECT_FALSE(solver.update({}).conditions.has(TickCondition::startedOutside));
  // The proxy stayed outside with the finger at the centre: it is not trapped, it is pressing.
  EXPECT_FALSE(insideAny(*scene, solver.proxy()));
  // A plain reset reports nothing.
  solver.resetProxy({0.0, 0.0, 0.09});
  EXPECT_FALSE(solver.update({0.0, 0.0, 0.09}).conditions.has(TickCondition::startedOutside));
}

} // namespace
} // namespace proxima
