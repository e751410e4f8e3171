// The worst tick on person-like probing (DESIGN.md section 5: "the tail is the headline"): the
// seeded probe path of Paths/PathGenerators.h on every shared mesh at proxy radii of 0.5, 1, 2
// and 3 mm, several seeds each, and the four shared person-like paths at the scale and radius
// their README gives, each played in lockstep as `proxima run` plays it. Per case: ticks,
// contact ticks, per-tick solve time (median, p99, p99.9, max over contact ticks and over all
// ticks), iterations (p99.9, max) and triangles tested (mean, max); the same pooled over seeds
// per mesh and radius, and over meshes per radius, with the tail of all ticks' solve times
// (fraction slower than t) thinned to about 200 points. Tools/tail-report.sh plots them.
//
// Every tick's cost is reported twice: the single run's `solve_ns`, as a trace has it, and its
// replayed work, the least wall time over five repeats of the same update from the same solver
// state (Runtime/TickReplay.h): a stall of the VM hits about one tick in 80 and rarely all five
// repeats of one, so the replayed figures are the solver's and the single-run ones the solver's
// plus the platform's.
//
// Every case runs without a work budget and with each iteration budget of kBudgets (1, 2, 4, 8,
// 16 and 32 iterations; the real-time default, TickWorkBudget::realtimeDefault(), is one of them):
// run time against error. A budgeted run adds what the budget cost: limited ticks, recovery (the
// length of each run of limited ticks, counted by RunSummary as the summary counts it), and the
// error of each limited tick against the same tick from the same state without a budget
// (TickReplay::settledWithoutBudget): how far the proxy stopped from where it would have
// settled, and the angle and relative magnitude of the spring force kp (proxy - finger) against
// the settled one's (over limited ticks whose settled force is at least kMinimumForce; the others
// settle free and are counted with their absolute force). Per case also the cost of one
// iteration (replayed work / iterations over ticks with an iteration, and triangles tested per
// iteration), and per mesh that cost against r / median edge length, to show whether an
// iteration grows with the number of triangles within reach, ~(r / edge)^2.
//
// The platform's own floor comes first, in the same run: a busy loop that only reads the clock,
// for kFloorSeconds. Every gap between two reads longer than kStallNanoseconds is a stall the
// thread did not cause (the scheduler, the hypervisor, an interrupt): a tick that meets one is
// that much slower whatever the solver does, so the report puts the stalls beside the ticks.
//
// Usage: BenchProbeTail OUT.json [--quick] [--seeds N] [--repeats N]
//   --quick: one seed, radii 0.5 and 2 mm, for a short check; default 3 seeds, all radii.
//   --repeats: replays per tick (default 5).
#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Proxy/ProxySolver.h"
#include "Runtime/BudgetResidual.h"
#include "Runtime/LockstepRuntime.h"
#include "Paths/PathGenerators.h"
#include "Runtime/RunSummary.h"
#include "Runtime/SimulatedDevice.h"
#include "Runtime/TickBudget.h"
#include "Runtime/TickReplay.h"

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

// The sliver-fan stress mesh, made here rather than read: two crossing cylinders of CAD
// triangulation (Geometry/ProceduralMeshes.h, makeSliverCylinder), 2 cm in radius and 10 cm
// long, 192 sides each, one along z and one along x, overlapping as the solids of a soup do.
constexpr const char* kSliverCylinders = "sliver-cylinders (procedural)";

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
                                         {"featuretype.STL", 0.0},
                                         {kSliverCylinders, 1.0}};

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

// The budgets of the sweep, in iterations (0: none). The real-time default is among them.
const std::vector<int> kBudgets = {0, 1, 2, 4, 8, 16, 32};

// A limited tick whose settled spring force is below this (newtons) settles free: its force error
// has no direction or ratio, only a size.
constexpr double kMinimumForce = 0.01;

std::string budgetName(int iterations)
{
  return iterations > 0 ? std::to_string(iterations) + "it" : "none";
}

struct Ticks
{
  /// Per tick, in tick order (solveAll, workAll, iterations and trianglesTested line up).
  std::vector<double> solveAll;
  std::vector<double> solveContact;
  /// Replayed work (TickReplay), all ticks and ticks in contact.
  std::vector<double> workAll;
  std::vector<double> workContact;
  std::vector<double> iterations;
  std::vector<double> trianglesTested;
  /// Budgeted runs only: how many ticks the budget limited; per limited tick the distance to
  /// where it would have settled (metres) and, where the settled force is at least kMinimumForce,
  /// the force's angle (degrees) and relative magnitude error against the settled one; the
  /// limited ticks that settle free, with their force (newtons); the length in ticks of each run
  /// of limited ticks that recovered, and the limited ticks of a run still going at the path's
  /// end (they never recovered, so they are no recovery length).
  bool budgeted = false;
  std::uint64_t limited = 0;
  std::vector<double> residuals;
  std::vector<double> forceAngles;
  std::vector<double> forceMagnitudeErrors;
  std::vector<double> settledFreeForces;
  std::vector<double> recoveries;
  std::uint64_t unrecovered = 0;
  void append(const Ticks& other)
  {
    auto add = [](std::vector<double>& to, const std::vector<double>& from) {
      to.insert(to.end(), from.begin(), from.end());
    };
    add(solveAll, other.solveAll);
    add(solveContact, other.solveContact);
    add(workAll, other.workAll);
    add(workContact, other.workContact);
    add(iterations, other.iterations);
    add(trianglesTested, other.trianglesTested);
    budgeted = budgeted || other.budgeted;
    limited += other.limited;
    add(residuals, other.residuals);
    add(forceAngles, other.forceAngles);
    add(forceMagnitudeErrors, other.forceMagnitudeErrors);
    add(settledFreeForces, other.settledFreeForces);
    add(recoveries, other.recoveries);
    unrecovered += other.unrecovered;
  }
};

/// Replayed work and triangle tests per iteration over the ticks that ran at least one: ticks
/// with none (free motion that needs no move) would only dilute the cost of the ones that do.
struct IterationCost
{
  std::uint64_t ticks = 0;
  double iterations = 0.0;
  double workNanoseconds = 0.0;
  double trianglesTested = 0.0;
  /// The most replayed work of any one iteration's share: a tick's work over its iterations.
  double maxNanosecondsPerIteration = 0.0;
  double nanosecondsPerIteration() const
  {
    return iterations > 0.0 ? workNanoseconds / iterations : 0.0;
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
      cost.workNanoseconds += ticks.workAll[i];
      cost.trianglesTested += ticks.trianglesTested[i];
      cost.maxNanosecondsPerIteration =
        std::max(cost.maxNanosecondsPerIteration, ticks.workAll[i] / ticks.iterations[i]);
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

nlohmann::json quantiles(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return nlohmann::json{{"median", quantile(v, 0.5)},
                        {"p99", quantile(v, 0.99)},
                        {"p99.9", quantile(v, 0.999)},
                        {"max", v.empty() ? 0.0 : v.back()}};
}

nlohmann::json statistics(const Ticks& ticks, bool withTail)
{
  const IterationCost cost = iterationCost(ticks);
  double tested = 0.0;
  for (double t : ticks.trianglesTested)
  {
    tested += t;
  }
  const double numTicks = static_cast<double>(ticks.solveAll.size());
  nlohmann::json json = {
    {"ticks", ticks.solveAll.size()},
    {"contact_ticks", ticks.solveContact.size()},
    {"contact_solve_ns", quantiles(ticks.solveContact)},
    {"solve_ns", quantiles(ticks.solveAll)},
    {"contact_work_ns", quantiles(ticks.workContact)},
    {"work_ns", quantiles(ticks.workAll)},
    {"iterations", quantiles(ticks.iterations)},
    {"triangles_tested",
     {{"mean", ticks.trianglesTested.empty() ? 0.0 : tested / numTicks},
      {"max", ticks.trianglesTested.empty()
                ? 0.0
                : *std::max_element(ticks.trianglesTested.begin(), ticks.trianglesTested.end())}}},
    {"per_iteration",
     {{"ticks_with_iterations", cost.ticks},
      {"iterations", cost.iterations},
      {"work_ns", cost.nanosecondsPerIteration()},
      {"max_work_ns", cost.maxNanosecondsPerIteration},
      {"triangles_tested", cost.trianglesPerIteration()}}}};
  if (ticks.budgeted)
  {
    json["budget"] = {
      {"limited_ticks", ticks.limited},
      {"limited_fraction", numTicks > 0.0 ? static_cast<double>(ticks.limited) / numTicks : 0.0},
      {"residual_m", quantiles(ticks.residuals)},
      {"force_angle_deg", quantiles(ticks.forceAngles)},
      {"force_magnitude_error", quantiles(ticks.forceMagnitudeErrors)},
      {"settled_free_ticks", ticks.settledFreeForces.size()},
      {"settled_free_force_n", quantiles(ticks.settledFreeForces)},
      {"recoveries", ticks.recoveries.size()},
      {"recovery_ticks", quantiles(ticks.recoveries)},
      {"unrecovered_limited_ticks", ticks.unrecovered}};
  }
  if (withTail)
  {
    std::vector<double> solve = ticks.solveAll;
    std::vector<double> work = ticks.workAll;
    std::sort(solve.begin(), solve.end());
    std::sort(work.begin(), work.end());
    json["tail"] = tail(solve);
    json["work_tail"] = tail(work);
  }
  return json;
}

// The force error of a limited tick against the same tick settled without a budget.
void addForceError(Ticks& ticks, const Vec3& finger, const Vec3& limited, const Vec3& settled,
                   double stiffness)
{
  const Vec3 limitedForce = stiffness * (limited - finger);
  const Vec3 settledForce = stiffness * (settled - finger);
  ticks.residuals.push_back(distance(limited, settled));
  const double settledMagnitude = norm(settledForce);
  if (settledMagnitude < kMinimumForce)
  {
    ticks.settledFreeForces.push_back(norm(limitedForce));
    return;
  }
  const double limitedMagnitude = norm(limitedForce);
  const double cosine = limitedMagnitude > 0.0
                          ? dot(limitedForce, settledForce) / (limitedMagnitude * settledMagnitude)
                          : -1.0;
  ticks.forceAngles.push_back(std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI);
  ticks.forceMagnitudeErrors.push_back(std::abs(limitedMagnitude - settledMagnitude) /
                                       settledMagnitude);
}

// Plays `path` through the scene as `proxima run` does (lockstep, default servo and proxy
// parameters but the radius and the budget), replaying each tick `repeats` times after it ran.
Ticks play(const CollisionScene& scene, const FingerPath& path, double radius,
           const TickWorkBudget& budget, int repeats)
{
  ProxyParameters parameters;
  parameters.radius = radius;
  parameters.timeStep = 1.0 / kRate;
  budget.applyTo(parameters);
  // On the heap: a solver and each of the replay's two copies are about a hundred kilobytes.
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  solver->resetProxy(path.positions.front());
  auto replay = std::make_unique<TickReplay>(repeats);
  const LockstepSettings settings = lockstepCovering(path, kRate);
  SimulatedDevice device(path);
  const ServoParameters servo;
  Ticks ticks;
  ticks.budgeted = !budget.none();
  RunSummary summary;
  replay->remember(*solver);
  runLockstep(settings, *solver, device, servo, [&](const HapticState& record) {
    // The tick has run (its solve_ns is the single run's); the replays start from the state
    // remembered before it.
    summary.add(record);
    const auto work = static_cast<double>(replay->workNanoseconds(record.finger));
    if (record.conditions.has(TickCondition::budgetLimited))
    {
      const ProxyTickResult settled = replay->settledWithoutBudget(record.finger);
      addForceError(ticks, record.finger, record.proxy, settled.proxy, servo.stiffness);
    }
    replay->remember(*solver);
    const auto ns = static_cast<double>(record.solveNanoseconds);
    ticks.solveAll.push_back(ns);
    ticks.workAll.push_back(work);
    if (record.numContacts > 0)
    {
      ticks.solveContact.push_back(ns);
      ticks.workContact.push_back(work);
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

/// The runs of one case, one per budget of kBudgets, in its order.
using Runs = std::vector<Ticks>;

Runs playAll(const CollisionScene& scene, const FingerPath& path, double radius, int repeats)
{
  Runs runs;
  for (int iterations : kBudgets)
  {
    runs.push_back(play(scene, path, radius, TickWorkBudget{0.0, iterations}, repeats));
  }
  return runs;
}

/// The unbudgeted statistics at the top level, every budget's under "budgets" by name.
nlohmann::json statistics(const Runs& runs, bool withTail)
{
  nlohmann::json json = statistics(runs.front(), withTail);
  nlohmann::json budgets = nlohmann::json::object();
  for (std::size_t k = 1; k < runs.size(); ++k)
  {
    // Tails only for the default budget: the plot draws it beside the unbudgeted one.
    const bool isDefault = kBudgets[k] == TickWorkBudget::realtimeDefault().iterations;
    budgets[budgetName(kBudgets[k])] = statistics(runs[k], withTail && isDefault);
  }
  json["budgets"] = budgets;
  return json;
}

void append(Runs& to, const Runs& from)
{
  if (to.empty())
  {
    to.resize(from.size());
  }
  for (std::size_t k = 0; k < from.size(); ++k)
  {
    to[k].append(from[k]);
  }
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

// One line per case on stderr: replayed work without a budget, and with the real-time default.
void printProgress(const std::string& label, const nlohmann::json& json)
{
  const nlohmann::json& byDefault =
    json["budgets"][budgetName(TickWorkBudget::realtimeDefault().iterations)];
  std::fprintf(stderr,
               "%-44s work: contact median %6.0f ns, p99.9 %7.0f ns, max %8.0f ns (single run "
               "max %8.0f ns); default budget max %7.0f ns, %5.2f%% limited\n",
               label.c_str(), json["contact_work_ns"]["median"].get<double>(),
               json["work_ns"]["p99.9"].get<double>(), json["work_ns"]["max"].get<double>(),
               json["solve_ns"]["max"].get<double>(), byDefault["work_ns"]["max"].get<double>(),
               100.0 * byDefault["budget"]["limited_fraction"].get<double>());
}

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

TriangleMesh crossingSliverCylinders()
{
  TriangleSoup soup = makeSliverCylinder(192, 0.02, 0.1);
  const TriangleSoup across = makeSliverCylinder(192, 0.02, 0.1);
  const auto base = static_cast<std::uint32_t>(soup.points.size());
  for (const Vec3& p : across.points)
  {
    soup.points.push_back({p.z, p.y, -p.x}); // a quarter turn about y: its axis along x
  }
  for (const auto& t : across.triangles)
  {
    soup.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(soup, error))
  {
    std::fprintf(stderr, "%s: %s\n", kSliverCylinders, error.message.c_str());
    std::exit(1);
  }
  return mesh;
}

// The shared mesh in metres, as `proxima run --scale` loads it (or the procedural one).
bool loadShared(const SharedMesh& mesh, CollisionScene& scene, double& scale)
{
  if (std::string(mesh.file) == kSliverCylinders)
  {
    scale = 1.0;
    scene.addObject(crossingSliverCylinders());
    return true;
  }
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
    std::fprintf(stderr, "usage: %s OUT.json [--quick] [--seeds N] [--repeats N]\n", argv[0]);
    return 2;
  }
  bool quick = false;
  int seeds = 3;
  int repeats = TickReplay::kDefaultRepeats;
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
    else if (argument == "--repeats" && i + 1 < argc)
    {
      repeats = std::max(1, std::atoi(argv[++i]));
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
        const Runs ticks =
          playAll(scene, paths[static_cast<std::size_t>(seed - 1)], radius, repeats);
        // Tails only where they are plotted (pooled over seeds), to keep the report small.
        nlohmann::json json = statistics(ticks, false);
        json["mesh"] = mesh.file;
        json["scale"] = scale;
        json["triangles"] = object.mesh.numTriangles();
        json["radius_m"] = radius;
        json["seed"] = seed;
        cases.push_back(json);
        append(all, ticks);
        char label[96];
        std::snprintf(label, sizeof label, "%s r %.1f mm seed %d", mesh.file, radius * 1e3, seed);
        printProgress(label, json);
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
         {"work_ns_per_iteration", json["per_iteration"]["work_ns"]},
         {"max_work_ns_per_iteration", json["per_iteration"]["max_work_ns"]},
         {"triangles_tested_per_iteration", json["per_iteration"]["triangles_tested"]}});
      append(byRadius[radius], all);
    }
    meshes.push_back({{"mesh", mesh.file},
                      {"scale", scale},
                      {"triangles", object.mesh.numTriangles()},
                      {"median_edge_m", edge},
                      {"iteration_cost", series}});
  }
  Runs everything;
  for (const auto& [radius, ticks] : byRadius)
  {
    nlohmann::json json = statistics(ticks, true);
    json["mesh"] = "all meshes";
    json["radius_m"] = radius;
    json["seeds"] = seeds;
    pooled.push_back(json);
    append(everything, ticks);
  }
  // The whole probe corpus in one: every mesh, radius and seed (radius_m 0).
  if (!everything.empty())
  {
    nlohmann::json json = statistics(everything, false);
    json["mesh"] = "all meshes";
    json["radius_m"] = 0.0;
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
    const Runs ticks = playAll(scene, readFingerPathFile(pathFile), shared.radius, repeats);
    nlohmann::json json = statistics(ticks, true);
    json["path"] = shared.file;
    json["mesh"] = shared.mesh;
    json["scale"] = shared.scale;
    json["triangles"] = scene.objects.front().mesh.numTriangles();
    json["radius_m"] = shared.radius;
    sharedPaths.push_back(json);
    printProgress(std::string(shared.file) + " (shared path)", json);
  }

  const nlohmann::json report = {
    {"quick", quick},
    {"seeds", seeds},
    {"radii_m", radii},
    {"rate_hz", kRate},
    {"budgets_it", kBudgets},
    {"default_budget", budgetName(TickWorkBudget::realtimeDefault().iterations)},
    {"repeats", repeats},
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
