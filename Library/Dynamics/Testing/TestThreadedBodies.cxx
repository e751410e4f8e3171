// Bodies in the threaded runtime (paper sections 6 and 8): the proxy thread runs the same force
// stage and dynamics step after each proxy update as the lockstep runner runs after each tick,
// so until the proxy loop first skips a finger sample the two runs agree bit for bit, proxy,
// force and the body's pose alike; and the runtime hands the bodies' poses over without locks.
// Nothing here asserts on how fast the machine is.
#include "Dynamics/BodyCoupling.h"

#include "Geometry/ProceduralMeshes.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"
#include "Runtime/ThreadedRuntime.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <thread>

namespace proxima
{
namespace
{
using namespace std::chrono_literals;

constexpr double kRate = 1000.0;

std::shared_ptr<const CollisionScene> plateScene()
{
  auto scene = std::make_shared<CollisionScene>();
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(makeBox(Vec3{0.05, 0.1, 0.005}), error)) << error.message;
  scene->addObject(std::move(mesh));
  return scene;
}

// The lever of Data/Scenes/lever.json: hinged along x at y = -0.1 m, 2 N m/rad, damped.
std::unique_ptr<BodyCoupling> lever(const CollisionScene& scene)
{
  CoupledBody body;
  body.object = 0;
  body.description.name = "lever";
  body.description.joint.type = JointType::Hinge;
  body.description.joint.axis = Vec3{1.0, 0.0, 0.0};
  body.description.joint.anchor = Vec3{0.0, -0.1, 0.0};
  body.description.joint.stiffness = 2.0;
  body.description.joint.damping = 0.1;
  body.description.mass = solidMassProperties(scene.objects[0].mesh, 1000.0);
  DynamicsSettings settings;
  settings.timeStep = 1.0 / kRate;
  return std::make_unique<BodyCoupling>(std::vector<CoupledBody>{body}, settings);
}

FingerPath pressAndHold()
{
  FingerPath path;
  for (int k = 0; k <= 600; ++k)
  {
    const double t = k / kRate;
    const double z = t < 0.2 ? 0.03 - 0.15 * t : 0.0;
    path.times.push_back(t);
    path.positions.push_back(Vec3{0.0, 0.08, z});
  }
  return path;
}

ProxyParameters parameters()
{
  ProxyParameters proxy;
  proxy.radius = 0.001;
  proxy.timeStep = 1.0 / kRate;
  return proxy;
}

bool sameBits(const Vec3& a, const Vec3& b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ThreadedBodies, AgreeWithLockstepUntilTheFirstSkippedSample)
{
  const auto scene = plateScene();
  const FingerPath path = pressAndHold();
  const std::uint64_t ticks = ticksCovering(path.startTime(), path.endTime(), kRate);
  const Vec3 start = path.positions.front();

  std::vector<HapticState> lockstep;
  std::vector<RigidTransform> lockstepPoses;
  {
    const std::unique_ptr<BodyCoupling> bodies = lever(*scene);
    auto solver = std::make_unique<ProxySolver>();
    solver->setScene(scene.get(), parameters());
    solver->resetProxy(start);
    bodies->attach(*solver);
    SimulatedDevice device(path);
    LockstepSettings settings;
    settings.rate = kRate;
    settings.numTicks = ticks;
    runLockstep(
      settings, *solver, device, ServoParameters{},
      [&](const HapticState& state) {
        lockstep.push_back(state);
        lockstepPoses.push_back(bodies->transform(0));
      },
      bodies.get());
  }
  ASSERT_LT(lockstepPoses.back().row[2].y, -0.01); // the lever went down (q below 0)

  SimulatedDevice device(path);
  RuntimeSettings settings;
  settings.servoRate = kRate;
  settings.realtimeScheduling = false;
  settings.recordTicks = ticks + 16;
  settings.duration = path.endTime();
  settings.tickBudget = TickWorkBudget{};
  ThreadedRuntime runtime(device, ServoParameters{}, settings);
  std::shared_ptr<BodyCoupling> bodies = lever(*scene);
  runtime.publishScene(scene, parameters(), start, nullptr, bodies);
  EXPECT_EQ(runtime.latestBodyPoses().count, 0);
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  // The poses reach this thread while the loops run.
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (runtime.latestBodyPoses().count == 0 && std::chrono::steady_clock::now() < deadline)
  {
    std::this_thread::sleep_for(1ms);
  }
  const BodyPoses live = runtime.latestBodyPoses();
  EXPECT_EQ(live.count, 1);
  EXPECT_EQ(live.objects[0], 0u);
  while (!runtime.finished() && std::chrono::steady_clock::now() < deadline)
  {
    std::this_thread::sleep_for(5ms);
  }
  runtime.stop();
  const std::vector<HapticState> threaded = runtime.records();
  ASSERT_FALSE(threaded.empty());

  // The proxy thread's first update may come after tick 0 (it starts after the servo): the
  // finger is then still in free space, where the proxy is the finger and the lever at rest in
  // both runs. From there, until the first skipped sample (a dynamics step not taken), every
  // update must equal lockstep's tick bit for bit.
  const std::uint64_t firstContact = static_cast<std::uint64_t>(
    std::find_if(lockstep.begin(), lockstep.end(),
                 [](const HapticState& state) { return state.numContacts > 0; }) -
    lockstep.begin());
  ASSERT_LT(threaded.front().tick, firstContact) << "the proxy thread's first update came late";
  std::size_t bitForBit = 0;
  for (std::size_t i = 0; i < threaded.size(); ++i)
  {
    const HapticState& a = threaded[i];
    if (i > 0 && a.tick != threaded[i - 1].tick + 1)
    {
      break; // the first skipped sample
    }
    const HapticState& b = lockstep[a.tick];
    ASSERT_TRUE(sameBits(a.proxy, b.proxy)) << "tick " << a.tick;
    ASSERT_TRUE(sameBits(a.force, b.force)) << "tick " << a.tick;
    ASSERT_EQ(a.conditions.has(TickCondition::pushedByObject),
              b.conditions.has(TickCondition::pushedByObject))
      << "tick " << a.tick;
    ++bitForBit;
  }
  const BodyPoses last = runtime.latestBodyPoses();
  ASSERT_EQ(last.count, 1);
  ASSERT_LT(last.tick, lockstepPoses.size());
  if (bitForBit == threaded.size() && last.tick == threaded.back().tick)
  {
    // No sample skipped: the body ended where lockstep left it, bit for bit.
    const RigidTransform& expected = lockstepPoses[last.tick];
    EXPECT_TRUE(sameBits(last.poses[0].translation, expected.translation));
    for (int r = 0; r < 3; ++r)
    {
      EXPECT_TRUE(sameBits(last.poses[0].row[r], expected.row[r]));
    }
  }
  std::printf("[ measured ] %zu of %zu proxy updates bit for bit with lockstep (%zu lockstep "
              "ticks)\n",
              bitForBit, threaded.size(), lockstep.size());
}

} // namespace
} // namespace proxima
