// The threaded runtime against the lockstep runner and against its safety rules. Nothing here
// asserts on how fast the machine is: where timing matters the test waits for a state with a
// generous deadline, and what it checks is a sequence or a bound the design guarantees.
#include "Runtime/ThreadedRuntime.h"

#include "ThreadedTestSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "Runtime/LockstepRuntime.h"
#include "Paths/PathGenerators.h"
#include "Runtime/SimulatedDevice.h"

#if PROXIMA_WITH_MESH_IO
#include "IO/Mesh/MeshReader.h"
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <stdexcept>
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
  parameters.radius = 0.002;
  return parameters;
}

ServoParameters servoParameters()
{
  ServoParameters servo;
  servo.stiffness = 800.0;
  servo.maxForce = 8.0;
  return servo;
}

bool sameBits(const Vec3& a, const Vec3& b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

RuntimeSettings quietSettings(double rate)
{
  RuntimeSettings settings;
  settings.servoRate = rate;
  settings.realtimeScheduling = false;
  return settings;
}

// A press into a sphere and a stroke across it: contact, sliding, release.
FingerPath pressAndStroke(double rate)
{
  PressAndStroke press;
  press.surfacePoint = {0.0, 0.0, 0.05};
  press.inward = {0.0, 0.0, -1.0};
  press.depth = 0.004;
  press.strokeLength = 0.03;
  press.speed = 0.2;
  return makePressAndStrokePath(press, rate);
}

// A finger far from every scene, so that only the scene hand-over matters.
FingerPath restingFarAway()
{
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 1000.0});
  path.append(1000.0, {0.0, 0.0, 1000.0});
  return path;
}

TEST(ThreadedRuntime, AgreesWithLockstepOnTheSamePath)
{
  constexpr double kRate = 2000.0;
  const auto scene = makeSharedScene(makeIcosphere(4, 0.05));
  const FingerPath path = pressAndStroke(kRate);
  const Vec3 start = path.positions.front();
  const std::uint64_t ticks = ticksCovering(path.startTime(), path.endTime(), kRate);
  ASSERT_GT(ticks, 500u);

  // Lockstep on a virtual clock.
  std::vector<HapticState> lockstep;
  {
    ProxySolver solver;
    solver.setScene(scene.get(), proxyParameters());
    solver.resetProxy(start);
    SimulatedDevice device(path);
    LockstepSettings settings;
    settings.rate = kRate;
    settings.numTicks = ticks;
    runLockstep(settings, solver, device, servoParameters(),
                [&](const HapticState& record) { lockstep.push_back(record); });
  }

  // The same path played in real time through both threads.
  SimulatedDevice device(path);
  RuntimeSettings settings = quietSettings(kRate);
  settings.recordTicks = ticks + 16;
  settings.duration = path.endTime();
  // No tick budget: the runtime's default (50 us) stops a tick wherever the clock says, and
  // under ThreadSanitizer, ten times slower, it did (0.28 mm apart at tick 142).
  settings.tickBudget = TickWorkBudget{};
  ThreadedRuntime runtime(device, servoParameters(), settings);
  EXPECT_EQ(runtime.publishScene(scene, proxyParameters(), start), 1u);
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  ASSERT_TRUE(waitFor([&] { return runtime.finished(); }, 60s));
  runtime.stop();
  const std::vector<HapticState> threaded = runtime.records();
  ASSERT_FALSE(threaded.empty());

  // Each proxy update took the servo's newest sample; the records name the sample's tick. Until
  // the proxy loop skips a sample (it does not on an idle machine) the two runs must agree bit
  // for bit. A skip only changes the steps the proxy took: on this convex, frictionless model the
  // proxy at each tick is the one point of the free region nearest the finger, so after a skip
  // they must still agree to the solver's accuracy (1 nm). Ticks lost before the first sample are
  // free space, where the proxy is the finger in both runs.
  std::size_t bitForBit = 0;
  bool skipped = false;
  std::uint64_t contactTicks = 0;
  for (std::size_t i = 0; i < threaded.size(); ++i)
  {
    const HapticState& a = threaded[i];
    ASSERT_LT(a.tick, lockstep.size());
    const HapticState& b = lockstep[a.tick];
    if (i > 0)
    {
      ASSERT_GT(a.tick, threaded[i - 1].tick);
      skipped = skipped || a.tick != threaded[i - 1].tick + 1;
    }
    else
    {
      // A first update after tick 0 (the proxy thread started late: ThreadSanitizer on a loaded
      // machine) reaches the same proxy in a different number of iterations than lockstep's
      // tick-by-tick steps: compared to the solver's accuracy, as after a skip.
      skipped = a.tick != 0;
    }
    ASSERT_EQ(a.time, b.time) << "tick " << a.tick;
    ASSERT_TRUE(sameBits(a.finger, b.finger)) << "tick " << a.tick;
    ASSERT_EQ(a.numContacts > 0, b.numContacts > 0) << "tick " << a.tick;
    if (!skipped)
    {
      ASSERT_TRUE(sameBits(a.proxy, b.proxy)) << "tick " << a.tick;
      ASSERT_TRUE(sameBits(a.force, b.force)) << "tick " << a.tick;
      ASSERT_EQ(a.iterations, b.iterations) << "tick " << a.tick;
      ++bitForBit;
    }
    else
    {
      ASSERT_LT(distance(a.proxy, b.proxy), 1e-9) << "tick " << a.tick;
      ASSERT_LT(distance(a.force, b.force), 800.0 * 1e-9) << "tick " << a.tick;
    }
    contactTicks += a.numContacts > 0 ? 1 : 0;
  }
  RecordProperty("ticks", static_cast<int>(ticks));
  RecordProperty("ticks_compared", static_cast<int>(threaded.size()));
  RecordProperty("ticks_agreeing_bit_for_bit", static_cast<int>(bitForBit));
  EXPECT_GT(threaded.size(), ticks / 2) << "most ticks must have been compared";
  EXPECT_GT(contactTicks, 50u);
  const LoopStatistics servo = runtime.servoStatistics();
  EXPECT_GE(servo.ticks + servo.missedDeadlines + 2, ticks);
}

TEST(ThreadedRuntime, StreamsEveryServoTickToAReaderWhileRunning)
{
  constexpr double kRate = 2000.0;
  const auto scene = makeSharedScene(makeIcosphere(4, 0.05));
  const FingerPath path = pressAndStroke(kRate);
  SimulatedDevice device(path);
  RuntimeSettings settings = quietSettings(kRate);
  settings.duration = path.endTime();
  // Room for the whole run, so that a reader slowed down by a sanitizer still drops nothing.
  settings.streamCapacity = ticksCovering(path.startTime(), path.endTime(), kRate) + 64;
  ThreadedRuntime runtime(device, servoParameters(), settings);
  runtime.publishScene(scene, proxyParameters(), path.positions.front());
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  // Drained while the loops run, as a window's timer does, and once more after they stop.
  std::vector<HapticState> streamed;
  while (!runtime.finished())
  {
    runtime.drainStates(streamed);
    std::this_thread::sleep_for(5ms);
  }
  runtime.stop();
  runtime.drainStates(streamed);

  ASSERT_FALSE(streamed.empty());
  EXPECT_EQ(runtime.droppedStates(), 0u);
  // One state per servo tick, in order: the servo's own count, and tick numbers that only rise
  // (a late servo skips the ticks it missed).
  EXPECT_EQ(streamed.size(), runtime.servoStatistics().ticks);
  for (std::size_t i = 1; i < streamed.size(); ++i)
  {
    ASSERT_GT(streamed[i].tick, streamed[i - 1].tick);
  }
  // The stream carries the contacts, tick by tick. How many ticks a starved servo ran is not
  // known in advance (a late one skips ticks), so each streamed tick is checked on its own: where
  // the proxy step's finger was well inside the sphere offset by the proxy radius, the tick is in
  // contact. The proxy step read the finger `proxyAge` earlier, when it was at most the path's
  // speed times that age from this tick's finger; 1 mm covers the facets' sag (22 um here). A
  // proxy step the runtime's real-time budget (50 us) cut short may have stopped anywhere on its
  // way in, as it did under ThreadSanitizer (5 mm deep, no contact yet): only settled steps count.
  const double offset = 0.05 + proxyParameters().radius;
  std::uint64_t deepTicks = 0;
  for (const HapticState& state : streamed)
  {
    const double depth = offset - norm(state.finger) - 0.2 * state.proxyAge;
    const bool settled = !state.conditions.has(TickCondition::budgetLimited) &&
                         !state.conditions.has(TickCondition::hitIterationCap);
    if (depth > 1e-3 && !state.proxyStale && settled)
    {
      ++deepTicks;
      EXPECT_GT(state.numContacts, 0) << "tick " << state.tick << " at depth " << depth;
    }
  }
  EXPECT_GT(deepTicks, 0u) << "the press must have been streamed";
  // The last streamed state is the one the runtime published last.
  const HapticState latest = runtime.latestState();
  EXPECT_EQ(streamed.back().tick, latest.tick);
  EXPECT_TRUE(sameBits(streamed.back().force, latest.force));
  EXPECT_TRUE(sameBits(streamed.back().proxy, latest.proxy));
}

TEST(ThreadedRuntime, AStateStreamNobodyDrainsDropsAndCountsWithoutStallingTheServo)
{
  constexpr double kRate = 2000.0;
  const auto scene = makeSharedScene(makeIcosphere(3, 0.05));
  const FingerPath path = pressAndStroke(kRate);
  SimulatedDevice device(path);
  RuntimeSettings settings = quietSettings(kRate);
  settings.duration = 0.2;
  settings.streamCapacity = 16;
  ThreadedRuntime runtime(device, servoParameters(), settings);
  runtime.publishScene(scene, proxyParameters(), path.positions.front());
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  ASSERT_TRUE(waitFor([&] { return runtime.finished(); }, 60s));
  runtime.stop();
  std::vector<HapticState> streamed;
  EXPECT_EQ(runtime.drainStates(streamed), 16u);
  // The ring kept the first 16 ticks; the servo went on and counted every other tick dropped.
  EXPECT_EQ(streamed.size() + runtime.droppedStates(), runtime.servoStatistics().ticks);
  EXPECT_GT(runtime.droppedStates(), 0u);
  for (std::size_t i = 1; i < streamed.size(); ++i)
  {
    EXPECT_GT(streamed[i].tick, streamed[i - 1].tick);
  }
}

TEST(ThreadedRuntime, WatchdogFadesTheForceWhenTheProxyLoopStallsAndRecovers)
{
  const auto scene = makeSharedScene(makeGrid(0.2, 4, 0.0));
  // A finger held 3 mm under a floor: a steady 800 N/m * 3 mm = 2.4 N, after coming down.
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.01});
  path.append(0.05, {0.0, 0.0, -0.003});
  path.append(100.0, {0.0, 0.0, -0.003});
  SimulatedDevice device(path);
  ServoParameters servo = servoParameters();
  servo.watchdogTimeout = 0.005;
  servo.fadeTime = 0.05;
  ThreadedRuntime runtime(device, servo, quietSettings(4000.0));
  runtime.publishScene(scene, proxyParameters(), path.positions.front());
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  const double spring = 800.0 * (0.003 + 0.002);
  ASSERT_TRUE(waitFor([&] { return std::abs(runtime.latestState().force.z - spring) < 1e-6; }, 10s))
    << runtime.latestState().force.z;
  EXPECT_FALSE(runtime.latestState().conditions.has(TickCondition::forceFading));

  runtime.injectProxyStall(0.4);
  ASSERT_TRUE(
    waitFor([&] { return runtime.latestState().conditions.has(TickCondition::forceFading); }, 10s));
  // Faded to nothing while the proxy loop is still asleep, never above the force it had.
  double largest = 0.0;
  const bool faded = waitFor(
    [&] {
      const HapticState state = runtime.latestState();
      largest = std::max(largest, norm(state.force));
      return state.conditions.has(TickCondition::forceFading) && state.force == Vec3{};
    },
    10s);
  EXPECT_TRUE(faded) << runtime.latestState().force.z;
  EXPECT_LE(largest, spring + 1e-9);
  // The loop wakes again: the spring comes back in full.
  ASSERT_TRUE(waitFor(
    [&] {
      const HapticState state = runtime.latestState();
      return !state.conditions.has(TickCondition::forceFading) &&
             std::abs(state.force.z - spring) < 1e-6;
    },
    10s))
    << runtime.latestState().force.z;
  runtime.stop();
  EXPECT_FALSE(runtime.running());
}

TEST(ThreadedRuntime, LostDeviceFadesTheForceAndIsReported)
{
  const auto scene = makeSharedScene(makeGrid(0.2, 4, 0.0));
  class UnpluggedLater final : public HapticDevice
  {
  public:
    std::atomic<bool> unplugged{false};
    DeviceSample read(double) override
    {
      DeviceSample sample;
      sample.position = {0.0, 0.0, -0.003};
      sample.connected = !unplugged.load();
      sample.valid = sample.connected;
      return sample;
    }
    void writeForce(const Vec3&, double) override {}
  } device;
  ServoParameters servo = servoParameters();
  ThreadedRuntime runtime(device, servo, quietSettings(4000.0));
  runtime.publishScene(scene, proxyParameters(), {0.0, 0.0, 0.01});
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().force.z > 1.0; }, 10s));
  device.unplugged = true;
  ASSERT_TRUE(waitFor(
    [&] {
      const HapticState state = runtime.latestState();
      return state.conditions.has(TickCondition::deviceLost) &&
             state.conditions.has(TickCondition::forceFading) && state.force == Vec3{};
    },
    10s));
  runtime.stop();
}

TEST(ThreadedRuntime, ModelSwapWhileRunningInstallsOnlyCompleteScenes)
{
  // The new model: the 1.5M-triangle skull where the shared meshes are, else a 1.3M-triangle
  // sphere. Built on this thread while the haptic threads run on a small sphere.
  const std::string skull = std::string(PROXIMA_SHARED_MESHES) + "/cranium_bone_iso075mm.ply";
  // The skull comes through the IO layer's reader when that layer is built (PROXIMA_BUILD_IO).
  TriangleSoup model;
  bool haveSkull = false;
#if PROXIMA_WITH_MESH_IO
  try
  {
    model = readMeshFile(skull);
    haveSkull = true;
  }
  catch (const InputError&)
  {}
#endif
  if (!haveSkull)
  {
    model = makeIcosphere(8, 0.05);
  }

  const auto small = makeSharedScene(makeIcosphere(3, 0.05));
  const FingerPath path = restingFarAway(); // far outside both models
  SimulatedDevice device(path);
  ThreadedRuntime runtime(device, servoParameters(), quietSettings(4000.0));
  runtime.publishScene(small, proxyParameters(), path.positions.front());
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  // Installed in the proxy loop, then seen in a state the servo published (before that, under
  // load, the servo can still be publishing states from before the first proxy update: version 0).
  ASSERT_TRUE(runtime.waitForScene(1, 10s));
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().sceneVersion == 1; }, 10s));

  // Sample the published states while the big model is built and swapped in.
  std::atomic<bool> sampling{true};
  std::vector<std::uint64_t> versions;
  versions.reserve(1 << 20);
  std::thread sampler([&] {
    while (sampling.load())
    {
      versions.push_back(runtime.latestState().sceneVersion);
      std::this_thread::sleep_for(50us);
    }
  });
  const LoopStatistics before = runtime.proxyStatistics();
  const auto buildStart = std::chrono::steady_clock::now();
  std::shared_ptr<const CollisionScene> big = makeSharedScene(std::move(model));
  const auto buildNanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                  std::chrono::steady_clock::now() - buildStart)
                                  .count();
  const std::uint64_t version = runtime.publishScene(big, proxyParameters(), {0.0, 0.0, 1000.0});
  EXPECT_EQ(version, 2u);
  ASSERT_TRUE(runtime.waitForScene(2, 10s));
  ASSERT_TRUE(waitFor([&] { return runtime.latestState().sceneVersion == 2; }, 10s));
  sampling = false;
  sampler.join();
  const LoopStatistics after = runtime.proxyStatistics();
  runtime.stop();

  // Versions seen go 1 then 2, never back, never anything else.
  ASSERT_FALSE(versions.empty());
  for (std::size_t i = 0; i < versions.size(); ++i)
  {
    ASSERT_TRUE(versions[i] == 1 || versions[i] == 2) << versions[i];
    if (i > 0)
    {
      ASSERT_GE(versions[i], versions[i - 1]);
    }
  }
  EXPECT_GT(after.ticks, before.ticks);
  // The build happened off the haptic threads: installing the 1.5M-triangle scene is a pointer
  // swap and a few assignments (about 100 ns in Release), and no proxy tick came near the
  // build's hundreds of milliseconds. Compared with the build measured in this same run, not
  // with a fixed time: under ThreadSanitizer on a VM that stalls for a millisecond now and then,
  // an install once took 382 us, still a thousandth of the build.
  EXPECT_LT(runtime.longestSceneInstallNanoseconds(), buildNanoseconds / 100);
  EXPECT_LT(after.maxWorkNanoseconds, 100000000) << "a proxy tick took as long as a tree build";
  RecordProperty("scene_install_ns", static_cast<int>(runtime.longestSceneInstallNanoseconds()));
  RecordProperty("build_ns",
                 static_cast<int>(std::min<std::int64_t>(buildNanoseconds, 2000000000)));
  RecordProperty("model_triangles", static_cast<int>(big->objects[0].mesh.numTriangles()));
  RecordProperty("proxy_max_work_ns", static_cast<int>(after.maxWorkNanoseconds));
  RecordProperty("proxy_over_budget_ticks", static_cast<int>(after.overBudgetTicks));
  RecordProperty("skull", haveSkull ? 1 : 0);
}

// waitForScene's sleeper must be woken by the event it waits for: each wait below is given a
// minute and must end within half of it, where the event comes in milliseconds. A wait that only
// ended at its timeout would fail that, however slow the machine.
TEST(ThreadedRuntime, WaitForSceneReturnsOnceTheCommittedSceneIsLive)
{
  const auto scene = makeSharedScene(makeIcosphere(2, 0.05));
  const FingerPath path = restingFarAway();
  SimulatedDevice device(path);
  ThreadedRuntime runtime(device, servoParameters(), quietSettings(1000.0));
  EXPECT_EQ(runtime.publishScene(scene, proxyParameters(), path.positions.front()), 1u);
  // Published but not live: no proxy loop runs yet to install it.
  EXPECT_FALSE(runtime.waitForScene(1, 50ms));
  EXPECT_EQ(runtime.liveSceneVersion(), 0u);

  // The loops begin 10 ms after start() returns: this thread is asleep by then.
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  auto waitStart = std::chrono::steady_clock::now();
  ASSERT_TRUE(runtime.waitForScene(1, 60s));
  EXPECT_LT(std::chrono::steady_clock::now() - waitStart, 30s);
  EXPECT_GE(runtime.liveSceneVersion(), 1u);

  // A swap the proxy loop takes only after a 0.2 s stall: the wait sleeps through the stall and
  // is woken by the install.
  runtime.injectProxyStall(0.2);
  EXPECT_EQ(runtime.publishScene(scene, proxyParameters(), path.positions.front()), 2u);
  waitStart = std::chrono::steady_clock::now();
  ASSERT_TRUE(runtime.waitForScene(2, 60s));
  const auto waited = std::chrono::steady_clock::now() - waitStart;
  EXPECT_LT(waited, 30s);
  EXPECT_EQ(runtime.liveSceneVersion(), 2u);
  // A version already live (or older) is answered at once.
  EXPECT_TRUE(runtime.waitForScene(1, 0ms));
  runtime.stop();
  std::printf("[ measured ] a wait through a 0.2 s proxy stall ended after %.1f ms\n",
              std::chrono::duration<double, std::milli>(waited).count());
}

TEST(ThreadedRuntime, WaitForSceneTimesOutOnAVersionNeverCommitted)
{
  const FingerPath path = restingFarAway();
  SimulatedDevice device(path);
  ThreadedRuntime runtime(device, servoParameters(), quietSettings(1000.0));
  runtime.publishScene(makeSharedScene(makeIcosphere(2, 0.05)), proxyParameters(),
                       path.positions.front());
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  ASSERT_TRUE(runtime.waitForScene(1, 60s));
  // The loops run on and install nothing new: the wait lasts its whole timeout, then says no.
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(runtime.waitForScene(2, 200ms));
  EXPECT_GE(std::chrono::steady_clock::now() - start, 200ms);
  EXPECT_EQ(runtime.liveSceneVersion(), 1u);

  // Stopped loops install nothing more: a wait is told so at once, not at its timeout; what is
  // live stays live.
  runtime.stop();
  const auto afterStop = std::chrono::steady_clock::now();
  EXPECT_FALSE(runtime.waitForScene(2, 60s));
  EXPECT_LT(std::chrono::steady_clock::now() - afterStop, 30s);
  EXPECT_TRUE(runtime.waitForScene(1, 60s));
}

TEST(ThreadedRuntime, WaitForSceneEndsWhenTheRunEnds)
{
  const FingerPath path = restingFarAway();
  SimulatedDevice device(path);
  RuntimeSettings settings = quietSettings(1000.0);
  settings.duration = 0.5;
  ThreadedRuntime runtime(device, servoParameters(), settings);
  runtime.publishScene(makeSharedScene(makeIcosphere(2, 0.05)), proxyParameters(),
                       path.positions.front());
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  // Asleep long before the run's half second is over, and woken when it ends.
  const auto waitStart = std::chrono::steady_clock::now();
  EXPECT_FALSE(runtime.waitForScene(2, 60s));
  EXPECT_LT(std::chrono::steady_clock::now() - waitStart, 30s);
  EXPECT_TRUE(runtime.finished());
  runtime.stop();
}

TEST(ThreadedRuntime, RefusesAServoRateOutsideTheRuleAtConstruction)
{
  // Refused, not clamped: a clamped rate ran the loops at one rate while the proxy's time step
  // came from another.
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.0});
  SimulatedDevice device(path);
  for (const double rate : {20000.0, 999.0, 0.0, -4000.0, std::nan("")})
  {
    RuntimeSettings settings;
    settings.servoRate = rate;
    EXPECT_THROW(ThreadedRuntime(device, ServoParameters{}, settings), std::invalid_argument)
      << rate;
  }
  RuntimeSettings floor;
  floor.servoRate = 1000.0;
  EXPECT_NO_THROW(ThreadedRuntime(device, ServoParameters{}, floor));
}

TEST(ThreadedRuntime, StartMessageNamesTheRatesAndTheSchedulingOutcome)
{
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.0});
  SimulatedDevice device(path);
  RuntimeSettings settings;
  settings.servoRate = 10000.0; // the ceiling (ServoRate.h): a rate above it is refused
  settings.realtimeScheduling = true;
  settings.duration = 0.02;
  ThreadedRuntime runtime(device, ServoParameters{}, settings);
  std::string message;
  ASSERT_TRUE(runtime.start(message)) << message;
  EXPECT_NE(message.find("servo loop at 10000 Hz"), std::string::npos) << message;
  EXPECT_NE(message.find("real-time scheduling"), std::string::npos) << message;
  std::string again;
  EXPECT_FALSE(runtime.start(again));
  ASSERT_TRUE(waitFor([&] { return runtime.finished(); }, 10s));
  runtime.stop();
  runtime.stop();
  const LoopStatistics servo = runtime.servoStatistics();
  EXPECT_EQ(servo.rate, 10000.0);
  // Every deadline of the 20 ms either ran or is counted missed. Not ticks > 0: on a loaded
  // machine (the ThreadSanitizer run) the first wake-up can come after the whole duration, and
  // the loop then rightly ends having run no period at all.
  EXPECT_GT(servo.wakeUps, 0u);
  EXPECT_GE(servo.ticks + servo.missedDeadlines + 2,
            ticksCovering(0.0, settings.duration, 10000.0));
}

} // namespace
} // namespace proxima
