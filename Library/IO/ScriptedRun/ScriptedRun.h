// A scripted run: a finger path played through a scene in lockstep (the virtual clock of
// Runtime/LockstepRuntime.h), one HapticState per tick, and the summary `proxima run` prints.
// The command line and the Python module both run paths through here, so that a trace is the
// same, bit for bit but the solve times, whoever asked for it.
#pragma once

#include "IO/InputChecks/ParameterRanges.h"
#include "IO/Scene/SceneBuilder.h"
#include "IO/Scene/SceneTissue.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticDevice.h"
#include "Runtime/HapticState.h"
#include "Runtime/RunSummary.h"
#include "Runtime/TickBudget.h"
#include "Runtime/TickDynamics.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace proxima
{

class BodyCoupling;

/// A body of the scene at the end of a run (paper section 6), for the summary.
struct BodyOutcome
{
  /// The body's name (BodyCoupling::name).
  std::string name;
  /// The scene object the body moves.
  std::uint32_t object = 0;
  /// The joint's type: "hinge", "slide", "ball", "free" or "mechanism".
  std::string joint;
  /// The joint coordinate (hinge: rad; slide: m; ball, free and mechanism: the angle of the
  /// body's turn from the start, rad) and its rate (for those: the angular speed, rad/s).
  double jointPosition = 0.0;
  /// The joint coordinate's rate at the end (rad/s or m/s; for ball, free and mechanism bodies
  /// the angular speed, rad/s).
  double jointVelocity = 0.0;
  /// Kinetic energy at the end (J).
  double kinetic = 0.0;
  /// Potential energy at the end (J).
  double potential = 0.0;
  /// The work the finger did on the body over the run (J).
  double work = 0.0;
  /// Seconds into the run at which the body left the scene's bounds (Documentation/Dynamics.md),
  /// or -1 when it stayed.
  double leftBoundsAt = -1.0;
};

/// A tissue of the scene at the end of a run (Documentation/Tissue.md), for the summary.
struct TissueOutcome
{
  /// The scene object whose surface the solid is.
  std::uint32_t object = 0;
  /// The solid's tetrahedra and vertices, and of them the vertices held in its fixed box.
  std::size_t tetrahedra = 0;
  /// The solid's vertices.
  std::size_t vertices = 0;
  /// The vertices held in the fixed box.
  std::size_t fixedVertices = 0;
  /// Servo ticks between two steps of the solid, and the steps it took.
  int ticksPerStep = 1;
  /// The solid's steps over the run.
  std::uint64_t steps = 0;
  /// On the real clock, where the solid steps on its own thread: the steps launched late, the
  /// last one still running at their tick (TissueDynamics::lateSteps). 0 in lockstep.
  std::uint64_t lateSteps = 0;
  /// On the real clock: the proxy updates that met a surface a step older than lockstep's
  /// (TissueDynamics::staleUpdates). 0 in lockstep.
  std::uint64_t staleUpdates = 0;
  /// The deepest the proxy pushed the surface in over the run (m).
  double deepestIndentation = 0.0;
  /// The largest distance of a vertex from its rest position at the end (m).
  double maxDisplacement = 0.0;
  /// Kinetic plus elastic energy at the end (J).
  double energy = 0.0;
  /// Wall time of meshing (or reading) the tetrahedra when the scene was built (s).
  double meshingSeconds = 0.0;
};

/// What playing a path gave, beside the ticks themselves.
struct ScriptedRunOutcome
{
  /// The statistics of the run's ticks.
  RunSummary summary;
  /// Where the proxy started: at the path's first sample, or moved out of a closed object.
  ProxyStartPlacement start;
  /// The budget the ticks ran with.
  TickWorkBudget budget;
  /// The contact skin the solver used (the settings', or the scene's when they give 0).
  double skin = 0.0;
  /// Wall time of the ticks (ms), without the replays.
  double runMilliseconds = 0.0;
  /// Wall time of replaying the budget-limited ticks without the budget to measure their
  /// residual (ms); not part of the run's time.
  double replayMilliseconds = 0.0;
  /// The scene's bodies at the end (empty without bodies).
  std::vector<BodyOutcome> bodies;
  /// The scene's tissues at the end (empty without tissue).
  std::vector<TissueOutcome> tissues;
};

/// Plays `path` through `scene` in lockstep at the settings' rate, reading the finger from
/// `device` (a SimulatedDevice of `path` for a plain scripted run). The proxy starts at the
/// path's first sample, or outside the closed object that holds it (ProxyStart.h). Each tick is
/// handed to `onTick` as it ends, then added to the summary; a budget-limited tick is replayed
/// without the budget for its residual. `byDefault` is the budget when the settings give none.
/// `progress`, when set, is called now and then with the ticks done. With `bodies` (the scene's,
/// buildSceneBodies), each tick ends with their dynamics step, and `onTick` sees them where that
/// step left them; with `tissue` (buildSceneTissue; a scene has bodies or tissue, not both),
/// each tick ends with the tissues' step instead.
ScriptedRunOutcome playScriptedPath(const ScriptedRunSettings& settings,
                                    const CollisionScene& scene, const FingerPath& path,
                                    HapticDevice& device,
                                    const std::function<void(const HapticState&)>& onTick,
                                    const std::function<void(std::uint64_t)>& progress = {},
                                    BodyCoupling* bodies = nullptr,
                                    TissueDynamics* tissue = nullptr);

/// The summary's report of each tissue of `tissue` where the run left it; `loaded` gives their
/// sizes and meshing times.
std::vector<TissueOutcome> tissueOutcomes(const TissueDynamics& tissue, const LoadedScene& loaded);

/// One body where a tick's dynamics step left it: a row of `--bodies-out` (BodyPoseWriter).
struct BodyPoseRow
{
  /// The tick whose dynamics step left the body here.
  std::uint64_t tick = 0;
  /// That tick's time (s).
  double time = 0.0;
  /// The scene object the body moves.
  std::uint32_t object = 0;
  /// The world pose of the object's frame: a point p of the object as placed is now at
  /// position + rotate(orientation, p); orientation is w, x, y, z.
  Vec3 position;
  /// The object's orientation, a unit quaternion (w, x, y, z).
  double orientation[4] = {1.0, 0.0, 0.0, 0.0};
  /// BodyWorld::jointPosition.
  double jointPosition = 0.0;
};

/// Hands each body of `bodies` where it is now to `onPose`, as the row of the tick `record`.
void forEachBodyPose(const BodyCoupling& bodies, const HapticState& record,
                     const std::function<void(const BodyPoseRow&)>& onPose);

/// The refusal of --bodies-out for a scene without bodies, as every runner words it.
[[noreturn]] void refuseBodiesOutWithoutBodies();

/// The summary's report of each body where `bodies` left it.
std::vector<BodyOutcome> bodyOutcomes(BodyCoupling& bodies);

/// The bodies of `loaded`'s scene coupled at the settings' kp and rate, or null when it has
/// none. Throws InputError as buildSceneBodies does, or when this build has no Dynamics layer.
std::unique_ptr<BodyCoupling> sceneBodies(const ScriptedRunSettings& settings,
                                          const LoadedScene& loaded);
/// The scene's bodies, or its tissues (coupled as buildSceneTissue does), as the runners see them
/// (for HapticSession::setDynamics, ThreadedRuntime::publishScene and the like), or null. Throws
/// InputError as sceneBodies does.
std::shared_ptr<TickDynamics> sceneDynamics(const ScriptedRunSettings& settings,
                                            const LoadedScene& loaded);

/// What a scripted run reads and checks before it plays anything, made by prepareScriptedRun.
/// Every runner of a scripted path (runScriptedPath, `proxima run` in lockstep or on the real
/// clock) starts from it, so that all of them refuse the same inputs in the same words.
struct PreparedScriptedRun
{
  /// The settings' scene, its trees built.
  LoadedScene loaded;
  /// The scene's bodies coupled at the settings' kp and rate, or null when it has none.
  std::unique_ptr<BodyCoupling> bodies;
  /// The scene's tissues coupled at the settings' kp and rate, or null when it has none.
  std::unique_ptr<TissueDynamics> tissue;
  /// The servo ticks that cover the path at the settings' rate.
  std::uint64_t numTicks = 0;
  /// Wall time of reading the scene (without building its trees).
  double readMilliseconds = 0.0;
};

/// Checks the settings, the path (not empty, at most `maxTicks` ticks at the settings' rate),
/// loads the scene, checks the proxy's radius against it and the path's start, and builds the
/// scene's bodies or tissues. Throws InputError naming the option or file (`settings.path` names the path);
/// nothing is written.
PreparedScriptedRun prepareScriptedRun(const ScriptedRunSettings& settings, const FingerPath& path,
                                       double maxTicks);

/// What the summary names beside the settings and the outcome.
struct ScriptedRunReportContext
{
  /// "sim" for a scripted path, or the device the finger came from.
  std::string device = "sim";
  /// The trace file written, empty when none was.
  std::string trace;
  /// True for a run on the real clock (the threaded runtime), whose ticks cannot be replayed;
  /// false for a lockstep run.
  bool realtime = false;
  /// Wall time of reading the scene and the path (without building the trees).
  double readMilliseconds = 0.0;
};

/// The summary of a run as `proxima run` prints it (Documentation/CommandLine.md): JSON text,
/// indented by two, ending in a newline. `loaded` gives the objects' files and triangle counts,
/// `scene` their materials; `realtimeJson`, when not empty, is the JSON object of the threaded
/// runtime's loops (the summary's "realtime").
std::string scriptedRunSummaryJson(const ScriptedRunSettings& settings, const LoadedScene& loaded,
                                   const CollisionScene& scene, const ScriptedRunOutcome& outcome,
                                   const ScriptedRunReportContext& context,
                                   const std::string& realtimeJson = {});

/// What runScriptedPath() returns: every tick and the summary.
struct ScriptedRunResult
{
  /// Every tick's state, in order.
  std::vector<HapticState> ticks;
  /// The summary as `proxima run` prints it (scriptedRunSummaryJson()).
  std::string summaryJson;
};
/// A whole scripted run as a library call: loads the settings' scene, checks the path's start
/// against it, plays `path` (with no budget unless the settings give one) and returns every tick
/// and the summary. Throws InputError for settings, files or a path that cannot be used, naming
/// the option or file (`settings.path` names the path in messages); nothing is written.
ScriptedRunResult runScriptedPath(const ScriptedRunSettings& settings, const FingerPath& path,
                                  double maxTicks = kDefaultMaxTicks);
/// The same, handing each tick to `onTick` as it ends instead of keeping it (a server streams
/// them); returns the summary. With `onBodyPose`, each body's pose after each tick goes to it
/// after the tick's `onTick` (`--bodies-out`), and a scene without bodies is refused
/// (refuseBodiesOutWithoutBodies).
std::string runScriptedPath(const ScriptedRunSettings& settings, const FingerPath& path,
                            const std::function<void(const HapticState&)>& onTick,
                            const ScriptedRunReportContext& context, double maxTicks,
                            const std::function<void(const BodyPoseRow&)>& onBodyPose = {});

} // namespace proxima
