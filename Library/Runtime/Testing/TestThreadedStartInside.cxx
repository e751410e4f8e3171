// Start inside on the threaded runtime (issue 13): the first scene published with the finger
// inside the sphere, and a scene swap that puts a sphere around a free proxy. publishScene
// decides on the caller's thread; the proxy loop installs the outside start with the scene.
// Real threads on the real clock: nothing asserts on speed, only on states waited for.
#include "Runtime/ThreadedRuntime.h"

#include "ThreadedTestSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "Geometry/WindingNumber.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <thread>

namespace proxima
{
namespace
{
using namespace std::chrono_literals;
using testing_support::makeSharedScene;
using testing_support::waitFor;

ProxyParameters proxyParameters()
{
  ProxyParameters parameters;
  parameters.radius = 0.001;
  return parameters;
}

RuntimeSettings quietSettings()
{
  RuntimeSettings settings;
  settings.servoRate = 1000.0;
  settings.realtimeScheduling = false;
  settings.tickBudget = TickWorkBudget{};
  return settings;
}

FingerPath restingAt(const Vec3& position)
{
  FingerPath path;
  path.append(0.0, position);
  path.append(100.0, position);
  return path;
}

bool inside(const CollisionScene& scene, const Vec3& point)
{
  return isInsideByWindingNumber(windingNumber(scene.objects.front().mesh, point));
}

TEST(ThreadedStartInside, FirstSceneWithTheFingerInsideStartsOutside)
{
  const auto sphere = makeSharedScene(makeIcosphere(4, 0.05));
  SimulatedDevice device(restingAt({}));
  RuntimeSettings settings = quietSettings();
  settings.recordTicks = 64;
  ThreadedRuntime runtime(device, ServoParameters{}, settings);
  ProxyStartPlacement placement;
  runtime.publishScene(sphere, proxyParameters(), {}, &placement);
  ASSERT_TRUE(placement.movedOutside);
  EXPECT_FALSE(inside(*sphere, placement.position));
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().sceneVersion == 1; }, 5000ms));
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().tick > 80; }, 5000ms));
  runtime.stop();
  const HapticState state = runtime.latestState();
  EXPECT_FALSE(inside(*sphere, state.proxy));
  EXPECT_LE(norm(state.force), ServoParameters{}.maxForce * (1.0 + 1e-12));
  // The first update on the scene carries the flag; the servo ramps the force from nothing.
  const std::vector<HapticState> records = runtime.records();
  ASSERT_FALSE(records.empty());
  int flagged = 0;
  for (const HapticState& record : records)
  {
    flagged += record.conditions.has(TickCondition::startedOutside) ? 1 : 0;
  }
  EXPECT_EQ(flagged, 1);
}

TEST(ThreadedStartInside, ASwapThatPutsTheProxyInsideMovesItOut)
{
  // First a small box far away: the finger at the origin is free, the proxy with it.
  const auto farBox = makeSharedScene(makeBox({0.01, 0.01, 0.01}, {1.0, 0.0, 0.0}));
  const auto sphere = makeSharedScene(makeIcosphere(4, 0.05));
  SimulatedDevice device(restingAt({0.0, 0.0, 0.01}));
  ThreadedRuntime runtime(device, ServoParameters{}, quietSettings());
  ProxyStartPlacement first;
  runtime.publishScene(farBox, proxyParameters(), {0.0, 0.0, 0.01}, &first);
  EXPECT_FALSE(first.movedOutside);
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().sceneVersion == 1; }, 5000ms));
  // Then a sphere around it, as a new model from the application: decided at publish with the
  // proxy where the proxy loop left it.
  ProxyStartPlacement swap;
  const std::uint64_t version = runtime.publishScene(sphere, proxyParameters(), {}, &swap);
  ASSERT_TRUE(swap.movedOutside);
  EXPECT_EQ(swap.object, 0);
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().sceneVersion == version; }, 5000ms));
  const std::uint64_t installedAt = runtime.latestState().tick;
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().tick > installedAt + 150; }, 5000ms));
  const HapticState state = runtime.latestState();
  runtime.stop();
  EXPECT_FALSE(inside(*sphere, state.proxy));
  EXPECT_GT(norm(state.proxy), 0.05);
  // The finger is inside and the proxy on the surface: pressed, the force at the clamp by now,
  // unless the watchdog is fading it (a slow machine, or ThreadSanitizer, can stall the loop).
  EXPECT_LE(norm(state.force), ServoParameters{}.maxForce * (1.0 + 1e-12));
  if (!state.conditions.has(TickCondition::forceFading))
  {
    EXPECT_NEAR(norm(state.force), ServoParameters{}.maxForce, 1e-9);
  }
}

} // namespace
} // namespace proxima
