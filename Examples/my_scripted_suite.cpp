// A ctest suite of one's own on Proxima's scripted-path harness: a scene, a finger path, and the
// oracle (exact geometry, independent of the solver) checking every tick for penetration,
// tunnelling, the constrained minimum and the force.
#include "ScriptedHarness.h"
#include "TestScenes.h"

#include "Geometry/ProceduralMeshes.h"

#include <gtest/gtest.h>

TEST(MyScriptedSuite, PressAndStrokeOnAFloor)
{
  const auto scene = proxima::scenes::makeScene(proxima::makeGrid(0.1, 10));
  const proxima::oracle::MeshOracle oracle(*scene);
  proxima::scripted::ScriptedCase c;
  c.name = "my-floor-stroke";
  c.scene = scene.get();
  c.oracle = &oracle;
  c.proxy.radius = 0.001;
  c.path.append(0.0, {-0.02, 0.0, 0.004});
  c.path.append(0.2, {-0.02, 0.0, -0.002});
  c.path.append(0.6, {0.02, 0.01, -0.002});
  c.path.append(0.8, {0.02, 0.01, 0.004});
  const proxima::scripted::ScriptedOutcome outcome = proxima::scripted::runScriptedCase(c);
  proxima::scripted::expectInvariants(c.name, outcome);
  EXPECT_GT(outcome.stats.contactTicks, 300u);
}
