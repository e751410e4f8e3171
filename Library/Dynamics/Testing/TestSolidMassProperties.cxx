// Mass properties of closed meshes against the closed forms of a box and a sphere, far from the
// origin too, and the refusal of meshes that bound no solid.
#include "Dynamics/SolidMassProperties.h"
#include "Geometry/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace proxima
{
namespace
{
TriangleMesh meshOf(TriangleSoup soup)
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(std::move(soup), error));
  return mesh;
}

// `relative`: how far the box's corners, as doubles, may make its true size differ.
void expectBox(const Vec3& half, const Vec3& center, double density, double relative = 1e-12)
{
  const SolidMassProperties p = solidMassProperties(meshOf(makeBox(half, center)), density);
  const double volume = 8.0 * half.x * half.y * half.z;
  const double mass = density * volume;
  EXPECT_NEAR(p.volume, volume, relative * volume);
  EXPECT_NEAR(p.mass, mass, relative * mass);
  const double scale = norm(center) + norm(half);
  EXPECT_NEAR(p.centroid.x, center.x, 1e-12 * scale);
  EXPECT_NEAR(p.centroid.y, center.y, 1e-12 * scale);
  EXPECT_NEAR(p.centroid.z, center.z, 1e-12 * scale);
  // A box of sides 2a, 2b, 2c: Ixx = m (b^2 + c^2) / 3, no products of inertia.
  const double ixx = mass * (half.y * half.y + half.z * half.z) / 3.0;
  const double iyy = mass * (half.x * half.x + half.z * half.z) / 3.0;
  const double izz = mass * (half.x * half.x + half.y * half.y) / 3.0;
  const double tolerance = std::max(1e-9, 10.0 * relative) * (ixx + iyy + izz);
  EXPECT_NEAR(p.inertia[0], ixx, tolerance);
  EXPECT_NEAR(p.inertia[1], iyy, tolerance);
  EXPECT_NEAR(p.inertia[2], izz, tolerance);
  EXPECT_NEAR(p.inertia[3], 0.0, tolerance);
  EXPECT_NEAR(p.inertia[4], 0.0, tolerance);
  EXPECT_NEAR(p.inertia[5], 0.0, tolerance);
}

TEST(SolidMassProperties, BoxMatchesTheClosedForm)
{
  expectBox({0.01, 0.02, 0.1}, {0.0, 0.0, 0.0}, 1000.0);
  expectBox({0.3, 0.05, 0.2}, {0.1, -0.2, 0.05}, 7800.0);
}

TEST(SolidMassProperties, BoxFarFromTheOriginKeepsItsDigits)
{
  // A 2 cm part 1 km away: integrated about its own centre, not the world's. Its corners, as
  // doubles, are only good to 1.1e-13 m (the spacing of doubles near 1000) on 2 cm sides: the
  // box itself differs from the ideal one by up to about 2e-11 in volume. Integrated about the
  // world's origin instead, the products of 1 km coordinates miss it by 0.2 % (measured).
  expectBox({0.01, 0.01, 0.01}, {1000.0, -1000.0, 500.0}, 2700.0, 5e-11);
}

TEST(SolidMassProperties, IcosphereApproachesTheSphereFromInside)
{
  const double radius = 0.05;
  const SolidMassProperties p = solidMassProperties(meshOf(makeIcosphere(5, radius)), 1000.0);
  const double volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  // An inscribed polyhedron: a little less than the sphere, by about 0.2 % at 20480 faces.
  EXPECT_LT(p.volume, volume);
  EXPECT_GT(p.volume, 0.995 * volume);
  // Isotropic, with I = 2/5 m r^2 to the same order.
  const double expected = 0.4 * p.mass * radius * radius;
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_NEAR(p.inertia[axis], expected, 0.01 * expected);
  }
  EXPECT_NEAR(p.inertia[0], p.inertia[1], 1e-3 * expected);
  EXPECT_NEAR(p.inertia[3], 0.0, 1e-6 * expected);
}

TEST(SolidMassProperties, GivenMassIsSpreadThroughTheSolid)
{
  const TriangleMesh box = meshOf(makeBox({0.1, 0.1, 0.1}));
  const SolidMassProperties p = solidMassPropertiesWithMass(box, 2.0);
  EXPECT_NEAR(p.mass, 2.0, 1e-12);
  EXPECT_NEAR(p.inertia[0], 2.0 * 0.02 / 3.0, 1e-12);
}

TEST(SolidMassProperties, OpenOrInsideOutMeshesAreRefused)
{
  const TriangleMesh grid = meshOf(makeGrid(0.1, 4));
  EXPECT_NE(closedSolidDefect(grid).find("not closed"), std::string::npos)
    << closedSolidDefect(grid);
  EXPECT_THROW(solidMassProperties(grid, 1000.0), std::invalid_argument);

  TriangleSoup flipped = makeBox({0.1, 0.1, 0.1});
  for (auto& triangle : flipped.triangles)
  {
    std::swap(triangle[1], triangle[2]);
  }
  const TriangleMesh insideOut = meshOf(std::move(flipped));
  EXPECT_NE(closedSolidDefect(insideOut).find("inside out"), std::string::npos)
    << closedSolidDefect(insideOut);
  EXPECT_THROW(solidMassPropertiesWithMass(insideOut, 1.0), std::invalid_argument);
  EXPECT_THROW(solidMassProperties(meshOf(makeBox({0.1, 0.1, 0.1})), 0.0), std::invalid_argument);
}
} // namespace
} // namespace proxima
