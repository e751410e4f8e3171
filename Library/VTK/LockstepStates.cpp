#include "VTK/LockstepStates.h"

#include "Proxy/ProxySolver.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/LockstepTick.h"
#include "Runtime/SimulatedDevice.h"

#include <memory>

namespace proxima::vtk
{

HapticState hapticStateOf(std::uint64_t tick, double time, const Vec3& finger,
                          const ProxyTickResult& result, const Vec3& proxy, double proxyRadius,
                          const Vec3& force, bool fading)
{
  HapticState state;
  state.tick = tick;
  state.time = time;
  state.finger = finger;
  state.proxy = proxy;
  state.proxyRadius = proxyRadius;
  state.force = force;
  state.numContacts = snapshotContacts(result, state.contacts);
  state.stuck = result.stuck;
  state.frictionLimited = result.frictionLimited;
  state.fading = fading;
  state.sceneVersion = 1;
  return state;
}

void playLockstepStates(const CollisionScene& scene, const ProxyParameters& parameters,
                        const ServoParameters& servo, const FingerPath& path, double rate,
                        const std::function<bool(const HapticState&)>& onState)
{
  // The solver is large (fixed buffers): on the heap, not the stack.
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  solver->resetProxy(path.positions.front());
  SimulatedDevice device(path);
  ServoForce force(servo, device.limits());
  const std::uint64_t numTicks = ticksCovering(path.startTime(), path.endTime(), rate);
  for (std::uint64_t tick = 0; tick < numTicks; ++tick)
  {
    const double time = path.startTime() + static_cast<double>(tick) / rate;
    const LockstepTick step = stepLockstepTick(time, *solver, device, force, 1);
    if (!onState(hapticStateOf(tick, time, step.sample.position, step.outcome.result,
                               step.outcome.proxy, parameters.radius, step.force.force,
                               step.force.fading)))
    {
      return;
    }
  }
}

} // namespace proxima::vtk
