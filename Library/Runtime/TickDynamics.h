// The dynamics step of a haptic tick (paper section 6) as the runners see it: after the force
// stage, something that pushes the scene's bodies with the force the device renders and moves
// their objects for the next proxy update. The Dynamics layer implements it on MuJoCo
// (Dynamics/BodyCoupling.h); the runners only call it, so the Runtime layer, and every scene
// without bodies, needs no physics engine.
#pragma once

#include "Core/RigidTransform.h"
#include "Proxy/ProxySolver.h"
#include "Runtime/HapticState.h"

#include <cstdint>
#include <vector>

namespace proxima
{

/// Where the bodies' objects are, for a viewer: plain values, so that a copy is a snapshot the
/// threaded runtime can hand over without locks. The first kCapacity bodies of a scene.
struct BodyPoses
{
  /// Most bodies a snapshot holds; a scene's bodies past it are left out.
  static constexpr int kCapacity = 16;
  /// The tick whose dynamics step left the bodies here.
  std::uint64_t tick = 0;
  /// Number of bodies held, 0 to kCapacity: the first entries of `objects` and `poses`.
  int count = 0;
  /// Scene object index of each body.
  std::uint32_t objects[kCapacity] = {};
  /// Each object's pose: where a point of the object as placed is now.
  RigidTransform poses[kCapacity];
};

/// The dynamics step of a haptic tick: moves a scene's bodies with the force the device renders.
/// Implemented by the Dynamics layer; called by the runners on the thread that owns the solver.
class TickDynamics
{
public:
  virtual ~TickDynamics() = default;

  /// The scene objects that move (for makeMovingObjects, off the haptic thread).
  virtual std::vector<std::uint32_t> movingObjects() const = 0;
  /// Gives `solver` the bodies' present poses. Allocates nothing.
  virtual void placeBodies(ProxySolver& solver) const = 0;
  /// Once per tick, after the force stage filled `state.force` (the force on the finger): apply
  /// it, equal and opposite, to the bodies touched at `state.contacts`, step the bodies one
  /// period, and give `solver` their new poses. Sets `state.dynamicsNanoseconds`. Allocates
  /// nothing.
  virtual void step(HapticState& state, ProxySolver& solver) = 0;
  /// The bodies' present poses (`tick` is left to the caller). Allocates nothing.
  virtual void poses(BodyPoses& out) const = 0;

  /// For one thread that owns `solver`: lets the bodies' objects move in it (after its
  /// setScene; allocates their moved copies) at their present poses. A dynamics whose objects
  /// deform instead (Tissue/TissueDynamics.h) makes them deforming here.
  virtual void attach(ProxySolver& solver)
  {
    solver.setMovingObjects(movingObjects());
    placeBodies(solver);
  }
};

} // namespace proxima
