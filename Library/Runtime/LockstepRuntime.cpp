#include "Runtime/LockstepRuntime.h"

#include "Runtime/HapticStep.h"

#include <cmath>

namespace proxima
{

std::uint64_t ticksCovering(double start, double end, double rate)
{
  if (!(end >= start) || !(rate > 0.0))
  {
    return 0;
  }
  // A small allowance keeps a path that ends exactly on a tick from losing that tick to rounding.
  return static_cast<std::uint64_t>(std::floor((end - start) * rate + 1e-9)) + 1;
}

LockstepSettings lockstepCovering(const FingerPath& path, double rate)
{
  LockstepSettings settings;
  settings.rate = rate;
  settings.startTime = path.startTime();
  settings.numTicks = ticksCovering(path.startTime(), path.endTime(), rate);
  return settings;
}

void runLockstep(const LockstepSettings& settings, ProxySolver& solver, HapticDevice& device,
                 const ServoParameters& parameters,
                 const std::function<void(const HapticState&)>& onTick, TickDynamics* dynamics)
{
  ServoForce servo(parameters, device.limits());
  for (std::uint64_t tick = 0; tick < settings.numTicks; ++tick)
  {
    // Time from the tick count, not by accumulating 1/rate: no drift over millions of ticks.
    const double time = settings.startTime + static_cast<double>(tick) / settings.rate;
    onTick(hapticStep(tick, time, solver, device, servo, 0, dynamics));
  }
}

} // namespace proxima
