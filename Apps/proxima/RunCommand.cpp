// `proxima run`: plays a scripted finger path through a mesh or a scene file in lockstep mode (or,
// with --realtime, through the threaded runtime on the real clock, as a real device needs) and
// writes the trace (DESIGN.md section 3) and a summary of per-tick solve times and iterations.
#include "Command.h"
#include "LoopReport.h"
#include "DeviceChoice.h"
#include "OutputChecks.h"
#include "SceneOptions.h"
#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "Dynamics/BodyCoupling.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/PathAndTrace/BodyPoseWriter.h"
#include "IO/PathAndTrace/TissueStateWriter.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/PathAndTrace/TraceWriter.h"
#include "IO/Scene/SceneBuilder.h"
#include "IO/ScriptedRun/ScriptedRun.h"
#include "Proxy/ProxyParameters.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/DeadlineClock.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/ServoRate.h"
#include "Runtime/ThreadedRuntime.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <thread>
#include <unistd.h>

namespace proxima::cli
{
namespace
{
struct RunOptions
{
  SceneOptions scene;
  std::string out;
  std::string bodiesOut;
  std::string tissueOut;
  std::string summary;
  DeviceChoiceOptions device;
  bool realtime = false;
  bool noFloor = false;
  double maxTicks = kDefaultMaxTicks;
};

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

// Progress on standard error, only for a person watching a terminal.
class Progress
{
public:
  explicit Progress(std::uint64_t total)
    : m_total(total)
    , m_enabled(isatty(STDERR_FILENO) != 0)
  {}
  void update(std::uint64_t done)
  {
    if (!m_enabled || m_total == 0)
    {
      return;
    }
    const auto percent = static_cast<int>(100 * done / m_total);
    if (percent != m_lastPercent)
    {
      m_lastPercent = percent;
      std::fprintf(stderr, "\rproxima run: %3d%% (%llu of %llu ticks)", percent,
                   static_cast<unsigned long long>(done), static_cast<unsigned long long>(m_total));
      std::fflush(stderr);
    }
  }
  void finish()
  {
    if (m_enabled && m_total > 0)
    {
      std::fprintf(stderr, "\n");
    }
  }

private:
  std::uint64_t m_total;
  bool m_enabled;
  int m_lastPercent = -1;
};

/// Plays the path through the threaded runtime on the real clock: the servo and proxy loops on
/// their own threads, as with a real device. One trace row per proxy update; the summary gains
/// the loops' statistics.
void runRealtime(const RunOptions& options, std::shared_ptr<const CollisionScene> scene,
                 const FingerPath& fingerPath, std::uint64_t numTicks, HapticDevice& device,
                 const std::function<void(const HapticState&)>& onTick,
                 nlohmann::ordered_json& report, ProxyStartPlacement& start,
                 std::shared_ptr<TickDynamics> dynamics)
{
  const SceneOptions& shared = options.scene;
  RuntimeSettings settings;
  settings.servoRate = shared.rate;
  settings.recordTicks = numTicks;
  settings.duration = fingerPath.endTime();
  settings.tickBudget = tickBudget(shared, TickWorkBudget::realtimeDefault());
  // The platform's floor, right before the run in this process: a bare loop with the servo's
  // rate, duration and scheduling and no work, counted by the servo's own clock code.
  DeadlineFloorReport floor;
  if (!options.noFloor)
  {
    DeadlineFloorSettings floorSettings;
    floorSettings.rate = settings.servoRate;
    floorSettings.duration = settings.duration;
    floorSettings.realtimeScheduling = settings.realtimeScheduling;
    floorSettings.priority = settings.servoPriority;
    floor = measureDeadlineFloor(floorSettings);
  }
  ThreadedRuntime runtime(device, servoParameters(shared), settings);
  runtime.publishScene(std::move(scene), proxyParameters(shared), fingerPath.positions.front(),
                       &start, std::move(dynamics));
  std::string message;
  if (!runtime.start(message))
  {
    throw std::runtime_error(message);
  }
  if (message.find("refused") != std::string::npos)
  {
    // The run goes on at normal priority; the summary's "scheduling" says so too.
    std::cerr << "proxima run: " << message << "\n";
  }
  Progress progress(numTicks);
  while (!runtime.finished())
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    progress.update(runtime.latestState().tick);
  }
  runtime.stop();
  progress.update(numTicks);
  progress.finish();
  for (const HapticState& record : runtime.records())
  {
    onTick(record);
  }
  report["scheduling"] = message;
  const LoopStatistics servoStatistics = runtime.servoStatistics();
  report["servo"] = loopJson(servoStatistics, runtime.servoScheduling());
  report["proxy"] = loopJson(runtime.proxyStatistics());
  std::string line = "proxima run: servo " + deadlineLine(servoStatistics);
  if (!options.noFloor)
  {
    report["floor"] = loopJson(floor.statistics, floor.scheduling);
    line +=
      "; bare floor loop just before (" + floor.scheduling + ") " + deadlineLine(floor.statistics);
  }
  // For a person at a terminal, like the progress; a script reads the summary, and a run that
  // succeeds prints nothing else on standard error.
  if (isatty(STDERR_FILENO) != 0)
  {
    std::cerr << line << "\n";
  }
}

// One row per body: where its object's frame is now, and its joint coordinate.
void writeBodyPoses(BodyPoseWriter& poses, const BodyCoupling& bodies, const HapticState& record)
{
  forEachBodyPose(bodies, record, [&poses](const BodyPoseRow& row) {
    poses.write(row.tick, row.time, row.object, row.position, row.orientation, &row.jointPosition);
  });
}

int run(const RunOptions& options)
{
  const SceneOptions& shared = options.scene;
  if (options.device.device == "mouse")
  {
    throw InputError("--device", "mouse: the mouse aims the finger from a window's pointer, "
                                 "which run has not (use proxima view --device mouse)");
  }
  if (options.realtime && !isServoRate(shared.rate))
  {
    throw InputError("--rate",
                     "must be " + servoRateRange() + " with --realtime (the servo loop's range)");
  }
  const auto readStart = std::chrono::steady_clock::now();
  const FingerPath fingerPath = readFingerPathFile(shared.path);
  const double pathMilliseconds = millisecondsSince(readStart);
  // The same reading and checks as every scripted run's (runScriptedPath's, Python's, a remote
  // run's): the tick count, the scene, the radius, the path's start and the bodies.
  PreparedScriptedRun prepared = prepareScriptedRun(shared, fingerPath, options.maxTicks);
  LoadedScene& loaded = prepared.loaded;
  const std::uint64_t numTicks = prepared.numTicks;
  ScriptedRunReportContext context;
  context.device = options.device.device;
  context.trace = options.out;
  context.realtime = options.realtime;
  context.readMilliseconds = pathMilliseconds + prepared.readMilliseconds;
  // Shared from here on: the threaded runtime keeps the bodies for as long as its loops use them.
  const std::shared_ptr<BodyCoupling> bodies = std::move(prepared.bodies);
  if (bodies != nullptr && options.realtime && !options.bodiesOut.empty())
  {
    // The threaded runtime records each tick's state, not where the bodies were at each tick.
    throw InputError("--bodies-out", "is written in lockstep only: leave out --realtime, or "
                                     "--bodies-out (the summary still reports the bodies)");
  }
  if (bodies == nullptr && !options.bodiesOut.empty())
  {
    refuseBodiesOutWithoutBodies();
  }
  const std::shared_ptr<TissueDynamics> tissue = std::move(prepared.tissue);
  if (tissue != nullptr && options.realtime && !options.tissueOut.empty())
  {
    // The threaded runtime records each tick's state, not what the tissue did at each tick.
    throw InputError("--tissue-out", "is written in lockstep only: leave out --realtime, or "
                                     "--tissue-out (the summary still reports the tissue)");
  }
  if (tissue == nullptr && !options.tissueOut.empty())
  {
    throw InputError("--tissue-out", "the scene has no tissue (a scene file's objects with a "
                                     "\"tissue\", Documentation/Tissue.md)");
  }
  // Before the trace's temporary exists: a run never replaces what it reads, nor writes two
  // outputs into one file.
  refuseOverlappingFiles({{options.out, "--out"},
                          {options.bodiesOut, "--bodies-out"},
                          {options.tissueOut, "--tissue-out"},
                          {options.summary, "--summary"},
                          {options.device.recordDevice, "--record-device"}},
                         runInputs(shared, loaded, options.device));
  // Shared from here on: the threaded runtime keeps the scene for as long as its loops use it.
  const std::shared_ptr<const CollisionScene> sceneHolder(std::move(loaded.scene));
  const CollisionScene& scene = *sceneHolder;

  RunDevice device(options.device, fingerPath, numTicks);
  TraceWriter trace(options.out);
  std::unique_ptr<BodyPoseWriter> poses;
  if (!options.bodiesOut.empty())
  {
    poses = std::make_unique<BodyPoseWriter>(options.bodiesOut);
  }
  std::unique_ptr<TissueStateWriter> tissueStates;
  if (!options.tissueOut.empty())
  {
    tissueStates = std::make_unique<TissueStateWriter>(options.tissueOut);
  }
  const auto writeTick = [&](const HapticState& record) {
    trace.write(record);
    if (poses != nullptr)
    {
      writeBodyPoses(*poses, *bodies, record);
    }
    if (tissueStates != nullptr)
    {
      for (std::size_t k = 0; k < tissue->numTissues(); ++k)
      {
        const TissueReading& reading = tissue->reading(k);
        tissueStates->write(record.tick, record.time, tissue->object(k), reading.maxDisplacement,
                            reading.indentation, reading.force, reading.touched);
      }
    }
  };
  ScriptedRunOutcome outcome;
  std::string realtimeJson;
  if (options.realtime)
  {
    // The threaded runtime defaults to the real-time default budget.
    outcome.budget = tickBudget(shared, TickWorkBudget::realtimeDefault());
    // The skin the runtime's solver takes: the settings', or the scene's when they give 0.
    outcome.skin = resolveSkin(proxyParameters(shared), scene.diagonal(), scene.maxAbsCoordinate());
    const auto runStart = std::chrono::steady_clock::now();
    nlohmann::ordered_json realtimeReport;
    runRealtime(
      options, sceneHolder, fingerPath, numTicks, device.device(),
      [&](const HapticState& record) {
        writeTick(record);
        outcome.summary.add(record);
      },
      realtimeReport, outcome.start,
      tissue != nullptr ? std::shared_ptr<TickDynamics>(tissue)
                        : std::shared_ptr<TickDynamics>(bodies));
    outcome.runMilliseconds = millisecondsSince(runStart);
    // The threads have stopped: what the bodies and tissues did is read here.
    if (bodies != nullptr)
    {
      outcome.bodies = bodyOutcomes(*bodies);
    }
    if (tissue != nullptr)
    {
      outcome.tissues = tissueOutcomes(*tissue, loaded);
    }
    realtimeJson = realtimeReport.dump();
  }
  else
  {
    Progress progress(numTicks);
    outcome = playScriptedPath(
      shared, scene, fingerPath, device.device(), writeTick,
      [&progress](std::uint64_t done) { progress.update(done); }, bodies.get(), tissue.get());
    progress.finish();
    if (tissue != nullptr)
    {
      outcome.tissues = tissueOutcomes(*tissue, loaded);
    }
  }
  // The trace is put in place last, once the recording and the summary are written: a failure
  // of either then leaves no trace behind.
  trace.finish();
  if (poses != nullptr)
  {
    poses->finish();
  }
  if (tissueStates != nullptr)
  {
    tissueStates->finish();
  }
  device.finish();

  const std::string text =
    scriptedRunSummaryJson(shared, loaded, scene, outcome, context, realtimeJson);
  if (!options.summary.empty())
  {
    writeFileAtomically(options.summary, text);
  }
  trace.close();
  if (poses != nullptr)
  {
    poses->close();
  }
  if (tissueStates != nullptr)
  {
    tissueStates->close();
  }
  writeStandardOutput(text);
  return kExitOk;
}

} // namespace

Command addRunCommand(CLI::App& parent)
{
  auto options = std::make_shared<RunOptions>();
  CLI::App* app = parent.add_subcommand(kRunSummary.name, kRunSummary.description);
  addSceneOptionsThroughPath(*app, options->scene);
  app
    ->add_option("--out", options->out,
                 "Trace CSV to write (trace v2: v1's columns, then "
                 "object and flags)")
    ->required();
  app->add_option("--summary", options->summary, "Also write the summary JSON to this file");
  app->add_option("--bodies-out", options->bodiesOut,
                  "With a scene that has bodies: write their poses, one row per body per tick "
                  "(tick,t,object,x,y,z,qw,qx,qy,qz,q; Documentation/Dynamics.md)");
  app->add_option("--tissue-out", options->tissueOut,
                  "With a scene that has tissue: write its state, one row per tissue per tick "
                  "(tick,t,object,max_displacement,indentation,force,touched; "
                  "Documentation/Tissue.md)");
  addDeviceOptions(*app, options->device);
  app->add_flag("--realtime", options->realtime,
                "Run on the real clock through the threaded runtime (servo and proxy threads at "
                "--rate, 1000 to 10000 Hz), as a real device needs; the default is lockstep");
  app->add_flag("--no-floor", options->noFloor,
                "With --realtime: skip the bare deadline loop that otherwise runs just before, for "
                "as long as the path, to measure the platform's floor (the summary's \"floor\")");
  addSceneOptionsAfterPath(*app, options->scene);
  app
    ->add_option("--max-ticks", options->maxTicks,
                 "The most ticks the run may take (default 1e7, about 40 minutes at 4 kHz): a "
                 "longer path is refused before anything is written")
    ->check(tickCount());
  addTickBudgetOption(*app, options->scene,
                      "Default: none in lockstep; default with --realtime. Lockstep traces stay "
                      "reproducible bit for bit with an iteration budget (default is one: "
                      "`--tick-budget default` limits the ticks the real-time loop limits), not "
                      "with a time budget");
  app->callback([options, app] { checkSceneOptions(options->scene, *app); });
  return Command{app, [options] { return run(*options); }};
}

} // namespace proxima::cli
