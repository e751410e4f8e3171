#include "VTK/LockstepStates.h"

#include "Proxy/ProxySolver.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/HapticStep.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"

#include <memory>

namespace proxima::vtk
{

void playLockstepStates(const CollisionScene& scene, const ProxyParameters& parameters,
                        const ServoParameters& servo, const FingerPath& path, double rate,
                        const std::function<bool(const HapticState&)>& onState)
{
  SimulatedDevice device(path);
  playLockstepStates(scene, parameters, servo, path, rate, device, onState);
}

void playLockstepStates(const CollisionScene& scene, const ProxyParameters& parameters,
                        const ServoParameters& servo, const FingerPath& path, double rate,
                        HapticDevice& device,
                        const std::function<bool(const HapticState&)>& onState,
                        TickDynamics* bodies)
{
  // The solver is large (fixed buffers): on the heap, not the stack.
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  // As `proxima run` starts it: outside the closed object the path may start in (ProxyStart.h).
  resetProxyTo(*solver, placeProxyStart(scene, parameters, path.positions.front()));
  if (bodies != nullptr)
  {
    bodies->attach(*solver);
  }
  ServoForce force(servo, device.limits());
  const std::uint64_t numTicks = ticksCovering(path.startTime(), path.endTime(), rate);
  for (std::uint64_t tick = 0; tick < numTicks; ++tick)
  {
    const double time = path.startTime() + static_cast<double>(tick) / rate;
    // Scene version 1, as the threaded runtime numbers its first scene.
    if (!onState(hapticStep(tick, time, *solver, device, force, 1, bodies)))
    {
      return;
    }
  }
}

} // namespace proxima::vtk
