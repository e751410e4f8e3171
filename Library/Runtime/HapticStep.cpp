#include "Runtime/HapticStep.h"

#include <chrono>

namespace proxima
{

void stepProxy(ProxySolver& solver, const TickInput& input, HapticState& state)
{
  state.tick = input.tick;
  state.time = input.time;
  state.finger = input.sample.position;
  const bool usable = input.sample.valid && input.sample.connected;
  ProxyTickResult result;
  const auto begin = std::chrono::steady_clock::now();
  if (usable)
  {
    result = solver.update(input.sample.position);
  }
  const auto end = std::chrono::steady_clock::now();
  state.solveNanoseconds =
    std::chrono::duration_cast<std::chrono::nanoseconds>(end - begin).count();
  state.proxy = solver.proxy();
  state.proxyRadius = solver.radius();

  state.numContacts = result.numContacts < 3 ? result.numContacts : 3;
  for (int i = 0; i < state.numContacts; ++i)
  {
    const ContactPlane& plane = result.contacts[i];
    ContactSnapshot& contact = state.contacts[i];
    contact.point = plane.closest.point;
    contact.normal = plane.normal;
    contact.object = plane.object;
    contact.triangle = plane.triangle;
    contact.staticFriction = plane.staticFriction;
    contact.dynamicFriction = plane.dynamicFriction;
    contact.depth = plane.depth;
    contact.deforms = solver.isDeforming(plane.object);
  }
  state.surfaceChanges = solver.surfaceChanges();
  state.contactObject = result.numContacts > 0 ? static_cast<int>(result.contacts[0].object) : -1;
  state.iterations = result.iterations;
  state.trianglesTested = result.queries.trianglesTested;
  state.stiffnessScale = result.stiffnessScale;
  // The proxy step's conditions are the solver's, and a refused sample's; the force step's are
  // left as they are for ServoForce to set.
  state.conditions = state.conditions.without(kProxyStepConditions) | result.conditions;
  if (!usable)
  {
    state.conditions.set(TickCondition::fingerRefused);
  }
}

void stepProxyHalf(ProxySolver& solver, const TickInput& input, std::uint64_t sceneVersion,
                   ServoForce& force, TickDynamics* dynamics, HapticState& state)
{
  const bool lagging = dynamics != nullptr && dynamics->beforeUpdate(solver, input.tick);
  stepProxy(solver, input, state);
  state.conditions.set(TickCondition::surfaceLagging, lagging);
  state.sceneVersion = sceneVersion;
  state.proxyAge = 0.0;
  force.step(input, state);
  stepDynamics(dynamics, solver, state);
}

HapticState hapticStep(std::uint64_t tick, double time, ProxySolver& solver, HapticDevice& device,
                       ServoForce& servo, std::uint64_t sceneVersion, TickDynamics* dynamics)
{
  const TickInput input{tick, time, device.read(time)};
  HapticState state;
  stepProxyHalf(solver, input, sceneVersion, servo, dynamics, state);
  device.writeForce(state.force, time);
  return state;
}

} // namespace proxima
