// One haptic tick's input and output, the data of the tick's step (HapticStep.h) in every runner.
// TickInput is what a tick starts from: its number, its time and the device's sample; the threaded
// runtime's servo thread posts it to the proxy thread. HapticState is what the tick did: the
// lockstep runner hands it to the trace (one row per tick, DESIGN.md section 3), the threaded
// runtime's proxy thread posts its proxy half to the servo thread and the servo thread publishes
// the whole of it (ThreadedRuntime::latestState), and the VTK layer draws it. Plain values only,
// so a copy is a snapshot.
#pragma once

#include "Core/Vec3.h"
#include "Runtime/HapticDevice.h"

#include <cstdint>

namespace proxima
{

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
  std::uint32_t object = 0;
  std::uint32_t triangle = 0;
  /// Static and dynamic friction coefficients here (0 without friction): the cone half-angles are
  /// atan(staticFriction) and atan(dynamicFriction).
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
  /// How far the spring presses into this plane (m; the goal solver's multiplier): the contacts
  /// share the force on the finger in proportion to it, and a moving body feels its share.
  double depth = 0.0;
};

struct HapticState
{
  /// Servo tick that produced this state, its time on the runtime's clock (seconds), and the
  /// finger the device reported then.
  std::uint64_t tick = 0;
  double time = 0.0;
  Vec3 finger;

  // The proxy step (HapticStep.h: stepProxy).
  Vec3 proxy;
  double proxyRadius = 0.0;
  /// Active constraint planes (at most 3), and the touched object: the object of the first
  /// active contact, -1 when free.
  int numContacts = 0;
  ContactSnapshot contacts[3];
  int contactObject = -1;
  /// Move/update iterations of the proxy update, and triangles its queries tested.
  int iterations = 0;
  std::uint32_t trianglesTested = 0;
  /// The factor on the servo's stiffness from stiffness maps at the contacts (1 elsewhere).
  double stiffnessScale = 1.0;
  /// Wall time of the proxy update in nanoseconds: the one field that is not deterministic.
  std::int64_t solveNanoseconds = 0;
  /// A moving body came into the proxy at the tick's start and pushed it (paper section 6).
  bool pushedByObject = false;
  /// Wall time of the dynamics step (TickDynamics.h) in nanoseconds; 0 in a scene without bodies.
  std::int64_t dynamicsNanoseconds = 0;
  /// The sample held no usable finger (invalid, device lost, or not finite): the proxy held.
  bool fingerRefused = false;
  bool hitIterationCap = false;
  /// More primitives were within reach than the solver's fixed buffers hold.
  bool contactOverflow = false;
  /// Static friction held the proxy (the finger is inside a cone: sticking); dynamic or viscous
  /// friction shortened its slide.
  bool stuck = false;
  bool frictionLimited = false;
  /// The tick's work budget (ProxyParameters::tickBudget*) stopped the proxy before it settled:
  /// feasible, but not yet at the constrained minimum; the next tick goes on from there.
  bool budgetLimited = false;
  /// The proxy began this tick at a start moved out of the closed object that held the finger
  /// (ProxyStart.h), at the start of the run or at a scene install: the force ramps in.
  bool startedOutside = false;
  /// Version of the scene the proxy step ran on (ThreadedRuntime::publishScene).
  std::uint64_t sceneVersion = 0;
  /// Seconds between this tick and the finger sample the proxy was computed from: 0 in
  /// lockstep, about one period in the threaded runtime, more when the proxy loop stalls.
  double proxyAge = 0.0;

  // The force step (ServoForce.h).
  /// Force commanded to the device (on the finger), after clamping, rate limiting and fading.
  Vec3 force;
  bool forceClamped = false;
  /// The force was fading (proxy loop stalled, device lost, or coming back after either), the
  /// device was lost, the proxy state was older than the watchdog allows, or the force's rate of
  /// change was limited after a scene change.
  bool fading = false;
  bool deviceLost = false;
  bool proxyStale = false;
  bool rateLimited = false;
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
  kTickStartedOutside = 1u << 10,
  kTickPushedByObject = 1u << 11,
};

/// The state's conditions as a TickFlag bitmask.
std::uint32_t tickFlags(const HapticState& state);
/// Sets the state's conditions from a TickFlag bitmask (the inverse of tickFlags): for a state
/// rebuilt from a trace row or a remote run's stream.
void setTickFlags(HapticState& state, std::uint32_t flags);

} // namespace proxima
