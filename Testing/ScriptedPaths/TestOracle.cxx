// The oracle checked on cases with known answers, and shown to catch each kind of violation: an
// oracle that cannot fail would make every scripted case pass.
#include "ProxyOracle.h"
#include "TestScenes.h"

#include "Geometry/ProceduralMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace proxima
{
namespace
{
using oracle::MeshOracle;

const TriangleCorners kTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

TEST(OracleDistance, PointTriangleKnownAnswers)
{
  Vec3 closest;
  EXPECT_DOUBLE_EQ(MeshOracle::pointTriangleDistance({0.2, 0.2, 0.5}, kTriangle, &closest), 0.5);
  EXPECT_EQ(closest, (Vec3{0.2, 0.2, 0}));
  EXPECT_DOUBLE_EQ(MeshOracle::pointTriangleDistance({-3, -4, 0}, kTriangle, &closest), 5.0);
  EXPECT_EQ(closest, (Vec3{0, 0, 0}));
  // Beyond the hypotenuse: the nearest point is on the edge x + y = 1.
  EXPECT_NEAR(MeshOracle::pointTriangleDistance({1, 1, 0}, kTriangle, &closest), std::sqrt(0.5),
              1e-16);
  EXPECT_NEAR(closest.x, 0.5, 1e-16);
  // Zero area: the triangle is its longest edge.
  const TriangleCorners line{{0, 0, 0}, {2, 0, 0}, {1, 0, 0}};
  EXPECT_DOUBLE_EQ(MeshOracle::pointTriangleDistance({1.5, 0, 2}, line), 2.0);
  EXPECT_DOUBLE_EQ(MeshOracle::pointTriangleDistance({3, 0, 0}, line), 1.0);
}

TEST(OracleDistance, SameAnswerOneKilometreFromTheOrigin)
{
  // 1/1024 m above a triangle 1 km out (binary fractions, so the inputs are exact): the frame of
  // the query keeps the answer exact, where plain double arithmetic at 1 km would lose 1e-13.
  const Vec3 o{1000, 1000, 1000};
  const double s = 1.0 / 64;
  const TriangleCorners far{o, o + Vec3{s, 0, 0}, o + Vec3{0, s, 0}};
  const Vec3 p = o + Vec3{s / 8, s / 8, s / 16};
  EXPECT_EQ(MeshOracle::pointTriangleDistance(p, far), s / 16);
  // A vertical segment beyond the corner b: nearest to b itself.
  const double slanted =
    MeshOracle::segmentTriangleDistance(o + Vec3{2 * s, -s, s / 16}, o + Vec3{2 * s, -s, 1}, far);
  EXPECT_NEAR(slanted, std::sqrt(s * s + s * s + s * s / 256), 1e-17);
}

TEST(OracleDistance, SegmentTriangle)
{
  // Parallel above: the height.
  EXPECT_DOUBLE_EQ(MeshOracle::segmentTriangleDistance({-1, 0.2, 0.3}, {2, 0.2, 0.3}, kTriangle),
                   0.3);
  // Through the triangle: 0, and it touches.
  EXPECT_EQ(MeshOracle::segmentTriangleDistance({0.2, 0.2, 1}, {0.2, 0.2, -1}, kTriangle), 0.0);
  EXPECT_TRUE(MeshOracle::segmentTouchesTriangle({0.2, 0.2, 1}, {0.2, 0.2, -1}, kTriangle));
  // Skew to an edge: segment along z at (0.5, -0.25), nearest to the edge on y = 0.
  EXPECT_DOUBLE_EQ(
    MeshOracle::segmentTriangleDistance({0.5, -0.25, 1}, {0.5, -0.25, -1}, kTriangle), 0.25);
  // Ending exactly on a corner touches; one ulp short does not.
  EXPECT_TRUE(MeshOracle::segmentTouchesTriangle({1, 0, 1}, {1, 0, 0}, kTriangle));
  EXPECT_FALSE(
    MeshOracle::segmentTouchesTriangle({1, 0, 1}, {1, 0, std::nextafter(0.0, 1.0)}, kTriangle));
  EXPECT_FALSE(
    MeshOracle::segmentTouchesTriangle({1.0000000001, 0, 1}, {1.0000000001, 0, -1}, kTriangle));
  // A zero-area triangle is crossed through its edges.
  const TriangleCorners line{{0, 0, 0}, {2, 0, 0}, {1, 0, 0}};
  EXPECT_TRUE(MeshOracle::segmentTouchesTriangle({1.5, -1, 0}, {1.5, 1, 0}, line));
  EXPECT_FALSE(MeshOracle::segmentTouchesTriangle({1.5, -1, 1e-300}, {1.5, 1, 1e-300}, line));
}

TEST(OracleDistance, RandomSegmentsAgainstDenseSampling)
{
  // Sampling the segment finely bounds the true distance from above; the oracle must never be
  // above the sampled minimum, and within the sampling step of it.
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial)
  {
    const TriangleCorners t{{u(engine), u(engine), u(engine)},
                            {u(engine), u(engine), u(engine)},
                            {u(engine), u(engine), u(engine)}};
    const Vec3 a{2 * u(engine), 2 * u(engine), 2 * u(engine)};
    const Vec3 b{2 * u(engine), 2 * u(engine), 2 * u(engine)};
    const double d = MeshOracle::segmentTriangleDistance(a, b, t);
    double sampled = 1e300;
    const int steps = 2000;
    for (int i = 0; i <= steps; ++i)
    {
      sampled = std::min(sampled, MeshOracle::pointTriangleDistance(
                                    a + (b - a) * (static_cast<double>(i) / steps), t));
    }
    ASSERT_LE(d, sampled + 1e-15) << trial;
    ASSERT_GE(d, sampled - distance(a, b) / steps) << trial;
  }
}

TEST(OracleMesh, GridDistancesAndGather)
{
  const TriangleSoup grid = makeGrid(0.2, 8, 0.0);
  const Vec3 vertex = grid.points[5 * 9 + 5];
  auto scene = scenes::makeScene(grid);
  const MeshOracle oracle(*scene);
  EXPECT_EQ(oracle.numTriangles(), 128u);
  EXPECT_DOUBLE_EQ(oracle.distance({0.01, 0.02, 0.003}), 0.003);
  EXPECT_DOUBLE_EQ(oracle.distance({0.01, 0.02, -0.5}), 0.5);
  EXPECT_DOUBLE_EQ(oracle.distance({0.01, 0.02, -0.5}, 0.1), 0.1); // capped
  EXPECT_NEAR(oracle.distance({0.3, 0.0, 0.0}), 0.2, 1e-15);       // beyond the edge x = 0.1
  EXPECT_DOUBLE_EQ(oracle.segmentDistance({-1, 0.013, 0.004}, {1, 0.013, 0.004}), 0.004);
  EXPECT_EQ(oracle.segmentDistance({0.013, 0.013, 0.004}, {0.013, 0.013, -0.004}), 0.0);
  EXPECT_TRUE(oracle.segmentTouchesAny({0.013, 0.013, 0.004}, {0.013, 0.013, -0.004}));
  // Above a grid vertex: the six triangles around it all hold the same closest point.
  const auto near = oracle.within(vertex + Vec3{0, 0, 0.001}, 0.001);
  EXPECT_EQ(near.size(), 6u);
  for (const auto& n : near)
  {
    EXPECT_EQ(n.away, (Vec3{0, 0, 0.001}));
  }
}

TEST(OracleCone, KnownProjections)
{
  const Vec3 up{0, 0, 1};
  EXPECT_EQ(oracle::projectOntoCone({1, 2, -3}, &up, 1), (Vec3{1, 2, 0}));
  EXPECT_EQ(oracle::projectOntoCone({1, 2, 3}, &up, 1), (Vec3{1, 2, 3}));
  const Vec3 two[2] = {{0, 0, 1}, {1, 0, 0}};
  EXPECT_EQ(oracle::projectOntoCone({-1, 2, -3}, two, 2), (Vec3{0, 2, 0}));
  const Vec3 three[3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(oracle::projectOntoCone({-1, -2, -3}, three, 3), (Vec3{0, 0, 0}));
  // A 90-degree groove along x: the finger below both lands on the groove line.
  const double h = std::sqrt(0.5);
  const Vec3 groove[2] = {{0, h, h}, {0, -h, h}};
  const Vec3 x = oracle::projectOntoCone({0.5, 0.1, -1}, groove, 2);
  EXPECT_NEAR(x.x, 0.5, 1e-16);
  EXPECT_NEAR(x.y, 0.0, 1e-16);
  EXPECT_NEAR(x.z, 0.0, 1e-16);
  // v nearly opposite one normal: CGAL's default pricing crashes here; the oracle must not.
  const Vec3 n{0.57735026918962573, -0.57735026918962573, -0.57735026918962573};
  const Vec3 nearlyOpposite = oracle::projectOntoCone(
    {-0.013689695822515193, 0.013689695822515195, 0.013689695822515193}, &n, 1);
  EXPECT_LT(norm(nearlyOpposite), 1e-17);
}

// The checker must see each kind of violation: fed positions no solver should produce.
class OracleCatches : public testing::Test
{
protected:
  OracleCatches()
    : scene(scenes::makeScene(makeGrid(0.2, 4, 0.0)))
    , oracle(*scene)
    , settings(oracle::OracleSettings::forScene(scene->diagonal(), 1e-12))
  {
    parameters.radius = 0.001;
  }
  std::unique_ptr<CollisionScene> scene;
  MeshOracle oracle;
  ProxyParameters parameters;
  oracle::OracleSettings settings;
};

TEST_F(OracleCatches, PenetrationAndTunnel)
{
  oracle::TickChecker checker(oracle, *scene, parameters, settings);
  checker.reset({0, 0, 0.01});
  checker.check(0, {0, 0, -0.01}, {0.0, 0.0, 0.0005}, 1, 1, false, false, false);
  EXPECT_EQ(checker.stats().penetrations, 1u);
  EXPECT_EQ(checker.stats().tunnels, 1u);
  checker.check(1, {0, 0, -0.01}, {0.0, 0.0, -0.002}, 1, 1, false, false, false);
  EXPECT_EQ(checker.stats().crossings, 1u);
  EXPECT_NEAR(checker.stats().minClearance, -0.0005, 1e-15);
}

TEST_F(OracleCatches, BudgetLimitedTicksLongAfterTheFingerCameToRest)
{
  // Rule (h): with the finger still, a budgeted run must stop being limited within
  // maxRestingLimitedTicks (20) ticks. A moving finger may be limited on every tick.
  oracle::TickChecker moving(oracle, *scene, parameters, settings);
  moving.reset({0, 0, 0.01});
  for (std::uint64_t t = 0; t < 30; ++t)
  {
    moving.check(t, {0, 0, 0.01 - 1e-5 * static_cast<double>(t)}, {0, 0, 0.01}, 1, 0, false, false,
                 false, true);
  }
  EXPECT_EQ(moving.stats().settleFailures, 0u);

  oracle::TickChecker resting(oracle, *scene, parameters, settings);
  resting.reset({0, 0, 0.01});
  for (std::uint64_t t = 0; t < 25; ++t)
  {
    resting.check(t, {0, 0, 0.005}, {0, 0, 0.01}, 1, 0, false, false, false, true);
  }
  // Ticks 21 to 24 are 21 to 24 ticks into the rest.
  EXPECT_EQ(resting.stats().settleFailures, 4u);
  EXPECT_EQ(resting.stats().maxRestingLimitedTick, 24u);
}

TEST_F(OracleCatches, StoppedShortAndNotAMinimum)
{
  oracle::TickChecker checker(oracle, *scene, parameters, settings);
  checker.reset({0, 0, 0.01});
  // Free path to the finger, proxy stayed put: (c) and (d) both fail.
  checker.check(0, {0.01, 0, 0.01}, {0, 0, 0.01}, 1, 0, false, false, false);
  EXPECT_EQ(checker.stats().freePathFailures, 1u);
  EXPECT_EQ(checker.stats().residualFailures, 1u);
  // Resting on the plane with the finger below and to the side: sliding gets nearer.
  checker.reset({0, 0, 0.001});
  checker.check(1, {0.003, 0, -0.004}, {0, 0, 0.001}, 1, 1, false, false, false);
  EXPECT_EQ(checker.stats().residualFailures, 2u);
  EXPECT_NEAR(checker.stats().maxResidual, 0.01 - std::sqrt(0.005 * 0.005 + 0.0) + 0.0, 0.01);
  // The true local minimum passes: above the finger, at the radius.
  checker.reset({0.003, 0, 0.001});
  checker.check(2, {0.003, 0, -0.004}, {0.003, 0, 0.001}, 0, 1, false, false, false);
  EXPECT_EQ(checker.stats().residualFailures, 2u);
  EXPECT_EQ(checker.stats().gapFailures, 0u);
  // A contact reported 1 um away from the surface is a gap failure.
  checker.check(3, {0.003, 0, -0.004}, {0.003, 0, 0.001001}, 1, 1, false, false, false);
  EXPECT_EQ(checker.stats().gapFailures, 1u);
}

} // namespace
} // namespace proxima
