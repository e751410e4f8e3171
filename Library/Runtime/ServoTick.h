// One servo tick of the lockstep runner: read the device, run the proxy step, run the force stage,
// write the force. The threaded runtime runs the same two steps (ProxyStep.h, ServoForce.h) on
// two threads.
#pragma once

#include "Proxy/ProxySolver.h"
#include "Runtime/HapticDevice.h"

#include <cstdint>

namespace proxima
{

struct ServoParameters
{
  /// Spring stiffness kp in N/m: force on the finger = kp (proxy - finger).
  double stiffness = 1000.0;
  /// Forces are clamped to this magnitude (the device's limit), in newtons.
  double maxForce = 10.0;
  /// Watchdog: a proxy state older than this (seconds) means the proxy loop stalled, and the
  /// force fades out. Only the threaded runtime has stale states.
  double watchdogTimeout = 0.005;
  /// Time in seconds over which the force fades to zero (stall, device lost).
  double fadeTime = 0.05;
  /// After a scene change, the force may change by at most this many newtons per second, for
  /// `sceneChangeWindow` seconds, so that a new model does not kick the hand.
  double forceRateLimit = 200.0;
  double sceneChangeWindow = 0.1;
};

/// What one tick did: the rows of the trace file (DESIGN.md section 3).
struct TickRecord
{
  std::uint64_t tick = 0;
  double time = 0.0;
  Vec3 finger;
  Vec3 proxy;
  Vec3 force;
  int contacts = 0;
  int iterations = 0;
  /// Wall time of the proxy update in nanoseconds: the one field that is not deterministic.
  std::int64_t solveNanoseconds = 0;
  bool fingerRefused = false;
  bool hitIterationCap = false;
  bool contactOverflow = false;
  bool forceClamped = false;
  /// The force was fading (proxy loop stalled, device lost, or coming back after either), the
  /// device was lost, or the force's rate of change was limited after a scene change.
  bool fading = false;
  bool deviceLost = false;
  bool rateLimited = false;
  /// Static friction held the proxy; dynamic or viscous friction shortened its slide.
  bool stuck = false;
  bool frictionLimited = false;
  /// The tick's work budget (ProxyParameters::tickBudget*) stopped the proxy before it settled:
  /// feasible, but not yet at the constrained minimum; the next tick goes on from there.
  bool budgetLimited = false;
  /// Index in the scene of the object of the first active contact, -1 when free.
  int contactObject = -1;
  std::uint32_t trianglesTested = 0;
};

/// The bits of trace v2's `flags` column (Documentation/CommandLine.md). Values are part of the
/// file format: append new bits, never renumber.
enum TickFlag : std::uint32_t
{
  kTickBudgetLimited = 1u << 0,
  kTickIterationCap = 1u << 1,
  kTickForceClamped = 1u << 2,
  kTickForceFading = 1u << 3,
  kTickDeviceLost = 1u << 4,
  kTickFingerRefused = 1u << 5,
  kTickStuck = 1u << 6,
  kTickFrictionLimited = 1u << 7,
  kTickContactOverflow = 1u << 8,
  kTickForceRateLimited = 1u << 9,
};

/// The record's conditions as a TickFlag bitmask.
std::uint32_t tickFlags(const TickRecord& record);

struct ProxyStepOutcome;
struct ServoForceOutput;
class ServoForce;

/// The record of a tick whose proxy step on `sample` gave `outcome` and whose force stage gave
/// `force`.
TickRecord makeTickRecord(std::uint64_t tick, double time, const DeviceSample& sample,
                          const ProxyStepOutcome& outcome, const ServoForceOutput& force);

/// Runs one tick at `time`; `servo` keeps the force stage's state (last force, fade) across ticks.
TickRecord runServoTick(std::uint64_t tick, double time, ProxySolver& solver, HapticDevice& device,
                        ServoForce& servo);

} // namespace proxima
