#include "Runtime/LockstepTick.h"

namespace proxima
{

ServoForceInput freshForceInput(const DeviceSample& sample, const ProxyStepOutcome& outcome,
                                double time, std::uint64_t sceneVersion)
{
  ServoForceInput input;
  input.sample = sample;
  input.proxy = outcome.proxy;
  input.stiffnessScale = outcome.result.stiffnessScale;
  input.proxyRefused = outcome.refused;
  input.sceneVersion = sceneVersion;
  input.time = time;
  return input;
}

LockstepTick stepLockstepTick(double time, ProxySolver& solver, HapticDevice& device,
                              ServoForce& servo, std::uint64_t sceneVersion)
{
  LockstepTick tick;
  tick.sample = device.read(time);
  tick.outcome = runProxyStep(solver, tick.sample);
  tick.force = servo.step(freshForceInput(tick.sample, tick.outcome, time, sceneVersion));
  device.writeForce(tick.force.force, time);
  return tick;
}

} // namespace proxima
