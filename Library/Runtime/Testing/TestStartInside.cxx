// A finger that starts inside a closed object (issue 13): the bundled 5 cm sphere, a path from
// its centre out through the surface and away. The proxy starts outside and is never inside,
// the force ramps in under the clamp, the first tick carries the flag, and once the finger is
// out the proxy is at the finger. The same run without the placement is trapped: the case is real.
#include "Geometry/ProceduralMeshes.h"
#include "Geometry/WindingNumber.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/RunSummary.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace proxima
{
namespace
{
constexpr double kSphereRadius = 0.05;
constexpr double kProxyRadius = 0.001;

std::unique_ptr<CollisionScene> bundledSphere()
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(makeIcosphere(4, kSphereRadius), error)) << error.message;
  auto scene = std::make_unique<CollisionScene>();
  scene->addObject(std::move(mesh));
  return scene;
}

/// Rests at the centre for 0.1 s, leaves along +z to 10 cm by 1 s, and dwells there to 1.5 s.
FingerPath centreThenOut()
{
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.0});
  path.append(0.1, {0.0, 0.0, 0.0});
  path.append(1.0, {0.0, 0.0, 0.1});
  path.append(1.5, {0.0, 0.0, 0.1});
  return path;
}

struct StartRun
{
  std::vector<HapticState> records;
  ProxyStartPlacement start;
};

StartRun runFromTheCentre(const CollisionScene& scene, const ServoParameters& servo,
                          bool placeOutside)
{
  ProxyParameters parameters;
  parameters.radius = kProxyRadius;
  ProxySolver solver;
  solver.setScene(&scene, parameters);
  const FingerPath path = centreThenOut();
  StartRun run;
  if (placeOutside)
  {
    run.start = placeProxyStart(scene, parameters, path.positions.front());
    resetProxyTo(solver, run.start);
  }
  else
  {
    solver.resetProxy(path.positions.front());
  }
  SimulatedDevice device(path);
  LockstepSettings settings;
  settings.rate = 1000.0;
  settings.numTicks = ticksCovering(path.startTime(), path.endTime(), settings.rate);
  runLockstep(settings, solver, device, servo,
              [&run](const HapticState& record) { run.records.push_back(record); });
  return run;
}

TEST(StartInside, TheProxyStartsOutsideAndIsNeverInside)
{
  const auto scene = bundledSphere();
  const ServoParameters servo;
  const StartRun run = runFromTheCentre(*scene, servo, true);
  ASSERT_TRUE(run.start.movedOutside);
  EXPECT_EQ(run.start.object, 0);
  ASSERT_FALSE(run.records.empty());
  const TriangleMesh& mesh = scene->objects.front().mesh;
  for (const HapticState& record : run.records)
  {
    ASSERT_FALSE(isInsideByWindingNumber(windingNumber(mesh, record.proxy)))
      << "tick " << record.tick;
    // Outside the faceted sphere by the radius, less its facets' sag (under 0.1 mm at 5120).
    ASSERT_GT(norm(record.proxy), kSphereRadius + kProxyRadius - 1e-4) << "tick " << record.tick;
  }
}

TEST(StartInside, TheFlagMarksTheFirstTickOnly)
{
  const auto scene = bundledSphere();
  const StartRun run = runFromTheCentre(*scene, ServoParameters{}, true);
  RunSummary summary;
  for (const HapticState& record : run.records)
  {
    EXPECT_EQ(record.conditions.has(TickCondition::startedOutside), record.tick == 0)
      << "tick " << record.tick;
    summary.add(record);
  }
  EXPECT_EQ(summary.startedOutsideTicks(), 1u);
}

TEST(StartInside, TheForceRampsInUnderTheClamp)
{
  const auto scene = bundledSphere();
  const ServoParameters servo;
  const StartRun run = runFromTheCentre(*scene, servo, true);
  const double dt = 1e-3;
  // At the start the proxy is 5 cm from the finger: 50 N of spring, clamped to 10 N, and not at
  // once: from nothing at the forceRateLimit.
  EXPECT_EQ(norm(run.records.front().force), 0.0);
  double largestStep = 0.0;
  Vec3 last;
  for (const HapticState& record : run.records)
  {
    ASSERT_LE(norm(record.force), servo.maxForce * (1.0 + 1e-12)) << "tick " << record.tick;
    if (record.time < servo.sceneChangeWindow)
    {
      largestStep = std::max(largestStep, norm(record.force - last));
    }
    last = record.force;
  }
  EXPECT_LE(largestStep, servo.forceRateLimit * dt * (1.0 + 1e-9));
  // It did reach the clamp inside the window: the ramp is a ramp, not a hold at zero.
  EXPECT_NEAR(norm(run.records[static_cast<std::size_t>(servo.sceneChangeWindow / dt) - 1].force),
              servo.maxForce, 1e-9);
}

TEST(StartInside, OnceTheFingerIsOutTheProxyIsAtTheFinger)
{
  const auto scene = bundledSphere();
  const StartRun run = runFromTheCentre(*scene, ServoParameters{}, true);
  int free = 0;
  for (const HapticState& record : run.records)
  {
    // Clear of the sphere by more than the radius (and the facets' sag): nothing between.
    if (norm(record.finger) > kSphereRadius + 2.0 * kProxyRadius && record.finger.z > 0.0)
    {
      ++free;
      EXPECT_LT(distance(record.proxy, record.finger), 1e-9) << "tick " << record.tick;
      EXPECT_LT(norm(record.force), 1e-6) << "tick " << record.tick;
    }
  }
  EXPECT_GT(free, 400);
}

TEST(StartInside, WithoutThePlacementTheProxyIsTrapped)
{
  // The defect of issue 13, kept as the reason for the rest: a proxy started at the finger inside
  // the sphere stays inside, and at the end pulls the finger in at the clamp.
  const auto scene = bundledSphere();
  const ServoParameters servo;
  const StartRun run = runFromTheCentre(*scene, servo, false);
  const HapticState& last = run.records.back();
  EXPECT_LT(norm(last.proxy), kSphereRadius);
  EXPECT_NEAR(norm(last.force), servo.maxForce, 1e-9);
}

} // namespace
} // namespace proxima
