// Tissue in the threaded runtime (issue 35: a real-time runner that steps a solid). The runtime
// makes the tissue's deforming copy and its coupling on the publisher's thread and only binds
// them at the scene's install; the solid then steps on a thread of its own, launched by the proxy
// thread at lockstep's step ticks and handed to the solver before the first update after it
// finished. So, until the proxy loop first skips a finger sample or first meets a step not yet
// finished, a threaded run of a press on a soft block equals a lockstep run bit for bit, proxy,
// force and the solid's surface alike; and whatever the machine's load, the solid gives way under
// the press. Nothing here asserts on how fast the machine is.
#include "Tissue/TissueDynamics.h"

#include "Proxy/CollisionScene.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"
#include "Runtime/ThreadedRuntime.h"
#include "Tissue/Testing/SoftBlock.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

namespace proxima
{
namespace
{
using namespace std::chrono_literals;

constexpr double kRate = 1000.0;
constexpr double kRadius = 0.005;

// The block of 8 x 8 x 4 cells of 5 mm, TestTissueContact's, kp = 1000 N/m at 1 kHz.
constexpr int kCellsAcross = 8;

std::shared_ptr<const CollisionScene> blockScene()
{
  return testing_support::softBlockScene(kCellsAcross);
}

std::shared_ptr<TissueDynamics> softBlock()
{
  return testing_support::softBlockDynamics(kCellsAcross, ServoParameters{}.stiffness, kRate);
}

// From 1 cm above the top's centre down to 3 mm below it in 0.3 s, then held for 0.3 s.
FingerPath pressAndHold()
{
  FingerPath path;
  for (int k = 0; k <= 600; ++k)
  {
    const double t = k / kRate;
    const double z = t < 0.3 ? 0.01 - 0.013 * t / 0.3 : -0.003;
    path.times.push_back(t);
    path.positions.push_back(Vec3{0.001, 0.002, z + kRadius});
  }
  return path;
}

ProxyParameters parameters()
{
  ProxyParameters proxy;
  proxy.radius = kRadius;
  proxy.timeStep = 1.0 / kRate;
  return proxy;
}

bool sameBits(const Vec3& a, const Vec3& b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ThreadedTissue, AgreesWithLockstepUntilTheFirstSkippedSampleAndGivesWayUnderAPress)
{
  const auto scene = blockScene();
  const FingerPath path = pressAndHold();
  const std::uint64_t ticks = ticksCovering(path.startTime(), path.endTime(), kRate);
  const Vec3 start = path.positions.front();

  std::vector<HapticState> lockstep;
  std::vector<std::vector<Vec3>> lockstepPoints; // the solid's points after each tick
  {
    const std::shared_ptr<TissueDynamics> tissue = softBlock();
    auto solver = std::make_unique<ProxySolver>();
    solver->setScene(scene.get(), parameters());
    solver->resetProxy(start);
    tissue->attach(*solver);
    SimulatedDevice device(path);
    LockstepSettings settings;
    settings.rate = kRate;
    settings.numTicks = ticks;
    runLockstep(
      settings, *solver, device, ServoParameters{},
      [&](const HapticState& state) {
        lockstep.push_back(state);
        lockstepPoints.push_back(tissue->solid(0).positions());
      },
      tissue.get());
    // The press dents the block by millimetres: what the threaded run is compared on.
    ASSERT_GT(tissue->reading(0).maxDisplacement, 0.001);
  }

  SimulatedDevice device(path);
  RuntimeSettings settings;
  settings.servoRate = kRate;
  settings.realtimeScheduling = false;
  settings.recordTicks = ticks + 16;
  settings.duration = path.endTime();
  settings.tickBudget = TickWorkBudget{};
  ThreadedRuntime runtime(device, ServoParameters{}, settings);
  const std::shared_ptr<TissueDynamics> tissue = softBlock();
  EXPECT_EQ(runtime.publishScene(scene, parameters(), start, nullptr, tissue), 1u);
  // Published again before the loops took the first: each publication has its own coupling
  // (the first one's is freed here, unseen), and the second is the one that runs.
  EXPECT_EQ(runtime.publishScene(scene, parameters(), start, nullptr, tissue), 2u);
  EXPECT_FALSE(tissue->takeSurfaces()); // no step yet: the surfaces at rest
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  ASSERT_TRUE(runtime.waitForScene(2, 60s)) << "the proxy loop never installed the scene";
  // Meanwhile this thread draws as a window would: each take is a newer step's surfaces, whole.
  std::uint64_t taken = 0;
  std::uint64_t lastSteps = 0;
  while (!runtime.finished())
  {
    if (tissue->takeSurfaces())
    {
      const TissueDynamics::Surfaces& surfaces = tissue->latestSurfaces();
      EXPECT_GT(surfaces.steps, lastSteps);
      EXPECT_EQ(surfaces.points.at(0).size(), tissue->solid(0).rest().points.size());
      lastSteps = surfaces.steps;
      ++taken;
    }
    // The run ends by itself at the path's end; the loops raise the scene event then.
    runtime.waitForScene(3, 10ms);
  }
  runtime.stop();
  EXPECT_EQ(runtime.liveSceneVersion(), 2u);
  // The real-time runner gave the solid a thread of its own; the last step launched may still
  // be running.
  EXPECT_TRUE(tissue->stepsOnOwnThread());
  tissue->waitForSolids();
  // The surfaces drawn last are the ones last handed to the solver (taken now, or already by the
  // loop above when no step was handed over after its last take): the last step's, or the one
  // before when the run ended with a step in flight.
  tissue->takeSurfaces();
  const TissueDynamics::Surfaces& drawn = tissue->latestSurfaces();
  EXPECT_TRUE(drawn.steps == tissue->steps() || drawn.steps + 1 == tissue->steps())
    << drawn.steps << " drawn of " << tissue->steps();
  ASSERT_EQ(drawn.points.size(), 1u);
  ASSERT_EQ(drawn.points[0].size(), tissue->surface(0).size());
  for (std::size_t v = 0; v < drawn.points[0].size(); ++v)
  {
    ASSERT_TRUE(sameBits(drawn.points[0][v], tissue->surface(0)[v])) << "point " << v;
  }
  EXPECT_FALSE(tissue->takeSurfaces());
  const std::vector<HapticState> threaded = runtime.records();
  ASSERT_FALSE(threaded.empty());
  // Each update that met a step-old surface is flagged, and only those.
  std::uint64_t flagged = 0;
  for (const HapticState& record : threaded)
  {
    if (record.conditions.has(TickCondition::surfaceLagging))
    {
      EXPECT_GE(record.tick, tissue->firstStaleUpdate());
      ++flagged;
    }
  }
  EXPECT_EQ(flagged, tissue->staleUpdates());

  // Whatever the load: the solid's thread stepped it and the press dented it.
  EXPECT_GT(tissue->steps(), 0u);
  EXPECT_GT(tissue->reading(0).maxDisplacement, 0.001);

  const std::uint64_t firstContact = static_cast<std::uint64_t>(
    std::find_if(lockstep.begin(), lockstep.end(),
                 [](const HapticState& state) { return state.numContacts > 0; }) -
    lockstep.begin());
  ASSERT_LT(firstContact, lockstep.size());
  ASSERT_LT(threaded.front().tick, firstContact) << "the proxy thread's first update came late";
  std::size_t bitForBit = 0;
  for (std::size_t i = 0; i < threaded.size(); ++i)
  {
    const HapticState& a = threaded[i];
    if ((i > 0 && a.tick != threaded[i - 1].tick + 1) || a.tick >= tissue->firstStaleUpdate())
    {
      break; // the first skipped sample, or the first update that met a step not yet finished
    }
    ASSERT_LT(a.tick, lockstep.size());
    const HapticState& b = lockstep[a.tick];
    ASSERT_TRUE(sameBits(a.proxy, b.proxy)) << "tick " << a.tick;
    ASSERT_TRUE(sameBits(a.force, b.force)) << "tick " << a.tick;
    ASSERT_EQ(a.numContacts, b.numContacts) << "tick " << a.tick;
    ++bitForBit;
  }
  EXPECT_LE(drawn.tick, threaded.back().tick);
  if (bitForBit == threaded.size())
  {
    // No sample skipped, no step late: the surface last handed over is the one lockstep's
    // solid had after the same step's tick, point for point.
    EXPECT_EQ(tissue->staleUpdates(), 0u);
    EXPECT_EQ((drawn.tick + 1) % static_cast<std::uint64_t>(tissue->ticksPerStep()), 0u);
    const std::vector<Vec3>& expected = lockstepPoints[drawn.tick];
    const std::vector<Vec3>& points = tissue->surface(0);
    ASSERT_EQ(points.size(), expected.size());
    for (std::size_t v = 0; v < points.size(); ++v)
    {
      ASSERT_TRUE(sameBits(points[v], expected[v])) << "point " << v;
    }
  }
  std::printf(
    "[ measured ] %zu of %zu proxy updates bit for bit with lockstep (%zu lockstep "
    "ticks, first contact at tick %llu); %llu solid steps (%llu launched late), %llu updates "
    "met a step not yet finished, %llu surfaces taken live\n",
    bitForBit, threaded.size(), lockstep.size(), static_cast<unsigned long long>(firstContact),
    static_cast<unsigned long long>(tissue->steps()),
    static_cast<unsigned long long>(tissue->lateSteps()),
    static_cast<unsigned long long>(tissue->staleUpdates()),
    static_cast<unsigned long long>(taken));
}

} // namespace
} // namespace proxima
