// HapticSession (Runtime/HapticSession.h), the library's small public way in, against answers
// worked out by hand: a finger pressed into a flat floor (the proxy rests a radius above it, the
// force is the spring kp (proxy - finger), clamped), a finger inside a closed sphere (the proxy
// starts outside it, by the winding number and by its distance from every triangle), and a path
// played whole (`run`, as `proxima run` composes it: placeProxyStart, then runLockstep) or tick
// by tick (`step`), which must agree bit for bit.
#include "Geometry/ClosestPoint.h"
#include "Geometry/ProceduralMeshes.h"
#include "Geometry/WindingNumber.h"
#include "Runtime/HapticSession.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

namespace proxima
{
namespace
{
constexpr double kProxyRadius = 0.001;

std::shared_ptr<const CollisionScene> sceneOf(TriangleSoup soup)
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(std::move(soup), error)) << error.message;
  auto scene = std::make_shared<CollisionScene>();
  scene->addObject(std::move(mesh));
  return scene;
}

HapticSessionSettings settings()
{
  HapticSessionSettings s;
  s.proxy.radius = kProxyRadius;
  s.servo.stiffness = 1000.0;
  s.servo.maxForce = 10.0;
  s.rate = 1000.0;
  return s;
}

// A press from 5 mm above the floor z = 0 to `depth` below it over 0.2 s, then held 0.1 s.
FingerPath press(double depth)
{
  FingerPath path;
  path.append(0.0, {0.01, 0.02, 0.005});
  path.append(0.2, {0.01, 0.02, -depth});
  path.append(0.3, {0.01, 0.02, -depth});
  return path;
}

TEST(HapticSession, FingerPressedIntoAFloorFeelsTheSpringAboveIt)
{
  HapticSession session(sceneOf(makeGrid(0.1, 10)), settings());
  for (const double depth : {0.002, 0.004})
  {
    const std::vector<HapticState> states = session.run(press(depth));
    ASSERT_FALSE(states.empty());
    const HapticState& last = states.back();
    // Resting on the floor: the centre a radius above it (the skin is far below 1e-9 m here).
    EXPECT_NEAR(last.proxy.z, kProxyRadius, 1e-9);
    EXPECT_NEAR(last.proxy.x, 0.01, 1e-9);
    EXPECT_NEAR(last.proxy.y, 0.02, 1e-9);
    EXPECT_EQ(last.numContacts, 1);
    // kp (proxy - finger) = 1000 N/m x 3 mm = 3 N straight up; 5 mm would be 5 N.
    EXPECT_NEAR(last.force.z, 1000.0 * (kProxyRadius + depth), 1e-6);
    EXPECT_NEAR(last.force.x, 0.0, 1e-9);
    EXPECT_FALSE(last.conditions.has(TickCondition::forceClamped));
  }
}

TEST(HapticSession, ForceIsClampedToTheServoLimit)
{
  HapticSessionSettings s = settings();
  s.servo.maxForce = 2.0;
  HapticSession session(sceneOf(makeGrid(0.1, 10)), s);
  const HapticState last = session.run(press(0.004)).back();
  EXPECT_TRUE(last.conditions.has(TickCondition::forceClamped));
  EXPECT_NEAR(std::sqrt(dot(last.force, last.force)), 2.0, 1e-12);
  EXPECT_GT(last.force.z, 0.0);
}

TEST(HapticSession, AFingerInsideAClosedObjectStartsTheProxyOutside)
{
  const auto scene = sceneOf(makeIcosphere(4, 0.05));
  HapticSession session(scene, settings());
  const ProxyStartPlacement& placement = session.placeProxy({0.0, 0.0, 0.01});
  EXPECT_TRUE(placement.movedOutside);
  EXPECT_FALSE(
    isInsideByWindingNumber(windingNumber(scene->objects.front().mesh, session.proxy())));
  // And no nearer than the radius to any triangle (brute force over all of them).
  const TriangleMesh& mesh = scene->objects.front().mesh;
  double nearest = 1.0;
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    const TriangleCorners& c = mesh.corners(t);
    nearest = std::min(
      nearest, std::sqrt(closestPointOnTriangle(session.proxy(), c.a, c.b, c.c).squaredDistance));
  }
  EXPECT_GE(nearest, kProxyRadius);
  EXPECT_LT(nearest, 2.0 * kProxyRadius); // moved out to the surface, not far beyond
  const HapticState first = session.step({0.0, 0.0, 0.01});
  EXPECT_TRUE(first.conditions.has(TickCondition::startedOutside));
  EXPECT_LE(std::sqrt(dot(first.force, first.force)), settings().servo.maxForce);
}

TEST(HapticSession, RunIsWhatProximaRunComposesAndStepAgreesWithIt)
{
  const auto scene = sceneOf(makeIcosphere(3, 0.03));
  const HapticSessionSettings s = settings();
  // Samples on the ticks, so that `step` sees exactly the fingers `run` interpolates.
  FingerPath path;
  for (int k = 0; k <= 300; ++k)
  {
    const double t = k / s.rate;
    path.append(t, {0.01 * std::sin(10.0 * t), 0.005, 0.04 - 0.05 * t});
  }
  HapticSession session(scene, s);
  const std::vector<HapticState> run = session.run(path);

  // `proxima run`'s composition (RunCommand.cpp), written out.
  ProxyParameters parameters = s.proxy;
  parameters.stiffness = s.servo.stiffness;
  parameters.timeStep = 1.0 / s.rate;
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(scene.get(), parameters);
  resetProxyTo(*solver, placeProxyStart(*scene, parameters, path.positions.front()));
  LockstepSettings lockstep;
  lockstep.rate = s.rate;
  lockstep.numTicks = ticksCovering(path.startTime(), path.endTime(), s.rate);
  SimulatedDevice device(path);
  std::vector<HapticState> composed;
  runLockstep(lockstep, *solver, device, s.servo,
              [&](const HapticState& state) { composed.push_back(state); });

  HapticSession stepped(scene, s);
  ASSERT_EQ(run.size(), composed.size());
  ASSERT_EQ(run.size(), path.size());
  int contactTicks = 0;
  for (std::size_t i = 0; i < run.size(); ++i)
  {
    const HapticState one = stepped.step(path.positions[i]);
    for (const HapticState* other : {static_cast<const HapticState*>(&composed[i]), &one})
    {
      EXPECT_EQ(run[i].proxy, other->proxy) << "tick " << i;
      EXPECT_EQ(run[i].force, other->force) << "tick " << i;
      EXPECT_EQ(run[i].iterations, other->iterations) << "tick " << i;
    }
    contactTicks += run[i].numContacts > 0 ? 1 : 0;
  }
  EXPECT_GT(contactTicks, 50); // the path presses into the sphere: the case is not free flight
}

TEST(HapticSession, RefusesWhatItCannotRun)
{
  EXPECT_THROW(HapticSession(nullptr, settings()), std::invalid_argument);
  HapticSessionSettings s = settings();
  s.rate = 0.0;
  EXPECT_THROW(HapticSession(sceneOf(makeGrid(0.1, 2)), s), std::invalid_argument);
  HapticSession session(sceneOf(makeGrid(0.1, 2)), settings());
  EXPECT_THROW(session.run(FingerPath{}), std::invalid_argument);
}

} // namespace
} // namespace proxima
