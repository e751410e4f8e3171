// hapticStep: force on the finger = kp (proxy - finger), clamped to the device limit; a finger
// sample that is invalid or not finite is refused, the proxy held and the last force held
// (DESIGN.md section 6: never NaN into a force).
#include "Runtime/HapticStep.h"

#include "Runtime/ServoForce.h"

#include "Geometry/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace proxima
{
namespace
{
// A device that reports the samples it is given and records what it is told.
class FakeDevice final : public HapticDevice
{
public:
  DeviceSample next;
  std::vector<Vec3> forces;
  std::vector<double> readTimes;
  std::vector<double> writeTimes;

  DeviceSample read(double time) override
  {
    readTimes.push_back(time);
    return next;
  }
  void writeForce(const Vec3& force, double time) override
  {
    forces.push_back(force);
    writeTimes.push_back(time);
  }
};

class HapticStepTest : public testing::Test
{
protected:
  HapticStepTest()
  {
    TriangleMesh mesh;
    MeshError error;
    EXPECT_TRUE(mesh.build(makeGrid(0.2, 4, 0.0), error)) << error.message;
    scene.addObject(std::move(mesh));
    ProxyParameters parameters;
    parameters.radius = 0.001;
    solver = std::make_unique<ProxySolver>();
    solver->setScene(&scene, parameters);
    solver->resetProxy({0.0, 0.0, 0.01});
  }
  CollisionScene scene;
  std::unique_ptr<ProxySolver> solver;
  FakeDevice device;
};

// The scene's grid under `material`, and the state of a finger pressed to z = -2 mm at (x, 0)
// from a proxy dropped onto it (r = 1 mm, kp = 1000 N/m): a 3 mm stretch. `free`, when given, is
// the state of the tick before, with the finger 5 mm above the floor.
HapticState pressedAt(const CollisionScene& scene, double x, HapticState* free = nullptr)
{
  ProxyParameters parameters;
  parameters.radius = 0.001;
  ServoParameters servo;
  servo.stiffness = 1000.0;
  servo.maxForce = 100.0;
  ProxySolver solver;
  solver.setScene(&scene, parameters);
  solver.resetProxy({x, 0.0, 0.01});
  FakeDevice device;
  ServoForce stage(servo);
  device.next = DeviceSample{{x, 0.0, 0.005}, true};
  const HapticState before = hapticStep(0, 0.0, solver, device, stage);
  if (free != nullptr)
  {
    *free = before;
  }
  device.next = DeviceSample{{x, 0.0, -0.002}, true};
  return hapticStep(1, 0.001, solver, device, stage);
}

TEST(HapticStepStiffnessMap, StiffnessMapScalesTheSpringAtTheContact)
{
  // A grid with texture coordinates u = x / 0.2 + 1/2 and a stiffness map of 1 left of u = 1/2,
  // 0.5 right of it: pressing 3 mm under the proxy's plane gives kp * 3 mm on the left, half that
  // on the right, and nothing changes out of contact.
  TriangleSoup soup = makeGrid(0.2, 16, 0.0);
  for (const Vec3& p : soup.points)
  {
    soup.texCoords.push_back({p.x / 0.2 + 0.5, p.y / 0.2 + 0.5});
  }
  std::vector<float> values(64 * 2);
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 64; ++i)
    {
      values[j * 64 + i] = i < 32 ? 1.0f : 0.5f;
    }
  }
  SurfaceMaterial material;
  material.textures.push_back(TextureMap{
    std::make_shared<const TextureImage>(64, 2, std::move(values)), TextureRole::Stiffness, 0.0});
  CollisionScene scene;
  TriangleMesh mesh;
  MeshError error;
  ASSERT_TRUE(mesh.build(std::move(soup), error));
  scene.addObject(std::move(mesh), SphereTreeOptions{}, material);
  for (const double x : {-0.03, 0.03})
  {
    HapticState free;
    const HapticState pressed = pressedAt(scene, x, &free);
    EXPECT_EQ(norm(free.force), 0.0);
    const double scale = x < 0.0 ? 1.0 : 0.5;
    EXPECT_NEAR(pressed.force.z, 1000.0 * scale * 0.003, 1e-8) << "x " << x; // the skin: 1e-12 m
    EXPECT_NEAR(pressed.force.x, 0.0, 1e-12);
  }
}

TEST(HapticStepStiffnessMap, StiffnessRegionsScaleTheSpringWithASmoothFalloff)
{
  // A floor of softness 0.5 with a nodule under it: a region of scale 4 and radius 2 cm centred 5
  // mm below the floor at the origin. Pressing 3 mm, the force is kp 0.5 (1 + 3 s(1 - d / R))
  // 3 mm, with d the contact's distance from the centre and s(x) = x^2 (3 - 2x): checked at the
  // nodule, on its slope and beyond it.
  CollisionScene scene;
  TriangleMesh mesh;
  MeshError error;
  ASSERT_TRUE(mesh.build(makeGrid(0.2, 16, 0.0), error));
  SurfaceMaterial material;
  material.stiffness = 0.5;
  const StiffnessRegion nodule{{0.0, 0.0, -0.005}, 0.02, 4.0};
  material.stiffnessRegions.push_back(nodule);
  scene.addObject(std::move(mesh), SphereTreeOptions{}, material);
  for (const double x : {0.0, 0.01, 0.015, 0.03})
  {
    const HapticState pressed = pressedAt(scene, x);
    const double d = std::sqrt(x * x + 0.005 * 0.005);
    const double u = std::max(0.0, 1.0 - d / 0.02);
    const double scale = 0.5 * (1.0 + 3.0 * u * u * (3.0 - 2.0 * u));
    EXPECT_NEAR(pressed.stiffnessScale, scale, 1e-12) << "x " << x;
    EXPECT_NEAR(pressed.force.z, 1000.0 * scale * 0.003, 1e-8) << "x " << x;
  }
  // The region's edge: the factor is 1 there and its slope 0, so sliding across never steps the
  // force.
  EXPECT_EQ(stiffnessRegionScale(nodule, {0.02, 0.0, -0.005}), 1.0);
  // A tenth of a micrometre inside: x = 5e-6 of the way in, a factor of 1 + 3 x^2 (3 - 2x).
  const double x = 1.0 - 0.0199999 / 0.02;
  EXPECT_NEAR(stiffnessRegionScale(nodule, {0.0199999, 0.0, -0.005}),
              1.0 + 3.0 * x * x * (3.0 - 2.0 * x), 1e-15);
  EXPECT_LT(stiffnessRegionScale(nodule, {0.0199999, 0.0, -0.005}), 1.0 + 1e-9);
  EXPECT_EQ(stiffnessRegionScale(nodule, nodule.center), 4.0);
}

TEST_F(HapticStepTest, ForceIsStiffnessTimesProxyMinusFinger)
{
  ServoParameters servo;
  servo.stiffness = 750.0;
  servo.maxForce = 100.0;
  ServoForce stage(servo);
  device.next = DeviceSample{{0.002, -0.001, -0.004}, true};
  const HapticState r = hapticStep(7, 0.25, *solver, device, stage);
  EXPECT_EQ(r.tick, 7u);
  EXPECT_EQ(r.time, 0.25);
  EXPECT_EQ(r.finger, device.next.position);
  EXPECT_EQ(r.proxy, solver->proxy());
  EXPECT_GT(r.proxy.z, 0.0009);
  const Vec3 expected = (r.proxy - r.finger) * 750.0;
  EXPECT_NEAR(r.force.x, expected.x, 1e-15 * norm(expected));
  EXPECT_NEAR(r.force.y, expected.y, 1e-15 * norm(expected));
  EXPECT_NEAR(r.force.z, expected.z, 1e-15 * norm(expected));
  EXPECT_GT(r.force.z, 0.0); // pushes the finger out of the floor
  EXPECT_FALSE(r.conditions.has(TickCondition::forceClamped));
  EXPECT_FALSE(r.conditions.has(TickCondition::fingerRefused));
  EXPECT_EQ(r.numContacts, 1);
  EXPECT_GE(r.iterations, 1);
  EXPECT_GE(r.solveNanoseconds, 0);
  // The device got that force at that time, and the stage keeps it as its last force.
  ASSERT_EQ(device.forces.size(), 1u);
  EXPECT_EQ(device.forces[0], r.force);
  EXPECT_EQ(device.writeTimes[0], 0.25);
  EXPECT_EQ(device.readTimes[0], 0.25);
  EXPECT_EQ(stage.lastForce(), r.force);
}

TEST_F(HapticStepTest, FreeFingerGivesZeroForce)
{
  ServoParameters servo;
  ServoForce stage(servo);
  device.next = DeviceSample{{0.01, 0.02, 0.03}, true};
  const HapticState r = hapticStep(0, 0.0, *solver, device, stage);
  EXPECT_EQ(r.proxy, r.finger);
  EXPECT_EQ(r.force, Vec3{});
  EXPECT_EQ(r.numContacts, 0);
  EXPECT_EQ(stage.lastForce(), Vec3{});
}

TEST_F(HapticStepTest, ClampedToTheDeviceLimitKeepingDirection)
{
  ServoParameters servo;
  servo.stiffness = 5000.0;
  servo.maxForce = 3.0;
  ServoForce stage(servo);
  device.next = DeviceSample{{0.003, 0.0, -0.02}, true};
  const HapticState r = hapticStep(0, 0.0, *solver, device, stage);
  const Vec3 spring = (r.proxy - r.finger) * servo.stiffness;
  ASSERT_GT(norm(spring), servo.maxForce);
  EXPECT_TRUE(r.conditions.has(TickCondition::forceClamped));
  EXPECT_NEAR(norm(r.force), 3.0, 1e-14);
  EXPECT_NEAR(dot(normalizedOrZero(r.force), normalizedOrZero(spring)), 1.0, 1e-15);
  EXPECT_EQ(device.forces.back(), r.force);
}

TEST_F(HapticStepTest, NonFiniteFingerIsRefusedAndTheForceHeld)
{
  ServoParameters servo;
  ServoForce stage(servo);
  device.next = DeviceSample{{0.0, 0.0, -0.003}, true};
  const HapticState pressed = hapticStep(0, 0.0, *solver, device, stage);
  const Vec3 proxy = solver->proxy();
  ASSERT_NE(pressed.force, Vec3{});
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t tick = 1;
  for (const Vec3& bad : {Vec3{nan, 0, 0}, Vec3{0, inf, 0}, Vec3{0, 0, -inf}, Vec3{nan, nan, nan}})
  {
    device.next = DeviceSample{bad, true};
    const HapticState r = hapticStep(tick, tick * 0.001, *solver, device, stage);
    ++tick;
    EXPECT_TRUE(r.conditions.has(TickCondition::fingerRefused));
    EXPECT_EQ(r.force, pressed.force);
    EXPECT_EQ(device.forces.back(), pressed.force);
    EXPECT_EQ(stage.lastForce(), pressed.force);
    EXPECT_EQ(r.proxy, proxy);
    EXPECT_EQ(solver->proxy(), proxy);
    EXPECT_FALSE(r.conditions.has(TickCondition::forceClamped));
  }
  // An invalid sample (device read error) is refused the same way, whatever it holds.
  device.next = DeviceSample{{0.0, 0.0, -0.5}, false};
  const HapticState invalid = hapticStep(tick, tick * 0.001, *solver, device, stage);
  EXPECT_TRUE(invalid.conditions.has(TickCondition::fingerRefused));
  EXPECT_EQ(invalid.force, pressed.force);
  EXPECT_EQ(solver->proxy(), proxy);
  // A good sample again: the spring law resumes.
  device.next = DeviceSample{{0.001, 0.0, -0.003}, true};
  const HapticState again = hapticStep(tick + 1, 0.01, *solver, device, stage);
  EXPECT_FALSE(again.conditions.has(TickCondition::fingerRefused));
  const Vec3 expected = (again.proxy - again.finger) * servo.stiffness;
  EXPECT_NEAR(distance(again.force, expected), 0.0, 1e-15 * norm(expected));
}

} // namespace
} // namespace proxima
