#include "Runtime/ServoTick.h"

#include <chrono>

namespace proxima
{

TickRecord runServoTick(std::uint64_t tick, double time, ProxySolver& solver, HapticDevice& device,
                        const ServoParameters& parameters, Vec3& lastForce)
{
  TickRecord record;
  record.tick = tick;
  record.time = time;
  const DeviceSample sample = device.read(time);
  record.finger = sample.position;

  const auto begin = std::chrono::steady_clock::now();
  const ProxyTickResult result =
    sample.valid ? solver.update(sample.position) : ProxyTickResult{};
  const auto end = std::chrono::steady_clock::now();
  record.solveNanoseconds =
    std::chrono::duration_cast<std::chrono::nanoseconds>(end - begin).count();

  record.proxy = solver.proxy();
  record.contacts = result.numContacts;
  record.iterations = result.iterations;
  record.hitIterationCap = result.hitIterationCap;
  record.contactOverflow = result.contactOverflow;
  record.stuck = result.stuck;
  record.frictionLimited = result.frictionLimited;
  record.trianglesTested = result.queries.trianglesTested;
  record.fingerRefused = !sample.valid || result.refusedFinger;

  Vec3 force = lastForce;
  if (!record.fingerRefused)
  {
    // A stiffness map at the contact scales kp there (1 elsewhere): the spring stays continuous,
    // since proxy and finger coincide out of contact.
    force = (record.proxy - sample.position) * (parameters.stiffness * result.stiffnessScale);
    const double magnitude = norm(force);
    if (magnitude > parameters.maxForce)
    {
      force = force * (parameters.maxForce / magnitude);
      record.forceClamped = true;
    }
  }
  record.force = force;
  lastForce = force;
  device.writeForce(force, time);
  return record;
}

} // namespace proxima
