#include "Runtime/ProxyStep.h"

#include <chrono>

namespace proxima
{

ProxyStepOutcome runProxyStep(ProxySolver& solver, const DeviceSample& sample)
{
  ProxyStepOutcome outcome;
  const bool usable = sample.valid && sample.connected;
  const auto begin = std::chrono::steady_clock::now();
  if (usable)
  {
    outcome.result = solver.update(sample.position);
  }
  const auto end = std::chrono::steady_clock::now();
  outcome.solveNanoseconds =
    std::chrono::duration_cast<std::chrono::nanoseconds>(end - begin).count();
  outcome.proxy = solver.proxy();
  outcome.refused = !usable || outcome.result.refusedFinger;
  return outcome;
}

int snapshotContacts(const ProxyTickResult& result, ContactSnapshot (&contacts)[3])
{
  const int count = result.numContacts < 3 ? result.numContacts : 3;
  for (int i = 0; i < count; ++i)
  {
    const ContactPlane& plane = result.contacts[i];
    ContactSnapshot& contact = contacts[i];
    contact.point = plane.closest.point;
    contact.normal = plane.normal;
    contact.object = plane.object;
    contact.triangle = plane.triangle;
    contact.staticFriction = plane.staticFriction;
    contact.dynamicFriction = plane.dynamicFriction;
  }
  return count;
}

} // namespace proxima
