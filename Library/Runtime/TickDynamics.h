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
#include <memory>
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

  /// What a dynamics keeps for one scene besides its own state (a tissue's coupling to the
  /// solver: its buffers and the press it is summing). Made by prepare() off the haptic thread,
  /// owned and freed by whoever published the scene (ThreadedRuntime's scene slot), so that a
  /// scene published again, or to a new runtime, gets its own while the old one is still used.
  class SceneBinding
  {
  public:
    virtual ~SceneBinding() = default;
  };
  /// Off the haptic thread, before `scene` is installed: makes what install() needs for it, and
  /// may allocate; null when nothing is needed (the default, and bodies). Throws
  /// std::invalid_argument for a scene this dynamics cannot act on.
  virtual std::unique_ptr<SceneBinding> prepare(const CollisionScene& scene)
  {
    (void)scene;
    return nullptr;
  }
  /// Called by a real-time runner (ThreadedRuntime::publishScene) on the publisher's thread
  /// before prepare(): a dynamics whose step is long may from now on run it on a thread of its
  /// own, handing its result to the solver in beforeUpdate(); with `fifoPriority` above 0 it
  /// asks for SCHED_FIFO at that priority (the runner's loops run above it). Nothing by default.
  virtual void runStepsOnOwnThread(int fifoPriority) { (void)fifoPriority; }
  /// Before each proxy update (HapticStep.h: stepProxyHalf), on the solver's thread: a step
  /// finished on the dynamics' own thread gives the solver its result here. True when the
  /// update is to meet a surface older than lockstep would give it (a step still running): the
  /// tick is flagged TickCondition::surfaceLagging. Nothing by default. Allocates nothing; never
  /// waits.
  virtual bool beforeUpdate(ProxySolver& solver, std::uint64_t tick)
  {
    (void)solver;
    (void)tick;
    return false;
  }
  /// On the thread that owns `solver`, once it has the scene prepare() made `binding` for and the
  /// moved and deforming copies of the objects listed above (useMovingObjects,
  /// useDeformingObjects): acts through `binding` from now on and gives the solver the bodies'
  /// present poses or surfaces. `binding` must outlive its use (until the next install). Allocates
  /// nothing.
  virtual void install(ProxySolver& solver, SceneBinding* binding)
  {
    (void)binding;
    placeBodies(solver);
  }

  /// For one thread that owns `solver` (a lockstep runner), after its setScene: the whole of the
  /// above in one go (allocates); the binding is kept here.
  void attach(ProxySolver& solver)
  {
    solver.setMovingObjects(movingObjects());
    solver.setDeformingObjects(deformingObjects());
    std::unique_ptr<SceneBinding> binding =
      solver.scene() != nullptr ? prepare(*solver.scene()) : nullptr;
    install(solver, binding.get());
    m_attached = std::move(binding);
  }

private:
  /// attach()'s binding.
  std::unique_ptr<SceneBinding> m_attached;
};

} // namespace proxima
