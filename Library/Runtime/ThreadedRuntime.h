// The threaded runtime (paper sections 7 and 8): a servo thread and a proxy-update thread with
// fixed absolute deadlines. The servo thread reads the device, posts the finger to the proxy
// thread and renders the spring force from the last published proxy; the proxy thread runs the
// solver on the latest finger. Everything between threads is lock-free: the finger and the proxy
// state go through single-writer snapshots, scenes through an atomic swap that only ever installs
// a complete scene and never frees one on a haptic thread. The steps are the lockstep runner's
// (HapticStep.h): the servo thread posts a TickInput, the proxy thread runs stepProxyHalf on it
// and posts the HapticState, and the servo thread runs ServoForce::step on that state and
// publishes it. A threaded run and a lockstep run of a path agree.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Proxy/ProxyParameters.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"
#include "Runtime/LoopStatistics.h"
#include "Runtime/ServoParameters.h"
#include "Runtime/TickBudget.h"
#include "Runtime/TickDynamics.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace proxima
{

/// How a ThreadedRuntime runs: the loops' rates and scheduling, what it records and streams, how
/// long it runs and the proxy loop's work budget.
struct RuntimeSettings
{
  /// Servo loop rate in Hz, 1 to 10 kHz (ServoRate.h; the runtime refuses any other).
  double servoRate = 4000.0;
  /// Proxy-update loop rate in Hz; 0 runs it at the servo rate.
  double proxyRate = 0.0;
  /// Ask for SCHED_FIFO on both threads (servo above proxy). Refused without the privilege:
  /// start() then says so and the threads run at normal priority.
  bool realtimeScheduling = true;
  /// SCHED_FIFO priority asked for the servo thread when `realtimeScheduling`.
  int servoPriority = 80;
  /// SCHED_FIFO priority asked for the proxy thread when `realtimeScheduling`.
  int proxyPriority = 70;
  /// SCHED_FIFO priority asked for a dynamics' own thread (a tissue's solid:
  /// TickDynamics::runStepsOnOwnThread) when `realtimeScheduling`; 0 (the default) leaves it at
  /// normal priority. Below both loops when set (e.g. 60), so that a step yields to them and to
  /// nothing else. Not the default: on this project's 2-core VM the soft liver's solid stepped
  /// late 1,406 times in 1,529 steps at SCHED_FIFO 60, against 12 in 1,972 at normal priority
  /// (Documentation/Tissue.md, "On the real clock").
  int dynamicsPriority = 0;
  /// Keep the states of the first `recordTicks` proxy updates (preallocated), each with the
  /// force the lockstep runner would give it, for comparing a threaded run with a lockstep one;
  /// 0 keeps none.
  std::size_t recordTicks = 0;
  /// Stream every servo tick's published state to one reader (drainStates), through a ring of
  /// this many states (preallocated; StateStream.h): a live scorer or recorder sees every tick
  /// as long as it drains within capacity / servoRate seconds, and the states it was too slow
  /// for are dropped and counted (droppedStates), never waited for. 0 streams nothing.
  std::size_t streamCapacity = 0;
  /// The run ends by itself when the servo clock reaches this many seconds (finished() turns
  /// true); 0 runs until stop().
  double duration = 0.0;
  /// The proxy loop's work budget per tick; it replaces the budget fields of every scene's
  /// ProxyParameters (publishScene), because how long a proxy tick may take is a property of
  /// the loops' schedule, not of the scene. Default: TickWorkBudget::realtimeDefault(), an
  /// iteration budget (deterministic, so a lockstep run given `--tick-budget default` limits the
  /// same ticks) with a wall-time safety cap applied only here (applyToRealTime). A
  /// budget-limited tick leaves the proxy feasible where it stopped and the next tick goes on
  /// from there.
  TickWorkBudget tickBudget = TickWorkBudget::realtimeDefault();
};

/// The real-time runner: a servo thread and a proxy-update thread on fixed absolute deadlines,
/// lock-free between them. Started and stopped from one thread; scenes are published and states
/// read from any.
class ThreadedRuntime
{
public:
  /// `device` must outlive the runtime; it is used by the servo thread only while running.
  /// Throws std::invalid_argument when settings.servoRate is not a servo rate (ServoRate.h): a
  /// rate is refused at configuration time, never clamped.
  ThreadedRuntime(HapticDevice& device, const ServoParameters& servo,
                  const RuntimeSettings& settings);
  ~ThreadedRuntime();
  ThreadedRuntime(const ThreadedRuntime&) = delete;
  ThreadedRuntime& operator=(const ThreadedRuntime&) = delete;

  /// Hands a complete scene to the proxy loop; callable from any thread, before or while
  /// running, and never blocks the haptic threads. The proxy loop installs it at its next tick
  /// (the servo then limits the force's rate of change for a moment, so the change does not
  /// kick). The first scene also places the proxy at `proxyStart`. Returns the scene's version
  /// (1, 2, ...). Scenes the proxy loop has let go of are freed here, on the caller's thread.
  /// The parameters' tick-budget fields are replaced by RuntimeSettings::tickBudget.
  /// Start inside: when the proxy would be inside a closed object of the new scene (the first
  /// scene: at `proxyStart`; a later one: where the proxy loop last left it), the proxy starts
  /// at the nearest free point outside instead (ProxyStart.h), decided here on the caller's
  /// thread in O(triangles), and the first tick on the scene reports it; `placement`, when
  /// given, receives the decision.
  /// Bodies (paper section 6): with `dynamics` (the scene's, e.g. Dynamics/BodyCoupling), the
  /// moved copies of their objects are made here, and each proxy update on the scene runs the
  /// force stage and the dynamics step after the proxy step, as lockstep does; a skipped finger
  /// sample is a dynamics step not taken. latestBodyPoses hands over where they are.
  /// Tissue (issue 35): a dynamics with deforming objects (Tissue/TissueDynamics.h) has their
  /// deforming copies made and is prepared (TickDynamics::prepare) here too, so the proxy loop
  /// only binds it at the install; its solids then step inside the proxy updates, every few
  /// ticks, as lockstep steps them. A dynamics that refuses the scene throws here, on the
  /// caller's thread, before anything is published. The same dynamics may be published again
  /// (each scene gets its own binding, freed here with the scene), but to one runtime at a time:
  /// two running runtimes would step one solid from two threads.
  std::uint64_t publishScene(std::shared_ptr<const CollisionScene> scene,
                             const ProxyParameters& parameters, const Vec3& proxyStart,
                             ProxyStartPlacement* placement = nullptr,
                             std::shared_ptr<TickDynamics> dynamics = nullptr);

  /// Starts both threads; false (and `message` says why) if they could not start. `message`
  /// also says whether real-time scheduling was granted.
  bool start(std::string& message);
  /// Stops both threads and waits for them. Idempotent.
  void stop();
  /// True from a successful start() until stop() or the end of the run's duration. For the
  /// thread that calls start() and stop().
  bool running() const;
  /// True once the servo clock reached `duration`: both loops have ended.
  bool finished() const;

  /// The last state the servo thread published: lock-free, any thread.
  HapticState latestState() const;
  /// Where the live scene's bodies are after the proxy thread's newest dynamics step (count 0
  /// before any, or without bodies): lock-free, any thread.
  BodyPoses latestBodyPoses() const;
  /// Version of the scene the proxy loop is using (0 before the first is installed).
  std::uint64_t liveSceneVersion() const;
  /// Blocks the calling thread until the proxy loop is using the scene of `version` or a newer
  /// one (a scene published before the loop took the one before it replaces that one unseen), and
  /// returns true; false once `timeout` has passed, or at once when the loops have ended (stop()
  /// or the run's duration), since no scene goes live after that. The caller sleeps on an event
  /// the proxy loop raises when it installs a scene, outside its proxy update: the haptic threads
  /// take no lock for it and nothing is polled. Any thread but the haptic ones.
  bool waitForScene(std::uint64_t version, std::chrono::nanoseconds timeout) const;
  /// The longest time the proxy loop spent installing a published scene, in nanoseconds: the
  /// whole cost of a model swap on the haptic side.
  std::int64_t longestSceneInstallNanoseconds() const;
  /// Period and deadline statistics of the servo loop, readable while running.
  LoopStatistics servoStatistics() const;
  /// Period and deadline statistics of the proxy loop, readable while running.
  LoopStatistics proxyStatistics() const;
  /// The servo thread's policy and priority as start() left them (e.g. "SCHED_FIFO 80"): what a
  /// floor loop (DeadlineClock.h) must run with to be comparable.
  std::string servoScheduling() const;
  /// The recorded ticks (RuntimeSettings::recordTicks), after stop().
  std::vector<HapticState> records() const;
  /// Appends the servo ticks' states published since the last call to `out`, in tick order
  /// (RuntimeSettings::streamCapacity; none when it is 0). One reader thread; while running or
  /// after stop(). Returns how many were appended.
  std::size_t drainStates(std::vector<HapticState>& out);
  /// States the stream dropped because its reader was a whole ring behind.
  std::uint64_t droppedStates() const;

  /// Fault injection for tests and demonstrations: the proxy loop sleeps `seconds` at its next
  /// tick, as if it had stalled, so the servo's watchdog fades the force.
  void injectProxyStall(double seconds);

private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

} // namespace proxima
