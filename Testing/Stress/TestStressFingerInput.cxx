// Stress: what a device can send. Jumps of up to a metre in one tick (a dropped connection, a
// recalibration) into, through and around a scene of a sphere, a box and a thin sheet; finger
// samples that are NaN or infinite in one or all components (refused, the force held); and
// finite but absurd positions (1e30 .. 1e300 m), which must neither break the proxy nor give a
// non-finite force. Random with recorded seeds; the oracle watches every tick.
#include "StressSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "Paths/PathGenerators.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace proxima::stress
{
namespace
{
TriangleSoup jumpScene()
{
  return scenes::merge({makeIcosphere(3, 0.03), makeBox({0.02, 0.02, 0.02}, {0.1, 0, 0}),
                        scenes::translate(scenes::makeSheet(0.08), {-0.1, 0, 0})});
}

Aabb sceneBox()
{
  Aabb box;
  box.expand(Vec3{-0.15, -0.05, -0.05});
  box.expand(Vec3{0.15, 0.05, 0.05});
  return box;
}

TEST(StressFingerInput, JumpsOfAMetre)
{
  runCases(9000, 6, [&](Random& random, StressCase& c) {
    c.name = "jumps";
    c.proxy.radius = 0.001;
    c.soup = jumpScene();
    c.soup.pointNormals.clear();
    // Between slow wanders through the scene, the finger is somewhere up to a metre away for a
    // few ticks, then jumps back.
    c.path = randomWander(random, sceneBox(), 6, 0.2, c.rate);
    const auto ticks = static_cast<std::uint64_t>(c.path.size());
    for (int j = 0; j < 12; ++j)
    {
      const auto tick = static_cast<std::uint64_t>(random.integer(1, static_cast<int>(ticks) - 4));
      const Vec3 there = random.direction() * random.uniform(0.1, 1.0);
      for (std::uint64_t t = tick; t < tick + static_cast<std::uint64_t>(random.integer(1, 3)); ++t)
      {
        c.fingerOverrides[t] = there;
      }
    }
  });
}

TEST(StressFingerInput, NaNAndInfinityAreRefused)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  runCases(9100, 4, [&](Random& random, StressCase& c) {
    c.name = "nan-and-infinity";
    c.proxy.radius = 0.001;
    c.soup = jumpScene();
    c.soup.pointNormals.clear();
    c.path = randomWander(random, sceneBox(), 5, 0.2, c.rate);
    const auto ticks = static_cast<int>(c.path.size());
    const double bad[] = {nan, inf, -inf, -nan};
    for (int j = 0; j < 40; ++j)
    {
      const auto tick = static_cast<std::uint64_t>(random.integer(1, ticks - 1));
      std::size_t hint = 0;
      Vec3 finger =
        c.path.positionAt(c.path.startTime() + static_cast<double>(tick) / c.rate, hint);
      const double value = bad[random.integer(0, 3)];
      switch (random.integer(0, 3))
      {
        case 0: finger.x = value; break;
        case 1: finger.y = value; break;
        case 2: finger.z = value; break;
        default: finger = {value, value, value}; break;
      }
      c.fingerOverrides[tick] = finger;
    }
  });
}

// Finite but far beyond any device: the proxy heads off toward it (nothing is in the way, or the
// scene stops it) and must come back intact; forces stay finite and are clamped.
TEST(StressFingerInput, AbsurdlyFarFiniteFingers)
{
  runCases(9200, 4, [&](Random& random, StressCase& c) {
    c.name = "absurd-fingers";
    c.proxy.radius = 0.001;
    c.soup = jumpScene();
    c.soup.pointNormals.clear();
    c.path = randomWander(random, sceneBox(), 5, 0.2, c.rate);
    const auto ticks = static_cast<int>(c.path.size());
    for (int j = 0; j < 6; ++j)
    {
      const auto tick = static_cast<std::uint64_t>(random.integer(1, ticks - 1));
      c.fingerOverrides[tick] = random.direction() * random.logUniform(1e30, 1e300);
    }
  });
}

} // namespace
} // namespace proxima::stress
