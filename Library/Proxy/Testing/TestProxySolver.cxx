// ProxySolver (paper 2.1-2.2: move, update, repeat) on procedural scenes, each the smallest mesh
// holding one hard case of DESIGN.md section 4. Every update is checked by the oracle of
// Testing/ScriptedPaths/ProxyOracle.h (no penetration, no tunnelling of any move stage, free path
// taken, local minimum, contact gap) and, where the answer is known in closed form, against it.
#include "Proxy/ProxySolver.h"

#include "Geometry/ProceduralMeshes.h"
#include "ProxyOracle.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <random>

namespace proxima
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.001;

// A scene, its oracle, a solver and a tick checker: step() runs one update and checks it.
class Rig
{
public:
  explicit Rig(TriangleSoup soup, const Vec3& start, double radius = kRadius)
    : m_scene(scenes::makeScene(std::move(soup)))
    , m_oracle(*m_scene)
  {
    m_parameters.radius = radius;
    m_solver = std::make_unique<ProxySolver>();
    m_solver->setScene(m_scene.get(), m_parameters);
    m_solver->resetProxy(start);
    m_checker = std::make_unique<oracle::TickChecker>(
      m_oracle, *m_scene, m_parameters,
      oracle::OracleSettings::forScene(m_scene->diagonal(), m_solver->skin()));
    m_checker->reset(start);
  }

  ProxyTickResult step(const Vec3& finger)
  {
    const ProxyTickResult result = m_solver->update(finger);
    m_checker->check(m_ticks++, finger, result);
    return result;
  }
  /// Moves the finger from where it is to `to` in steps no longer than `stepLength`.
  ProxyTickResult drive(const Vec3& from, const Vec3& to, double stepLength)
  {
    const int steps = std::max(1, static_cast<int>(std::ceil(distance(from, to) / stepLength)));
    ProxyTickResult result;
    for (int i = 1; i <= steps; ++i)
    {
      result = step(from + (to - from) * (static_cast<double>(i) / steps));
    }
    return result;
  }
  void teleport(const Vec3& proxy)
  {
    m_solver->resetProxy(proxy);
    m_checker->reset(proxy);
  }

  /// Prints the worst margins and fails the test on any oracle violation.
  void expectClean(const std::string& name) const
  {
    const oracle::InvariantStats& s = m_checker->stats();
    std::cout << s.summary(name);
    testing::Test::RecordProperty(name + "_max_residual_m", oracle::str(s.maxResidual));
    testing::Test::RecordProperty(name + "_min_clearance_m", oracle::str(s.minClearance));
    EXPECT_EQ(s.failures(), 0u) << name << ": see the [oracle] lines above";
  }

  ProxySolver& solver() { return *m_solver; }
  const CollisionScene& scene() const { return *m_scene; }
  const oracle::MeshOracle& oracle() const { return m_oracle; }
  double skin() const { return m_solver->skin(); }

private:
  std::unique_ptr<CollisionScene> m_scene;
  oracle::MeshOracle m_oracle;
  ProxyParameters m_parameters;
  std::unique_ptr<ProxySolver> m_solver;
  std::unique_ptr<oracle::TickChecker> m_checker;
  std::uint64_t m_ticks = 0;
};

TEST(ProxySolverPlane, RestsAboveTheFingerAndFollowsIt)
{
  Rig rig(makeGrid(0.2, 10, 0.0), {0.01, 0.02, 0.01});
  // Straight down through the plane in one jump: the proxy stops at radius + skin, over the finger.
  ProxyTickResult r = rig.step({0.013, 0.021, -0.004});
  EXPECT_NEAR(r.proxy.x, 0.013, 1e-12);
  EXPECT_NEAR(r.proxy.y, 0.021, 1e-12);
  EXPECT_GE(r.proxy.z, kRadius);
  EXPECT_LE(r.proxy.z, kRadius + 2.0 * rig.skin());
  ASSERT_EQ(r.numContacts, 1);
  EXPECT_NEAR(r.contacts[0].normal.z, 1.0, 1e-15);
  EXPECT_NEAR(r.contacts[0].depth, r.proxy.z + 0.004, 1e-12);
  // Stroke under the surface, crossing grid edges and vertices: the proxy follows in x and y to
  // section 4's 1e-9 m. (It may lag by ~1e-10: a tangential move over a coplanar neighbour that
  // rounding makes "approaching" is blocked at once; the worst lag is printed.)
  double lag = 0.0;
  Vec3 finger{0.013, 0.021, -0.004};
  for (int i = 1; i <= 80; ++i)
  {
    finger = Vec3{0.013, 0.021, -0.004} + Vec3{-0.053, -0.041, 0.002} * (i / 80.0);
    r = rig.step(finger);
    lag = std::max(lag, std::hypot(r.proxy.x - finger.x, r.proxy.y - finger.y));
  }
  std::cout << "[plane] worst tangential lag while stroking: " << lag << " m\n";
  EXPECT_LE(lag, 1e-9);
  EXPECT_LE(r.proxy.z, kRadius + 2.0 * rig.skin());
  // Lift: free again, the proxy is at the finger.
  r = rig.step({-0.04, -0.02, 0.005});
  EXPECT_EQ(r.proxy, (Vec3{-0.04, -0.02, 0.005}));
  EXPECT_EQ(r.numContacts, 0);
  rig.expectClean("plane");
}

TEST(ProxySolverPlane, FingerInTheContactPlaneToRounding)
{
  // The finger one unit in the last place below the resting proxy, moving sideways: u . n is
  // about -1e-17, the finger lies in the constraint plane to rounding (the dual point c_i n_i of
  // eq. 17 is ~1e17 from the origin).
  Rig rig(makeGrid(0.2, 10, 0.0), {0.0, 0.0, 0.01});
  ProxyTickResult r = rig.step({0.0, 0.0, -0.001});
  const double rest = r.proxy.z;
  for (int i = 1; i <= 40; ++i)
  {
    const double below = std::nextafter(rest, 0.0);
    const Vec3 finger{0.0005 * i, -0.0003 * i, i % 2 == 0 ? below : rest};
    r = rig.step(finger);
    EXPECT_NEAR(r.proxy.x, finger.x, 1e-12) << i;
    EXPECT_NEAR(r.proxy.y, finger.y, 1e-12) << i;
    EXPECT_GE(r.proxy.z, kRadius) << i;
  }
  rig.expectClean("plane-in-contact-plane");
}

TEST(ProxySolverBox, NoPopThroughAndWrapsAroundEdges)
{
  const Vec3 half{0.03, 0.02, 0.01};
  Rig rig(makeBox(half), {0.0, 0.0, 0.03});
  // Press into the top and drive the finger right through the box to below it (10 mm per tick,
  // 10 m/s at 1 kHz): the proxy stays on top, over the finger.
  ProxyTickResult r = rig.drive({0.0, 0.0, 0.03}, {0.005, 0.004, -0.03}, 0.01);
  EXPECT_NEAR(r.proxy.x, 0.005, 1e-12);
  EXPECT_NEAR(r.proxy.y, 0.004, 1e-12);
  EXPECT_GE(r.proxy.z, half.z + kRadius);
  EXPECT_LE(r.proxy.z, half.z + kRadius + 2.0 * rig.skin());
  // Move the finger out past the side under the box: the proxy slides to the edge, wraps around
  // it and ends at the finger once the way is free.
  r = rig.drive({0.005, 0.004, -0.03}, {0.05, 0.004, -0.03}, 0.002);
  r = rig.drive({0.05, 0.004, -0.03}, {0.05, 0.004, -0.02}, 0.002);
  EXPECT_EQ(r.proxy, (Vec3{0.05, 0.004, -0.02}));
  // Jab the edge between the top and the +x side diagonally.
  rig.teleport({0.05, 0.0, 0.03});
  r = rig.drive({0.05, 0.0, 0.03}, {0.02, 0.0, 0.0}, 0.01);
  EXPECT_GE(rig.oracle().distance(r.proxy), kRadius - 1e-12);
  rig.expectClean("box");
}

TEST(ProxySolverConcaveCorner, PinnedByThreePlanes)
{
  Rig rig(scenes::makeConcaveCorner(0.05), {0.02, 0.02, 0.02});
  ProxyTickResult r = rig.step({-0.01, -0.01, -0.01});
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_GE(r.proxy[axis], kRadius) << axis;
    EXPECT_LE(r.proxy[axis], kRadius + 2.0 * rig.skin()) << axis;
  }
  EXPECT_EQ(r.numContacts, 3);
  // Finger pushed along one wall: the proxy slides out of the corner along the floor and wall.
  r = rig.drive({-0.01, -0.01, -0.01}, {0.03, -0.01, -0.01}, 0.003);
  EXPECT_NEAR(r.proxy.x, 0.03, 1e-12);
  EXPECT_EQ(r.numContacts, 2);
  // And around the corner at 10 m/s.
  r = rig.drive({0.03, -0.01, -0.01}, {-0.01, 0.03, -0.01}, 0.01);
  r = rig.drive({-0.01, 0.03, -0.01}, {-0.01, -0.01, 0.04}, 0.01);
  rig.expectClean("concave-corner");
}

TEST(ProxySolverGroove, SixtyDegreeGroove)
{
  // Faces 60 degrees apart (narrower than 90): the proxy on the groove line sits at 2r (r over
  // sin 30 degrees) above it.
  Rig rig(scenes::makeVGroove(60.0, 0.05, 0.04), {0.0, 0.0, 0.03});
  ProxyTickResult r = rig.step({0.0, 0.0, -0.02});
  EXPECT_NEAR(r.proxy.y, 0.0, 1e-12);
  EXPECT_GE(r.proxy.z, 2.0 * kRadius);
  EXPECT_LE(r.proxy.z, 2.0 * kRadius + 6.0 * rig.skin());
  // Along the groove, below it: the proxy follows on the groove line.
  r = rig.drive({0.0, 0.0, -0.02}, {0.03, 0.0, -0.01}, 0.002);
  EXPECT_NEAR(r.proxy.x, 0.03, 1e-12);
  EXPECT_NEAR(r.proxy.y, 0.0, 1e-12);
  // Sideways: the finger ends behind one face and in front of the other (the narrow-groove case
  // of the goal solver), and in every direction around the groove line.
  for (int i = 0; i < 72; ++i)
  {
    const double phi = 2 * kPi * i / 72;
    rig.step({0.03, 0.015 * std::cos(phi), 0.008 + 0.015 * std::sin(phi)});
  }
  rig.expectClean("v-groove-60");
}

TEST(ProxySolverApex, ConvexPyramidApex)
{
  for (int sides : {4, 5, 8})
  {
    // Apex up at the origin, faces falling 45 degrees to a base below.
    Rig rig(scenes::makePyramid(sides, 0.03, -0.03), {0.0, 0.0, 0.02});
    ProxyTickResult r = rig.step({0.0, 0.0, -0.01});
    // Straight down onto the apex: the proxy rests on the apex point itself.
    EXPECT_NEAR(r.proxy.x, 0.0, 1e-12) << sides;
    EXPECT_NEAR(r.proxy.y, 0.0, 1e-12) << sides;
    EXPECT_NEAR(r.proxy.z, kRadius, 2.0 * rig.skin()) << sides;
    // Jabs at the apex from five directions at 10 m/s.
    for (const Vec3& from :
         {Vec3{0, 0, 1}, Vec3{1, 0, 1}, Vec3{-1, 0, 1}, Vec3{0, 1, 1}, Vec3{0.3, -1, 1}})
    {
      const Vec3 start = normalizedOrZero(from) * 0.02;
      rig.drive(r.proxy, start, 0.01);
      r = rig.drive(start, normalizedOrZero(from) * -0.008, 0.01);
    }
    rig.expectClean("apex-" + std::to_string(sides));
  }
}

TEST(ProxySolverApex, FunnelFourToSixteenFaces)
{
  // The bottom of a funnel of n faces: n constraint planes through (nearly) one point.
  for (int sides = 4; sides <= 16; sides += 3)
  {
    const double radius = 0.03;
    const double height = 0.03;
    Rig rig(scenes::makePyramid(sides, radius, height), {0.0, 0.0, 0.02});
    ProxyTickResult r = rig.step({0.0, 0.0, -0.02});
    const double slope = std::atan(height / (radius * std::cos(kPi / sides)));
    const double rest = kRadius / std::cos(slope);
    EXPECT_NEAR(r.proxy.x, 0.0, 1e-9) << sides;
    EXPECT_NEAR(r.proxy.y, 0.0, 1e-9) << sides;
    EXPECT_NEAR(r.proxy.z, rest, 1e-9) << sides;
    // Any two opposite faces (or three around) hold a vertical push.
    EXPECT_GE(r.numContacts, 2) << sides;
    // Push around inside the funnel, below it and off-axis, then jab down at 10 m/s.
    std::mt19937_64 engine(static_cast<std::uint64_t>(sides));
    std::uniform_real_distribution<double> u(-0.02, 0.02);
    for (int i = 0; i < 40; ++i)
    {
      rig.step({u(engine), u(engine), -0.02 + 0.5 * u(engine)});
    }
    rig.drive({0, 0, 0.03}, {0.001, -0.0005, -0.03}, 0.01);
    rig.expectClean("funnel-" + std::to_string(sides));
  }
}

TEST(ProxySolverSheet, ThinSheetNeverPassedFromEitherSide)
{
  for (const double side : {1.0, -1.0})
  {
    // A single triangle and a two-triangle quad (jabs on the shared diagonal and the corner).
    for (const bool quad : {false, true})
    {
      TriangleSoup soup = quad ? scenes::makeQuad({-0.05, -0.05, 0}, {0.05, -0.05, 0},
                                                  {0.05, 0.05, 0}, {-0.05, 0.05, 0})
                               : scenes::makeSheet(0.1);
      Rig rig(std::move(soup), {0.0, 0.0, 0.02 * side});
      const std::string name =
        std::string("sheet-") + (quad ? "quad" : "triangle") + (side > 0 ? "-above" : "-below");
      // 10 mm per tick through the sheet at points inside it (for the quad: on the shared
      // diagonal, at its middle and near a corner), then a stroke while pressed beyond it.
      const std::vector<Vec3> targets =
        quad ? std::vector<Vec3>{{0, 0, 0}, {0.02, 0.02, 0}, {0.045, 0.045, 0}, {0.01, -0.03, 0}}
             : std::vector<Vec3>{{0, 0, 0}, {0.01, 0, 0}, {-0.01, -0.02, 0}, {0.02, -0.02, 0}};
      for (const Vec3& at : targets)
      {
        rig.teleport(at + Vec3{0, 0, 0.02 * side});
        const ProxyTickResult r =
          rig.drive(at + Vec3{0, 0, 0.02 * side}, at - Vec3{0, 0, 0.03 * side}, 0.01);
        EXPECT_GE(r.proxy.z * side, kRadius) << name;
        EXPECT_NEAR(r.proxy.x, at.x, 1e-9) << name;
        EXPECT_NEAR(r.proxy.y, at.y, 1e-9) << name;
        rig.drive(at - Vec3{0, 0, 0.03 * side}, at + Vec3{0.004, -0.002, -0.03 * side}, 0.01);
        EXPECT_GE(rig.solver().proxy().z * side, kRadius) << name;
      }
      rig.expectClean(name);
    }
  }
}

TEST(ProxySolverSphere, IcospheresAtSeveralResolutions)
{
  const double sphereRadius = 0.03;
  for (std::uint32_t subdivisions = 0; subdivisions <= 4; ++subdivisions)
  {
    Rig rig(makeIcosphere(subdivisions, sphereRadius), {0.0, 0.0, 0.05});
    // The faceted sphere lies between its inradius (faces) and its radius (corners).
    double inradius = sphereRadius;
    for (std::uint32_t t = 0; t < rig.scene().objects[0].mesh.numTriangles(); ++t)
    {
      inradius = std::min(inradius, oracle::MeshOracle::pointTriangleDistance(
                                      Vec3{}, rig.scene().objects[0].mesh.corners(t)));
    }
    std::mt19937_64 engine(subdivisions);
    std::normal_distribution<double> g;
    Vec3 out{0, 0, 0.05};
    for (int i = 0; i < 30; ++i)
    {
      // From outside to the centre, then around the inside.
      const Vec3 direction = normalizedOrZero(Vec3{g(engine), g(engine), g(engine)});
      out = direction * 0.05;
      rig.teleport(out);
      const ProxyTickResult r = rig.drive(out, direction * 0.002, 0.01);
      const double d = norm(r.proxy);
      EXPECT_GE(d, inradius + kRadius - 1e-12) << subdivisions;
      EXPECT_LE(d, sphereRadius + kRadius + 4.0 * rig.skin()) << subdivisions;
      rig.drive(direction * 0.002, normalizedOrZero(Vec3{g(engine), g(engine), g(engine)}) * 0.01,
                0.002);
    }
    rig.expectClean("icosphere-" + std::to_string(subdivisions));
  }
}

TEST(ProxySolverSoup, GapsNarrowerThanTheProxyHoldIt)
{
  // Tiles 10 mm wide, 1.2 mm apart (proxy diameter 2 mm; where two gaps cross, the hole's
  // diagonal is 1.7 mm), duplicated, with an intersecting tilted tile: pressed into a gap the
  // proxy rests on both edges at sqrt(r^2 - (gap/2)^2).
  const double gap = 0.0012;
  Rig rig(scenes::makeTiles(4, 0.01, gap, true), {0.0, 0.0, 0.02});
  const double pitch = 0.01 + gap;
  const double gapX = -0.5 * (4 * pitch - gap) + 0.01 + 0.5 * gap; // between columns 0 and 1
  rig.teleport({gapX, -0.01, 0.02});
  ProxyTickResult r = rig.drive({gapX, -0.01, 0.02}, {gapX, -0.01, -0.03}, 0.01);
  const double expected = std::sqrt(kRadius * kRadius - 0.25 * gap * gap);
  EXPECT_NEAR(r.proxy.x, gapX, 1e-9);
  EXPECT_NEAR(r.proxy.z, expected, 1e-9);
  // Stroke along the gap and across gaps, pressed 30 mm below: never through.
  r = rig.drive({gapX, -0.01, -0.03}, {gapX, 0.01, -0.03}, 0.003);
  EXPECT_GT(r.proxy.z, 0.0);
  r = rig.drive({gapX, 0.01, -0.03}, {0.015, 0.012, -0.03}, 0.003);
  EXPECT_GT(r.proxy.z, 0.0);
  rig.expectClean("tiles-gap-1.2mm");

  // Where two 1.6 mm gaps cross, the hole's diagonal (2.26 mm) passes the proxy; a 2.5 mm gap
  // passes it anywhere: the free path is taken.
  for (const double wide : {0.0016, 0.0025})
  {
    Rig open(scenes::makeTiles(2, 0.01, wide, false), {0.0, 0.0, 0.02});
    r = open.drive({0.0, 0.0, 0.02}, {0.0, 0.0, -0.03}, 0.01);
    EXPECT_LE(distance(r.proxy, Vec3{0.0, 0.0, -0.03}), 1e-15) << wide;
    open.expectClean("tiles-crossing-" + std::to_string(wide));
  }
}

TEST(ProxySolverOffset, OneKilometreFromTheOriginBehavesTheSame)
{
  const Vec3 offset{1000, 1000, 1000};
  const std::vector<std::pair<std::string, TriangleSoup>> cases = {
    {"box", makeBox({0.03, 0.02, 0.01})},
    {"groove", scenes::makeVGroove(60.0, 0.05, 0.04)},
    {"funnel", scenes::makePyramid(7, 0.03, 0.03)},
    {"corner", scenes::makeConcaveCorner(0.05)}};
  for (const auto& [name, soup] : cases)
  {
    Rig near(soup, {0.001, 0.002, 0.04});
    Rig far(scenes::translate(soup, offset), offset + Vec3{0.001, 0.002, 0.04});
    std::mt19937_64 engine(3);
    std::uniform_real_distribution<double> u(-0.03, 0.03);
    double worst = 0.0;
    for (int i = 0; i < 200; ++i)
    {
      const Vec3 finger{u(engine), u(engine), u(engine) - 0.01};
      const ProxyTickResult a = near.step(finger);
      const ProxyTickResult b = far.step(offset + finger);
      // The shifted coordinates carry 1e-13 of rounding and a skin of 256 ulp (6e-11 m):
      // agreement to 1e-9 m is section 4's accuracy.
      worst = std::max(worst, distance(a.proxy, b.proxy - offset));
    }
    std::cout << "[offset] " << name << ": worst |proxy - shifted proxy| " << worst << " m\n";
    EXPECT_LE(worst, 1e-9) << name;
    near.expectClean(name + "-origin");
    far.expectClean(name + "-1km");
  }
}

TEST(ProxySolverInput, NonFiniteFingerIsRefused)
{
  Rig rig(makeGrid(0.2, 4, 0.0), {0.0, 0.0, 0.01});
  rig.step({0.0, 0.0, -0.002});
  const Vec3 held = rig.solver().proxy();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Vec3& bad : {Vec3{std::nan(""), 0, 0}, Vec3{0, inf, 0}, Vec3{0, 0, -inf}})
  {
    const ProxyTickResult r = rig.step(bad);
    EXPECT_TRUE(r.conditions.has(TickCondition::fingerRefused));
    EXPECT_EQ(r.proxy, held);
    EXPECT_EQ(rig.solver().proxy(), held);
    EXPECT_EQ(r.numContacts, 0);
  }
  // And the next good finger carries on from the held proxy.
  const ProxyTickResult r = rig.step({0.002, 0.0, -0.002});
  EXPECT_FALSE(r.conditions.has(TickCondition::fingerRefused));
  EXPECT_NEAR(r.proxy.x, 0.002, 1e-12);
  rig.expectClean("nan-finger");
}

// Minimal reproducers of the failures the scripted suites found (see the [oracle] FAIL lines of
// ScriptedProceduralPaths): one tick each, from the recorded proxy and finger.

TEST(ProxySolverFound, LoopTerminatesOneKilometreFromTheOrigin)
{
  // 60-degree groove shifted by (1000, 1000, 1000), finger behind one face: the proxy alternates
  // between two points 6.6e-13 m apart (plane normals from rounded closest points differ by
  // 1e-10 rad), each step above the stop tolerance (1% of the 5.7e-11 m skin), for ever.
  const Vec3 offset{1000, 1000, 1000};
  Rig rig(scenes::translate(scenes::makeVGroove(60.0, 0.05, 0.04), offset),
          {1000.008222173818, 1000.0106370659917, 1000.0204239388526});
  const ProxyTickResult r = rig.step({1000.0081718289953, 1000.0160381174354, 1000.0173205080757});
  EXPECT_FALSE(r.conditions.has(TickCondition::hitIterationCap)) << "iterations " << r.iterations;
  rig.expectClean("found-livelock-1km");
}

TEST(ProxySolverFound, ConvexEdgeConvergesWithinTheIterationCap)
{
  // Icosphere (3 subdivisions, 4 cm), pressing 1 mm in near a convex edge: each slide along a
  // face's plane leaves contact over the edge and the next sweep falls back, so the proxy
  // zig-zags and converges linearly: 574 iterations to settle, 44 um from where the 32nd ends
  // (hovering 2e-9 m off the surface, which the oracle sees as a free step toward the finger).
  Rig rig(makeIcosphere(3, 0.04), {0.016439692163224457, 0, 0.037409688147095096});
  const ProxyTickResult r = rig.step({0.016, 0, 0.036560000000000002});
  EXPECT_FALSE(r.conditions.has(TickCondition::hitIterationCap)) << "iterations " << r.iterations;
  rig.expectClean("found-zigzag-icosphere");
}

TEST(ProxySolverFound, FingerAtTheApexOfANarrowConcaveCornerConverges)
{
  // Stress seed 6010 (StressPlanes.ConcaveCornersEnteredFromASphereOfDirections): a trihedral
  // corner too narrow for the proxy to reach its apex; the finger 5 um from the apex, the proxy
  // touching only the apex corner. The Hessian across the corner's sphere vanishes there, and
  // the plain slides crept along the sphere: 2752 iterations, the cap ending 0.8 mm short.
  TriangleSoup corner;
  corner.points = {{0, 0, 0},
                   {-0.007307013309434083, -0.049439088928338176, -0.00154403446581447},
                   {-0.0006428439240449843, 0.019032608987268225, -0.046231445433028324},
                   {0.027293161911775318, -0.00993007124619735, -0.04069984026876595}};
  corner.triangles = {{0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
  Rig rig(corner, {-0.0012556588587140172, -0.00068060738288177138, -0.0019432438991826028});
  const ProxyTickResult r =
    rig.step({-1.0777595127525665e-07, 2.0409831476357046e-06, 4.7842233758979384e-06});
  EXPECT_FALSE(r.conditions.has(TickCondition::hitIterationCap)) << "iterations " << r.iterations;
  EXPECT_LE(r.iterations, 16);
  rig.expectClean("found-narrow-corner-apex");
}

TEST(ProxySolverMoveRecord, ChainStartsAtTheProxyEndsAtTheTickAndApproachesAtAcceptedPoints)
{
  // The debug record the oracles read (MoveRecord.h): one point per move stage, plus the walk back
  // over trials that did not pay off. Its ends are the tick's, its accepted points approach the
  // finger, and a solver without a record makes the same tick bit for bit.
  const TriangleSoup sphere = makeIcosphere(3, 0.04);
  const Vec3 start{0.016439692163224457, 0, 0.037409688147095096};
  const Vec3 finger{0.016, 0, 0.036560000000000002};
  Rig rig(sphere, start);
  MoveRecord record;
  rig.solver().recordMoves(&record);
  const ProxyTickResult recorded = rig.step(finger);
  rig.solver().recordMoves(nullptr);
  ASSERT_FALSE(record.overflowed);
  ASSERT_GE(record.count, static_cast<std::size_t>(recorded.iterations) + 1);
  EXPECT_EQ(record.points[0].position, start);
  EXPECT_EQ(record.points[record.count - 1].position, recorded.proxy);
  EXPECT_EQ(record.points[record.count - 1].kind, MovePointKind::Accepted);
  std::size_t trials = 0;
  double accepted = distance(start, finger);
  for (std::size_t k = 1; k < record.count; ++k)
  {
    if (record.points[k].kind == MovePointKind::Trial)
    {
      ++trials;
      continue;
    }
    const double d = distance(record.points[k].position, finger);
    EXPECT_LE(d, accepted + 1e-12) << "accepted point " << k;
    accepted = std::min(accepted, d);
  }
  // The stretched slide over the convex edge overshoots, ending farther from the finger (a
  // trial), and the fall after it wins the distance back: no retrace, so one point per move.
  // SharedProbePathTicks.BunnyTick2630... records a retrace.
  EXPECT_GT(trials, 0u);
  EXPECT_EQ(record.count, static_cast<std::size_t>(recorded.iterations) + 1);

  Rig unrecorded(sphere, start);
  const ProxyTickResult plain = unrecorded.step(finger);
  EXPECT_EQ(plain.proxy, recorded.proxy);
  EXPECT_EQ(plain.iterations, recorded.iterations);
  rig.expectClean("move-record-icosphere");
}

TEST(ProxySolverFound, AbsurdlyFarFingerNeitherTunnelsNorStrandsTheProxy)
{
  // Stress suite (StressFingerInput.AbsurdlyFarFiniteFingers): a finger 1e200 m below a 3 cm
  // sphere let the proxy through it (the swept-sphere quadratic overflowed), and a proxy sent
  // 1e30 m up came back 2 mm inside the sphere (a move of 1e30 m rounds by 1e14 m). The solver
  // now seeks such a finger at its reach, 16 (M + L) from the scene's centre.
  TriangleSoup sphere = makeIcosphere(3, 0.03);
  sphere.pointNormals.clear();
  const Vec3 start{0, 0, 0.05};
  Rig rig(sphere, start);
  for (const double far : {1e3, 1e30, 1e200, 1e300, 1.7e308})
  {
    for (const Vec3& direction : {Vec3{0, 0, -1}, Vec3{0.6, 0, -0.8}, Vec3{0, 0, 1}})
    {
      const ProxyTickResult away = rig.step(direction * far);
      EXPECT_TRUE(isFinite(away.proxy));
      EXPECT_LE(distance(away.proxy, rig.solver().reachCenter()),
                rig.solver().reachRadius() * (1.0 + 1e-12));
      rig.step(start);
    }
  }
  EXPECT_LT(distance(rig.solver().proxy(), start), 1e-12); // back where it began, to rounding
  rig.expectClean("found-absurd-fingers");
}

TEST(ProxySolverFound, SheetsCrossingAtATinyAngleAreTwoPlanes)
{
  // Found by the stress suite (StressPlanes, seed 4009): two sheets crossing at 8.2e-11 rad, the
  // proxy resting on their crossing line, face contacts with both. Their normals passed the
  // same-plane test (cosine 1 - 1e-14, i.e. 1.4e-7 rad; the cosine cannot even resolve angles
  // below 1.5e-8 rad), so the goal solver saw one plane and slid along it, 2.7e-14 m into the
  // other sheet, which the proxy already touched 1.5e-18 m inside the radius: the touching sweep
  // (no stop nearer than r) blocked that at once and the proxy stayed while the finger slid away
  // (residual 1.3e-5 m). Both halves had to change: two face contacts are now merged only when
  // their cross product is below 1e-13, and a sweep starting in touching contact lets through a
  // slide whose heading into the triangle is below 1e-12 of its length (with both planes seen,
  // the slide along the crossing line is such a slide, blocked before by rounding). Either
  // change alone leaves the proxy stuck (lowering the touching floor alone only delayed it).
  TriangleSoup soup;
  soup.points = {{0.0025917756012839178, 0.016876844476840822, -0.022548942763178863},
                 {-0.027850187166712052, 0.0049132731673626785, 0.00047625787340578075},
                 {-0.0025917756012839178, -0.016876844476840822, 0.022548942763178863},
                 {0.027850187166712052, -0.0049132731673626785, -0.00047625787340578075},
                 {0.0025917756010396123, 0.01687684447555222, -0.022548942764171402},
                 {-0.027850187166467748, 0.00491327316865128, 0.0004762578743983199},
                 {-0.0025917756010396123, -0.01687684447555222, 0.022548942764171402},
                 {0.027850187166467748, -0.00491327316865128, -0.0004762578743983199}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  Rig rig(soup, {0.0050445016476208197, -0.0071224523150369848, 0.0096624751975080986});
  const ProxyTickResult r =
    rig.step({0.0042323920805787205, -0.010614414223410255, 0.0073350757347480046});
  EXPECT_FALSE(r.conditions.has(TickCondition::hitIterationCap)) << "iterations " << r.iterations;
  rig.expectClean("found-crossing-planes-8e-11-rad");
}

TEST(ProxySolverReserve, AFaceABandAwayThatTheSlideWouldGrazeIsAPlaneBeforeTheMove)
{
  // A floor (z = 0, x <= 0) and a ramp rising from x = 0 at a slope of 0.2: a concave crease. The
  // proxy rests on the floor 0.4 nm short of where it would touch the ramp too, and the finger
  // pulls along the floor into the crease. The ramp is beyond the contact reach (two
  // skins) and within the reserve band (ProxySolver::nearBand), and the slide along the floor
  // heads into it at a fifth of its length: its plane joins the floor's before any move, the goal
  // is the proxy itself, and the tick ends where it began, against both planes. Without the
  // reserve, the slide is stopped after a few nanometres and the tick makes a move to get there.
  constexpr double kSlope = 0.2;
  TriangleSoup soup;
  soup.points = {
    {-0.05, -0.05, 0.0},          {0.0, -0.05, 0.0},          {0.0, 0.05, 0.0}, {-0.05, 0.05, 0.0},
    {0.05, -0.05, 0.05 * kSlope}, {0.05, 0.05, 0.05 * kSlope}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  const double rampLength = std::sqrt(1.0 + kSlope * kSlope);
  // Where, on the floor at the fresh-contact height, the ramp (the plane through the origin with
  // normal (-slope, 0, 1) / rampLength) is `gap` beyond the radius.
  const auto along = [&](double height, double gap) {
    return (height - (kRadius + gap) * rampLength) / kSlope;
  };
  const double probeSkin = [&] {
    Rig probe(soup, {-0.01, 0.0, 0.01});
    return probe.skin();
  }();
  const double height = kRadius + probeSkin;
  const double gap = 4e-10;
  const Vec3 start{along(height, gap), 0.0, height};
  Rig rig(soup, start);
  ASSERT_GT(rig.solver().nearBand(), gap);
  ASSERT_LT(rig.solver().contactEpsilon(), gap);
  // Deep below both faces, within the crease's normal cone: the crease is the local minimum.
  const ProxyTickResult r = rig.step({0.001, 0.0, -0.01});
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.proxy, start);
  EXPECT_EQ(r.numContacts, 2);
  // The ramp holds the proxy the band's width off at most: within the contact gap of section 4.
  const double rampGap = (dot(Vec3{-kSlope, 0.0, 1.0}, r.proxy)) / rampLength - kRadius;
  EXPECT_GT(rampGap, 0.0);
  EXPECT_LE(rampGap, rig.solver().nearBand());
  rig.expectClean("reserve-band-crease");
}

TEST(ProxySolverFound, StretchedSlideIntoATouchedPlaneFallsBackToThePlaneSlide)
{
  // Found by the performance report's scaling run (BenchTimeVersusError --scaling,
  // VH_M_Liver.glb scaled to a 25 cm diagonal, tick 284 of its press); the 7 triangles around one
  // vertex of the liver reproduce it alone. The proxy touches two edges (two cylinder planes);
  // the goal solve slides along one, feasibly for the other, but the curvature stretch of that
  // slide (1 / (1 - h / rho) across the edge) headed 2.6e-8 m into the other plane. The sweep
  // blocked it at once (the proxy touches that edge), the next update stage at the same point
  // stretched the same slide again, and a stretched move skips the progress check, so stretching
  // was never turned off: the tick ended after 6 iterations, 1.6e-7 m short of its minimum (with
  // the solver before the stress suite's fixes too). A stretched step must now stay above every
  // plane, or the planar slide is taken: 7 iterations, residual 0.
  TriangleSoup fan;
  fan.points = {{-0.021871522220944142, 0.27700766192788784, 0.079287406921861717},
                {-0.021240691600740234, 0.27776010877189061, 0.081161381482735648},
                {-0.021533068076824039, 0.28346286977190333, 0.076566107048598078},
                {-0.021533068076824039, 0.28346286977190333, 0.076566107048598078},
                {-0.020965236839053776, 0.28221395052144987, 0.074062289002984213},
                {-0.021871522220944142, 0.27700766192788784, 0.079287406921861717},
                {-0.021871522220944142, 0.27700766192788784, 0.079287406921861717},
                {-0.020965236839053776, 0.28221395052144987, 0.074062289002984213},
                {-0.021382935551820522, 0.27580308434862033, 0.077075111536887259},
                {-0.021382935551820522, 0.27580308434862033, 0.077075111536887259},
                {-0.022892181996634779, 0.27092967598772238, 0.080744452905826561},
                {-0.021871522220944142, 0.27700766192788784, 0.079287406921861717},
                {-0.021871522220944142, 0.27700766192788784, 0.079287406921861717},
                {-0.022892181996634779, 0.27092967598772238, 0.080744452905826561},
                {-0.022751708081558839, 0.2715896951824211, 0.08203786700365856},
                {-0.022751708081558839, 0.2715896951824211, 0.08203786700365856},
                {-0.022161164218328921, 0.27204477597769317, 0.083061526479789247},
                {-0.021871522220944142, 0.27700766192788784, 0.079287406921861717},
                {-0.021871522220944142, 0.27700766192788784, 0.079287406921861717},
                {-0.022161164218328921, 0.27204477597769317, 0.083061526479789247},
                {-0.021240691600740234, 0.27776010877189061, 0.081161381482735648}};
  for (std::uint32_t t = 0; t < 7; ++t)
  {
    fan.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  Rig rig(fan, {-0.022827663512652936, 0.27721059655127489, 0.079505884813446767});
  const ProxyTickResult r =
    rig.step({-0.022243077317040279, 0.27712438269938672, 0.079372737804346741});
  EXPECT_FALSE(r.conditions.has(TickCondition::hitIterationCap)) << "iterations " << r.iterations;
  rig.expectClean("found-liver-corner");
}

TEST(ProxySolverLimits, IterationCapIsReported)
{
  // One move stage cannot both reach the floor and slide into the corner.
  Rig rig(scenes::makeConcaveCorner(0.05), {0.02, 0.02, 0.02});
  ProxyParameters capped;
  capped.radius = kRadius;
  capped.maxIterations = 1;
  rig.solver().setScene(&rig.scene(), capped);
  const ProxyTickResult r = rig.solver().update({0.01, -0.01, -0.01});
  EXPECT_EQ(r.iterations, 1);
  EXPECT_TRUE(r.conditions.has(TickCondition::hitIterationCap));
}

} // namespace
} // namespace proxima
