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
  record.budgetLimited = result.budgetLimited;
  record.contactObject = result.numContacts > 0 ? static_cast<int>(result.contacts[0].object) : -1;
  record.trianglesTested = result.queries.trianglesTested;
  record.fingerRefused = outcome.refused;
  record.force = force.force;
  record.forceClamped = force.clamped;
  record.fading = force.fading;
  record.deviceLost = force.deviceLost;
  record.rateLimited = force.rateLimited;
  return record;
}

std::uint32_t tickFlags(const TickRecord& record)
{
  std::uint32_t flags = 0;
  const auto set = [&flags](bool condition, TickFlag flag) { flags |= condition ? flag : 0u; };
  set(record.budgetLimited, kTickBudgetLimited);
  set(record.hitIterationCap, kTickIterationCap);
  set(record.forceClamped, kTickForceClamped);
  set(record.fading, kTickForceFading);
  set(record.deviceLost, kTickDeviceLost);
  set(record.fingerRefused, kTickFingerRefused);
  set(record.stuck, kTickStuck);
  set(record.frictionLimited, kTickFrictionLimited);
  set(record.contactOverflow, kTickContactOverflow);
  set(record.rateLimited, kTickForceRateLimited);
  return flags;
}

TickRecord runServoTick(std::uint64_t tick, double time, ProxySolver& solver, HapticDevice& device,
                        ServoForce& servo)
{
  const LockstepTick step = stepLockstepTick(time, solver, device, servo);
  return makeTickRecord(tick, time, step.sample, step.outcome, step.force);
}

} // namespace proxima
