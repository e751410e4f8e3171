// Static, dynamic and viscous friction (paper 4.1 and 4.2) against analytic oracles on a plane:
// the friction cone |f_t| <= mu |f_n| and the steady sliding of eq. 21, computed from the finger
// path and the plane's geometry, not from the solver's numbers. Forces are kp (proxy - finger).
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
constexpr double kRadius = 0.001;
constexpr double kStiffness = 1000.0;
constexpr double kTimeStep = 0.001;
// The finger 2 mm under the plane z = 0: 3 mm under the proxy's plane z = r, so |f_n| = 3 N.
constexpr double kFingerZ = -0.002;
constexpr double kDepth = kRadius - kFingerZ;

class FrictionRig
{
public:
  explicit FrictionRig(const SurfaceMaterial& material)
  {
    TriangleMesh mesh;
    MeshError error;
    EXPECT_TRUE(mesh.build(makeGrid(0.2, 16), error)) << error.message;
    m_scene.addObject(std::move(mesh), SphereTreeOptions{}, material);
    ProxyParameters parameters;
    parameters.radius = kRadius;
    parameters.stiffness = kStiffness;
    parameters.timeStep = kTimeStep;
    m_solver.setScene(&m_scene, parameters);
    m_solver.resetProxy({0.0, 0.0, 0.005});
    // Press straight down at the origin.
    for (int i = 1; i <= 70; ++i)
    {
      step({0.0, 0.0, 0.005 + (kFingerZ - 0.005) * i / 70.0});
    }
  }

  ProxyTickResult step(const Vec3& finger)
  {
    const ProxyTickResult r = m_solver.update(finger);
    // The plane is z = 0: the proxy's centre never comes nearer than the radius.
    EXPECT_GE(r.proxy.z, kRadius - 1e-12);
    return r;
  }
  const Vec3& proxy() const { return m_solver.proxy(); }

private:
  CollisionScene m_scene;
  ProxySolver m_solver;
};

// Tangential over normal force on the finger, from positions: the plane's normal is +z.
double forceRatio(const Vec3& proxy, const Vec3& finger)
{
  const Vec3 spring = proxy - finger;
  return std::hypot(spring.x, spring.y) / spring.z;
}

TEST(StaticFriction, ProxyHoldsInsideTheConeAndSlipsOutside)
{
  SurfaceMaterial material;
  material.staticFriction = 0.5;
  FrictionRig rig(material);
  const Vec3 rest = rig.proxy();
  EXPECT_NEAR(rest.z, kRadius, 1e-11);
  // Inside the cone: tangential offset up to mu_s * depth = 1.5 mm, in any direction.
  for (int i = 1; i <= 140; ++i)
  {
    const double angle = 0.1 * i;
    const double offset = 0.0014 * i / 140.0;
    const ProxyTickResult r =
      rig.step({offset * std::cos(angle), offset * std::sin(angle), kFingerZ});
    ASSERT_EQ(r.proxy, rest) << "tick " << i << ": the proxy moved inside the friction cone";
    ASSERT_TRUE(r.conditions.has(TickCondition::stuck));
  }
  // Out of the cone (1.6 mm > 1.5 mm): it slips, and without dynamic friction all the way.
  const Vec3 out{0.0016, 0.0, kFingerZ};
  const ProxyTickResult r = rig.step(out);
  EXPECT_FALSE(r.conditions.has(TickCondition::stuck));
  EXPECT_NEAR(r.proxy.x, out.x, 1e-9);
  EXPECT_NEAR(r.proxy.y, 0.0, 1e-9);
}

TEST(DynamicFriction, SlidingForceRatioIsMuD)
{
  SurfaceMaterial material;
  material.dynamicFriction = 0.3;
  FrictionRig rig(material);
  // Stroke along x at 5 cm/s (0.05 mm a tick).
  int sliding = 0;
  double worst = 0.0;
  Vec3 previous = rig.proxy();
  for (int i = 1; i <= 600; ++i)
  {
    const Vec3 finger{0.00005 * i, 0.0, kFingerZ};
    const ProxyTickResult r = rig.step(finger);
    if (r.proxy != previous)
    {
      ++sliding;
      worst = std::max(worst, std::fabs(forceRatio(r.proxy, finger) / 0.3 - 1.0));
    }
    else
    {
      // Not sliding: the finger must still be inside the dynamic cone.
      EXPECT_LE(forceRatio(r.proxy, finger), 0.3 * (1.0 + 1e-9)) << "tick " << i;
    }
    previous = r.proxy;
  }
  std::cout << "[friction] dynamic: " << sliding << " sliding ticks, worst |ratio / mu_d - 1| "
            << worst << "\n";
  // The lag builds up to mu_d * depth = 0.9 mm in 18 ticks, then every tick slides.
  EXPECT_GE(sliding, 570);
  EXPECT_LT(worst, 0.01);
}

TEST(ViscousFriction, SpeedBoundAndSteadyLag)
{
  SurfaceMaterial material;
  material.dynamicFriction = 0.2;
  material.viscosity = 5.0; // N s / m
  FrictionRig rig(material);
  const double speed = 0.05;
  Vec3 finger;
  double worstExcess = 0.0;
  for (int i = 1; i <= 1500; ++i)
  {
    const Vec3 before = rig.proxy();
    finger = Vec3{speed * kTimeStep * i, 0.0, kFingerZ};
    // Eq. 21: the speed along the surface is at most (|f_t| - mu_d |f_n|) / b at the tick's start.
    const double tangential = kStiffness * std::hypot(finger.x - before.x, finger.y - before.y);
    const double normal = kStiffness * (before.z - finger.z);
    const double bound = std::max(0.0, (tangential - 0.2 * normal) / 5.0) * kTimeStep;
    const ProxyTickResult r = rig.step(finger);
    worstExcess = std::max(worstExcess, distance(r.proxy, before) - bound);
  }
  EXPECT_LE(worstExcess, 1e-12);
  // Steady sliding at the finger's speed: kp (lag - mu_d depth) / b = speed, with the lag taken
  // at the tick's start, after the finger's step; the tick's slide of speed * dt leaves the lag
  // at its end that much shorter.
  const double lag = finger.x - rig.proxy().x;
  const double expected = 0.2 * kDepth + 5.0 * speed / kStiffness - speed * kTimeStep;
  std::cout << "[friction] viscous: steady lag " << lag << " m, expected " << expected << " m\n";
  EXPECT_NEAR(lag, expected, 0.01 * expected);
}

TEST(Friction, StickThenSlipWithStaticAboveDynamic)
{
  // mu_s 0.6 > mu_d 0.3: it holds until the finger leaves the static cone (1.8 mm), slips back
  // to the dynamic cone (0.9 mm behind the finger) and holds again while the finger rests.
  SurfaceMaterial material;
  material.staticFriction = 0.6;
  material.dynamicFriction = 0.3;
  FrictionRig rig(material);
  const Vec3 rest = rig.proxy();
  ProxyTickResult r = rig.step({0.0017, 0.0, kFingerZ});
  EXPECT_EQ(r.proxy, rest);
  r = rig.step({0.0019, 0.0, kFingerZ});
  EXPECT_FALSE(r.conditions.has(TickCondition::stuck));
  EXPECT_NEAR(0.0019 - r.proxy.x, 0.3 * kDepth, 1e-9);
  const Vec3 slipped = r.proxy;
  for (int i = 0; i < 10; ++i)
  {
    EXPECT_EQ(rig.step({0.0019, 0.0, kFingerZ}).proxy, slipped);
  }
}

TEST(Friction, SurfaceWithoutFrictionTakesNoFrictionTest)
{
  FrictionRig rig{SurfaceMaterial{}};
  const ProxyTickResult r = rig.step({0.001, 0.0, kFingerZ});
  EXPECT_FALSE(r.conditions.has(TickCondition::stuck));
  EXPECT_FALSE(r.conditions.has(TickCondition::frictionLimited));
  EXPECT_NEAR(r.proxy.x, 0.001, 1e-12);
}

} // namespace
} // namespace proxima
