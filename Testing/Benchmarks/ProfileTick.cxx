// Replays chosen ticks of a finger path many times from the same solver state, for a profiler:
// `perf record` or callgrind then see only those ticks' work. Plays the path as `proxima run`
// does (lockstep, default servo and proxy parameters but the radius), no budget.
//
// Usage: ProfileTick MESH SCALE RADIUS PATH.csv REPEATS TICK [TICK...]
//   Prints, per tick, its iterations, the least and median wall time of the repeats and its query
//   counters (QueryStats); with
//   PROFILE_TICK_MOVES set, also the chain of points the tick moved through (MoveRecord.h); with
//   PROFILE_TICK_BUDGET=N, the path is played and the ticks replayed with an iteration budget.
//   For exact counts of the ticks' work alone:
//   valgrind --tool=callgrind --toggle-collect='*replayedUpdate*' ProfileTick ... 1 TICK
#include "IO/Mesh/MeshReader.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Proxy/ProxySolver.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <set>
#include <string>
#include <vector>

using namespace proxima;

namespace
{
// The replayed update alone, in a function of its own: `valgrind --tool=callgrind
// --toggle-collect='*replayedUpdate*'` then counts the chosen ticks' instructions and nothing of
// the path played to reach them.
[[gnu::noinline]] ProxyTickResult replayedUpdate(ProxySolver& replica, const Vec3& finger)
{
  return replica.update(finger);
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 7)
  {
    std::fprintf(stderr, "usage: ProfileTick MESH SCALE RADIUS PATH.csv REPEATS TICK...\n");
    return 2;
  }
  const double scale = std::atof(argv[2]);
  const double radius = std::atof(argv[3]);
  const int repeats = std::atoi(argv[5]);
  std::set<long> wanted;
  for (int i = 6; i < argc; ++i)
  {
    wanted.insert(std::atol(argv[i]));
  }
  CollisionScene scene;
  scene.addObject(loadTriangleMesh(argv[1], scale));
  const FingerPath path = readFingerPathFile(argv[4]);
  constexpr double kRate = 1000.0;
  ProxyParameters parameters;
  parameters.radius = radius;
  parameters.timeStep = 1.0 / kRate;
  // PROFILE_TICK_BUDGET=N plays the path, and replays the ticks, with an iteration budget of N
  // (as `proxima run --tick-budget Nit`): the ticks a budget limits start elsewhere.
  if (const char* budget = std::getenv("PROFILE_TICK_BUDGET"))
  {
    parameters.tickBudgetIterations = std::atoi(budget);
  }
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  solver->resetProxy(path.positions.front());
  auto start = std::make_unique<ProxySolver>(*solver);
  auto replica = std::make_unique<ProxySolver>(*solver);
  const LockstepSettings settings = lockstepCovering(path, kRate);
  SimulatedDevice device(path);
  const ServoParameters servo;
  long tick = 0;
  runLockstep(settings, *solver, device, servo, [&](const HapticState& record) {
    if (wanted.count(tick) != 0)
    {
      const Vec3 fingerHere = record.finger;
      std::vector<double> times;
      int iterations = 0;
      QueryStats queries;
      for (int r = 0; r < repeats; ++r)
      {
        *replica = *start;
        const auto t0 = std::chrono::steady_clock::now();
        const ProxyTickResult result = replayedUpdate(*replica, record.finger);
        const auto t1 = std::chrono::steady_clock::now();
        iterations = result.iterations;
        queries = result.queries;
        times.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
      }
      std::sort(times.begin(), times.end());
      if (std::getenv("PROFILE_TICK_MOVES") != nullptr)
      {
        MoveRecord record(4096);
        *replica = *start;
        replica->recordMoves(&record);
        replica->update(fingerHere);
        replica->recordMoves(nullptr);
        std::printf("  start %.17g %.17g %.17g, finger %.17g %.17g %.17g\n",
                    record.points[0].position.x, record.points[0].position.y,
                    record.points[0].position.z, fingerHere.x, fingerHere.y, fingerHere.z);
        for (std::size_t k = 0; k < record.count; ++k)
        {
          const Vec3 p = record.points[k].position;
          const double step = k > 0 ? norm(p - record.points[k - 1].position) : 0.0;
          std::printf("  %3zu %c %.9f %.9f %.9f  to finger %.9f  step %.3e\n", k,
                      record.points[k].kind == MovePointKind::Trial ? 'T' : 'A', p.x, p.y, p.z,
                      norm(p - fingerHere), step);
        }
      }
      std::printf("tick %ld: %d iterations, least %.1f us, median %.1f us; %u nodes, %u leaf "
                  "spheres, %u triangles tested\n",
                  tick, iterations, times.front(), times[times.size() / 2], queries.nodesVisited,
                  queries.leafSpheresTested, queries.trianglesTested);
    }
    *start = *solver;
    ++tick;
  });
  return 0;
}
