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

} // namespace proxima
