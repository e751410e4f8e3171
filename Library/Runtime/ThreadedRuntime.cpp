#include "Runtime/ThreadedRuntime.h"

#include "Proxy/ProxyStart.h"
#include "Runtime/DeadlineClock.h"
#include "Runtime/FutexWord.h"
#include "Runtime/HapticStep.h"
#include "Runtime/ServoRate.h"
#include "Runtime/SnapshotChannel.h"
#include "Runtime/StateStream.h"

#include <sys/prctl.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace proxima
{
namespace
{
struct SceneSlot
{
  std::shared_ptr<const CollisionScene> scene;
  ProxyParameters parameters;
  /// Where the proxy goes when the scene is installed: always for the first scene, and for a
  /// later one only when `movedOutside` (the proxy was inside one of its objects at publish).
  Vec3 proxyStart;
  bool movedOutside = false;
  std::uint64_t version = 0;
  /// The scene's bodies (null without), and the moved copies of their objects, made on the
  /// publisher's thread and freed there with the slot.
  std::shared_ptr<TickDynamics> dynamics;
  std::unique_ptr<MovingObjectSet> moving;
  /// The deforming copies of the dynamics' deforming objects (a tissue's), made on the
  /// publisher's thread; the slot's reference keeps the solver from ever freeing them.
  std::shared_ptr<DeformingObjectSet> deforming;
  /// What the dynamics keeps for this scene (TickDynamics::prepare), freed with the slot.
  std::unique_ptr<TickDynamics::SceneBinding> binding;
};

} // namespace

struct ThreadedRuntime::Impl
{
  Impl(HapticDevice& device_, const ServoParameters& servo_, const RuntimeSettings& settings_)
    : device(device_)
    , limits(device_.limits())
    , servo(servo_)
    , settings(settings_)
    , solver(std::make_unique<ProxySolver>())
  {
    const std::string rateError = servoRateError(settings.servoRate);
    if (!rateError.empty())
    {
      throw std::invalid_argument(rateError);
    }
    if (!(settings.proxyRate > 0.0))
    {
      settings.proxyRate = settings.servoRate;
    }
    records.resize(settings.recordTicks);
    if (settings.streamCapacity > 0)
    {
      stream = std::make_unique<StateStream<HapticState>>(settings.streamCapacity);
    }
  }

  void servoLoop(Nanoseconds start);
  void proxyLoop(Nanoseconds start);
  /// On the proxy thread: installs a published scene, unless the last one it let go of has not
  /// been collected yet (a haptic thread never frees a scene).
  void installPendingScene();
  void collectRetired() { delete retired.exchange(nullptr, std::memory_order_acq_rel); }
  /// Counts the scene event (a scene installed, or the loops ended) and wakes waitForScene's
  /// sleepers; after the change it announces is stored.
  void raiseSceneEvent()
  {
    sceneEvents.fetch_add(1, std::memory_order_release);
    wakeAllSleepers(sceneEvents);
  }

  HapticDevice& device;
  /// Asked once here, so that only the servo thread ever calls the device.
  DeviceLimits limits;
  ServoParameters servo;
  RuntimeSettings settings;
  std::unique_ptr<ProxySolver> solver;

  /// Servo thread to proxy thread: the newest tick's input.
  SnapshotChannel<TickInput> finger;
  /// Proxy thread to servo thread: the proxy half of the newest update's state.
  SnapshotChannel<HapticState> proxyState;
  /// Proxy thread to the application: where the bodies are after the newest dynamics step.
  SnapshotChannel<BodyPoses> bodyPoses;
  /// Servo thread to the application: each tick's whole state.
  SnapshotChannel<HapticState> state;
  /// Set (release) after the first write of `finger` and `proxyState`: a reader that sees one
  /// set reads a posted value, never the channel's default.
  std::atomic<bool> fingerPosted{false};
  std::atomic<bool> proxyPosted{false};

  std::atomic<SceneSlot*> pending{nullptr};
  std::atomic<SceneSlot*> retired{nullptr};
  SceneSlot* live = nullptr;
  std::atomic<std::uint64_t> publishedVersions{0};
  std::atomic<std::uint64_t> liveVersion{0};
  /// How many scene events there have been (wrapping): what waitForScene's sleepers sleep on.
  mutable std::atomic<std::uint32_t> sceneEvents{0};

  std::atomic<bool> stopRequested{false};
  std::atomic<bool> finishedFlag{false};
  std::atomic<Nanoseconds> stallRequest{0};
  std::atomic<Nanoseconds> longestInstall{0};
  bool started = false;

  LoopStatisticsRecorder servoStatistics;
  LoopStatisticsRecorder proxyStatistics;
  std::vector<HapticState> records;
  std::size_t recordCount = 0;
  /// Servo thread to one reader: every tick's state (RuntimeSettings::streamCapacity).
  std::unique_ptr<StateStream<HapticState>> stream;

  std::thread servoThread;
  std::thread proxyThread;
  std::string servoScheduling;
};

void ThreadedRuntime::Impl::installPendingScene()
{
  if (pending.load(std::memory_order_acquire) == nullptr ||
      retired.load(std::memory_order_acquire) != nullptr)
  {
    return;
  }
  SceneSlot* next = pending.exchange(nullptr, std::memory_order_acq_rel);
  if (next == nullptr)
  {
    return;
  }
  const Nanoseconds begin = monotonicNanoseconds();
  solver->setScene(next->scene.get(), next->parameters);
  solver->useMovingObjects(next->moving.get());
  solver->useDeformingObjects(next->deforming);
  if (next->dynamics != nullptr)
  {
    next->dynamics->install(*solver, next->binding.get());
  }
  if (next->movedOutside)
  {
    solver->resetProxyOutside(next->proxyStart);
  }
  else if (live == nullptr)
  {
    solver->resetProxy(next->proxyStart);
  }
  SceneSlot* previous = live;
  live = next;
  const Nanoseconds took = monotonicNanoseconds() - begin;
  if (took > longestInstall.load(std::memory_order_relaxed))
  {
    longestInstall.store(took, std::memory_order_relaxed);
  }
  liveVersion.store(next->version, std::memory_order_release);
  // Only this thread fills `retired`, and it was empty above: the store loses nothing.
  retired.store(previous, std::memory_order_release);
  // Once per installed scene, after the install was timed: not part of any proxy update.
  raiseSceneEvent();
}

void ThreadedRuntime::Impl::proxyLoop(Nanoseconds start)
{
  prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
  DeadlineClock clock(start, settings.proxyRate, proxyStatistics);
  // The force stage on this thread's sequence, in the proxy half as lockstep runs it: the force
  // the bodies feel and the one the records hold (the servo thread's own is for the device).
  ServoForce proxyForce(servo, limits);
  BodyPoses poses;
  bool updatedOnce = false;
  std::uint64_t lastTick = 0;
  while (!stopRequested.load(std::memory_order_acquire) &&
         !finishedFlag.load(std::memory_order_acquire))
  {
    clock.waitForNextTick();
    const Nanoseconds stall = stallRequest.exchange(0, std::memory_order_acq_rel);
    if (stall > 0)
    {
      sleepUntilNanoseconds(monotonicNanoseconds() + stall);
    }
    installPendingScene();
    if (!fingerPosted.load(std::memory_order_acquire))
    {
      clock.workDone();
      continue; // no finger sample yet
    }
    // New is decided by the sample's tick, not by the channel's write count: the servo can post
    // again between a count and the read that follows it, and the read then already holds the
    // newer sample, which the next count would have the loop update on a second time.
    const TickInput post = finger.read();
    if (updatedOnce && post.tick == lastTick)
    {
      clock.workDone();
      continue; // no new finger sample: nothing to update
    }
    updatedOnce = true;
    lastTick = post.tick;
    HapticState updated;
    if (live != nullptr)
    {
      stepProxyHalf(*solver, post, live->version, proxyForce, live->dynamics.get(), updated);
      if (live->dynamics != nullptr)
      {
        live->dynamics->poses(poses);
        poses.tick = post.tick;
        bodyPoses.write(poses);
      }
    }
    else
    {
      // No scene yet: free space, the proxy is the finger.
      updated.tick = post.tick;
      updated.time = post.time;
      updated.finger = post.sample.position;
      const bool refused = !(post.sample.valid && post.sample.connected);
      updated.conditions.set(TickCondition::fingerRefused, refused);
      updated.proxy = refused ? solver->proxy() : post.sample.position;
      if (!refused)
      {
        solver->resetProxy(post.sample.position);
      }
      proxyForce.step(post, updated);
    }
    proxyState.write(updated);
    proxyPosted.store(true, std::memory_order_release);
    if (recordCount < records.size())
    {
      // With no sample skipped, these records equal a lockstep run's.
      records[recordCount++] = updated;
    }
    clock.workDone();
  }
}

void ThreadedRuntime::Impl::servoLoop(Nanoseconds start)
{
  prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
  DeadlineClock clock(start, settings.servoRate, servoStatistics);
  ServoForce force(servo, limits);
  while (!stopRequested.load(std::memory_order_acquire))
  {
    const std::uint64_t tick = clock.waitForNextTick();
    // The servo clock counts ticks, so the device sees the time of the tick, not of the wake-up.
    const double time = static_cast<double>(tick) / settings.servoRate;
    if (settings.duration > 0.0 && time > settings.duration)
    {
      finishedFlag.store(true, std::memory_order_release);
      // The run is over: no scene goes live any more, so nobody need wait for one.
      raiseSceneEvent();
      break;
    }
    const TickInput input{tick, time, device.read(time)};
    finger.write(input);
    fingerPosted.store(true, std::memory_order_release);

    // The proxy half comes from the proxy thread's last update; this tick's finger, time and
    // force are the servo's own.
    HapticState snapshot;
    if (proxyPosted.load(std::memory_order_acquire))
    {
      snapshot = proxyState.read();
      snapshot.proxyAge = time - snapshot.time;
    }
    else
    {
      // Nothing from the proxy loop yet: no force, and the watchdog counts from the start.
      snapshot.proxy = input.sample.position;
      snapshot.proxyAge = time;
    }
    snapshot.tick = tick;
    snapshot.time = time;
    snapshot.finger = input.sample.position;
    force.step(input, snapshot);
    device.writeForce(snapshot.force, time);
    state.write(snapshot);
    if (stream)
    {
      stream->push(snapshot);
    }
    clock.workDone();
  }
}

ThreadedRuntime::ThreadedRuntime(HapticDevice& device, const ServoParameters& servo,
                                 const RuntimeSettings& settings)
  : m_impl(std::make_unique<Impl>(device, servo, settings))
{}

ThreadedRuntime::~ThreadedRuntime()
{
  stop();
  delete m_impl->pending.exchange(nullptr);
  m_impl->collectRetired();
  delete m_impl->live;
}

std::uint64_t ThreadedRuntime::publishScene(std::shared_ptr<const CollisionScene> scene,
                                            const ProxyParameters& parameters,
                                            const Vec3& proxyStart, ProxyStartPlacement* placement,
                                            std::shared_ptr<TickDynamics> dynamics)
{
  // What the dynamics needs is made here, on the caller's thread, first: a dynamics that refuses
  // the scene (prepare throws) then costs no version.
  std::unique_ptr<MovingObjectSet> moving;
  std::shared_ptr<DeformingObjectSet> deforming;
  std::unique_ptr<TickDynamics::SceneBinding> binding;
  if (dynamics != nullptr && scene != nullptr)
  {
    moving = makeMovingObjects(*scene, dynamics->movingObjects());
    const std::vector<std::uint32_t> deformingObjects = dynamics->deformingObjects();
    if (!deformingObjects.empty())
    {
      deforming = makeDeformingObjects(*scene, deformingObjects);
    }
    dynamics->runStepsOnOwnThread(
      m_impl->settings.realtimeScheduling ? m_impl->settings.dynamicsPriority : 0);
    binding = dynamics->prepare(*scene);
  }
  const std::uint64_t version =
    m_impl->publishedVersions.fetch_add(1, std::memory_order_relaxed) + 1;
  ProxyParameters budgeted = parameters;
  m_impl->settings.tickBudget.applyToRealTime(budgeted);
  // What the new scene must not trap: before any scene is live, the start the caller asks for;
  // after, the proxy where the proxy loop last left it. Not the finger: a finger pressed into an
  // object that the new scene keeps is in contact, not trapped, and its proxy stays put.
  Vec3 requested = proxyStart;
  if (m_impl->liveVersion.load(std::memory_order_acquire) != 0 &&
      m_impl->proxyPosted.load(std::memory_order_acquire))
  {
    requested = m_impl->proxyState.read().proxy;
  }
  ProxyStartPlacement decided;
  decided.position = requested;
  if (scene != nullptr)
  {
    decided = placeProxyStart(*scene, budgeted, requested);
  }
  if (placement != nullptr)
  {
    *placement = decided;
  }
  // A proxy that is not moved keeps its place at a swap; the first scene places it anyway.
  const Vec3 start = decided.movedOutside ? decided.position : proxyStart;
  auto* slot = new SceneSlot{std::move(scene),
                             budgeted,
                             start,
                             decided.movedOutside,
                             version,
                             std::move(dynamics),
                             std::move(moving),
                             std::move(deforming),
                             std::move(binding)};
  // A scene published before the proxy loop took the last one replaces it unseen.
  delete m_impl->pending.exchange(slot, std::memory_order_acq_rel);
  m_impl->collectRetired();
  return version;
}

bool ThreadedRuntime::start(std::string& message)
{
  Impl& impl = *m_impl;
  if (impl.started)
  {
    message = "the runtime is already running";
    return false;
  }
  impl.stopRequested.store(false);
  impl.finishedFlag.store(false);
  impl.servoStatistics.reset(impl.settings.servoRate);
  impl.proxyStatistics.reset(impl.settings.proxyRate);
  impl.recordCount = 0;
  // Both loops count from one start a little ahead, so the threads exist before their first
  // deadline. With equal rates the proxy loop runs half a period after the servo: each update
  // has the servo's newest sample and is published before the next servo tick.
  const Nanoseconds start = monotonicNanoseconds() + 10000000;
  const Nanoseconds proxyOffset =
    impl.settings.proxyRate == impl.settings.servoRate
      ? static_cast<Nanoseconds>(std::llround(0.5e9 / impl.settings.servoRate))
      : 0;
  try
  {
    impl.proxyThread =
      std::thread([&impl, start, proxyOffset] { impl.proxyLoop(start + proxyOffset); });
    impl.servoThread = std::thread([&impl, start] { impl.servoLoop(start); });
  }
  catch (const std::system_error& error)
  {
    impl.stopRequested.store(true);
    if (impl.proxyThread.joinable())
    {
      impl.proxyThread.join();
    }
    message = std::string("could not start the haptic threads: ") + error.what();
    return false;
  }
  impl.started = true;
  message = "servo loop at " + std::to_string(static_cast<int>(impl.settings.servoRate)) +
            " Hz, proxy loop at " + std::to_string(static_cast<int>(impl.settings.proxyRate)) +
            " Hz";
  if (impl.settings.realtimeScheduling)
  {
    const std::string servoError =
      requestFifoScheduling(impl.servoThread, impl.settings.servoPriority);
    const std::string proxyError =
      requestFifoScheduling(impl.proxyThread, impl.settings.proxyPriority);
    if (servoError.empty() && proxyError.empty())
    {
      message += "; real-time scheduling (SCHED_FIFO) granted";
    }
    else
    {
      message += "; real-time scheduling refused (" +
                 (servoError.empty() ? proxyError : servoError) +
                 "): the loops run at normal priority. Grant it with an rtprio limit "
                 "(/etc/security/limits.conf) or CAP_SYS_NICE";
    }
  }
  impl.servoScheduling = describeScheduling(impl.servoThread);
  return true;
}

void ThreadedRuntime::stop()
{
  Impl& impl = *m_impl;
  if (!impl.started)
  {
    return;
  }
  impl.stopRequested.store(true, std::memory_order_release);
  impl.servoThread.join();
  impl.proxyThread.join();
  impl.started = false;
  impl.raiseSceneEvent();
}

bool ThreadedRuntime::running() const
{
  return m_impl->started && !m_impl->finishedFlag.load(std::memory_order_acquire);
}

bool ThreadedRuntime::finished() const
{
  return m_impl->finishedFlag.load(std::memory_order_acquire);
}

BodyPoses ThreadedRuntime::latestBodyPoses() const
{
  return m_impl->bodyPoses.read();
}

HapticState ThreadedRuntime::latestState() const
{
  return m_impl->state.read();
}

std::uint64_t ThreadedRuntime::liveSceneVersion() const
{
  return m_impl->liveVersion.load(std::memory_order_acquire);
}

bool ThreadedRuntime::waitForScene(std::uint64_t version, std::chrono::nanoseconds timeout) const
{
  Impl& impl = *m_impl;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true)
  {
    // The count first: an event raised after this read changes it, and the sleep below then
    // returns at once instead of missing the event.
    const std::uint32_t seen = impl.sceneEvents.load(std::memory_order_acquire);
    if (impl.liveVersion.load(std::memory_order_acquire) >= version)
    {
      return true;
    }
    if (impl.stopRequested.load(std::memory_order_acquire) ||
        impl.finishedFlag.load(std::memory_order_acquire))
    {
      return false;
    }
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::nanoseconds::zero())
    {
      return false;
    }
    sleepWhileUnchanged(impl.sceneEvents, seen,
                        std::chrono::duration_cast<std::chrono::nanoseconds>(left));
  }
}

std::int64_t ThreadedRuntime::longestSceneInstallNanoseconds() const
{
  return m_impl->longestInstall.load(std::memory_order_relaxed);
}

LoopStatistics ThreadedRuntime::servoStatistics() const
{
  return m_impl->servoStatistics.snapshot();
}

std::string ThreadedRuntime::servoScheduling() const
{
  return m_impl->servoScheduling;
}

LoopStatistics ThreadedRuntime::proxyStatistics() const
{
  return m_impl->proxyStatistics.snapshot();
}

std::vector<HapticState> ThreadedRuntime::records() const
{
  if (m_impl->started)
  {
    return {};
  }
  return std::vector<HapticState>(m_impl->records.begin(),
                                  m_impl->records.begin() +
                                    static_cast<std::ptrdiff_t>(m_impl->recordCount));
}

std::size_t ThreadedRuntime::drainStates(std::vector<HapticState>& out)
{
  return m_impl->stream ? m_impl->stream->drain(out) : 0;
}

std::uint64_t ThreadedRuntime::droppedStates() const
{
  return m_impl->stream ? m_impl->stream->dropped() : 0;
}

void ThreadedRuntime::injectProxyStall(double seconds)
{
  m_impl->stallRequest.store(static_cast<Nanoseconds>(seconds * 1e9), std::memory_order_release);
}

} // namespace proxima
