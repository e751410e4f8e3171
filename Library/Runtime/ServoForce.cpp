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
  const double dt = m_started ? std::max(0.0, input.time - m_lastTime) : 0.0;
  m_started = true;
  m_lastTime = input.time;
  // A fade over fadeTime moves the gain by dt / fadeTime a tick; no fade time means at once.
  const double gainStep = m_parameters.fadeTime > 0.0 ? dt / m_parameters.fadeTime : 1.0;

  if (m_sceneSeen && state.sceneVersion != m_sceneVersion)
  {
    m_rateLimitUntil = input.time + m_parameters.sceneChangeWindow;
  }
  m_sceneSeen = true;
  m_sceneVersion = state.sceneVersion;
  // A proxy moved out of the object that holds the finger is far from it, a full clamped force
  // at once: ramp it in at the scene change's rate instead (from the last force, 0 at a start).
  if (state.conditions.has(TickCondition::startedOutside))
  {
    m_rateLimitUntil = input.time + m_parameters.sceneChangeWindow;
  }

  const bool deviceLost = !input.sample.connected;
  state.conditions.set(TickCondition::deviceLost, deviceLost);
  state.proxyStale = state.proxyAge > m_parameters.watchdogTimeout;
  Vec3 force;
  // The spring's extension (proxy minus finger): the direction of a force whose magnitude
  // overflowed.
  Vec3 stretch;
  bool held = false;
  if (deviceLost || state.proxyStale)
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
    force = m_fadeFrom * m_fadeLevel;
    // Once the fault clears, the spring comes back from the level the fade reached.
    m_gain = m_fadeLevel;
    state.conditions.set(TickCondition::forceFading);
  }
  else
  {
    m_faulted = false;
    const bool usable = input.sample.valid && !state.conditions.has(TickCondition::fingerRefused);
    if (usable)
    {
      // A stiffness map at the contact scales kp there (1 elsewhere): the spring stays
      // continuous, since proxy and finger coincide out of contact.
      stretch = state.proxy - input.sample.position;
      force = stretch * (m_parameters.stiffness * state.stiffnessScale);
      if (m_gain < 1.0)
      {
        m_gain = m_gain + gainStep;
        m_gain = m_gain < 1.0 - kGainRounding ? m_gain : 1.0;
        force = force * m_gain;
        state.conditions.set(TickCondition::forceFading, m_gain < 1.0);
      }
    }
    else
    {
      // Never NaN into a force (DESIGN.md section 6): hold the last one, exactly (it was clamped
      // when it was made; clamping it again can move it by rounding, so a held clamped force
      // changed in its last bit: found by the stress suite's NaN fingers).
      force = m_lastForce;
      held = true;
    }
  }

  // Overflow-safe: a finger 1e154 m away gave |F|^2 = inf and so a "clamped" force of 0 N, and
  // beyond 1e305 m the spring force itself is infinite; the clamp keeps its direction either way.
  // norm() first: in the usual range it is the value the traces have always been clamped with.
  double magnitude = norm(force);
  if (!std::isfinite(magnitude))
  {
    magnitude = overflowSafeNorm(force);
  }
  if (!held && magnitude > m_maxForce)
  {
    force = std::isfinite(magnitude)
              ? force * (m_maxForce / magnitude)
              : overflowSafeDirection(isFinite(stretch) ? stretch : force) * m_maxForce;
    state.conditions.set(TickCondition::forceClamped);
  }
  if (input.time < m_rateLimitUntil)
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
  m_lastForce = force;
  state.force = force;
}

} // namespace proxima
