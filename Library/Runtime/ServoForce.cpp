#include "Runtime/ServoForce.h"

#include <algorithm>
#include <cmath>

namespace proxima
{
namespace
{
/// Fade levels this close to 0 or 1 are 0 or 1: what summing dt / fadeTime leaves over.
constexpr double kGainRounding = 1e-9;
} // namespace

ServoForce::ServoForce(const ServoParameters& parameters, const DeviceLimits& limits)
  : m_parameters(parameters)
  , m_maxForce(std::min(parameters.maxForce, limits.maxForce))
{}

void ServoForce::step(const TickInput& input, HapticState& state)
{
  // Only this stage sets these; a state handed in twice must not keep the last tick's.
  state.conditions.clear(TickCondition::forceClamped);
  state.conditions.clear(TickCondition::forceFading);
  state.conditions.clear(TickCondition::forceRateLimited);
  const double dt = advanceClock(input.time);
  // A fade over fadeTime moves the gain by dt / fadeTime a tick; no fade time means at once.
  const double gainStep = m_parameters.fadeTime > 0.0 ? dt / m_parameters.fadeTime : 1.0;
  watchForSceneChanges(input.time, state);

  const bool deviceLost = !input.sample.connected;
  state.conditions.set(TickCondition::deviceLost, deviceLost);
  state.proxyStale = state.proxyAge > m_parameters.watchdogTimeout;
  SpringForce spring =
    deviceLost || state.proxyStale ? fadeOut(gainStep, state) : springForce(input, gainStep, state);
  clampToMaxForce(spring, state);
  limitRateOfChange(spring.force, input.time, dt, state);
  m_lastForce = spring.force;
  state.force = spring.force;
}

double ServoForce::advanceClock(double time)
{
  const double dt = m_started ? std::max(0.0, time - m_lastTime) : 0.0;
  m_started = true;
  m_lastTime = time;
  return dt;
}

void ServoForce::watchForSceneChanges(double time, const HapticState& state)
{
  if (m_sceneSeen && state.sceneVersion != m_sceneVersion)
  {
    m_rateLimitUntil = time + m_parameters.sceneChangeWindow;
    m_localModel.reset();
  }
  m_sceneSeen = true;
  m_sceneVersion = state.sceneVersion;
  // A proxy moved out of the object that holds the finger is far from it, a full clamped force
  // at once: ramp it in at the scene change's rate instead (from the last force, 0 at a start).
  if (state.conditions.has(TickCondition::startedOutside))
  {
    m_rateLimitUntil = time + m_parameters.sceneChangeWindow;
  }
}

ServoForce::SpringForce ServoForce::fadeOut(double gainStep, HapticState& state)
{
  // Fade what the hand was feeling, not the spring to a stale proxy: the finger may have moved
  // far from it while the proxy loop was stuck.
  if (!m_faulted)
  {
    m_faulted = true;
    m_fadeFrom = m_lastForce;
    m_fadeLevel = 1.0;
  }
  m_fadeLevel = m_fadeLevel - gainStep;
  // Ten steps of 0.1 leave 1e-16, not 0: a fade ends at exactly zero force.
  m_fadeLevel = m_fadeLevel > kGainRounding ? m_fadeLevel : 0.0;
  // Once the fault clears, the spring comes back from the level the fade reached.
  m_gain = m_fadeLevel;
  state.conditions.set(TickCondition::forceFading);
  SpringForce faded;
  faded.force = m_fadeFrom * m_fadeLevel;
  return faded;
}

ServoForce::SpringForce ServoForce::springForce(const TickInput& input, double gainStep,
                                                HapticState& state)
{
  m_faulted = false;
  SpringForce spring;
  const bool usable = input.sample.valid && !state.conditions.has(TickCondition::fingerRefused);
  if (!usable)
  {
    // Never NaN into a force (DESIGN.md section 6): hold the last one, exactly (it was clamped
    // when it was made; clamping it again can move it by rounding, so a held clamped force
    // changed in its last bit: found by the stress suite's NaN fingers).
    spring.force = m_lastForce;
    spring.held = true;
    return spring;
  }
  // A stiffness map at the contact scales kp there (1 elsewhere): the spring stays continuous,
  // since proxy and finger coincide out of contact.
  spring.stretch = state.proxy - input.sample.position;
  const double stiffness = m_parameters.stiffness * state.stiffnessScale;
  spring.force = spring.stretch * stiffness;
  // On tissue, between its steps: the contact's local model (the spring itself elsewhere).
  spring.force = m_localModel.force(state, input.sample.position, stiffness, spring.force);
  if (m_gain < 1.0)
  {
    // Fading back in after a fault.
    m_gain = m_gain + gainStep;
    m_gain = m_gain < 1.0 - kGainRounding ? m_gain : 1.0;
    spring.force = spring.force * m_gain;
    state.conditions.set(TickCondition::forceFading, m_gain < 1.0);
  }
  return spring;
}

void ServoForce::clampToMaxForce(SpringForce& spring, HapticState& state) const
{
  // Overflow-safe: a finger 1e154 m away gave |F|^2 = inf and so a "clamped" force of 0 N, and
  // beyond 1e305 m the spring force itself is infinite; the clamp keeps its direction either way.
  // norm() first: in the usual range it is the value the traces have always been clamped with.
  double magnitude = norm(spring.force);
  if (!std::isfinite(magnitude))
  {
    magnitude = overflowSafeNorm(spring.force);
  }
  if (!spring.held && magnitude > m_maxForce)
  {
    spring.force =
      std::isfinite(magnitude)
        ? spring.force * (m_maxForce / magnitude)
        : overflowSafeDirection(isFinite(spring.stretch) ? spring.stretch : spring.force) *
            m_maxForce;
    state.conditions.set(TickCondition::forceClamped);
  }
}

void ServoForce::limitRateOfChange(Vec3& force, double time, double dt, HapticState& state) const
{
  if (time < m_rateLimitUntil)
  {
    const double allowed = m_parameters.forceRateLimit * dt;
    const Vec3 change = force - m_lastForce;
    const double changeMagnitude = norm(change);
    if (changeMagnitude > allowed)
    {
      force = m_lastForce + change * (allowed / changeMagnitude);
      state.conditions.set(TickCondition::forceRateLimited);
    }
  }
}

} // namespace proxima
