// Texture (paper 4.3) against analytic oracles on a plane: a sinusoidal height map must tilt the
// force on the finger along the normal of the bumpy surface it stands for, n' ~ (-dh/dx, 0, 1),
// and a friction map must change the sliding ratio where the map says. The oracles are the
// height function and the map as the test wrote them, not the solver's numbers.
#include "Geometry/ProceduralMeshes.h"
#include "Proxy/ProxySolver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

namespace proxima
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;
constexpr double kRadius = 0.001;
constexpr double kSize = 0.2;
constexpr double kFingerZ = -0.002;

// The grid z = 0 with texture coordinates u = x / size + 1/2, v = y / size + 1/2.
TriangleSoup texturedGrid()
{
  TriangleSoup soup = makeGrid(kSize, 64);
  for (const Vec3& p : soup.points)
  {
    soup.texCoords.push_back({p.x / kSize + 0.5, p.y / kSize + 0.5});
  }
  return soup;
}

struct Plane
{
  CollisionScene scene;
  ProxySolver solver;

  explicit Plane(const SurfaceMaterial& material, TriangleSoup soup = texturedGrid())
  {
    TriangleMesh mesh;
    MeshError error;
    EXPECT_TRUE(mesh.build(std::move(soup), error)) << error.message;
    scene.addObject(std::move(mesh), SphereTreeOptions{}, material);
    ProxyParameters parameters;
    parameters.radius = kRadius;
    solver.setScene(&scene, parameters);
  }

  // Presses in at x = `x` from 5 mm above.
  void pressAt(double x)
  {
    solver.resetProxy({x, 0.0, 0.005});
    for (int i = 1; i <= 70; ++i)
    {
      solver.update({x, 0.0, 0.005 + (kFingerZ - 0.005) * i / 70.0});
    }
  }
};

// Height h(x) = amplitude * (1/2 + 1/2 sin(2 pi periods u)), sampled at texel centres.
constexpr int kTexels = 1024;
constexpr double kPeriods = 10.0;
constexpr double kAmplitude = 6e-4; // max slope amplitude * pi * periods / size = 0.094

std::shared_ptr<const TextureImage> sineImage()
{
  std::vector<float> values(kTexels * 2);
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < kTexels; ++i)
    {
      const double u = (i + 0.5) / kTexels;
      values[j * kTexels + i] = static_cast<float>(0.5 + 0.5 * std::sin(2.0 * kPi * kPeriods * u));
    }
  }
  return std::make_shared<const TextureImage>(kTexels, 2, std::move(values));
}

double heightSlope(double x)
{
  const double u = x / kSize + 0.5;
  return kAmplitude * 0.5 * 2.0 * kPi * kPeriods / kSize * std::cos(2.0 * kPi * kPeriods * u);
}

TEST(TextureBump, SinusoidalHeightMapTiltsTheForceLikeTheBumpySurface)
{
  SurfaceMaterial material;
  material.textures.push_back(TextureMap{sineImage(), TextureRole::Bump, kAmplitude});
  Plane plane(material);
  plane.pressAt(-0.03);
  double errorSum = 0.0;
  double maxError = 0.0;
  double tiltSum = 0.0;
  int ticks = 0;
  // Stroke 60 mm (three periods of the height) at 2 cm/s.
  for (int i = 1; i <= 3000; ++i)
  {
    const Vec3 finger{-0.03 + 0.00002 * i, 0.0, kFingerZ};
    const ProxyTickResult r = plane.solver.update(finger);
    ASSERT_GE(r.proxy.z, kRadius - 1e-12) << "tick " << i; // bumps never lift or sink the proxy
    const Vec3 force = r.proxy - finger;
    const Vec3 direction = force / norm(force);
    // The bumpy surface's normal under the proxy.
    const double slope = heightSlope(r.proxy.x);
    const Vec3 expected = Vec3{-slope, 0.0, 1.0} / std::sqrt(1.0 + slope * slope);
    const double error = std::acos(std::min(1.0, dot(direction, expected))) * kDegrees;
    errorSum += error;
    maxError = std::max(maxError, error);
    tiltSum += std::acos(std::min(1.0, direction.z)) * kDegrees;
    ++ticks;
    ASSERT_TRUE(r.usedShading);
  }
  std::cout << "[texture] bump: mean error " << errorSum / ticks << " deg, max " << maxError
            << " deg, mean tilt from the plane's normal " << tiltSum / ticks << " deg\n";
  EXPECT_GT(tiltSum / ticks, 2.5); // the flat plane alone would give 0
  EXPECT_LT(errorSum / ticks, 0.25);
  EXPECT_LT(maxError, 1.0);
}

TEST(TextureFriction, FrictionMapChangesTheSlidingRatioWhereItShould)
{
  // mu_d 0.4 scaled by 1 left of u = 0.5 (x < 0) and by 0.25 right of it (x > 0).
  std::vector<float> values(64 * 2);
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 64; ++i)
    {
      values[j * 64 + i] = i < 32 ? 1.0f : 0.25f;
    }
  }
  SurfaceMaterial material;
  material.dynamicFriction = 0.4;
  material.textures.push_back(TextureMap{
    std::make_shared<const TextureImage>(64, 2, std::move(values)), TextureRole::Friction, 0.0});
  Plane plane(material);
  plane.pressAt(-0.04);
  // The texel is 3.125 mm: the map blends between the texel centres at x = -1.6 and 1.6 mm.
  double worstLeft = 0.0;
  double worstRight = 0.0;
  int left = 0;
  int right = 0;
  Vec3 previous = plane.solver.proxy();
  for (int i = 1; i <= 4000; ++i)
  {
    const Vec3 finger{-0.04 + 0.00002 * i, 0.0, kFingerZ};
    const ProxyTickResult r = plane.solver.update(finger);
    const Vec3 spring = r.proxy - finger;
    const double ratio = std::hypot(spring.x, spring.y) / spring.z;
    if (r.proxy != previous && r.proxy.x < -0.002 && r.proxy.x > -0.035)
    {
      worstLeft = std::max(worstLeft, std::fabs(ratio / 0.4 - 1.0));
      ++left;
    }
    if (r.proxy != previous && r.proxy.x > 0.006)
    {
      worstRight = std::max(worstRight, std::fabs(ratio / 0.1 - 1.0));
      ++right;
    }
    previous = r.proxy;
  }
  std::cout << "[texture] friction map: " << left << " sliding ticks at mu 0.4 (worst relative "
            << worstLeft << "), " << right << " at mu 0.1 (worst " << worstRight << ")\n";
  EXPECT_GT(left, 1000);
  EXPECT_GT(right, 1000);
  EXPECT_LT(worstLeft, 0.01);
  EXPECT_LT(worstRight, 0.01);
}

TEST(TextureBump, MeshWithoutTextureCoordinatesTakesNoLookup)
{
  // The same bump map on the grid without texture coordinates: the plain algorithm, bit for bit.
  SurfaceMaterial bumpy;
  bumpy.textures.push_back(TextureMap{sineImage(), TextureRole::Bump, kAmplitude});
  Plane withMap(bumpy, makeGrid(kSize, 64));
  Plane plain(SurfaceMaterial{}, makeGrid(kSize, 64));
  withMap.pressAt(-0.03);
  plain.pressAt(-0.03);
  for (int i = 1; i <= 500; ++i)
  {
    const Vec3 finger{-0.03 + 0.00002 * i, 0.0, kFingerZ};
    const ProxyTickResult a = withMap.solver.update(finger);
    const ProxyTickResult b = plain.solver.update(finger);
    ASSERT_EQ(a.proxy, b.proxy) << "tick " << i;
    ASSERT_FALSE(a.usedShading);
  }
}

} // namespace
} // namespace proxima
