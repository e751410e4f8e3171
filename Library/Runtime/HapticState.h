// One haptic tick's input and output, the data of the tick's step (HapticStep.h) in every runner.
// TickInput is what a tick starts from: its number, its time and the device's sample; the threaded
// runtime's servo thread posts it to the proxy thread. HapticState is what the tick did: the
// lockstep runner hands it to the trace (one row per tick, DESIGN.md section 3), the threaded
// runtime's proxy thread posts its proxy half to the servo thread and the servo thread publishes
// the whole of it (ThreadedRuntime::latestState), and the VTK layer draws it. Plain values only,
// so a copy is a snapshot.
#pragma once

#include "Core/TickConditions.h"
#include "Core/Vec3.h"
#include "Runtime/HapticDevice.h"

#include <cstdint>

namespace proxima
{

/// What a haptic tick starts from: its number, its time and the device's sample.
struct TickInput
{
  /// Servo tick number: tick k of a run at rate f runs at startTime + k / f.
  std::uint64_t tick = 0;
  /// Seconds on the runtime's clock (virtual in lockstep, the servo clock's when threaded).
  double time = 0.0;
  /// The finger and the device's state (valid, connected, buttons) at `time`.
  DeviceSample sample;
};

/// One active contact, as drawn by the representations: a plane through `point` with `normal`,
/// and the friction cone around the normal.
struct ContactSnapshot
{
  /// Nearest point of the touched primitive to the proxy centre.
  Vec3 point;
  /// The constraint plane's normal, into free space.
  Vec3 normal;
  /// Index of the touched object in the scene.
  std::uint32_t object = 0;
  /// Index, in that object's mesh, of the triangle that gave the plane.
  std::uint32_t triangle = 0;
  /// Static friction coefficient here (0 without friction): the static cone's half-angle is
  /// atan(staticFriction).
  double staticFriction = 0.0;
  /// Dynamic friction coefficient here (0 without friction): the dynamic cone's half-angle is
  /// atan(dynamicFriction).
  double dynamicFriction = 0.0;
  /// How far the spring presses into this plane (m; the goal solver's multiplier): the contacts
  /// share the force on the finger in proportion to it, and a moving body feels its share.
  double depth = 0.0;
  /// True when the object deforms (a tissue): the servo renders its local model
  /// (LocalContactModel.h) between the tissue's steps.
  bool deforms = false;
};

/// What one haptic tick did: the proxy step's result, the force step's, and the conditions the
/// tick met. One trace row.
struct HapticState
{
  /// Servo tick that produced this state.
  std::uint64_t tick = 0;
  /// The tick's time on the runtime's clock (seconds).
  double time = 0.0;
  /// The finger the device reported for the tick (metres, world frame).
  Vec3 finger;

  // The proxy step (HapticStep.h: stepProxy).
  /// Proxy centre after the tick's update (metres, world frame).
  Vec3 proxy;
  /// Radius of the proxy sphere (m), the solver's.
  double proxyRadius = 0.0;
  /// Number of active constraint planes, 0 to 3: the first entries of `contacts`.
  int numContacts = 0;
  /// The active contacts; only the first `numContacts` are meaningful.
  ContactSnapshot contacts[3];
  /// The touched object: the object of the first active contact, -1 when free.
  int contactObject = -1;
  /// Move/update iterations of the proxy update.
  int iterations = 0;
  /// Triangles the proxy update's queries tested.
  std::uint32_t trianglesTested = 0;
  /// The factor on the servo's stiffness from stiffness maps at the contacts (1 elsewhere).
  double stiffnessScale = 1.0;
  /// Wall time of the proxy update in nanoseconds: the one field that is not deterministic.
  std::int64_t solveNanoseconds = 0;
  /// Wall time of the dynamics step (TickDynamics.h) in nanoseconds; 0 in a scene without bodies.
  std::int64_t dynamicsNanoseconds = 0;
  /// Version of the scene the proxy step ran on (ThreadedRuntime::publishScene).
  std::uint64_t sceneVersion = 0;
  /// How many times the solver's deforming objects have moved (ProxySolver::surfaceChanges): a
  /// new value is the first tick on a surface a tissue's step has just left.
  std::uint64_t surfaceChanges = 0;
  /// Seconds between this tick and the finger sample the proxy was computed from: 0 in
  /// lockstep, about one period in the threaded runtime, more when the proxy loop stalls.
  double proxyAge = 0.0;

  // The force step (ServoForce.h).
  /// Force commanded to the device (on the finger), after clamping, rate limiting and fading.
  Vec3 force;
  /// The proxy loop's state was older than the watchdog allows (ServoParameters::watchdogTimeout),
  /// so the force faded. Not a condition of the tick: the trace records the fade (forceFading).
  bool proxyStale = false;

  /// What the tick met: the proxy step's conditions (kProxyStepConditions, passed on from the
  /// solver) and the force step's (kForceStepConditions). `conditions.bits()` is the trace's
  /// `flags` column.
  TickConditions conditions;
};

/// The conditions the proxy step (HapticStep.h: stepProxy) reports: the solver's, and
/// fingerRefused for a sample it did not give the solver.
inline constexpr TickConditions kProxyStepConditions =
  TickCondition::budgetLimited | TickCondition::hitIterationCap | TickCondition::fingerRefused |
  TickCondition::stuck | TickCondition::frictionLimited | TickCondition::contactOverflow |
  TickCondition::startedOutside | TickCondition::pushedByObject | TickCondition::surfaceLagging;
/// The conditions the force step (ServoForce.h) reports.
inline constexpr TickConditions kForceStepConditions =
  TickCondition::forceClamped | TickCondition::forceFading | TickCondition::deviceLost |
  TickCondition::forceRateLimited;

} // namespace proxima
