// The worst tick on person-like probing (DESIGN.md section 5: "the tail is the headline"): the
// seeded probe path of Runtime/PathGenerators.h on every shared mesh at proxy radii of 0.5, 1, 2
// and 3 mm, several seeds each, and the four shared person-like paths at the scale and radius
// their README gives, each played in lockstep as `proxima run` plays it. Per case: ticks,
// contact ticks, per-tick solve time (median, p99, p99.9, max over contact ticks and over all
// ticks), iterations (p99.9, max) and triangles tested (mean, max); the same pooled over seeds
// per mesh and radius, and over meshes per radius, with the tail of all ticks' solve times
// (fraction slower than t) thinned to about 200 points. Tools/tail-report.sh plots them.
//
// Every case runs twice: without a work budget (the lockstep default, reproducible) and with
// the servo-safe budget that the real-time runtime uses (TickWorkBudget::servoSafe(), 50 us),
// because the budgeted tail is what a servo beside the proxy loop actually waits for. The
// budgeted run adds what the budget cost: limited ticks, their residual (BudgetResidualProbe,
// as `proxima run --summary` measures it) and the recovery of runs of limited ticks (counted
// by RunSummary, so that the numbers mean what the summary's mean). Per case also the cost of
// one iteration (solve time / iterations over ticks with an iteration, and triangles tested per
// iteration), and per mesh that cost against r / median edge length, to show whether an
// iteration grows with the number of triangles within reach, ~(r / edge)^2.
//
// The platform's own floor comes first, in the same run: a busy loop that only reads the clock,
// for kFloorSeconds. Every gap between two reads longer than kStallNanoseconds is a stall the
// thread did not cause (the scheduler, the hypervisor, an interrupt): a tick that meets one is
// that much slower whatever the solver does, so the report puts the stalls beside the ticks.
//
// Usage: BenchProbeTail OUT.json [--quick] [--seeds N]
//   --quick: one seed, radii 0.5 and 2 mm, for a short check; default 3 seeds, all radii.
#include "IO/Mesh/MeshReader.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Proxy/ProxySolver.h"
#include "Runtime/BudgetResidual.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/PathGenerators.h"
#include "Runtime/RunSummary.h"
#include "Runtime/SimulatedDevice.h"
#include "Runtime/TickBudget.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace proxima;

constexpr double kRate = 1000.0;
// About 200 points on the tail curve, spaced evenly in log(fraction) from 1 to 1 / ticks.
constexpr int kTailPoints = 200;

struct SharedMesh
{
  const char* file;
  /// File units to metres; 0 scales the mesh to a 25 cm box diagonal (the hand-held size that
  /// BenchTimeVersusError --scaling uses for meshes that carry no units).
  double scale;
};

// The scales of ../shared/data/paths/README.md where it gives one, so the probe paths and the
// shared paths see the same objects.
const std::vector<SharedMesh> kMeshes = {{"stanford-bunny.obj", 0.4},
                                         {"VH_M_Liver.glb", 0.5},
                                         {"M3x10_screw.stl", 0.005},
                                         {"cranium_bone_iso075mm.ply", 0.001},
                                         {"Angel_decimated.vtp", 0.0},
                                         {"fandisk.off", 0.0},
                                         {"teapot.obj", 0.0},
                                         {"spot_triangulated.obj", 0.0},
                                         {"abc_00000050_trimesh_000.stl", 0.0},
                                         {"featuretype.STL", 0.0}};

struct SharedPath
{
  const char* file;
  const char* mesh;
  double scale;
  double radius;
};

// ../shared/data/paths/README.md's table.
const std::vector<SharedPath> kSharedPaths = {
  {"bunny-probe.csv", "stanford-bunny.obj", 0.4, 0.002},
  {"liver-probe.csv", "VH_M_Liver.glb", 0.5, 0.002},
  {"screw-probe.csv", "M3x10_screw.stl", 0.005, 0.0005},
  {"cranium-probe.csv", "cranium_bone_iso075mm.ply", 0.001, 0.001}};

struct Ticks
{
  /// Per tick, in tick order (solveAll, iterations and trianglesTested line up).
  std::vector<double> solveAll;
  std::vector<double> solveContact;
  std::vector<double> iterations;
  std::vector<double> trianglesTested;
  /// Budgeted runs only: how many ticks the budget limited, the residual of each (metres), the
  /// length in ticks of each run of limited ticks that recovered, and the limited ticks of a run
  /// still going at the path's end (they never recovered, so they are no recovery length).
  bool budgeted = false;
  std::uint64_t limited = 0;
  std::vector<double> residuals;
  std::vector<double> recoveries;
  std::uint64_t unrecovered = 0;
  void append(const Ticks& other)
  {
    auto add = [](std::vector<double>& to, const std::vector<double>& from) {
      to.insert(to.end(), from.begin(), from.end());
    };
    add(solveAll, other.solveAll);
    add(solveContact, other.solveContact);
    add(iterations, other.iterations);
    add(trianglesTested, other.trianglesTested);
    budgeted = budgeted || other.budgeted;
    limited += other.limited;
    add(residuals, other.residuals);
    add(recoveries, other.recoveries);
    unrecovered += other.unrecovered;
  }
};

/// Solve time and triangle tests per iteration over the ticks that ran at least one: ticks with
/// none (free motion that needs no move) would only dilute the cost of the ones that do.
struct IterationCost
{
  std::uint64_t ticks = 0;
  double iterations = 0.0;
  double solveNanoseconds = 0.0;
  double trianglesTested = 0.0;
  double nanosecondsPerIteration() const
  {
    return iterations > 0.0 ? solveNanoseconds / iterations : 0.0;
  }
  double trianglesPerIteration() const
  {
    return iterations > 0.0 ? trianglesTested / iterations : 0.0;
  }
};

IterationCost iterationCost(const Ticks& ticks)
{
  IterationCost cost;
  for (std::size_t i = 0; i < ticks.iterations.size(); ++i)
  {
    if (ticks.iterations[i] >= 1.0)
    {
      ++cost.ticks;
      cost.iterations += ticks.iterations[i];
      cost.solveNanoseconds += ticks.solveAll[i];
      cost.trianglesTested += ticks.trianglesTested[i];
    }
  }
  return cost;
}

// Nearest-rank quantile, as RunSummary computes the summary's: the value below which a
// fraction q of the (sorted) samples lies.
double quantile(const std::vector<double>& sorted, double q)
{
  if (sorted.empty())
  {
    return 0.0;
  }
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::min(sorted.size(), std::max<std::size_t>(rank, 1)) - 1];
}

// (t, fraction of ticks slower than t) at fractions spaced evenly in log from 1 to 1 / N.
nlohmann::json tail(const std::vector<double>& sorted)
{
  nlohmann::json points = nlohmann::json::array();
  const auto n = static_cast<double>(sorted.size());
  std::size_t lastIndex = sorted.size();
  for (int k = 0; k <= kTailPoints && !sorted.empty(); ++k)
  {
    const double fraction = std::pow(n, -static_cast<double>(k) / kTailPoints);
    const auto slower = static_cast<std::size_t>(std::floor(fraction * n));
    const std::size_t index = sorted.size() - std::max<std::size_t>(slower, 1);
    if (index == lastIndex)
    {
      continue;
    }
    lastIndex = index;
    points.push_back({sorted[index], static_cast<double>(sorted.size() - 1 - index) / n});
  }
  return points;
}

nlohmann::json statistics(Ticks ticks, bool withTail)
{
  // Before the sort below, which breaks the per-tick alignment that this needs.
  const IterationCost cost = iterationCost(ticks);
  for (std::vector<double>* v :
       {&ticks.solveAll, &ticks.solveContact, &ticks.iterations, &ticks.trianglesTested})
  {
    std::sort(v->begin(), v->end());
  }
  auto summary = [](const std::vector<double>& v) {
    return nlohmann::json{{"median", quantile(v, 0.5)},
                          {"p99", quantile(v, 0.99)},
                          {"p99.9", quantile(v, 0.999)},
                          {"max", v.empty() ? 0.0 : v.back()}};
  };
  double tested = 0.0;
  for (double t : ticks.trianglesTested)
  {
    tested += t;
  }
  nlohmann::json json = {
    {"ticks", ticks.solveAll.size()},
    {"contact_ticks", ticks.solveContact.size()},
    {"contact_solve_ns", summary(ticks.solveContact)},
    {"solve_ns", summary(ticks.solveAll)},
    {"iterations",
     {{"p99.9", quantile(ticks.iterations, 0.999)},
      {"max", ticks.iterations.empty() ? 0.0 : ticks.iterations.back()}}},
    {"triangles_tested",
     {{"mean", ticks.trianglesTested.empty()
                 ? 0.0
                 : tested / static_cast<double>(ticks.trianglesTested.size())},
      {"max", ticks.trianglesTested.empty() ? 0.0 : ticks.trianglesTested.back()}}}};
  json["per_iteration"] = {{"ticks_with_iterations", cost.ticks},
                           {"iterations", cost.iterations},
                           {"solve_ns", cost.nanosecondsPerIteration()},
                           {"triangles_tested", cost.trianglesPerIteration()}};
  if (ticks.budgeted)
  {
    std::sort(ticks.residuals.begin(), ticks.residuals.end());
    std::sort(ticks.recoveries.begin(), ticks.recoveries.end());
    json["budget"] = {{"limited_ticks", ticks.limited},
                      {"limited_fraction", ticks.solveAll.empty()
                                             ? 0.0
                                             : static_cast<double>(ticks.limited) /
                                                 static_cast<double>(ticks.solveAll.size())},
                      {"residual_m",
                       {{"median", quantile(ticks.residuals, 0.5)},
                        {"max", ticks.residuals.empty() ? 0.0 : ticks.residuals.back()}}},
                      {"recoveries", ticks.recoveries.size()},
                      {"recovery_ticks",
                       {{"p99", quantile(ticks.recoveries, 0.99)},
                        {"max", ticks.recoveries.empty() ? 0.0 : ticks.recoveries.back()}}},
                      {"unrecovered_limited_ticks", ticks.unrecovered}};
  }
  if (withTail)
  {
    json["tail"] = tail(ticks.solveAll);
  }
  return json;
}

// Plays `path` through the scene as `proxima run` does (lockstep, default servo and proxy
// parameters but the radius and the budget).
Ticks play(const CollisionScene& scene, const FingerPath& path, double radius,
           const TickWorkBudget& budget)
{
  ProxyParameters parameters;
  parameters.radius = radius;
  parameters.timeStep = 1.0 / kRate;
  budget.applyTo(parameters);
  ProxySolver solver;
  solver.setScene(&scene, parameters);
  solver.resetProxy(path.positions.front());
  LockstepSettings settings;
  settings.rate = kRate;
  settings.startTime = path.startTime();
  settings.numTicks = ticksCovering(path.startTime(), path.endTime(), kRate);
  SimulatedDevice device(path);
  Ticks ticks;
  ticks.budgeted = !budget.none();
  // As RunCommand does: the replay runs after the tick's timed update, so solve_ns stays the
  // budgeted tick's own time.
  BudgetResidualProbe residualProbe(scene, parameters);
  RunSummary summary;
  Vec3 tickStart = solver.proxy();
  runLockstep(settings, solver, device, ServoParameters{}, [&](const HapticState& record) {
    summary.add(record);
    if (record.budgetLimited)
    {
      ticks.residuals.push_back(residualProbe.residual(tickStart, record.finger, record.proxy));
    }
    tickStart = record.proxy;
    const auto ns = static_cast<double>(record.solveNanoseconds);
    ticks.solveAll.push_back(ns);
    if (record.numContacts > 0)
    {
      ticks.solveContact.push_back(ns);
    }
    ticks.iterations.push_back(record.iterations);
    ticks.trianglesTested.push_back(record.trianglesTested);
  });
  ticks.limited = summary.budgetLimitedTicks();
  for (const auto& [length, count] : summary.recoveryHistogram())
  {
    ticks.recoveries.insert(ticks.recoveries.end(), count, static_cast<double>(length));
  }
  ticks.unrecovered = summary.unrecoveredLimitedTicks();
  return ticks;
}

/// Both runs of one case: the lockstep default (no budget) and the real-time runtime's.
struct Runs
{
  Ticks unbudgeted;
  Ticks budgeted;
};

Runs playBoth(const CollisionScene& scene, const FingerPath& path, double radius)
{
  return {play(scene, path, radius, TickWorkBudget{}),
          play(scene, path, radius, TickWorkBudget::servoSafe())};
}

/// The unbudgeted statistics at the top level (as before budgets), the budgeted ones under
/// "budgeted".
nlohmann::json statistics(const Runs& runs, bool withTail)
{
  nlohmann::json json = statistics(runs.unbudgeted, withTail);
  json["budgeted"] = statistics(runs.budgeted, withTail);
  return json;
}

void append(Runs& to, const Runs& from)
{
  to.unbudgeted.append(from.unbudgeted);
  to.budgeted.append(from.budgeted);
}

/// Median length in metres of the mesh's distinct edges (an edge shared by two triangles counts
/// once): the length that sets how many triangles a proxy of radius r has within reach.
double medianEdgeLength(const TriangleMesh& mesh)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * static_cast<std::size_t>(mesh.numTriangles()));
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    const auto& corner = mesh.indices(t);
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = corner[static_cast<std::size_t>(k)];
      const std::uint32_t b = corner[static_cast<std::size_t>((k + 1) % 3)];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> lengths;
  lengths.reserve(edges.size());
  for (const auto& [a, b] : edges)
  {
    lengths.push_back(distance(mesh.points()[a], mesh.points()[b]));
  }
  if (lengths.empty())
  {
    return 0.0;
  }
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

constexpr double kFloorSeconds = 2.0;
constexpr double kStallNanoseconds = 10e3;

// The busy loop of the header: stalls per second longer than 10, 30 and 100 us, the longest,
// and the share of the time spent in stalls.
nlohmann::json measurePlatformStalls()
{
  using Clock = std::chrono::steady_clock;
  std::vector<double> stalls;
  const auto start = Clock::now();
  const auto end = start + std::chrono::duration<double>(kFloorSeconds);
  auto last = start;
  for (auto now = Clock::now(); now < end; now = Clock::now())
  {
    const double gap = std::chrono::duration<double, std::nano>(now - last).count();
    if (gap > kStallNanoseconds)
    {
      stalls.push_back(gap);
    }
    last = now;
  }
  const double seconds = std::chrono::duration<double>(last - start).count();
  auto perSecond = [&](double threshold) {
    return static_cast<double>(std::count_if(stalls.begin(), stalls.end(),
                                             [&](double gap) { return gap > threshold; })) /
           seconds;
  };
  double stalled = 0.0;
  for (double gap : stalls)
  {
    stalled += gap;
  }
  return {
    {"seconds", seconds},
    {"stalls_over_10us_per_s", perSecond(10e3)},
    {"stalls_over_30us_per_s", perSecond(30e3)},
    {"stalls_over_100us_per_s", perSecond(100e3)},
    {"longest_stall_ns", stalls.empty() ? 0.0 : *std::max_element(stalls.begin(), stalls.end())},
    {"stalled_fraction", stalled / (seconds * 1e9)}};
}

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

// The shared mesh in metres, as `proxima run --scale` loads it.
bool loadShared(const SharedMesh& mesh, CollisionScene& scene, double& scale)
{
  const std::string file = std::string(PROXIMA_SHARED_MESHES) + "/" + mesh.file;
  if (!std::filesystem::exists(file))
  {
    std::fprintf(stderr, "%s: not in %s, skipped\n", mesh.file, PROXIMA_SHARED_MESHES);
    return false;
  }
  scale = mesh.scale;
  if (scale == 0.0)
  {
    scale = 0.25 / loadTriangleMesh(file).diagonal();
  }
  scene.addObject(loadTriangleMesh(file, scale));
  return true;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s OUT.json [--quick] [--seeds N]\n", argv[0]);
    return 2;
  }
  bool quick = false;
  int seeds = 3;
  for (int i = 2; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (argument == "--quick")
    {
      quick = true;
    }
    else if (argument == "--seeds" && i + 1 < argc)
    {
      seeds = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      std::fprintf(stderr, "%s: unknown argument %s\n", argv[0], argument.c_str());
      return 2;
    }
  }
  if (quick)
  {
    seeds = 1;
  }
  const std::vector<double> radii =
    quick ? std::vector<double>{0.0005, 0.002} : std::vector<double>{0.0005, 0.001, 0.002, 0.003};

  const nlohmann::json platformFloor = measurePlatformStalls();
  std::fprintf(stderr,
               "platform floor: %.0f stalls/s over 30 us, %.1f over 100 us, longest %.0f us, "
               "%.2f%% of the time stalled\n",
               platformFloor["stalls_over_30us_per_s"].get<double>(),
               platformFloor["stalls_over_100us_per_s"].get<double>(),
               platformFloor["longest_stall_ns"].get<double>() / 1e3,
               100.0 * platformFloor["stalled_fraction"].get<double>());
  const auto start = std::chrono::steady_clock::now();
  nlohmann::json cases = nlohmann::json::array();
  nlohmann::json pooled = nlohmann::json::array();
  nlohmann::json meshes = nlohmann::json::array();
  std::map<double, Runs> byRadius;
  for (const SharedMesh& mesh : kMeshes)
  {
    CollisionScene scene;
    double scale = 0.0;
    if (!loadShared(mesh, scene, scale))
    {
      continue;
    }
    const CollisionObject& object = scene.objects.front();
    const double edge = medianEdgeLength(object.mesh);
    nlohmann::json series = nlohmann::json::array();
    // One path per seed, the same at every radius, so radii compare on the same motion.
    std::vector<FingerPath> paths;
    for (int seed = 1; seed <= seeds; ++seed)
    {
      ProbeOptions options;
      options.seed = static_cast<std::uint64_t>(seed);
      options.rate = kRate;
      paths.push_back(makeProbePath({ProbeSurface{&object.mesh, &object.tree}}, options));
    }
    for (double radius : radii)
    {
      Runs all;
      for (int seed = 1; seed <= seeds; ++seed)
      {
        const Runs ticks = playBoth(scene, paths[static_cast<std::size_t>(seed - 1)], radius);
        // Tails only where they are plotted (pooled over seeds), to keep the report small.
        nlohmann::json json = statistics(ticks, false);
        json["mesh"] = mesh.file;
        json["scale"] = scale;
        json["triangles"] = object.mesh.numTriangles();
        json["radius_m"] = radius;
        json["seed"] = seed;
        cases.push_back(json);
        append(all, ticks);
        std::fprintf(stderr,
                     "%-30s r %.1f mm seed %d: contact median %7.0f ns, p99.9 %8.0f ns, "
                     "max %8.0f ns; budgeted max %8.0f ns, %5.2f%% limited\n",
                     mesh.file, radius * 1e3, seed,
                     json["contact_solve_ns"]["median"].get<double>(),
                     json["contact_solve_ns"]["p99.9"].get<double>(),
                     json["contact_solve_ns"]["max"].get<double>(),
                     json["budgeted"]["solve_ns"]["max"].get<double>(),
                     100.0 * json["budgeted"]["budget"]["limited_fraction"].get<double>());
      }
      nlohmann::json json = statistics(all, true);
      json["mesh"] = mesh.file;
      json["radius_m"] = radius;
      json["seeds"] = seeds;
      pooled.push_back(json);
      // Seeds pooled, unbudgeted: the budget would cut the longest ticks' iterations short.
      series.push_back(
        {{"radius_m", radius},
         {"r_over_edge", edge > 0.0 ? radius / edge : 0.0},
         {"solve_ns_per_iteration", json["per_iteration"]["solve_ns"]},
         {"triangles_tested_per_iteration", json["per_iteration"]["triangles_tested"]}});
      append(byRadius[radius], all);
    }
    meshes.push_back({{"mesh", mesh.file},
                      {"scale", scale},
                      {"triangles", object.mesh.numTriangles()},
                      {"median_edge_m", edge},
                      {"iteration_cost", series}});
  }
  for (const auto& [radius, ticks] : byRadius)
  {
    nlohmann::json json = statistics(ticks, true);
    json["mesh"] = "all meshes";
    json["radius_m"] = radius;
    json["seeds"] = seeds;
    pooled.push_back(json);
  }

  // The shared person-like paths, at their README's scale and radius.
  nlohmann::json sharedPaths = nlohmann::json::array();
  const std::string pathsFolder = std::string(PROXIMA_SHARED_MESHES) + "/../paths";
  for (const SharedPath& shared : kSharedPaths)
  {
    const std::string pathFile = pathsFolder + "/" + shared.file;
    const std::string meshFile = std::string(PROXIMA_SHARED_MESHES) + "/" + shared.mesh;
    if (!std::filesystem::exists(pathFile) || !std::filesystem::exists(meshFile))
    {
      std::fprintf(stderr, "%s: not in %s, skipped\n", shared.file, pathsFolder.c_str());
      continue;
    }
    CollisionScene scene;
    scene.addObject(loadTriangleMesh(meshFile, shared.scale));
    const Runs ticks = playBoth(scene, readFingerPathFile(pathFile), shared.radius);
    nlohmann::json json = statistics(ticks, true);
    json["path"] = shared.file;
    json["mesh"] = shared.mesh;
    json["scale"] = shared.scale;
    json["triangles"] = scene.objects.front().mesh.numTriangles();
    json["radius_m"] = shared.radius;
    sharedPaths.push_back(json);
    std::fprintf(stderr,
                 "%-30s (shared path): contact median %7.0f ns, p99.9 %8.0f ns; "
                 "budgeted max %8.0f ns, %5.2f%% limited\n",
                 shared.file, json["contact_solve_ns"]["median"].get<double>(),
                 json["contact_solve_ns"]["p99.9"].get<double>(),
                 json["budgeted"]["solve_ns"]["max"].get<double>(),
                 100.0 * json["budgeted"]["budget"]["limited_fraction"].get<double>());
  }

  const nlohmann::json report = {{"quick", quick},
                                 {"seeds", seeds},
                                 {"radii_m", radii},
                                 {"rate_hz", kRate},
                                 {"budget_s", TickWorkBudget::servoSafe().seconds},
                                 {"run_s", millisecondsSince(start) / 1e3},
                                 {"platform_floor", platformFloor},
                                 {"cases", cases},
                                 {"pooled", pooled},
                                 {"meshes", meshes},
                                 {"shared_paths", sharedPaths}};
  std::ofstream out(argv[1]);
  out << report.dump() << "\n"; // compact: the tails make it a megabyte indented
  if (!out)
  {
    std::perror(argv[1]);
    return 1;
  }
  std::fprintf(stderr, "%s written in %.0f s\n", argv[1], millisecondsSince(start) / 1e3);
  return 0;
}
