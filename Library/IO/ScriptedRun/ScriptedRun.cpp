#include "IO/ScriptedRun/ScriptedRun.h"

#include "Proxy/ProxySolver.h"
#include "Runtime/BudgetResidual.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"

#include <chrono>
#include <memory>

#ifdef PROXIMA_WITH_DYNAMICS
#include "IO/Scene/SceneBodies.h"
#else
namespace proxima
{
class BodyCoupling : public TickDynamics
{};
} // namespace proxima
#endif

namespace proxima
{
namespace
{
double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}
} // namespace

ScriptedRunOutcome playScriptedPath(const ScriptedRunSettings& settings,
                                    const CollisionScene& scene, const FingerPath& path,
                                    HapticDevice& device,
                                    const std::function<void(const HapticState&)>& onTick,
                                    const std::function<void(std::uint64_t)>& progress,
                                    BodyCoupling* bodies, TissueDynamics* tissue)
{
  ScriptedRunOutcome outcome;
  // Lockstep runs default to no budget, so that their traces stay reproducible bit for bit.
  outcome.budget = tickBudget(settings, TickWorkBudget{});
  ProxyParameters parameters = proxyParameters(settings);
  outcome.budget.applyTo(parameters);
  auto solver = std::make_unique<ProxySolver>(); // large (fixed buffers): on the heap
  solver->setScene(&scene, parameters);
  outcome.skin = solver->skin();
  // A finger that starts inside a closed object would trap the proxy there: it starts outside.
  outcome.start = placeProxyStart(scene, parameters, path.positions.front());
  resetProxyTo(*solver, outcome.start);
  // A scene's bodies or its tissues: the step that ends each tick.
  TickDynamics* dynamics = bodies;
  if (tissue != nullptr)
  {
    dynamics = tissue;
  }
  if (dynamics != nullptr)
  {
    dynamics->attach(*solver);
  }

  LockstepSettings lockstep;
  lockstep.rate = settings.rate;
  lockstep.startTime = path.startTime();
  lockstep.numTicks = ticksCovering(path.startTime(), path.endTime(), settings.rate);
  // The residual of a budget-limited tick: the same tick replayed without the budget, after the
  // tick's timed update, so that solve_ns stays the budgeted tick's own time.
  BudgetResidualProbe residualProbe(scene, parameters);
  Vec3 tickStart = solver->proxy();
  const auto runStart = std::chrono::steady_clock::now();
  runLockstep(
    lockstep, *solver, device, servoParameters(settings),
    [&](const HapticState& record) {
      onTick(record);
      outcome.summary.add(record);
      if (record.conditions.has(TickCondition::budgetLimited) && dynamics == nullptr)
      {
        // (With bodies or tissue the replay would need their motion too: no residual is
        // measured.)
        const auto replayStart = std::chrono::steady_clock::now();
        outcome.summary.addBudgetResidual(
          residualProbe.residual(tickStart, record.finger, record.proxy));
        outcome.replayMilliseconds += millisecondsSince(replayStart);
      }
      tickStart = record.proxy;
      if (progress && (record.tick & 1023u) == 0)
      {
        progress(record.tick);
      }
    },
    dynamics);
  if (progress)
  {
    progress(lockstep.numTicks);
  }
  outcome.runMilliseconds = millisecondsSince(runStart) - outcome.replayMilliseconds;
  if (bodies != nullptr)
  {
    outcome.bodies = bodyOutcomes(*bodies);
  }
  return outcome;
}

std::vector<TissueOutcome> tissueOutcomes(const TissueDynamics& tissue, const LoadedScene& loaded)
{
  std::vector<TissueOutcome> reports;
  tissue.waitForSolids(); // a real-time run's last step may still be running
  for (std::size_t k = 0; k < tissue.numTissues(); ++k)
  {
    const ElasticSolid& solid = tissue.solid(k);
    TissueOutcome report;
    report.object = tissue.object(k);
    report.tetrahedra = solid.rest().tets.size();
    report.vertices = solid.rest().points.size();
    for (std::uint32_t v = 0; v < report.vertices; ++v)
    {
      report.fixedVertices += solid.isFixed(v) ? 1u : 0u;
    }
    report.ticksPerStep = tissue.ticksPerStep();
    report.steps = tissue.steps();
    report.lateSteps = tissue.lateSteps();
    report.staleUpdates = tissue.staleUpdates();
    report.deepestIndentation = tissue.deepestIndentation(k);
    report.maxDisplacement = tissue.reading(k).maxDisplacement;
    report.energy = solid.kineticEnergy() + solid.elasticEnergy();
    for (const LoadedTissue& built : loaded.tissues)
    {
      if (built.object == report.object)
      {
        report.meshingSeconds = built.seconds;
      }
    }
    reports.push_back(report);
  }
  return reports;
}

void forEachBodyPose(const BodyCoupling& bodies, const HapticState& record,
                     const std::function<void(const BodyPoseRow&)>& onPose)
{
#ifdef PROXIMA_WITH_DYNAMICS
  for (std::size_t body = 0; body < bodies.numBodies(); ++body)
  {
    const BodyPose pose = bodies.world().pose(body);
    BodyPoseRow row;
    row.tick = record.tick;
    row.time = record.time;
    row.object = bodies.object(body);
    row.position = pose.position;
    for (int i = 0; i < 4; ++i)
    {
      row.orientation[i] = pose.orientation[i];
    }
    row.jointPosition = bodies.world().jointPosition(body);
    onPose(row);
  }
#else
  static_cast<void>(bodies);
  static_cast<void>(record);
  static_cast<void>(onPose);
#endif
}

void refuseBodiesOutWithoutBodies()
{
  throw InputError("--bodies-out", "the scene has no bodies (a scene file's objects with a "
                                   "\"body\", Documentation/Dynamics.md)");
}

std::vector<BodyOutcome> bodyOutcomes(BodyCoupling& bodies)
{
  std::vector<BodyOutcome> reports;
#ifdef PROXIMA_WITH_DYNAMICS
  for (std::size_t body = 0; body < bodies.numBodies(); ++body)
  {
    BodyOutcome report;
    report.name = bodies.name(body);
    report.object = bodies.object(body);
    report.joint = jointTypeName(bodies.world().jointType(body));
    report.jointPosition = bodies.world().jointPosition(body);
    report.jointVelocity = bodies.world().jointVelocity(body);
    const BodyEnergy energy = bodies.world().bodyEnergy(body);
    report.kinetic = energy.kinetic;
    report.potential = energy.potential;
    report.work = bodies.work(body);
    report.leftBoundsAt = bodies.leftBoundsAt(body);
    reports.push_back(report);
  }
#else
  static_cast<void>(bodies);
#endif
  return reports;
}

std::unique_ptr<BodyCoupling> sceneBodies(const ScriptedRunSettings& settings,
                                          const LoadedScene& loaded)
{
#ifdef PROXIMA_WITH_DYNAMICS
  return buildSceneBodies(loaded, settings.stiffness, settings.rate);
#else
  if (loaded.description.hasBodies())
  {
    throw InputError(loaded.description.path,
                     "the scene has bodies, and this build has no Dynamics layer "
                     "(configure with PROXIMA_BUILD_DYNAMICS=ON)");
  }
  return nullptr;
#endif
}

std::shared_ptr<TickDynamics> sceneDynamics(const ScriptedRunSettings& settings,
                                            const LoadedScene& loaded)
{
  // A scene has bodies or tissue, never both (the scene file refuses a scene with both).
  std::shared_ptr<TickDynamics> tissue =
    buildSceneTissue(loaded, settings.stiffness, settings.rate);
  if (tissue != nullptr)
  {
    return tissue;
  }
#ifdef PROXIMA_WITH_DYNAMICS
  return std::shared_ptr<TickDynamics>(sceneBodies(settings, loaded));
#else
  static_cast<void>(sceneBodies(settings, loaded)); // refuses a scene with bodies
  return nullptr;
#endif
}

PreparedScriptedRun prepareScriptedRun(const ScriptedRunSettings& settings, const FingerPath& path,
                                       double maxTicks)
{
  checkScriptedRunSettings(settings);
  if (path.positions.empty())
  {
    throw InputError(settings.path, "the path has no samples");
  }
  PreparedScriptedRun prepared;
  // Before the scene is read, and before any output exists: a path row at t = 1e9 s would
  // otherwise fill the disk.
  prepared.numTicks = ticksCovering(path.startTime(), path.endTime(), settings.rate);
  checkTickCount(static_cast<double>(prepared.numTicks), settings.rate, maxTicks,
                 settings.path + " (" + shortNumber(path.endTime() - path.startTime()) + " s)");
  const auto readStart = std::chrono::steady_clock::now();
  prepared.loaded = loadScene(settings);
  prepared.readMilliseconds = millisecondsSince(readStart) - prepared.loaded.treeBuildMilliseconds;
  checkRadiusAgainstScene(settings, prepared.loaded);
  checkPathStart(settings, prepared.loaded, path);
  // A body too light or a mesh with no volume is bad input, found before any output exists.
  prepared.bodies = sceneBodies(settings, prepared.loaded);
  prepared.tissue = buildSceneTissue(prepared.loaded, settings.stiffness, settings.rate);
  return prepared;
}

std::string runScriptedPath(const ScriptedRunSettings& settings, const FingerPath& path,
                            const std::function<void(const HapticState&)>& onTick,
                            const ScriptedRunReportContext& context, double maxTicks,
                            const std::function<void(const BodyPoseRow&)>& onBodyPose)
{
  PreparedScriptedRun prepared = prepareScriptedRun(settings, path, maxTicks);
  ScriptedRunReportContext report = context;
  report.readMilliseconds = prepared.readMilliseconds;
  const std::unique_ptr<BodyCoupling>& bodies = prepared.bodies;
  if (onBodyPose && bodies == nullptr)
  {
    refuseBodiesOutWithoutBodies();
  }
  SimulatedDevice device(path);
  const auto tickAndPoses = [&](const HapticState& record) {
    onTick(record);
    if (onBodyPose)
    {
      forEachBodyPose(*bodies, record, onBodyPose);
    }
  };
  const LoadedScene& loaded = prepared.loaded;
  ScriptedRunOutcome outcome = playScriptedPath(settings, *loaded.scene, path, device, tickAndPoses,
                                                {}, bodies.get(), prepared.tissue.get());
  if (prepared.tissue != nullptr)
  {
    outcome.tissues = tissueOutcomes(*prepared.tissue, loaded);
  }
  return scriptedRunSummaryJson(settings, loaded, *loaded.scene, outcome, report);
}

ScriptedRunResult runScriptedPath(const ScriptedRunSettings& settings, const FingerPath& path,
                                  double maxTicks)
{
  ScriptedRunResult result;
  result.summaryJson = runScriptedPath(
    settings, path, [&result](const HapticState& record) { result.ticks.push_back(record); },
    ScriptedRunReportContext{}, maxTicks);
  return result;
}

} // namespace proxima
