#include "Runtime/ThreadedRuntime.h"

#include "Runtime/DeadlineClock.h"
#include "Runtime/LockstepTick.h"
#include "Runtime/SnapshotChannel.h"

#include <sys/prctl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

namespace proxima
{
namespace
{
/// The finger sample the servo thread posts to the proxy thread.
struct FingerPost
{
  std::uint64_t tick = 0;
  double time = 0.0;
  DeviceSample sample;
  bool posted = false;
};

/// What the proxy thread publishes after each update.
struct ProxyPost
{
  bool valid = false;
  std::uint64_t sampleTick = 0;
  double sampleTime = 0.0;
  Vec3 proxy;
  double stiffnessScale = 1.0;
  bool refused = false;
  int numContacts = 0;
  ContactSnapshot contacts[3];
  bool stuck = false;
  bool frictionLimited = false;
  std::uint64_t sceneVersion = 0;
  double proxyRadius = 0.0;
};

struct SceneSlot
{
  std::shared_ptr<const CollisionScene> scene;
  ProxyParameters parameters;
  Vec3 proxyStart;
  std::uint64_t version = 0;
};

ProxyPost makeProxyPost(const FingerPost& finger, const ProxyStepOutcome& outcome,
                        const SceneSlot* scene)
{
  ProxyPost post;
  post.valid = true;
  post.sampleTick = finger.tick;
  post.sampleTime = finger.time;
  post.proxy = outcome.proxy;
  post.stiffnessScale = outcome.result.stiffnessScale;
  post.refused = outcome.refused;
  post.numContacts = snapshotContacts(outcome.result, post.contacts);
  post.stuck = outcome.result.stuck;
  post.frictionLimited = outcome.result.frictionLimited;
  post.sceneVersion = scene != nullptr ? scene->version : 0;
  post.proxyRadius = scene != nullptr ? scene->parameters.radius : 0.0;
  return post;
}
} // namespace

struct ThreadedRuntime::Impl
{
  Impl(HapticDevice& device_, const ServoParameters& servo_, const RuntimeSettings& settings_)
    : device(device_), limits(device_.limits()), servo(servo_), settings(settings_),
      solver(std::make_unique<ProxySolver>())
  {
    settings.servoRate = std::clamp(settings.servoRate, 1000.0, 10000.0);
    if (!(settings.proxyRate > 0.0))
    {
      settings.proxyRate = settings.servoRate;
    }
    records.resize(settings.recordTicks);
  }

  void servoLoop(Nanoseconds start);
  void proxyLoop(Nanoseconds start);
  /// On the proxy thread: installs a published scene, unless the last one it let go of has not
  /// been collected yet (a haptic thread never frees a scene).
  void installPendingScene();
  void collectRetired()
  {
    delete retired.exchange(nullptr, std::memory_order_acq_rel);
  }

  HapticDevice& device;
  /// Asked once here, so that only the servo thread ever calls the device.
  DeviceLimits limits;
  ServoParameters servo;
  RuntimeSettings settings;
  std::unique_ptr<ProxySolver> solver;

  SnapshotChannel<FingerPost> finger;
  SnapshotChannel<ProxyPost> proxyState;
  SnapshotChannel<HapticState> state;

  std::atomic<SceneSlot*> pending{nullptr};
  std::atomic<SceneSlot*> retired{nullptr};
  SceneSlot* live = nullptr;
  std::atomic<std::uint64_t> publishedVersions{0};
  std::atomic<std::uint64_t> liveVersion{0};

  std::atomic<bool> stopRequested{false};
  std::atomic<bool> finishedFlag{false};
  std::atomic<Nanoseconds> stallRequest{0};
  std::atomic<Nanoseconds> longestInstall{0};
  bool started = false;

  LoopStatisticsRecorder servoStatistics;
  LoopStatisticsRecorder proxyStatistics;
  std::vector<TickRecord> records;
  std::size_t recordCount = 0;

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
  if (live == nullptr)
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
}

void ThreadedRuntime::Impl::proxyLoop(Nanoseconds start)
{
  prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
  DeadlineClock clock(start, settings.proxyRate, proxyStatistics);
  ServoForce recordForce(servo, limits);
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
    // New is decided by the sample's tick, not by the channel's write count: the servo can post
    // again between a count and the read that follows it, and the read then already holds the
    // newer sample, which the next count would have the loop update on a second time.
    const FingerPost post = finger.read();
    if (!post.posted || (updatedOnce && post.tick == lastTick))
    {
      clock.workDone();
      continue; // no new finger sample: nothing to update
    }
    updatedOnce = true;
    lastTick = post.tick;
    ProxyStepOutcome outcome;
    if (live != nullptr)
    {
      outcome = runProxyStep(*solver, post.sample);
    }
    else
    {
      // No scene yet: free space, the proxy is the finger.
      outcome.refused = !(post.sample.valid && post.sample.connected);
      outcome.proxy = outcome.refused ? solver->proxy() : post.sample.position;
      if (!outcome.refused)
      {
        solver->resetProxy(post.sample.position);
      }
    }
    const std::uint64_t version = live != nullptr ? live->version : 0;
    proxyState.write(makeProxyPost(post, outcome, live));
    if (recordCount < records.size())
    {
      // The lockstep runner's force stage on this thread's sequence: with no sample skipped,
      // these records equal a lockstep run's.
      const ServoForceOutput force =
        recordForce.step(freshForceInput(post.sample, outcome, post.time, version));
      records[recordCount++] = makeTickRecord(post.tick, post.time, post.sample, outcome, force);
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
      break;
    }
    const DeviceSample sample = device.read(time);
    finger.write(FingerPost{tick, time, sample, true});

    const ProxyPost proxy = proxyState.read();
    ServoForceInput input;
    input.sample = sample;
    input.time = time;
    if (proxy.valid)
    {
      input.proxy = proxy.proxy;
      input.stiffnessScale = proxy.stiffnessScale;
      input.proxyRefused = proxy.refused;
      input.proxyAge = time - proxy.sampleTime;
      input.sceneVersion = proxy.sceneVersion;
    }
    else
    {
      // Nothing from the proxy loop yet: no force, and the watchdog counts from the start.
      input.proxy = sample.position;
      input.proxyAge = time;
    }
    const ServoForceOutput output = force.step(input);
    device.writeForce(output.force, time);

    HapticState snapshot;
    snapshot.tick = tick;
    snapshot.time = time;
    snapshot.finger = sample.position;
    snapshot.proxy = input.proxy;
    snapshot.proxyRadius = proxy.proxyRadius;
    snapshot.force = output.force;
    snapshot.numContacts = proxy.numContacts;
    std::copy(std::begin(proxy.contacts), std::end(proxy.contacts), std::begin(snapshot.contacts));
    snapshot.stuck = proxy.stuck;
    snapshot.frictionLimited = proxy.frictionLimited;
    snapshot.fading = output.fading;
    snapshot.deviceLost = output.deviceLost;
    snapshot.sceneVersion = proxy.sceneVersion;
    state.write(snapshot);
    clock.workDone();
  }
}

ThreadedRuntime::ThreadedRuntime(HapticDevice& device, const ServoParameters& servo,
                                 const RuntimeSettings& settings)
  : m_impl(std::make_unique<Impl>(device, servo, settings))
{
}

ThreadedRuntime::~ThreadedRuntime()
{
  stop();
  delete m_impl->pending.exchange(nullptr);
  m_impl->collectRetired();
  delete m_impl->live;
}

std::uint64_t ThreadedRuntime::publishScene(std::shared_ptr<const CollisionScene> scene,
                                            const ProxyParameters& parameters,
                                            const Vec3& proxyStart)
{
  const std::uint64_t version =
    m_impl->publishedVersions.fetch_add(1, std::memory_order_relaxed) + 1;
  ProxyParameters budgeted = parameters;
  m_impl->settings.tickBudget.applyTo(budgeted);
  auto* slot = new SceneSlot{std::move(scene), budgeted, proxyStart, version};
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
    impl.proxyThread = std::thread([&impl, start, proxyOffset] { impl.proxyLoop(start + proxyOffset); });
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
    const std::string servoError = requestFifoScheduling(impl.servoThread, impl.settings.servoPriority);
    const std::string proxyError = requestFifoScheduling(impl.proxyThread, impl.settings.proxyPriority);
    if (servoError.empty() && proxyError.empty())
    {
      message += "; real-time scheduling (SCHED_FIFO) granted";
    }
    else
    {
      message += "; real-time scheduling refused (" + (servoError.empty() ? proxyError : servoError) +
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
}

bool ThreadedRuntime::running() const
{
  return m_impl->started && !m_impl->finishedFlag.load(std::memory_order_acquire);
}

bool ThreadedRuntime::finished() const
{
  return m_impl->finishedFlag.load(std::memory_order_acquire);
}

HapticState ThreadedRuntime::latestState() const
{
  return m_impl->state.read();
}

std::uint64_t ThreadedRuntime::liveSceneVersion() const
{
  return m_impl->liveVersion.load(std::memory_order_acquire);
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

std::vector<TickRecord> ThreadedRuntime::records() const
{
  if (m_impl->started)
  {
    return {};
  }
  return std::vector<TickRecord>(m_impl->records.begin(),
                                 m_impl->records.begin() +
                                   static_cast<std::ptrdiff_t>(m_impl->recordCount));
}

void ThreadedRuntime::injectProxyStall(double seconds)
{
  m_impl->stallRequest.store(static_cast<Nanoseconds>(seconds * 1e9), std::memory_order_release);
}

} // namespace proxima
