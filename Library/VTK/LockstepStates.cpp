#include "VTK/LockstepStates.h"

#include "Proxy/ProxySolver.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/ProxyStep.h"
#include "Runtime/ServoForce.h"
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
  state.numContacts = result.numContacts;
  for (int i = 0; i < result.numContacts && i < 3; ++i)
  {
    const ContactPlane& plane = result.contacts[i];
    ContactSnapshot& contact = state.contacts[i];
    contact.point = plane.closest.point;
    contact.normal = plane.normal;
    contact.object = plane.object;
    contact.triangle = plane.triangle;
    contact.staticFriction = plane.staticFriction;
    contact.dynamicFriction = plane.dynamicFriction;
  }
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
    const DeviceSample sample = device.read(time);
    const ProxyStepOutcome outcome = runProxyStep(*solver, sample);
    ServoForceInput input;
    input.sample = sample;
    input.proxy = outcome.proxy;
    input.stiffnessScale = outcome.result.stiffnessScale;
    input.proxyRefused = outcome.refused;
    input.sceneVersion = 1;
    input.time = time;
    const ServoForceOutput output = force.step(input);
    device.writeForce(output.force, time);
    if (!onState(hapticStateOf(tick, time, sample.position, outcome.result, outcome.proxy,
                               parameters.radius, output.force, output.fading)))
    {
      return;
    }
  }
}

} // namespace proxima::vtk
