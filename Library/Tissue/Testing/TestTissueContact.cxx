// The tissue touched by the proxy (TissueContact, TetBoundary). The surface of a tetrahedral box
// against what a box's surface must be; then a soft block, fixed at its base, pressed and
// released by a finger through the proxy, in lockstep at 1 kHz with the solid stepping at 200 Hz:
// - no tick leaves the proxy inside the block's surface as that tick has it (the scripted suites'
//   oracle: CGAL, 128-bit distances, built over each tick's surface);
// - the block gives way under the press and the proxy stays on it, still while the finger is;
// - no energy gain: at every step the solid's energy (kinetic and elastic) is at most the work
//   the proxy's force has done on it so far, and after the release it comes back to rest.
#include "Tissue/TissueContact.h"

#include "Proxy/CollisionScene.h"
#include "Tissue/BoxTetMesh.h"
#include "Tissue/TetBoundary.h"

#include "ProxyOracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{
TEST(TetBoundary, ABoxOfTetrahedraIsBoundedByItsSixFacesFacedOut)
{
  const int nx = 3;
  const int ny = 2;
  const int nz = 4;
  const TetMesh mesh = makeBoxTetMesh(Vec3{-0.01, 0.0, 0.02}, Vec3{0.02, 0.01, 0.05}, nx, ny, nz);
  const auto triangles = boundaryTriangles(mesh);
  // Two triangles per cell face on the box's surface.
  EXPECT_EQ(triangles.size(), static_cast<std::size_t>(4 * (nx * ny + ny * nz + nz * nx)));
  // Closed and consistently oriented: every directed edge once, and its reverse once.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
    }
  }
  for (const auto& [edge, count] : directed)
  {
    EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
  // Faced out: the volume the faces enclose (divergence theorem) is the tetrahedra's, positive.
  double enclosed = 0.0;
  for (const auto& t : triangles)
  {
    enclosed += dot(mesh.points[t[0]], cross(mesh.points[t[1]], mesh.points[t[2]])) / 6.0;
  }
  EXPECT_NEAR(enclosed, totalVolume(mesh), 1e-15);
  EXPECT_NEAR(enclosed, 0.03 * 0.01 * 0.03, 1e-15);
  // Every point of the box's surface is on a triangle; the inside points on none.
  const TriangleSoup soup = boundarySoup(mesh);
  EXPECT_EQ(soup.points.size(), mesh.points.size());
  EXPECT_EQ(soup.triangles, triangles);
}

// A graded grid, as the Hertz check builds its block: spacing starting at `finest` and growing
// by at most `growth` until the last cell, which ends exactly at the far end; the grid's
// tetrahedra fill the box (their volumes, all positive, sum to its volume) and its surface is
// closed, as an even grid's is.
TEST(TetBoundary, AGradedGridFillsItsBoxAndIsClosed)
{
  const std::vector<double> xs = gradedCoordinates(0.0, 0.025, 0.001, 1.3);
  ASSERT_GE(xs.size(), 3u);
  EXPECT_EQ(xs.front(), 0.0);
  EXPECT_EQ(xs.back(), 0.025);
  EXPECT_NEAR(xs[1] - xs[0], 0.001, 1e-18);
  for (std::size_t i = 2; i + 1 < xs.size(); ++i)
  {
    EXPECT_NEAR((xs[i] - xs[i - 1]) / (xs[i - 1] - xs[i - 2]), 1.3, 1e-12) << i;
  }
  // The last cell ends at the far end, no shorter than the one before it (no sliver).
  const double last = xs.back() - xs[xs.size() - 2];
  const double before = xs[xs.size() - 2] - xs[xs.size() - 3];
  EXPECT_GE(last, before);
  EXPECT_LT(last, 2.0 * 1.3 * before);
  // Downward, and an even grid for a growth of 1.
  const std::vector<double> down = gradedCoordinates(0.0, -0.01, 0.0025, 1.0);
  const std::vector<double> even{0.0, -0.0025, -0.005, -0.0075, -0.01};
  ASSERT_EQ(down.size(), even.size());
  for (std::size_t i = 0; i < even.size(); ++i)
  {
    EXPECT_NEAR(down[i], even[i], 1e-17) << i;
  }

  const std::vector<double> ys{-0.01, -0.004, 0.0, 0.001, 0.003};
  const std::vector<double> zs{-0.02, 0.0};
  const TetMesh mesh = makeGridTetMesh(xs, ys, zs);
  EXPECT_EQ(mesh.points.size(), xs.size() * ys.size() * zs.size());
  EXPECT_EQ(mesh.tets.size(), 6 * (xs.size() - 1) * (ys.size() - 1) * (zs.size() - 1));
  EXPECT_EQ(countInvertedTets(mesh), 0u);
  EXPECT_NEAR(totalVolume(mesh), 0.025 * 0.013 * 0.02, 1e-15);
  const auto triangles = boundaryTriangles(mesh);
  const std::size_t nx = xs.size() - 1;
  const std::size_t ny = ys.size() - 1;
  const std::size_t nz = zs.size() - 1;
  EXPECT_EQ(triangles.size(), 4 * (nx * ny + ny * nz + nz * nx));
  double enclosed = 0.0;
  for (const auto& t : triangles)
  {
    enclosed += dot(mesh.points[t[0]], cross(mesh.points[t[1]], mesh.points[t[2]])) / 6.0;
  }
  EXPECT_NEAR(enclosed, totalVolume(mesh), 1e-15);
}

constexpr double kRadius = 0.005;
constexpr double kStiffness = 1000.0;
constexpr double kRate = 1000.0;
constexpr int kTicksPerStep = 5; // the solid at 200 Hz

// A block of 4 x 4 x 2 cm (cells of 5 mm), 5 kPa, fixed along its base, its surface a scene of
// one object; a proxy of 5 mm radius on a 1000 N/m spring.
struct SoftBlockContact
{
  TetMesh block = makeBoxTetMesh(Vec3{-0.02, -0.02, -0.02}, Vec3{0.02, 0.02, 0.0}, 8, 8, 4);
  std::unique_ptr<ElasticSolid> solid;
  CollisionScene scene;
  std::unique_ptr<ProxySolver> solver = std::make_unique<ProxySolver>();
  std::unique_ptr<TissueContact> contact;

  SoftBlockContact()
  {
    ElasticSolidSettings settings;
    settings.timeStep = kTicksPerStep / kRate;
    settings.damping = 20.0;
    solid = std::make_unique<ElasticSolid>(block, ElasticMaterial{5000.0, 0.45}, settings);
    for (std::uint32_t v = 0; v < block.points.size(); ++v)
    {
      if (block.points[v].z < -0.02 + 1e-9)
      {
        solid->fixVertex(v);
      }
    }
    TriangleMesh surface;
    MeshError error;
    if (!surface.build(boundarySoup(block), error))
    {
      ADD_FAILURE() << error.message;
    }
    scene.addObject(std::move(surface));
    ProxyParameters parameters;
    parameters.radius = kRadius;
    parameters.stiffness = kStiffness;
    parameters.timeStep = 1.0 / kRate;
    solver->setScene(&scene, parameters);
    contact = std::make_unique<TissueContact>(*solid, *solver, 0, kStiffness);
  }
};

// The finger comes down from 1 cm above the top's centre to 3 mm below it in 0.4 s, holds 1 s,
// goes back up in 0.4 s and waits 1.2 s; the solid loaded with `relaxation` of each step's
// footprint (TissueContact::setLoadRelaxation).
void pressAndReleaseTheSoftBlock(double relaxation)
{
  SoftBlockContact fixture;
  ElasticSolid& solid = *fixture.solid;
  ProxySolver* solver = fixture.solver.get();
  TissueContact& contact = *fixture.contact;
  contact.setLoadRelaxation(relaxation);
  ASSERT_EQ(contact.loadRelaxation(), relaxation);

  auto fingerAt = [](double t) {
    const double high = 0.01;
    const double low = -0.003;
    double z = low;
    if (t < 0.4)
    {
      z = high + (low - high) * t / 0.4;
    }
    else if (t >= 1.4 && t < 1.8)
    {
      z = low + (high - low) * (t - 1.4) / 0.4;
    }
    else if (t >= 1.8)
    {
      z = high;
    }
    return Vec3{0.0, 0.0, z + kRadius};
  };
  solver->resetProxy(fingerAt(0.0));
  double deepest = -1.0; // how far into the proxy radius the surface came, worst tick
  double work = 0.0;     // by the proxy's force on the solid, so far
  double excess = -1.0;  // the largest energy - work
  double indentation = 0.0;
  double heldForce = 0.0;
  double restless = 0.0; // the largest move of the proxy between ticks late in the hold
  Vec3 lastProxy;
  const int ticks = static_cast<int>(3.0 * kRate);
  std::vector<Vec3> before = solid.positions();
  for (int i = 0; i < ticks; ++i)
  {
    const Vec3 finger = fingerAt(i / kRate);
    const ProxyTickResult result = solver->update(finger);
    const oracle::MeshOracle surfaceNow(solver->placedMesh(0));
    deepest = std::max(deepest, kRadius - surfaceNow.distance(result.proxy, 2.0 * kRadius));
    contact.addTick(result);
    if ((i + 1) % kTicksPerStep == 0)
    {
      before = solid.positions();
      contact.step();
      // The work of the step's force: the held force times each vertex's displacement, less
      // what the implicit springs gave back as the surface gave way (a linear spring's force
      // falls by k s over a displacement s along its normal: its work is f0 s - k s^2 / 2).
      const std::vector<Vec3>& after = solid.positions();
      for (std::size_t v = 0; v < after.size(); ++v)
      {
        work += dot(solid.externalForce(static_cast<std::uint32_t>(v)), after[v] - before[v]);
      }
      for (int k = 0; k < solid.numContactSprings(); ++k)
      {
        const ContactSpring& spring = solid.contactSpring(k);
        double along = 0.0;
        for (int j = 0; j < 3; ++j)
        {
          along += spring.weights[static_cast<std::size_t>(j)] *
                   dot(spring.normal, after[spring.vertices[static_cast<std::size_t>(j)]] -
                                        before[spring.vertices[static_cast<std::size_t>(j)]]);
        }
        work -= 0.5 * spring.stiffness * along * along;
      }
      excess = std::max(excess, solid.kineticEnergy() + solid.elasticEnergy() - work);
    }
    if (i >= static_cast<int>(1.0 * kRate) && i < static_cast<int>(1.4 * kRate))
    {
      // Late in the hold, with the finger still: the proxy must be still too.
      if (i > static_cast<int>(1.0 * kRate))
      {
        restless = std::max(restless, distance(result.proxy, lastProxy));
      }
      lastProxy = result.proxy;
    }
    if (i == static_cast<int>(1.39 * kRate))
    {
      indentation = -(result.proxy.z - kRadius);
      heldForce = kStiffness * norm(finger - result.proxy);
    }
  }
  const double restEnergy = solid.kineticEnergy() + solid.elasticEnergy();
  std::printf("[ measured ] surface at most %.3g m into the proxy; held: indentation %.3g m, "
              "force %.3g N; work %.3g J, largest energy - work %.3g J, energy at the end %.3g J, "
              "largest displacement at the end %.3g m; late in the hold the proxy moved at most "
              "%.3g m a tick\n",
              deepest, indentation, heldForce, work, excess, restEnergy, contact.maxDisplacement(),
              restless);
  EXPECT_LE(deepest, 1e-9) << "the proxy was left inside the block's surface";
  EXPECT_GT(indentation, 0.001) << "the block did not give way";
  EXPECT_GT(heldForce, 0.01) << "the proxy lost the block while pressed";
  // Loaded only where the proxy's planes touched, the block flipped the proxy from one side of
  // the dent to the other every step (0.6 mm apart) with the finger still.
  EXPECT_LT(restless, 1e-6) << "the proxy chatters on the block with the finger at rest";
  EXPECT_GT(work, 0.0);
  EXPECT_LE(excess, 1e-6 * work) << "the solid gained energy the proxy did not put in";
  EXPECT_LT(restEnergy, 1e-3 * work) << "the block is not back at rest after the release";
  EXPECT_LT(contact.maxDisplacement(), 1e-4);
}

TEST(TissueContact, APressAndReleaseOnASoftBlock)
{
  pressAndReleaseTheSoftBlock(1.0);
}

// The same with a load that lags: still no penetration, no chatter, no energy gain, back at rest.
TEST(TissueContact, APressAndReleaseOnASoftBlockWithARelaxedLoad)
{
  pressAndReleaseTheSoftBlock(0.3);
}

// The soft block pressed 3 mm and held, with each step of the solid handed to the solver `lag`
// ticks after it was launched (a solid stepping on its own thread, slower than the ticks: the
// next step launches at the first step tick after the hand-over, as TissueDynamics does). Returns
// the force the spring holds the block with at the end, the least force from 20 steps after the
// press on, and the proxy's height at the end.
struct HeldPress
{
  double force = 0.0;
  double leastHeldForce = 0.0;
  double proxyZ = 0.0;
};

HeldPress holdTheSoftBlockPressed(int lag)
{
  SoftBlockContact fixture;
  ElasticSolid& solid = *fixture.solid;
  ProxySolver& solver = *fixture.solver;
  TissueContact& contact = *fixture.contact;
  // Above the block, then at once 3 mm into it (as a mouse wheel's notches put it).
  auto fingerAt = [](double t) { return Vec3{0.0, 0.0, (t < 0.1 ? 0.001 : -0.003) + kRadius}; };
  solver.resetProxy(fingerAt(0.0));
  HeldPress held;
  held.leastHeldForce = 1e9;
  int handOverAt = -1; // the tick of the pending hand-over, or -1
  // Long enough for 800 steps of the solid (4 s of its time) however late they come.
  const int ticks = 800 * (kTicksPerStep + lag);
  for (int i = 0; i < ticks; ++i)
  {
    if (handOverAt == i)
    {
      contact.beforeSurfaceHandOver();
      contact.handOverSurface();
      handOverAt = -1;
    }
    const Vec3 finger = fingerAt(i / kRate);
    const ProxyTickResult result = solver.update(finger);
    contact.addTick(result);
    held.force = kStiffness * norm(finger - result.proxy);
    held.proxyZ = result.proxy.z;
    if (i >= static_cast<int>(0.1 * kRate) + 20 * (kTicksPerStep + lag))
    {
      held.leastHeldForce = std::min(held.leastHeldForce, held.force);
    }
    if ((i + 1) % kTicksPerStep == 0 && handOverAt < 0)
    {
      contact.loadStep();
      solid.step();
      if (lag == 0)
      {
        contact.beforeSurfaceHandOver(); // nothing: no tick since loadStep()
        contact.handOverSurface();
      }
      else
      {
        handOverAt = i + lag;
      }
    }
  }
  return held;
}

// A solid whose steps reach the proxy late settles where one in step does, without falling away
// from the finger on the way: the ticks that pressed the surface before a step are corrected at
// its hand-over by the solid's move since (TissueContact::beforeSurfaceHandOver). Without the
// correction the block, pushed by ticks that still met the surface before it gave way, was driven
// down past where the press holds it: the held force dipped to 0.0675 N of 0.196 N at 40 ticks
// behind (0.189 N at 12), and on the mouse's press of the threaded runtime, a 10 ms step behind
// 1 ms ticks, the proxy came off the block (MouseFinger.OnTissueTheWheelSetsHowDeepTheFinger...
// under a sanitizer).
TEST(TissueContact, ASolidSteppingBehindTheProxySettlesWhereOneInStepDoes)
{
  const HeldPress inStep = holdTheSoftBlockPressed(0);
  ASSERT_GT(inStep.force, 0.05);
  for (const int lag : {3, 12, 40})
  {
    const HeldPress behind = holdTheSoftBlockPressed(lag);
    std::printf("[ measured ] a step %d ticks behind: held force %.6g N (in step %.6g N), least "
                "while held %.3g N\n",
                lag, behind.force, inStep.force, behind.leastHeldForce);
    EXPECT_NEAR(behind.force, inStep.force, 1e-3 * inStep.force) << lag << " ticks behind";
    EXPECT_NEAR(behind.proxyZ, inStep.proxyZ, 1e-6) << lag << " ticks behind";
    EXPECT_GT(behind.leastHeldForce, 0.9 * inStep.force)
      << lag << " ticks behind: the block fell away from the pressed finger";
  }
}

// The relaxed load in closed form: pressed at A for a step, then at B (far enough that the two
// footprints share no vertex) with a force of another size, the solid's load is the press's total
// every step, and A's footprint keeps (1 - a)^n of it after n steps at B, a the relaxation.
TEST(TissueContact, ARelaxedLoadKeepsThePressesTotalAndForgetsTheLastShapeGeometrically)
{
  constexpr double kRelaxation = 0.3;
  SoftBlockContact fixture;
  TissueContact& contact = *fixture.contact;
  const ElasticSolid& solid = *fixture.solid;
  contact.setLoadRelaxation(kRelaxation);
  contact.setLoadRelaxation(0.0); // outside (0, 1]: ignored
  contact.setLoadRelaxation(1.5);
  ASSERT_EQ(contact.loadRelaxation(), kRelaxation);
  // The proxy resting on the top (z = 0), 1 mm into its surface's reach, at x = -1 cm and +1 cm:
  // footprints of radius sqrt((1.25 R)^2 - (R - 1 mm)^2) = 4.8 mm, on cells 5 mm wide, so the
  // one reaches x = -5.2 mm and the other x = 5.2 mm: no vertex of the cells about x = 0.
  const Vec3 atA{-0.01, 0.0, kRadius - 0.001};
  const Vec3 atB{0.01, 0.0, kRadius - 0.001};
  const Vec3 pressA{0.0, 0.0, -0.4};
  const Vec3 pressB{0.0, 0.0, -1.0};
  auto loadOn = [&](double side) {
    // The load on the vertices of one half of the top (x < 0 for A, x > 0 for B).
    Vec3 sum;
    for (std::uint32_t v = 0; v < solid.positions().size(); ++v)
    {
      if (solid.positions()[v].x * side > 0.0)
      {
        sum += solid.externalForce(v);
      }
    }
    return sum;
  };
  for (int tick = 0; tick < kTicksPerStep; ++tick)
  {
    contact.addPress(atA, pressA, kStiffness);
  }
  contact.loadStep();
  // The first step has no last load: all of A's press on A's footprint.
  EXPECT_NEAR(loadOn(-1.0).z, pressA.z, 1e-12);
  EXPECT_NEAR(loadOn(+1.0).z, 0.0, 1e-15);
  EXPECT_NEAR(contact.lastForce().z, pressA.z, 1e-12);
  double kept = 1.0;
  for (int step = 1; step <= 8; ++step)
  {
    for (int tick = 0; tick < kTicksPerStep; ++tick)
    {
      contact.addPress(atB, pressB, kStiffness);
    }
    contact.loadStep();
    kept *= 1.0 - kRelaxation;
    EXPECT_NEAR(contact.lastForce().z, pressB.z, 1e-12) << "step " << step;
    EXPECT_NEAR(loadOn(-1.0).z, kept * pressB.z, 1e-12) << "step " << step;
    EXPECT_NEAR(loadOn(+1.0).z, (1.0 - kept) * pressB.z, 1e-12) << "step " << step;
  }
  // The proxy gone (no press): no load at all, at once.
  contact.loadStep();
  EXPECT_EQ(norm(contact.lastForce()), 0.0);
  EXPECT_EQ(norm(loadOn(-1.0)) + norm(loadOn(+1.0)), 0.0);
}
} // namespace
} // namespace proxima
