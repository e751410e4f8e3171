// Golden traces: small deterministic scripted runs whose whole trace (tick, t, finger, proxy,
// force, contacts, iterations; not solve_ns) must not drift. Compared within 1e-12 relative (to
// the larger of the two values and of the column's largest magnitude); integer columns exactly.
//
// To regenerate after an intended change of behaviour:
//   PROXIMA_UPDATE_GOLDEN=1 ctest --test-dir build -R ScriptedGoldenTraces
// then review `git diff Testing/ScriptedPaths/Golden/` before committing.
#include "ScriptedHarness.h"
#include "TestScenes.h"

#include "Geometry/ProceduralMeshes.h"
#include "Paths/PathGenerators.h"

#include <gtest/gtest.h>

namespace proxima
{
namespace
{
constexpr double kRadius = 0.001;
constexpr double kRate = 1000.0;

void runGolden(const std::string& name, TriangleSoup soup, const FingerPath& path)
{
  const std::unique_ptr<CollisionScene> scene = scenes::makeScene(std::move(soup));
  const oracle::MeshOracle oracle(*scene);
  scripted::ScriptedCase c;
  c.name = name;
  c.scene = scene.get();
  c.oracle = &oracle;
  c.proxy.radius = kRadius;
  c.path = path;
  c.rate = kRate;
  c.keepTrace = true;
  const scripted::ScriptedOutcome outcome = scripted::runScriptedCase(c);
  scripted::expectInvariants(name, outcome);
  scripted::expectMatchesGolden(name, outcome.trace);
}

TEST(ScriptedGoldenTraces, PlanePressAndStroke)
{
  PressAndStroke press;
  press.surfacePoint = {-0.02, 0.003, 0.0};
  press.depth = 0.002;
  press.strokeDirection = {1, 0.3, 0};
  press.strokeLength = 0.04;
  press.speed = 0.1;
  runGolden("plane-press-stroke", makeGrid(0.1, 10, 0.0), makePressAndStrokePath(press, kRate));
}

TEST(ScriptedGoldenTraces, BoxJabs)
{
  const TriangleSoup box = makeBox({0.03, 0.02, 0.01});
  Aabb bounds;
  bounds.expand({-0.03, -0.02, -0.01});
  bounds.expand({0.03, 0.02, 0.01});
  runGolden("box-jab", box, makeDefaultPath("jab", bounds, kRadius, kRate));
}

TEST(ScriptedGoldenTraces, GrooveCircle)
{
  // Around the line of a 60-degree groove: one face, both faces, the other face, free.
  const FingerPath path = concatenatePaths(
    {makeSlidePath({0.0, 0.0, 0.03}, {0.0, 0.012, 0.005}, 0.1, kRate),
     makeCirclePath({0.0, 0.0, 0.005}, {1, 0, 0}, {0, 1, 0}, 0.012, 1.0, 0.5, kRate)},
    kRate);
  runGolden("groove-circle", scenes::makeVGroove(60.0, 0.05, 0.04), path);
}

} // namespace
} // namespace proxima
