#include "Runtime/ServoTick.h"

#include "Runtime/LockstepTick.h"

namespace proxima
{

TickRecord makeTickRecord(std::uint64_t tick, double time, const DeviceSample& sample,
                          const ProxyStepOutcome& outcome, const ServoForceOutput& force)
{
  TickRecord record;
  record.tick = tick;
  record.time = time;
  record.finger = sample.position;
  record.proxy = outcome.proxy;
  record.solveNanoseconds = outcome.solveNanoseconds;
  const ProxyTickResult& result = outcome.result;
  record.contacts = result.numContacts;
  record.iterations = result.iterations;
  record.hitIterationCap = result.hitIterationCap;
  record.contactOverflow = result.contactOverflow;
  record.stuck = result.stuck;
  record.frictionLimited = result.frictionLimited;
  record.trianglesTested = result.queries.trianglesTested;
  record.fingerRefused = outcome.refused;
  record.force = force.force;
  record.forceClamped = force.clamped;
  record.fading = force.fading;
  record.deviceLost = force.deviceLost;
  record.rateLimited = force.rateLimited;
  return record;
}

TickRecord runServoTick(std::uint64_t tick, double time, ProxySolver& solver, HapticDevice& device,
                        ServoForce& servo)
{
  const LockstepTick step = stepLockstepTick(time, solver, device, servo);
  return makeTickRecord(tick, time, step.sample, step.outcome, step.force);
}

} // namespace proxima
