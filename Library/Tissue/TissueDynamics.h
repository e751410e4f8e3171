// A scene's tissues as the runners' dynamics step (Runtime/TickDynamics.h): each tissue object's
// elastic solid coupled to the proxy (TissueContact), pressed by the proxy's spring every tick and
// stepped at its own slower rate. In lockstep the solids step at a step's tick and the next
// proxy update meets their surface; in a real-time runner they step on a thread of their own
// (runStepsOnOwnThread), so the proxy thread only loads the press and hands the surface over
// before the first update after the step finished: the same run while a step takes less than a
// tick, a surface a few ticks late when it takes longer, and a proxy thread that never waits. What a
// scene file's "tissue" objects become (IO/Scene/SceneTissue.h); `proxima run --scene` plays it
// in lockstep, so that a run with tissue is reproducible bit for bit.
#pragma once

#include "Runtime/TickDynamics.h"
#include "Runtime/TripleBuffer.h"
#include "Tissue/ElasticSolid.h"
#include "Tissue/TetMesh.h"
#include "Tissue/TissueContact.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace proxima
{

/// One deforming object of a scene: its tetrahedra at rest in the scene's frame, whose boundary
/// (boundarySoup) is the scene object's mesh, point for point.
struct TissueObject
{
  /// The scene object whose surface the solid is.
  std::uint32_t object = 0;
  /// The solid at rest, in the scene's frame.
  TetMesh tets;
  /// One material per tetrahedron (a nodule is an inclusion of stiffer ones).
  std::vector<ElasticMaterial> materials;
  /// Density, damping, step and solver iterations.
  ElasticSolidSettings settings;
  /// The vertices held where they rest (the organ's attachment).
  std::vector<std::uint32_t> fixedVertices;
};

/// What a tissue is doing after a tick, for `--tissue-out` and the summary.
struct TissueReading
{
  /// The largest distance of any vertex from its rest position (m), as the last step left it.
  double maxDisplacement = 0.0;
  /// How far the proxy presses into the tissue (m): the depth of its deepest point below the
  /// tangent plane, at rest, of the surface point it touches (that point's weights on its
  /// triangle give the same material point at rest); Hertz's indentation where the surface was
  /// flat. 0 when the proxy does not touch the tissue.
  double indentation = 0.0;
  /// The magnitude of the force the proxy's spring pressed the tissue with this tick (N).
  double force = 0.0;
  /// True when the proxy touched the tissue this tick.
  bool touched = false;
};

/// The tissues of a scene, stepped by the runners once per tick (after the force stage) on the
/// thread that owns the solver. The solids step every ticksPerStep() ticks, at the ticks whose
/// number plus one is a multiple of it.
class TissueDynamics : public TickDynamics
{
public:
  /// `stiffness` is the servo's kp (N/m) and `rate` its tick rate (Hz). Each solid's step is its
  /// settings' timeStep rounded to a whole number of ticks (at least one), the same for every
  /// tissue: the first one's. Throws std::invalid_argument for materials or settings the solid
  /// refuses (ElasticSolid), a fixed vertex out of range, or no tissue.
  TissueDynamics(std::vector<TissueObject> tissues, double stiffness, double rate);
  ~TissueDynamics() override;

  /// None: tissues deform, they do not move as rigid bodies.
  std::vector<std::uint32_t> movingObjects() const override { return {}; }
  /// The tissues' scene objects: they deform.
  std::vector<std::uint32_t> deformingObjects() const override;
  /// Couples each solid to its object of `scene` (allocates; any thread but the haptic ones): the
  /// binding holds each tissue's TissueContact. Throws std::invalid_argument when an object is
  /// not in the scene or its mesh does not have its solid's points.
  std::unique_ptr<SceneBinding> prepare(const CollisionScene& scene) override;
  /// Acts through `binding` (prepare's, for the scene `solver` has, with these objects
  /// deforming) from now on: binds its couplings to `solver` and gives it the solids' present
  /// surfaces. A null or foreign binding leaves the solids unpressed and unstepped. Allocates
  /// nothing.
  void install(ProxySolver& solver, SceneBinding* binding) override;
  /// Gives `solver` the solids' present surfaces (after install). Allocates nothing.
  void placeBodies(ProxySolver& solver) const override;
  /// Presses each tissue with the tick's contacts on it (kp times their depths along their
  /// normals), and at the ticks whose number plus one is a multiple of ticksPerStep() (or the
  /// first tick after one, when a threaded runner skipped it, or the solids' thread was still
  /// stepping) hands the solver the surfaces the last step left and launches the next step under
  /// the mean press. Sets `state.dynamicsNanoseconds`. Allocates nothing; never waits.
  void step(HapticState& state, ProxySolver& solver) override;
  /// Before the proxy update of tick `tick`: a step that finished on the solids' thread is handed
  /// to the solver, so that this update meets its surface. Allocates nothing; never waits.
  bool beforeUpdate(ProxySolver& solver, std::uint64_t tick) override;
  /// From now on the solids step on a thread of their own, started here (once; joined when this
  /// is destroyed), so that a long step costs the proxy thread nothing: ThreadedRuntime calls it
  /// when a scene is published. With `fifoPriority` above 0 the thread asks for SCHED_FIFO at it
  /// (a refusal leaves it at normal priority). Without it (lockstep) they step on the caller's
  /// thread.
  void runStepsOnOwnThread(int fifoPriority) override;
  /// True once the solids step on their own thread.
  bool stepsOnOwnThread() const { return m_solidThread.joinable(); }
  /// Waits until no step is in flight (after a real-time run, before reading solid()); returns
  /// at once in lockstep. Not on a haptic thread.
  void waitForSolids() const;
  /// The step ticks at which the last step was still running on the solids' thread, so that the
  /// next launched late (never in lockstep).
  std::uint64_t lateSteps() const { return m_lateSteps; }
  /// The proxy updates that met a surface older than lockstep would have given them: the step
  /// launched before them had not finished (never in lockstep). While there are none, a
  /// real-time run is lockstep's bit for bit, sample for sample.
  std::uint64_t staleUpdates() const { return m_staleUpdates; }
  /// The first such update's tick, or the largest std::uint64_t while there is none.
  std::uint64_t firstStaleUpdate() const { return m_firstStaleUpdate; }
  /// No rigid poses: count 0.
  void poses(BodyPoses& out) const override { out.count = 0; }

  /// The number of tissues.
  std::size_t numTissues() const { return m_tissues.size(); }
  /// Tissue `k`'s scene object.
  std::uint32_t object(std::size_t k) const { return m_tissues[k].object; }
  /// Tissue `k`'s solid, a step ahead of the surface handed to the solver while a step is in
  /// flight (a real-time run's last: waitForSolids() first).
  const ElasticSolid& solid(std::size_t k) const { return *m_tissues[k].solid; }
  /// Tissue `k`'s surface as last handed to the solver: the points of the surface the proxy
  /// rests on (the solid's at rest before the first hand-over). On the solver's thread or after
  /// the run.
  const std::vector<Vec3>& surface(std::size_t k) const { return m_tissues[k].handedOver; }
  /// Tissue `k` after the last tick.
  const TissueReading& reading(std::size_t k) const { return m_tissues[k].reading; }
  /// The largest indentation tissue `k` has had in the run so far (m).
  double deepestIndentation(std::size_t k) const { return m_tissues[k].deepest; }
  /// The ticks between two steps of the solids.
  int ticksPerStep() const { return m_ticksPerStep; }
  /// The solids' steps so far.
  std::uint64_t steps() const { return m_steps; }

  /// The tissues' surfaces as a step left them, for drawing on another thread.
  struct Surfaces
  {
    /// The tick whose step left them (0 with the surfaces at rest, before any step).
    std::uint64_t tick = 0;
    /// The solids' steps so far when they were handed over.
    std::uint64_t steps = 0;
    /// Per tissue (in the order of object()), its solid's points: its object's mesh's points.
    std::vector<std::vector<Vec3>> points;
  };
  /// For one reader thread (a window drawing a live run), while the solids step on another:
  /// takes the surfaces of the newest step, and returns true, or returns false when no step came
  /// since the last take. The newest taken are latestSurfaces(); at rest before any take.
  bool takeSurfaces() { return m_surfaces.take(); }
  /// The surfaces the last takeSurfaces() took (the reader's thread only).
  const Surfaces& latestSurfaces() const { return m_surfaces.front(); }

private:
  struct Tissue
  {
    std::uint32_t object = 0;
    std::unique_ptr<ElasticSolid> solid;
    TissueReading reading;
    double deepest = 0.0;
    /// The points last handed to the solver.
    std::vector<Vec3> handedOver;
    /// True when the step in flight steps this solid (its coupling was bound at the launch).
    bool launched = false;
  };
  /// What prepare() makes: per tissue, its coupling to the scene's solver.
  struct Binding;
  /// Tissue `k`'s coupling when installed and bound to a solver, else null.
  TissueContact* coupling(std::size_t k) const;
  /// Copies the surfaces handed over into the drawing hand-over and publishes them (no
  /// allocation).
  void publishSurfaces(std::uint64_t tick);
  /// Hands the solver the surfaces the step in flight left (it has finished), and publishes
  /// them for drawing as left by the step of its launch's tick.
  void handOver(ProxySolver& solver);
  /// Loads the press into each bound solid and starts their step (on their thread, or here).
  void launch();
  /// Steps the solids launch() loaded (on the solids' thread, or the caller's in lockstep).
  void stepLaunchedSolids();
  /// True when the step in flight has finished.
  bool launchedStepDone() const;
  /// The solids' thread: steps each launch, sleeping between.
  void solidThreadLoop();
  /// The indentation of `tissue` by the proxy at `proxy` touching triangle `triangle` at `point`.
  double indentationAt(const Tissue& tissue, const ProxySolver& solver, std::uint32_t triangle,
                       const Vec3& point, const Vec3& proxy) const;

  std::vector<Tissue> m_tissues;
  /// The binding install() was given (owned by whoever published the scene), or null.
  Binding* m_binding = nullptr;
  /// The surfaces after each step, to a drawing thread.
  TripleBuffer<Surfaces> m_surfaces;
  double m_stiffness = 0.0;
  int m_ticksPerStep = 1;
  /// The tick at which the solids step next: the first whose number plus one is a multiple of
  /// m_ticksPerStep after the last step's.
  std::uint64_t m_nextStepTick = 0;
  /// The last tick step() was given, once it has been given one.
  std::uint64_t m_lastTick = 0;
  bool m_ticked = false;
  std::uint64_t m_steps = 0;
  /// A launched step not yet handed over, and a step tick that found it still running.
  bool m_inFlight = false;
  bool m_launchLate = false;
  std::uint64_t m_lateSteps = 0;
  /// The tick whose step is in flight (or was last).
  std::uint64_t m_launchTick = 0;
  std::uint64_t m_staleUpdates = 0;
  std::uint64_t m_firstStaleUpdate = ~std::uint64_t{0};
  /// The time the hand-over before this tick's update took (ns), added to its dynamics time.
  std::int64_t m_handOverNanoseconds = 0;
  /// Steps launched (the haptic thread's count, published to the solids' thread in
  /// m_requested) and finished (the solids' thread's, or the launcher's in lockstep).
  std::uint32_t m_launched = 0;
  std::atomic<std::uint32_t> m_requested{0};
  mutable std::atomic<std::uint32_t> m_completed{0};
  std::atomic<bool> m_stopping{false};
  std::thread m_solidThread;
};

} // namespace proxima
