// The servo's force stage (paper section 8): the spring between proxy and finger, and the safety
// around it. Forces are clamped to the smaller of the servo's and the device's limit; a finger
// sample that cannot be used holds the last force; after a scene change the force's rate of
// change is limited for a moment so a new model, or a proxy started outside the object that
// holds the finger (ProxyStart.h), cannot kick the hand; and when the proxy state is
// older than the watchdog allows (the proxy loop stalled) or the device is lost, the force fades
// to zero over the fade time, and fades back in once the fault clears. Allocation-free and
// deterministic: time is the tick's time on the runtime's clock, never read here.
#pragma once

#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"
#include "Runtime/LocalContactModel.h"
#include "Runtime/ServoParameters.h"

#include <cstdint>

namespace proxima
{

/// The force stage of one servo loop: keeps the state it needs from tick to tick (last force,
/// fade level, rate-limit window). For one thread; allocation-free.
class ServoForce
{
public:
  /// A force stage with `parameters`, clamping to the smaller of `parameters.maxForce` and
  /// `limits.maxForce`.
  explicit ServoForce(const ServoParameters& parameters, const DeviceLimits& limits = {});

  /// The force for the tick `input` from the proxy half of `state` (proxy, stiffnessScale, its
  /// fingerRefused and startedOutside conditions, proxyAge, sceneVersion): sets the state's force
  /// fields and the force step's conditions (kForceStepConditions).
  void step(const TickInput& input, HapticState& state);

  /// The parameters given at construction.
  const ServoParameters& parameters() const { return m_parameters; }
  /// The force clamp in newtons: the smaller of the servo's and the device's limit.
  double maxForce() const { return m_maxForce; }
  /// The force the last step commanded (N, on the finger); zero before the first.
  const Vec3& lastForce() const { return m_lastForce; }
  /// 1 when the spring force is rendered in full, 0 when faded out.
  double gain() const { return m_gain; }
  /// The local model of a contact on deforming tissue, rendered between the tissue's steps.
  const LocalContactModel& localModel() const { return m_localModel; }

private:
  /// The force before the clamp and the rate limit: the spring's, or a fading or held one.
  struct SpringForce
  {
    Vec3 force;
    /// The spring's extension (proxy minus finger): the direction of a force whose magnitude
    /// overflowed; zero when there is no spring this tick.
    Vec3 stretch;
    /// The last force held exactly (an unusable finger sample): not clamped again.
    bool held = false;
  };

  // The stages of step, in order.
  /// The time since the last tick (0 at the first), and the clock moved on.
  double advanceClock(double time);
  /// A new scene, or a proxy started outside, opens the rate limit's window.
  void watchForSceneChanges(double time, const HapticState& state);
  /// The device is lost or the proxy stale: what the hand felt, fading out.
  SpringForce fadeOut(double gainStep, HapticState& state);
  /// The spring to the proxy (fading back in after a fault), or the last force held when the
  /// finger sample cannot be used.
  SpringForce springForce(const TickInput& input, double gainStep, HapticState& state);
  void clampToMaxForce(SpringForce& spring, HapticState& state) const;
  void limitRateOfChange(Vec3& force, double time, double dt, HapticState& state) const;

  ServoParameters m_parameters;
  double m_maxForce;
  Vec3 m_lastForce;
  /// The force when the current fault began: what fades out.
  Vec3 m_fadeFrom;
  double m_fadeLevel = 1.0;
  /// The share of the spring force rendered: below 1 while fading back in after a fault.
  double m_gain = 1.0;
  bool m_faulted = false;
  bool m_started = false;
  double m_lastTime = 0.0;
  std::uint64_t m_sceneVersion = 0;
  bool m_sceneSeen = false;
  double m_rateLimitUntil = -1.0;
  LocalContactModel m_localModel;
};

} // namespace proxima
