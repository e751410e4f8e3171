// Measures the threaded runtime's loops on the real clock: the servo at a chosen rate (4 kHz by
// default) for a chosen time (60 s) while the finger strokes the 1.5M-triangle skull, and
// optionally a model swap half way: a second skull scene is built on this thread while the loops
// run and is published. Just before, unless --no-floor, the bare floor loop (DeadlineClock.h) runs
// for as long with the servo's rate and scheduling and no work: the platform's floor, counted by
// the same code. Prints one JSON object: wake-up latency and period jitter quantiles, late
// wake-ups, missed deadlines, ticks over budget, the longest period and tick for the servo, the
// proxy loop and the floor, and the swap's build-to-live time; and writes the servo's and the
// floor's period and wake-up latency histograms as CSV for Tools/servo_jitter.py. Not a test: the
// numbers depend on the machine and its load.
//
//   ServoLoopJitter [--seconds S] [--rate HZ] [--swap] [--no-floor] [--histogram FILE.csv]
//                   [--mesh FILE]
#include "IO/Mesh/MeshReader.h"
#include "Runtime/DeadlineClock.h"
#include "Paths/PathGenerators.h"
#include "Runtime/SimulatedDevice.h"
#include "Runtime/ThreadedRuntime.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

namespace
{
using namespace proxima;
using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::shared_ptr<const CollisionScene> buildScene(const std::string& file, double& buildMs)
{
  const auto start = Clock::now();
  auto scene = std::make_shared<CollisionScene>();
  scene->addObject(loadTriangleMesh(file, 0.001));
  buildMs = millisecondsSince(start);
  return scene;
}

nlohmann::json loopJson(const LoopStatistics& statistics, const std::string& scheduling = {})
{
  nlohmann::json json = {
    {"rate_hz", statistics.rate},
    {"ticks", statistics.ticks},
    {"wake_ups", statistics.wakeUps},
    {"late_wake_ups", statistics.lateWakeUps},
    {"missed_deadlines", statistics.missedDeadlines},
    {"over_budget_ticks", statistics.overBudgetTicks},
    {"wake_latency_us",
     {{"p50", statistics.wakeLatencyQuantileNanoseconds(0.5) / 1e3},
      {"p99", statistics.wakeLatencyQuantileNanoseconds(0.99) / 1e3},
      {"p99.9", statistics.wakeLatencyQuantileNanoseconds(0.999) / 1e3},
      {"max", static_cast<double>(statistics.maxWakeLatencyNanoseconds) / 1e3}}},
    {"jitter_us",
     {{"p50", statistics.jitterQuantileNanoseconds(0.5) / 1e3},
      {"p99", statistics.jitterQuantileNanoseconds(0.99) / 1e3},
      {"p99.9", statistics.jitterQuantileNanoseconds(0.999) / 1e3},
      {"max", statistics.jitterQuantileNanoseconds(1.0) / 1e3}}},
    {"period_us",
     {{"min", static_cast<double>(statistics.minPeriodNanoseconds) / 1e3},
      {"max", static_cast<double>(statistics.maxPeriodNanoseconds) / 1e3}}},
    {"max_work_us", static_cast<double>(statistics.maxWorkNanoseconds) / 1e3}};
  if (!scheduling.empty())
  {
    json["scheduling"] = scheduling;
  }
  return json;
}

/// One loop's two histograms as CSV rows `loop,quantity,bin_us,count`, empty bins left out.
void writeHistograms(std::ostream& file, const std::string& loop, const LoopStatistics& statistics)
{
  for (int i = 0; i < LoopStatistics::kBins; ++i)
  {
    if (statistics.periodHistogram[i] != 0)
    {
      file << loop << ",period," << i << "," << statistics.periodHistogram[i] << "\n";
    }
  }
  for (int i = 0; i < LoopStatistics::kWakeBins; ++i)
  {
    if (statistics.wakeLatencyHistogram[i] != 0)
    {
      file << loop << ",wake_latency," << i << "," << statistics.wakeLatencyHistogram[i] << "\n";
    }
  }
}
} // namespace

int main(int argc, char** argv)
{
  double seconds = 60.0;
  double rate = 4000.0;
  bool swap = false;
  bool floor = true;
  std::string histogram;
  std::string mesh = std::string(PROXIMA_SHARED_MESHES) + "/cranium_bone_iso075mm.ply";
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    const bool hasValue = i + 1 < argc;
    if (argument == "--seconds" && hasValue)
    {
      seconds = std::atof(argv[++i]);
    }
    else if (argument == "--rate" && hasValue)
    {
      rate = std::atof(argv[++i]);
    }
    else if (argument == "--swap")
    {
      swap = true;
    }
    else if (argument == "--no-floor")
    {
      floor = false;
    }
    else if (argument == "--histogram" && hasValue)
    {
      histogram = argv[++i];
    }
    else if (argument == "--mesh" && hasValue)
    {
      mesh = argv[++i];
    }
    else
    {
      std::cerr << "usage: ServoLoopJitter [--seconds S] [--rate HZ] [--swap] [--no-floor] "
                   "[--histogram FILE.csv] [--mesh FILE]\n";
      return 2;
    }
  }

  double firstBuildMs = 0.0;
  const auto scene = buildScene(mesh, firstBuildMs);
  ProxyParameters parameters;
  parameters.radius = 0.001;
  // Circles inside the skull at mid-height, repeated for the whole run: the proxy slides along
  // the bone's inside the whole time, so every proxy tick does real work.
  const Aabb bounds = scene->objects[0].mesh.bounds();
  const FingerPath lap = makeDefaultPath("circle", bounds, parameters.radius, rate);
  std::vector<FingerPath> laps;
  for (double covered = 0.0; covered < seconds + 1.0; covered += lap.endTime() - lap.startTime())
  {
    laps.push_back(lap);
  }
  SimulatedDevice device(concatenatePaths(laps, rate));

  RuntimeSettings settings;
  settings.servoRate = rate;
  settings.duration = seconds;
  ServoParameters servo;
  // The floor first, in this process, with the scene already built: nothing else runs meanwhile.
  DeadlineFloorReport floorReport;
  if (floor)
  {
    DeadlineFloorSettings floorSettings;
    floorSettings.rate = rate;
    floorSettings.duration = seconds;
    floorSettings.realtimeScheduling = settings.realtimeScheduling;
    floorSettings.priority = settings.servoPriority;
    floorReport = measureDeadlineFloor(floorSettings);
  }
  ThreadedRuntime runtime(device, servo, settings);
  runtime.publishScene(scene, parameters, device.path().positions.front());
  std::string message;
  if (!runtime.start(message))
  {
    std::cerr << "ServoLoopJitter: " << message << "\n";
    return 1;
  }
  std::cerr << "ServoLoopJitter: " << message << "\n";

  nlohmann::json swapJson = nullptr;
  if (swap)
  {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds / 2));
    const auto start = Clock::now();
    double buildMs = 0.0;
    auto next = buildScene(mesh, buildMs);
    const std::uint64_t version = runtime.publishScene(next, parameters, {});
    const double publishMs = millisecondsSince(start);
    if (!runtime.waitForScene(version, std::chrono::seconds(60)))
    {
      // The run's --seconds ended before the swap (reading and building the model took longer
      // than the second half of the run), or the proxy loop never took it.
      std::cerr << "ServoLoopJitter: the swapped model was not live before the run ended (give "
                   "more --seconds than twice the model's build time) or within 60 s\n";
      runtime.stop();
      return 1;
    }
    swapJson = {{"read_and_build_ms", buildMs},
                {"publish_ms", publishMs - buildMs},
                {"build_to_live_ms", millisecondsSince(start)},
                {"install_in_proxy_loop_us",
                 static_cast<double>(runtime.longestSceneInstallNanoseconds()) / 1e3},
                {"triangles", next->objects[0].mesh.numTriangles()}};
  }
  while (!runtime.finished())
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  runtime.stop();

  const LoopStatistics servoStatistics = runtime.servoStatistics();
  nlohmann::json report = {{"mesh", mesh},
                           {"triangles", scene->objects[0].mesh.numTriangles()},
                           {"seconds", seconds},
                           {"scheduling", message},
                           {"servo", loopJson(servoStatistics, runtime.servoScheduling())},
                           {"proxy", loopJson(runtime.proxyStatistics())},
                           {"floor", floor
                                       ? loopJson(floorReport.statistics, floorReport.scheduling)
                                       : nlohmann::json(nullptr)},
                           {"swap", swapJson}};
  std::cout << report.dump(2) << "\n";
  if (!histogram.empty())
  {
    std::ofstream file(histogram);
    file << "loop,quantity,bin_us,count\n";
    writeHistograms(file, "servo", servoStatistics);
    if (floor)
    {
      writeHistograms(file, "floor", floorReport.statistics);
    }
  }
  return 0;
}
