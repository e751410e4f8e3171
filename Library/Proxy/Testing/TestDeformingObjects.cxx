// Deforming objects in ProxySolver (issue 35: tissue; setDeformingObjects, setObjectPoints). A
// sheet whose points a test moves tick by tick, as a simulation would: a bump rising under a
// resting finger, a dent opening under a press, a bump sweeping through a free proxy. Every tick
// is checked by the oracle of Testing/ScriptedPaths against that tick's surface: a static scene
// made of the deformed sheet, its own CGAL oracle, and the tick replayed there from where the
// deformation left the proxy (the first point of the tick's move record). So no tick leaves the
// proxy inside the surface as it then is, no move tunnels, and a tick that settles settles at a
// local minimum of that surface.
#include "Proxy/ProxySolver.h"

#include "Geometry/ProceduralMeshes.h"
#include "ProxyOracle.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{
constexpr double kRadius = 0.002;
constexpr double kSheet = 0.1;
constexpr std::uint32_t kCells = 40;

// The sheet's points moved by `height(x, y)` along z.
std::vector<Vec3> deformed(const std::vector<Vec3>& rest,
                           const std::function<double(double, double)>& height)
{
  std::vector<Vec3> points = rest;
  for (Vec3& p : points)
  {
    p.z += height(p.x, p.y);
  }
  return points;
}

// The sheet as a static scene with `points`.
std::unique_ptr<CollisionScene> sheetScene(const std::vector<Vec3>& points)
{
  TriangleSoup soup = makeGrid(kSheet, kCells);
  soup.points = points;
  soup.pointNormals.clear();
  return scenes::makeScene(std::move(soup));
}

struct DeformedRun
{
  oracle::InvariantStats stats;
  Vec3 proxy;
  int pushedTicks = 0;
};

// Plays `ticks` ticks with the finger at `finger(i)` and the sheet's height at `height(i, x, y)`,
// each tick checked against its own surface.
DeformedRun playDeforming(int ticks, const std::function<Vec3(int)>& finger,
                          const std::function<double(int, double, double)>& height,
                          const Vec3& start)
{
  const auto scene = scenes::makeScene(makeGrid(kSheet, kCells));
  const std::vector<Vec3> rest = scene->objects[0].mesh.points();
  ProxyParameters parameters;
  parameters.radius = kRadius;
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(scene.get(), parameters);
  solver->setDeformingObjects({0});
  EXPECT_TRUE(solver->hasDeformingObjects());
  solver->resetProxy(start);
  auto record = std::make_unique<MoveRecord>();
  solver->recordMoves(record.get());
  DeformedRun run;
  for (int i = 0; i < ticks; ++i)
  {
    const std::vector<Vec3> points =
      deformed(rest, [&](double x, double y) { return height(i, x, y); });
    EXPECT_TRUE(solver->setObjectPoints(0, points.data(), points.size()));
    const Vec3 target = finger(i);
    const ProxyTickResult result = solver->update(target);
    run.pushedTicks += result.conditions.has(TickCondition::pushedByObject) ? 1 : 0;
    // The oracle of this tick's surface, the tick replayed there from where it began.
    const auto surface = sheetScene(points);
    const oracle::MeshOracle meshOracle(*surface);
    oracle::TickChecker checker(
      meshOracle, *surface, parameters,
      oracle::OracleSettings::forScene(surface->diagonal(), solver->skin()));
    checker.reset(record->points[0].position);
    checker.check(static_cast<std::uint64_t>(i), target, result);
    const oracle::InvariantStats& s = checker.stats();
    run.stats.penetrations += s.penetrations;
    run.stats.tunnels += s.tunnels;
    run.stats.crossings += s.crossings;
    run.stats.residualFailures += s.residualFailures;
    run.stats.replayFailures += s.replayFailures;
    run.stats.approachFailures += s.approachFailures;
    run.stats.gapFailures += s.gapFailures;
    run.stats.minClearance = std::min(run.stats.minClearance, s.minClearance);
    for (const std::string& message : s.messages)
    {
      if (run.stats.messages.size() < 5)
      {
        run.stats.messages.push_back("tick " + std::to_string(i) + ": " + message);
      }
    }
  }
  run.proxy = solver->proxy();
  return run;
}

void expectClean(const DeformedRun& run, const char* name)
{
  std::printf("[ measured ] %s: min clearance %.3g m, pushed on %d ticks\n", name,
              run.stats.minClearance, run.pushedTicks);
  EXPECT_EQ(run.stats.penetrations, 0u) << name;
  EXPECT_EQ(run.stats.tunnels, 0u) << name;
  EXPECT_EQ(run.stats.crossings, 0u) << name;
  EXPECT_EQ(run.stats.residualFailures, 0u) << name;
  EXPECT_EQ(run.stats.replayFailures, 0u) << name;
  EXPECT_EQ(run.stats.approachFailures, 0u) << name;
  EXPECT_EQ(run.stats.gapFailures, 0u) << name;
  for (const std::string& message : run.stats.messages)
  {
    ADD_FAILURE() << name << ": " << message;
  }
}

double bump(double x, double y, double width)
{
  return std::exp(-(x * x + y * y) / (width * width));
}

// A bump 15 mm high and 2 cm wide rises under a finger pressed 2 mm into the flat sheet, 0.1 mm
// a tick, then holds: the sheet carries the proxy up, and at rest the proxy sits on the top of
// the bump, above the finger, the spring stretched by the bump's height plus the press.
TEST(DeformingObjects, ARisingBumpCarriesTheProxyUp)
{
  const Vec3 fingerAt{0.0, 0.0, -0.002};
  const double top = 0.015;
  const DeformedRun run = playDeforming(
    200, [&](int) { return fingerAt; },
    [&](int i, double x, double y) { return top * std::min(1.0, i / 150.0) * bump(x, y, 0.02); },
    Vec3{0.0, 0.0, kRadius + 0.001});
  expectClean(run, "rising bump");
  EXPECT_GT(run.pushedTicks, 100);
  // The bump's top is the grid point at the origin (a vertex: the proxy rests on it).
  EXPECT_NEAR(run.proxy.x, 0.0, 1e-9);
  EXPECT_NEAR(run.proxy.y, 0.0, 1e-9);
  EXPECT_NEAR(run.proxy.z, top + kRadius, 1e-9);
}

// A dent 6 mm deep opens under a finger pressed 8 mm below the sheet, as tissue gives way under
// a press: the proxy follows the surface down and rests at the dent's bottom. The bottom is a
// grid point in a concave fan of facets: the proxy rests on the facets around it, a few
// micrometres above the point's height plus its radius (the oracle checks it is a local minimum).
TEST(DeformingObjects, ADentOpeningUnderAPressLetsTheProxyFollow)
{
  const Vec3 fingerAt{0.0, 0.0, -0.008};
  const double depth = 0.006;
  const DeformedRun run = playDeforming(
    200, [&](int) { return fingerAt; },
    [&](int i, double x, double y) { return -depth * std::min(1.0, i / 150.0) * bump(x, y, 0.02); },
    Vec3{0.0, 0.0, kRadius + 0.001});
  expectClean(run, "opening dent");
  EXPECT_NEAR(run.proxy.x, 0.0, 1e-9);
  EXPECT_NEAR(run.proxy.y, 0.0, 1e-9);
  EXPECT_GT(run.proxy.z, -depth + kRadius);
  EXPECT_LT(run.proxy.z, -depth + kRadius + 1e-5);
}

// A bump 3 mm high, as wide as the proxy, sweeps along x under a proxy hovering 1 mm above the
// sheet, 1 mm a tick (faster than the gap: it rises into where the proxy is), while the finger
// stays put: the proxy is pushed aside and up each time and never left inside.
TEST(DeformingObjects, ABumpSweepingThroughAFreeProxyPushesItOut)
{
  const Vec3 fingerAt{0.0, 0.0, kRadius + 0.001};
  const DeformedRun run = playDeforming(
    60, [&](int) { return fingerAt; },
    [&](int i, double x, double y) {
      const double centre = -0.03 + 0.001 * i;
      return 0.003 * bump(x - centre, y, 0.004);
    },
    fingerAt);
  expectClean(run, "sweeping bump");
  EXPECT_GT(run.pushedTicks, 0);
}

TEST(DeformingObjects, SetObjectPointsRefusesWhatItCannotApply)
{
  const auto scene = scenes::makeScene(makeGrid(kSheet, kCells));
  TriangleMesh sphere;
  MeshError error;
  ASSERT_TRUE(sphere.build(makeIcosphere(2, 0.01, Vec3{0.0, 0.0, 0.05}), error)) << error.message;
  scene->addObject(std::move(sphere));
  ProxyParameters parameters;
  parameters.radius = kRadius;
  ProxySolver solver;
  solver.setScene(scene.get(), parameters);
  std::vector<Vec3> points = scene->objects[0].mesh.points();
  EXPECT_FALSE(solver.setObjectPoints(0, points.data(), points.size())) << "nothing deforms yet";
  solver.setDeformingObjects({0});
  EXPECT_FALSE(solver.setObjectPoints(1, points.data(), points.size())) << "object 1 is rigid";
  EXPECT_FALSE(solver.setObjectPoints(0, points.data(), points.size() - 1)) << "a point short";
  points[7].z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(solver.setObjectPoints(0, points.data(), points.size())) << "a NaN point";
  points[7].z = 0.0;
  EXPECT_TRUE(solver.setObjectPoints(0, points.data(), points.size()));
  // The scene's own object never changes: queries use the solver's copy.
  EXPECT_EQ(&solver.queryObject(1), &scene->objects[1]);
  EXPECT_NE(&solver.queryObject(0), &scene->objects[0]);
}
} // namespace
} // namespace proxima
