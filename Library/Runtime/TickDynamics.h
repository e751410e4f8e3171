// The dynamics step of a haptic tick (paper section 6) as the runners see it: after the force
// stage, something that pushes the scene's bodies with the force the device renders and moves
// their objects for the next proxy update. The Dynamics layer implements it on MuJoCo
// (Dynamics/BodyCoupling.h); the runners only call it, so the Runtime layer, and every scene
// without bodies, needs no physics engine.
#pragma once

#include "Core/RigidTransform.h"
#include "Proxy/CollisionScene.h"
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

  /// The scene objects that deform (for makeDeformingObjects, off the haptic thread): none by
  /// default; a dynamics whose objects deform (Tissue/TissueDynamics.h) lists them.
  virtual std::vector<std::uint32_t> deformingObjects() const { return {}; }
  /// Off the haptic thread, before `scene` is installed: makes everything install() needs, and
  /// may allocate. A dynamics that keeps state for its scene (a tissue's coupling) is prepared
  /// for one scene once and throws std::logic_error when asked again. Nothing by default.
  virtual void prepare(const CollisionScene& scene) { (void)scene; }
  /// On the thread that owns `solver`, once it has the scene prepare() was given and the moved
  /// and deforming copies of the objects listed above (useMovingObjects, useDeformingObjects):
  /// binds to it and gives it the bodies' present poses or surfaces. Allocates nothing.
  virtual void install(ProxySolver& solver) { placeBodies(solver); }

  /// For one thread that owns `solver` (a lockstep runner), after its setScene: the whole of the
  /// above in one go (allocates).
  void attach(ProxySolver& solver)
  {
    solver.setMovingObjects(movingObjects());
    solver.setDeformingObjects(deformingObjects());
    if (solver.scene() != nullptr)
    {
      prepare(*solver.scene());
    }
    install(solver);
  }
};

} // namespace proxima
