// One haptic tick, the step every runner runs: device -> finger -> proxy -> (dynamics) -> force ->
// device (paper section 8; Documentation/Threading.md). Its input is a TickInput (tick, time,
// device sample) and its output a HapticState (proxy, contacts, force, flags, timings), both in
// HapticState.h. The lockstep runner (LockstepRuntime.h) and the VTK layer's lockstep pictures run
// hapticStep in one thread; the threaded runtime runs its halves on two threads, stepProxyHalf on
// the proxy thread and ServoForce::step on the servo thread, and hands the HapticState between
// them. Same steps, so a threaded run and a lockstep run of a path agree.
#pragma once

#include "Proxy/ProxySolver.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"
#include "Runtime/ServoForce.h"
#include "Runtime/TickDynamics.h"

#include <cstdint>

namespace proxima
{

/// The proxy half: the solver's update toward the input's finger (paper sections 2-4), timed, or
/// the proxy held when the sample has no usable finger. Sets the state's tick, time, finger and
/// proxy fields (not sceneVersion or proxyAge: the caller knows those).
void stepProxy(ProxySolver& solver, const TickInput& input, HapticState& state);

/// The dynamics step (paper section 6), after the force stage: the force the device renders,
/// equal and opposite, on the touched bodies (J^T f_c, eqs. 23-24), one step of the bodies, and
/// their new poses into `solver` for the next proxy update (TickDynamics.h). A scene without
/// bodies has no `dynamics` and runs nothing here.
inline void stepDynamics(TickDynamics* dynamics, ProxySolver& solver, HapticState& state)
{
  if (dynamics != nullptr)
  {
    dynamics->step(state, solver);
  }
}

/// The proxy half of a tick, which every runner runs the same way: the proxy step on `input`
/// (on the scene of version `sceneVersion`), the force stage on the fresh proxy (age 0), and the
/// dynamics step with that force when the scene has bodies. `force` keeps the force stage's
/// state across the ticks of this sequence. The lockstep runners write the state's force to the
/// device; the threaded runtime's proxy thread posts the state, and its servo thread makes the
/// device's force from it again at the servo's rate, so the bodies feel the force of the proxy's
/// sequence, as in lockstep.
void stepProxyHalf(ProxySolver& solver, const TickInput& input, std::uint64_t sceneVersion,
                   ServoForce& force, TickDynamics* dynamics, HapticState& state);

/// One whole tick in one thread: reads `device` at `time`, runs the proxy half on that sample
/// and writes its force to the device. `servo` keeps the force stage's state (last force, fade)
/// across ticks.
HapticState hapticStep(std::uint64_t tick, double time, ProxySolver& solver, HapticDevice& device,
                       ServoForce& servo, std::uint64_t sceneVersion = 0,
                       TickDynamics* dynamics = nullptr);

} // namespace proxima
