// The elastic solid against closed forms and invariants: a cantilever's tip deflection
// P L^3 / (3 E I) plus Timoshenko's shear term, approached as the mesh is refined; rest that stays
// rest; a rigid turn that stores no energy and makes no force; a released solid whose energy never
// grows; a stiffer inclusion that gives less; stability at the haptic simulation's step; refused
// settings.
#include "Tissue/BoxTetMesh.h"
#include "Tissue/ElasticSolid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace proxima
{
namespace
{

struct Cantilever
{
  double length = 0.1;     // m, along x
  double thickness = 0.01; // m, a square section
  double youngsModulus = 1e5;
  double load = 1e-3; // N at the free end, along -z
};

// The beam meshed with n cells across its section and 10 n along it, fixed at x = 0, the load
// spread over the end's vertices, solved to rest (big implicit steps, the solve converged).
double tipDeflection(const Cantilever& beam, int n)
{
  const TetMesh mesh =
    makeBoxTetMesh({0, 0, 0}, {beam.length, beam.thickness, beam.thickness}, 10 * n, n, n);
  ElasticSolidSettings settings;
  settings.timeStep = 10.0;
  settings.solverIterations = 5000;
  settings.solverTolerance = 1e-12;
  ElasticSolid solid(mesh, ElasticMaterial{beam.youngsModulus, 0.0}, settings);
  const int endVertices = (n + 1) * (n + 1);
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
  {
    if (mesh.points[v].x == 0.0)
    {
      solid.fixVertex(v);
    }
    else if (mesh.points[v].x == beam.length)
    {
      solid.setExternalForce(v, {0.0, 0.0, -beam.load / endVertices});
    }
  }
  for (int step = 0; step < 4; ++step)
  {
    solid.step();
  }
  EXPECT_LT(solid.lastRelativeResidual(), 1e-9);
  double sum = 0.0;
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
  {
    if (mesh.points[v].x == beam.length)
    {
      sum += mesh.points[v].z - solid.positions()[v].z;
    }
  }
  return sum / endVertices;
}

TEST(ElasticSolid, CantileverApproachesBeamTheoryAsTheMeshIsRefined)
{
  const Cantilever beam;
  const double inertia = std::pow(beam.thickness, 4) / 12.0;
  const double bending =
    beam.load * std::pow(beam.length, 3) / (3.0 * beam.youngsModulus * inertia);
  // Timoshenko's shear deflection P L / (kappa G A), kappa = 5/6, G = E / 2 at nu = 0: 0.6 % of
  // the bending at L = 10 thicknesses.
  const double shear = beam.load * beam.length /
                       (5.0 / 6.0 * beam.youngsModulus / 2.0 * beam.thickness * beam.thickness);
  const double expected = bending + shear;
  const int sizes[] = {3, 4, 6};
  double ratio[3] = {};
  for (int i = 0; i < 3; ++i)
  {
    ratio[i] = tipDeflection(beam, sizes[i]) / expected;
    std::cout << "[ measured ] cantilever " << 10 * sizes[i] << " x " << sizes[i] << " x "
              << sizes[i] << " cells (" << 60 * sizes[i] * sizes[i] * sizes[i]
              << " tetrahedra): tip / beam theory " << ratio[i] << "\n";
  }
  // Linear tetrahedra are too stiff in bending and converge from below, the error falling as
  // the cell size squared: 27 %, 18 %, 9 % short at n = 3, 4, 6. Richardson's extrapolation of
  // that rate from n = 4 and 6 is the mesh's limit, which beam theory must match within 5 %.
  EXPECT_LT(ratio[0], ratio[1]);
  EXPECT_LT(ratio[1], ratio[2]);
  EXPECT_LT(ratio[2], 1.0);
  EXPECT_GT(ratio[2], 0.88);
  const double limit = (36.0 * ratio[2] - 16.0 * ratio[1]) / 20.0;
  std::cout << "[ measured ] extrapolated limit / beam theory " << limit << "\n";
  EXPECT_NEAR(limit, 1.0, 0.05);
}

TEST(ElasticSolid, RestStaysRest)
{
  const TetMesh mesh = makeBoxTetMesh({0, 0, 0}, {0.03, 0.02, 0.01}, 6, 4, 2);
  ElasticSolid solid(mesh, ElasticMaterial{3000.0, 0.45}, ElasticSolidSettings{});
  for (int step = 0; step < 50; ++step)
  {
    solid.step();
  }
  double moved = 0.0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
  {
    moved = std::max(moved, distance(mesh.points[v], solid.positions()[v]));
  }
  EXPECT_LT(moved, 1e-12);
  EXPECT_LT(solid.elasticEnergy(), 1e-20);
}

TEST(ElasticSolid, ARigidTurnStoresNoEnergyAndMakesNoForce)
{
  // The co-rotational point: a body turned as a whole is at rest in its turned pose, where
  // linear elasticity alone would see a strain of 1 - cos(60 degrees) and push back.
  const TetMesh mesh = makeBoxTetMesh({0, 0, 0}, {0.03, 0.02, 0.01}, 6, 4, 2);
  ElasticSolidSettings settings;
  settings.damping = 0.0;
  ElasticSolid solid(mesh, ElasticMaterial{3000.0, 0.45}, settings);
  const double angle = std::numbers::pi / 3.0;
  const Vec3 axis = normalizedOrZero(Vec3{1.0, 2.0, 2.0});
  std::vector<Vec3> turned = mesh.points;
  for (Vec3& p : turned)
  {
    // Rodrigues' rotation about `axis` through the origin, then a shift.
    p = p * std::cos(angle) + cross(axis, p) * std::sin(angle) +
        axis * (dot(axis, p) * (1.0 - std::cos(angle))) + Vec3{0.1, -0.2, 0.3};
  }
  solid.setPositions(turned);
  EXPECT_LT(solid.elasticEnergy(), 1e-20);
  for (int step = 0; step < 20; ++step)
  {
    solid.step();
  }
  double moved = 0.0;
  for (std::size_t v = 0; v < turned.size(); ++v)
  {
    moved = std::max(moved, distance(turned[v], solid.positions()[v]));
  }
  EXPECT_LT(moved, 1e-12);
  // The same pose stretched by 1 % along the turned x axis does store energy: the check can fail.
  std::vector<Vec3> stretched = turned;
  const Vec3 turnedX = turned[1] - turned[0];
  for (std::size_t v = 0; v < stretched.size(); ++v)
  {
    stretched[v] = stretched[v] + normalizedOrZero(turnedX) * (0.01 * mesh.points[v].x);
  }
  solid.setPositions(stretched);
  // E/2 (strain^2) V for a free 1 % stretch at nu = 0.45 clamped laterally, at least E/2 eps^2 V.
  EXPECT_GT(solid.elasticEnergy(), 0.5 * 3000.0 * 1e-4 * 0.03 * 0.02 * 0.01);
}

TEST(ElasticSolid, EnergyNeverGrowsAfterRelease)
{
  // Bent by a load, then let go with no damping: implicit Euler may only lose energy.
  const TetMesh mesh = makeBoxTetMesh({0, 0, 0}, {0.04, 0.02, 0.02}, 8, 4, 4);
  ElasticSolidSettings settings;
  settings.damping = 0.0;
  settings.timeStep = 0.002;
  settings.solverIterations = 60;
  ElasticSolid solid(mesh, ElasticMaterial{5000.0, 0.45}, settings);
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
  {
    if (mesh.points[v].x == 0.0)
    {
      solid.fixVertex(v);
    }
    else if (mesh.points[v].x == 0.04)
    {
      solid.setExternalForce(v, {0.0, 0.0, -0.01});
    }
  }
  for (int step = 0; step < 100; ++step)
  {
    solid.step();
  }
  solid.clearExternalForces();
  const double released = solid.kineticEnergy() + solid.elasticEnergy();
  ASSERT_GT(released, 1e-6);
  double last = released;
  double worstGain = 0.0;
  for (int step = 0; step < 250; ++step)
  {
    solid.step();
    const double now = solid.kineticEnergy() + solid.elasticEnergy();
    worstGain = std::max(worstGain, (now - last) / released);
    last = now;
  }
  std::cout << "[ measured ] released " << released << " J, after 0.5 s " << last
            << " J, worst gain in a step " << worstGain << " of it\n";
  EXPECT_LE(worstGain, 1e-9);
  EXPECT_LT(last, released);
}

TEST(ElasticSolid, AStifferInclusionGivesLess)
{
  // A block pressed at the middle of its top: a nodule ten times stiffer under the press gives
  // less, as a trainee should feel.
  const TetMesh mesh = makeBoxTetMesh({0, 0, 0}, {0.04, 0.04, 0.02}, 8, 8, 4);
  ElasticSolidSettings settings;
  settings.timeStep = 10.0;
  settings.solverIterations = 3000;
  settings.solverTolerance = 1e-12;
  const Vec3 centre{0.02, 0.02, 0.015};
  std::vector<ElasticMaterial> materials(mesh.tets.size(), ElasticMaterial{3000.0, 0.45});
  const auto pressDepth = [&](const std::vector<ElasticMaterial>& tissue) {
    ElasticSolid solid(mesh, tissue, settings);
    std::uint32_t top = 0;
    for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
    {
      if (mesh.points[v].z == 0.0)
      {
        solid.fixVertex(v);
      }
      if (distance(mesh.points[v], {0.02, 0.02, 0.02}) < 1e-12)
      {
        top = v;
      }
    }
    solid.setExternalForce(top, {0.0, 0.0, -0.01});
    for (int step = 0; step < 4; ++step)
    {
      solid.step();
    }
    return mesh.points[top].z - solid.positions()[top].z;
  };
  const double soft = pressDepth(materials);
  for (std::size_t e = 0; e < mesh.tets.size(); ++e)
  {
    const auto& t = mesh.tets[e];
    const Vec3 c =
      (mesh.points[t[0]] + mesh.points[t[1]] + mesh.points[t[2]] + mesh.points[t[3]]) / 4.0;
    if (distance(c, centre) < 0.007)
    {
      materials[e].youngsModulus = 30000.0;
    }
  }
  const double withNodule = pressDepth(materials);
  std::cout << "[ measured ] press depth " << soft << " m soft, " << withNodule
            << " m over a nodule 10x stiffer\n";
  EXPECT_GT(soft, 0.0);
  EXPECT_LT(withNodule, 0.8 * soft);
}

TEST(ElasticSolid, StaysBoundedAtTheSimulationStep)
{
  // 200 Hz, stiff and soft elements side by side, a sudden large force: implicit Euler keeps it
  // bounded where an explicit step at this h would blow up (its limit is about 0.1 ms here).
  const TetMesh mesh = makeBoxTetMesh({0, 0, 0}, {0.04, 0.04, 0.02}, 8, 8, 4);
  std::vector<ElasticMaterial> materials(mesh.tets.size(), ElasticMaterial{3000.0, 0.49});
  for (std::size_t e = 0; e < materials.size(); e += 3)
  {
    materials[e].youngsModulus = 100000.0;
  }
  // 0.4 N on the 16 cm^2 top at once: some 250 Pa on a block whose soft part is 3 kPa.
  ElasticSolidSettings settings;
  settings.timeStep = 0.005;
  settings.solverIterations = 20;
  ElasticSolid solid(mesh, materials, settings);
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
  {
    if (mesh.points[v].z == 0.0)
    {
      solid.fixVertex(v);
    }
    else if (mesh.points[v].z == 0.02)
    {
      solid.setExternalForce(v, {0.0, 0.0, -0.005});
    }
  }
  double farthest = 0.0;
  for (int step = 0; step < 400; ++step)
  {
    solid.step();
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
    {
      farthest = std::max(farthest, distance(mesh.points[v], solid.positions()[v]));
    }
  }
  std::cout << "[ measured ] largest displacement in 2 s " << farthest << " m\n";
  EXPECT_TRUE(std::isfinite(farthest));
  EXPECT_LT(farthest, 0.005); // a quarter of the block's height
}

TEST(ElasticSolid, BadSettingsAreRefused)
{
  const TetMesh mesh = makeBoxTetMesh({0, 0, 0}, {0.01, 0.01, 0.01}, 1, 1, 1);
  const auto refusal = [&](const ElasticMaterial& material, const ElasticSolidSettings& s) {
    try
    {
      ElasticSolid solid(mesh, material, s);
    }
    catch (const std::invalid_argument& error)
    {
      return std::string(error.what());
    }
    return std::string("no refusal");
  };
  const ElasticSolidSettings good;
  EXPECT_EQ(refusal({0.0, 0.3}, good), "ElasticSolid: Young's modulus must be above 0");
  EXPECT_EQ(refusal({1000.0, 0.5}, good), "ElasticSolid: Poisson's ratio must be in [0, 0.5)");
  ElasticSolidSettings bad = good;
  bad.timeStep = 0.0;
  EXPECT_EQ(refusal({1000.0, 0.3}, bad), "ElasticSolid: the time step must be above 0");
  TetMesh inverted = mesh;
  std::swap(inverted.tets[0][1], inverted.tets[0][2]);
  try
  {
    ElasticSolid solid(inverted, ElasticMaterial{}, good);
    ADD_FAILURE() << "an inverted tetrahedron was taken";
  }
  catch (const std::invalid_argument& error)
  {
    EXPECT_EQ(std::string(error.what()), "ElasticSolid: tetrahedron 0 is inverted or flat");
  }
}

} // namespace
} // namespace proxima
