// The dynamics step of a haptic tick (paper section 6) as the runners see it: after the force
// stage, something that pushes the scene's bodies with the force the device renders and moves
// their objects for the next proxy update. The Dynamics layer implements it on MuJoCo
// (Dynamics/BodyCoupling.h); the runners only call it, so the Runtime layer, and every scene
// without bodies, needs no physics engine.
#pragma once

#include "Proxy/ProxySolver.h"
#include "Runtime/HapticState.h"

namespace proxima
{

class TickDynamics
{
public:
  virtual ~TickDynamics() = default;
  /// Lets the bodies' objects move in `solver` (after its setScene), at their present poses.
  /// Off the haptic thread: it may allocate.
  virtual void attach(ProxySolver& solver) = 0;
  /// Once per tick, after the force stage filled `state.force` (the force on the finger): apply
  /// it, equal and opposite, to the bodies touched at `state.contacts`, step the bodies one
  /// period, and give `solver` their new poses. Sets `state.dynamicsNanoseconds`.
  virtual void step(HapticState& state, ProxySolver& solver) = 0;
};

} // namespace proxima
