// `proxima run`: plays a scripted finger path through a mesh or a scene file in lockstep mode (or,
// with --realtime, through the threaded runtime on the real clock, as a real device needs) and
// writes the trace (DESIGN.md section 3) and a summary of per-tick solve times and iterations.
#include "Command.h"
#include "DeviceChoice.h"
#include "OutputChecks.h"
#include "SceneOptions.h"
#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/PathAndTrace/TraceWriter.h"
#include "IO/Scene/SceneBuilder.h"
#include "Proxy/ProxySolver.h"
#include "Proxy/ProxyStart.h"
#include "Runtime/BudgetResidual.h"
#include "Runtime/DeadlineClock.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/RunSummary.h"
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

// The surface keys of the summary, for a one-mesh run and for each object of a scene alike.
void addSurfaceKeys(nlohmann::ordered_json& json, const LoadedObject& object,
                    const SurfaceMaterial& material)
{
  json["shading"] = object.shaded;
  json["point_normals"] = normalsSourceName(object.normals);
  if (object.normals == NormalsSource::Computed)
  {
    json["feature_angle_deg"] = object.featureAngleDegrees;
  }
  json["static_friction"] = material.staticFriction;
  json["dynamic_friction"] = material.dynamicFriction;
  json["viscosity_N_s_per_m"] = material.viscosity;
}

nlohmann::ordered_json loopJson(const LoopStatistics& statistics,
                                const std::string& scheduling = {})
{
  nlohmann::ordered_json json;
  if (!scheduling.empty())
  {
    json["scheduling"] = scheduling;
  }
  json["ticks"] = statistics.ticks;
  json["wake_ups"] = statistics.wakeUps;
  json["late_wake_ups"] = statistics.lateWakeUps;
  json["missed_deadlines"] = statistics.missedDeadlines;
  json["over_budget_ticks"] = statistics.overBudgetTicks;
  json["wake_latency_us"] = {
    {"p50", statistics.wakeLatencyQuantileNanoseconds(0.5) / 1e3},
    {"p99", statistics.wakeLatencyQuantileNanoseconds(0.99) / 1e3},
    {"p99.9", statistics.wakeLatencyQuantileNanoseconds(0.999) / 1e3},
    {"max", static_cast<double>(statistics.maxWakeLatencyNanoseconds) / 1e3}};
  json["jitter_us"] = {{"p50", statistics.jitterQuantileNanoseconds(0.5) / 1e3},
                       {"p99", statistics.jitterQuantileNanoseconds(0.99) / 1e3},
                       {"max", statistics.jitterQuantileNanoseconds(1.0) / 1e3}};
  json["max_work_us"] = static_cast<double>(statistics.maxWorkNanoseconds) / 1e3;
  return json;
}

/// "woke late 12 of 29001 times (0.04 %), missed 30 deadlines": the human line's figures.
std::string deadlineLine(const LoopStatistics& statistics)
{
  const double percent = statistics.wakeUps > 0
                           ? 100.0 * static_cast<double>(statistics.lateWakeUps) /
                               static_cast<double>(statistics.wakeUps)
                           : 0.0;
  char text[160];
  std::snprintf(text, sizeof text, "woke late %llu of %llu times (%.2f %%), missed %llu deadlines",
                static_cast<unsigned long long>(statistics.lateWakeUps),
                static_cast<unsigned long long>(statistics.wakeUps), percent,
                static_cast<unsigned long long>(statistics.missedDeadlines));
  return text;
}

/// Plays the path through the threaded runtime on the real clock: the servo and proxy loops on
/// their own threads, as with a real device. One trace row per proxy update; the summary gains
/// the loops' statistics.
void runRealtime(const RunOptions& options, std::shared_ptr<const CollisionScene> scene,
                 const FingerPath& fingerPath, std::uint64_t numTicks, HapticDevice& device,
                 const std::function<void(const HapticState&)>& onTick,
                 nlohmann::ordered_json& report, ProxyStartPlacement& start)
{
  const SceneOptions& shared = options.scene;
  RuntimeSettings settings;
  settings.servoRate = shared.rate;
  settings.recordTicks = numTicks;
  settings.duration = fingerPath.endTime();
  settings.tickBudget = tickBudget(shared, TickWorkBudget::servoSafe());
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
                       &start);
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

int run(const RunOptions& options)
{
  const SceneOptions& shared = options.scene;
  if (options.realtime && !isServoRate(shared.rate))
  {
    throw InputError("--rate",
                     "must be " + servoRateRange() + " with --realtime (the servo loop's range)");
  }
  const auto readStart = std::chrono::steady_clock::now();
  LoadedScene loaded = loadScene(shared);
  const FingerPath fingerPath = readFingerPathFile(shared.path);
  const double readMilliseconds = millisecondsSince(readStart) - loaded.treeBuildMilliseconds;
  checkRadiusAgainstScene(shared, loaded);
  checkPathStart(shared, loaded, fingerPath);
  // Before a trace row is written: a path row at t = 1e9 s would otherwise fill the disk.
  checkTickCount(
    static_cast<double>(ticksCovering(fingerPath.startTime(), fingerPath.endTime(), shared.rate)),
    shared.rate, options.maxTicks,
    shared.path + " (" + shortNumber(fingerPath.endTime() - fingerPath.startTime()) + " s)");
  // Before the trace's temporary exists: a run never replaces what it reads, nor writes two
  // outputs into one file.
  refuseOverlappingFiles({{options.out, "--out"},
                          {options.summary, "--summary"},
                          {options.device.recordDevice, "--record-device"}},
                         runInputs(shared, loaded, options.device));
  // Shared from here on: the threaded runtime keeps the scene for as long as its loops use it.
  const std::shared_ptr<const CollisionScene> sceneHolder(std::move(loaded.scene));
  const CollisionScene& scene = *sceneHolder;

  // Lockstep runs default to no budget, so that their traces stay reproducible bit for bit; the
  // threaded runtime defaults to the budget that keeps a 4 kHz servo fed.
  const TickWorkBudget budget =
    tickBudget(shared, options.realtime ? TickWorkBudget::servoSafe() : TickWorkBudget{});
  ProxyParameters parameters = proxyParameters(shared);
  budget.applyTo(parameters);
  ProxySolver solver;
  solver.setScene(&scene, parameters);
  // A finger that starts inside a closed object would trap the proxy there: it starts outside.
  ProxyStartPlacement start;
  if (!options.realtime)
  {
    start = placeProxyStart(scene, parameters, fingerPath.positions.front());
    resetProxyTo(solver, start);
  }

  LockstepSettings settings;
  settings.rate = shared.rate;
  settings.startTime = fingerPath.startTime();
  settings.numTicks = ticksCovering(fingerPath.startTime(), fingerPath.endTime(), shared.rate);
  const ServoParameters servo = servoParameters(shared);

  RunDevice device(options.device, fingerPath, settings.numTicks);
  TraceWriter trace(options.out);
  RunSummary summary;
  const auto runStart = std::chrono::steady_clock::now();
  double replayMilliseconds = 0.0;
  nlohmann::ordered_json realtimeReport;
  if (options.realtime)
  {
    runRealtime(
      options, sceneHolder, fingerPath, settings.numTicks, device.device(),
      [&](const HapticState& record) {
        trace.write(record);
        summary.add(record);
      },
      realtimeReport, start);
  }
  else
  {
    Progress progress(settings.numTicks);
    // The residual of a budget-limited tick: the same tick replayed without the budget, after
    // the tick's timed update, so that solve_ns stays the budgeted tick's own time.
    BudgetResidualProbe residualProbe(scene, parameters);
    Vec3 tickStart = solver.proxy();
    runLockstep(settings, solver, device.device(), servo, [&](const HapticState& record) {
      trace.write(record);
      summary.add(record);
      if (record.budgetLimited)
      {
        const auto replayStart = std::chrono::steady_clock::now();
        summary.addBudgetResidual(residualProbe.residual(tickStart, record.finger, record.proxy));
        replayMilliseconds += millisecondsSince(replayStart);
      }
      tickStart = record.proxy;
      if ((record.tick & 1023u) == 0)
      {
        progress.update(record.tick);
      }
    });
    progress.update(settings.numTicks);
    progress.finish();
  }
  // The trace is put in place last, once the recording and the summary are written: a failure
  // of either then leaves no trace behind.
  trace.finish();
  device.finish();
  const double runMilliseconds = millisecondsSince(runStart) - replayMilliseconds;

  std::uint64_t numTriangles = 0;
  std::uint64_t numDegenerate = 0;
  for (const LoadedObject& object : loaded.objects)
  {
    numTriangles += object.numTriangles;
    numDegenerate += object.numDegenerateTriangles;
  }
  nlohmann::ordered_json json;
  if (shared.scene.empty())
  {
    json["mesh"] = shared.mesh;
  }
  else
  {
    json["scene"] = shared.scene;
  }
  json["path"] = shared.path;
  json["device"] = options.device.device;
  json["trace"] = options.out;
  json["triangles"] = numTriangles;
  json["degenerate_triangles"] = numDegenerate;
  json["radius_m"] = shared.radius;
  json["skin_m"] = solver.skin();
  json["stiffness_N_per_m"] = shared.stiffness;
  json["rate_hz"] = shared.rate;
  json["mode"] = options.realtime ? "realtime" : "lockstep";
  if (shared.scene.empty())
  {
    // The keys of a one-mesh run, as before scene files.
    const LoadedObject& object = loaded.objects.front();
    const SurfaceMaterial& material = scene.objects.front().material;
    addSurfaceKeys(json, object, material);
    if (!shared.texture.empty())
    {
      nlohmann::ordered_json texture;
      texture["image"] = shared.texture;
      texture["role"] = shared.textureRole;
      if (material.textures.front().role == TextureRole::Bump)
      {
        texture["amplitude_m"] = material.textures.front().amplitude;
      }
      texture["channel"] = shared.textureChannel;
      json["texture"] = std::move(texture);
    }
  }
  else
  {
    nlohmann::ordered_json objects = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < loaded.objects.size(); ++i)
    {
      const LoadedObject& object = loaded.objects[i];
      const SurfaceMaterial& material = scene.objects[i].material;
      nlohmann::ordered_json entry;
      entry["mesh"] = object.mesh;
      entry["triangles"] = object.numTriangles;
      entry["degenerate_triangles"] = object.numDegenerateTriangles;
      addSurfaceKeys(entry, object, material);
      entry["textures"] = material.textures.size();
      objects.push_back(std::move(entry));
    }
    json["objects"] = std::move(objects);
  }
  json["ticks"] = summary.ticks();
  json["contact_ticks"] = summary.contactTicks();
  json["iterations"] = {{"total", summary.totalIterations()},
                        {"mean", summary.ticks() > 0
                                   ? static_cast<double>(summary.totalIterations()) /
                                       static_cast<double>(summary.ticks())
                                   : 0.0},
                        {"max", summary.maxIterations()},
                        {"cap", shared.maxIterations},
                        {"ticks_at_cap", summary.iterationCapTicks()}};
  json["refused_finger_ticks"] = summary.refusedTicks();
  json["contact_overflow_ticks"] = summary.overflowTicks();
  json["clamped_force_ticks"] = summary.clampedTicks();
  json["fading_force_ticks"] = summary.fadingTicks();
  json["device_lost_ticks"] = summary.deviceLostTicks();
  json["stuck_ticks"] = summary.stuckTicks();
  json["friction_limited_ticks"] = summary.frictionLimitedTicks();
  if (start.movedOutside)
  {
    json["started_inside"] = {
      {"object", start.object},
      {"winding_number", start.windingNumber},
      {"moved_m", start.movedDistance},
      {"proxy_start", {start.position.x, start.position.y, start.position.z}},
      {"ticks", summary.startedOutsideTicks()}};
  }
  else
  {
    json["started_inside"] = nullptr;
  }
  json["max_force_N"] = summary.maxForce();
  json["solve_ns"] = {{"median", summary.solveNanosecondsQuantile(0.5)},
                      {"p99", summary.solveNanosecondsQuantile(0.99)},
                      {"p99.9", summary.solveNanosecondsQuantile(0.999)},
                      {"max", summary.solveNanosecondsQuantile(1.0)}};
  json["triangles_tested_per_tick"] = summary.meanTrianglesTested();
  nlohmann::ordered_json budgetJson;
  budgetJson["tick_budget"] = budget.text();
  budgetJson["seconds"] = budget.seconds;
  budgetJson["iterations"] = budget.iterations;
  budgetJson["limited_ticks"] = summary.budgetLimitedTicks();
  if (options.realtime)
  {
    // A realtime tick cannot be replayed as it ran: its start and its budget were the clock's.
    budgetJson["residual_m"] = nullptr;
  }
  else
  {
    budgetJson["residual_m"] = {{"max", summary.budgetResidualQuantile(1.0)},
                                {"median", summary.budgetResidualQuantile(0.5)}};
  }
  nlohmann::ordered_json histogram = nlohmann::ordered_json::object();
  for (const auto& [ticks, runs] : summary.recoveryHistogram())
  {
    histogram[std::to_string(ticks)] = runs;
  }
  budgetJson["recovery_ticks"] = {{"runs", summary.recoveries()},
                                  {"max", summary.recoveryTicksQuantile(1.0)},
                                  {"p99", summary.recoveryTicksQuantile(0.99)},
                                  {"histogram", std::move(histogram)},
                                  {"unrecovered_at_end", summary.unrecoveredLimitedTicks()}};
  budgetJson["replay_ms"] = replayMilliseconds;
  json["budget"] = std::move(budgetJson);
  json["read_ms"] = readMilliseconds;
  json["tree_build_ms"] = loaded.treeBuildMilliseconds;
  json["run_ms"] = runMilliseconds;
  if (options.realtime)
  {
    json["realtime"] = std::move(realtimeReport);
  }

  const std::string text = json.dump(2) + "\n";
  if (!options.summary.empty())
  {
    writeFileAtomically(options.summary, text);
  }
  trace.close();
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
                      "Default: none in lockstep, so that lockstep traces stay reproducible bit "
                      "for bit (an iteration budget keeps them so, a time budget does not); 50us "
                      "with --realtime, which keeps a 4 kHz servo fed");
  app->callback([options, app] { checkSceneOptions(options->scene, *app); });
  return Command{app, [options] { return run(*options); }};
}

} // namespace proxima::cli
