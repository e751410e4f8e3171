// Hertz's contact, measured (issue 35's check; Documentation/Tissue.md): the proxy pressed slowly
// into a block much larger than the contact, fixed at its base, through TissueContact in lockstep
// as `proxima run` plays a tissue. At each depth the finger holds for 0.1 s for the block to
// settle; the force the servo renders, F = kp |finger - proxy|, is set against Hertz's
// F = 4/3 E / (1 - nu^2) sqrt(R) d^1.5 at the proxy's indentation d below the block's rest top.
//
// The block's cells are finest under the proxy and grow away from it (makeGridTetMesh), so that
// the contact spans many cells while the block spans many contact radii.
//
//   TissueHertzContact FINEST_MM GROWTH [FOOTPRINT_GAP ITERATIONS LOAD_RELAXATION BLOCK_MM]
//
// BLOCK_MM is the block's half width and its depth (25: a 5 x 5 x 2.5 cm block). Hertz's law is
// for a half-space: a block fixed at its base a few contact radii below stiffens the contact (a
// bonded layer's correction, Dimitriadis et al. 2002, is about 1 + 0.88 a / h at nu = 0.3: 8 % at
// d = 0.2 R under 2.5 cm), so the finer meshes are pressed into a larger one.
//
// Tools/tissue_hertz.py runs it for Documentation/TissueHertzTable.md. It prints one JSON
// object: the mesh (tetrahedra) and per depth d/R, d, F, Hertz's F, their ratio and how much the
// force still changed from tick to tick at the end of the hold (relative).
#include "Proxy/CollisionScene.h"
#include "Tissue/BoxTetMesh.h"
#include "Tissue/TetBoundary.h"
#include "Tissue/TissueContact.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <utility>
#include <vector>

namespace
{
using namespace proxima;

constexpr double kRadius = 0.005;
constexpr double kYoungsModulus = 10000.0;
constexpr double kPoissonRatio = 0.3;
constexpr double kStiffness = 1000.0;
constexpr double kRate = 1000.0;
constexpr int kTicksPerStep = 5;

double hertzForce(double indentation)
{
  return 4.0 / 3.0 * kYoungsModulus / (1.0 - kPoissonRatio * kPoissonRatio) * std::sqrt(kRadius) *
         std::pow(indentation, 1.5);
}

std::vector<double> symmetricCoordinates(double halfWidth, double finest, double growth)
{
  std::vector<double> side = gradedCoordinates(0.0, halfWidth, finest, growth);
  std::vector<double> all;
  for (auto it = side.rbegin(); it != side.rend(); ++it)
  {
    all.push_back(-*it);
  }
  all.insert(all.end(), side.begin() + 1, side.end());
  return all;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: TissueHertzContact FINEST_MM GROWTH [FOOTPRINT_GAP ITERATIONS "
                         "LOAD_RELAXATION BLOCK_MM]\n");
    return 2;
  }
  const double finest = std::atof(argv[1]) * 1e-3;
  const double growth = std::atof(argv[2]);
  const double gap = argc > 3 ? std::atof(argv[3]) : TissueContact::kFootprintGap;
  const int iterations = argc > 4 ? std::atoi(argv[4]) : 200;
  const double relaxation = argc > 5 ? std::atof(argv[5]) : 1.0;
  const double blockSize = argc > 6 ? std::atof(argv[6]) * 1e-3 : 0.025;
  if (!(blockSize > 2.0 * kRadius && blockSize < 1.0) || !(finest > 0.0 && finest < blockSize) ||
      !(growth >= 1.0) || !(gap > 0.0) || iterations < 1 ||
      !(relaxation > 0.0 && relaxation <= 1.0))
  {
    std::fprintf(stderr, "TissueHertzContact: want 10 < BLOCK_MM < 1000, 0 < FINEST_MM < BLOCK_MM, "
                         "GROWTH >= 1, FOOTPRINT_GAP > 0, ITERATIONS >= 1 and "
                         "0 < LOAD_RELAXATION <= 1\n");
    return 2;
  }

  const std::vector<double> across = symmetricCoordinates(blockSize, finest, growth);
  std::vector<double> down = gradedCoordinates(0.0, -blockSize, finest, growth);
  std::reverse(down.begin(), down.end());
  const TetMesh block = makeGridTetMesh(across, across, down);

  ElasticSolidSettings settings;
  settings.timeStep = kTicksPerStep / kRate;
  settings.damping = 50.0;
  settings.solverIterations = iterations;
  ElasticSolid solid(block, ElasticMaterial{kYoungsModulus, kPoissonRatio}, settings);
  for (std::uint32_t v = 0; v < block.points.size(); ++v)
  {
    if (block.points[v].z < -blockSize + 1e-9)
    {
      solid.fixVertex(v);
    }
  }
  CollisionScene scene;
  TriangleMesh surface;
  MeshError error;
  if (!surface.build(boundarySoup(block), error))
  {
    std::fprintf(stderr, "TissueHertzContact: %s\n", error.message.c_str());
    return 1;
  }
  scene.addObject(std::move(surface));
  ProxyParameters parameters;
  parameters.radius = kRadius;
  parameters.stiffness = kStiffness;
  parameters.timeStep = 1.0 / kRate;
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  TissueContact contact(solid, *solver, 0, kStiffness);
  contact.setFootprintGap(gap);
  contact.setLoadRelaxation(relaxation);

  const auto started = std::chrono::steady_clock::now();
  const double depths[] = {0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2};
  const int moveTicks = 50;
  const int holdTicks = 100;
  double fingerZ = kRadius + 0.002;
  solver->resetProxy({0.0, 0.0, fingerZ});
  std::printf("{\"finest_m\": %g, \"growth\": %g, \"footprint_gap\": %g, \"iterations\": %d, "
              "\"load_relaxation\": %g, \"block_m\": %g, \"tetrahedra\": %zu, \"depths\": [",
              finest, growth, gap, iterations, relaxation, blockSize, block.tets.size());
  bool first = true;
  for (const double relative : depths)
  {
    const double target = relative * kRadius;
    const double goal = kRadius - target - hertzForce(target) / kStiffness;
    const double from = fingerZ;
    double lastForce = 0.0;
    double change = 0.0;
    Vec3 proxy;
    for (int i = 0; i < moveTicks + holdTicks; ++i)
    {
      fingerZ = i < moveTicks ? from + (goal - from) * (i + 1) / moveTicks : goal;
      const Vec3 finger{0.0, 0.0, fingerZ};
      const ProxyTickResult result = solver->update(finger);
      contact.addTick(result);
      if ((i + 1) % kTicksPerStep == 0)
      {
        contact.step();
      }
      proxy = result.proxy;
      const double force = kStiffness * norm(finger - proxy);
      if (i >= moveTicks + holdTicks - 20)
      {
        change = std::max(change, std::abs(force - lastForce));
      }
      lastForce = force;
    }
    const double indentation = kRadius - proxy.z;
    const double hertz = hertzForce(indentation);
    std::printf("%s\n  {\"d_over_r\": %.4f, \"d\": %.6g, \"force\": %.6g, \"hertz\": %.6g, "
                "\"ratio\": %.4f, \"settling\": %.3g}",
                first ? "" : ",", indentation / kRadius, indentation, lastForce, hertz,
                lastForce / hertz, change / std::max(lastForce, 1e-30));
    std::fflush(stdout);
    first = false;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("],\n \"seconds\": %.2f}\n", seconds);
  return 0;
}
