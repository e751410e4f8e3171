// One step of the tissue's elastic solid (Library/Tissue/ElasticSolid.h) on the shipped kidney,
// wrapped and filled at two tet sizes near the targets' 2,000 and 10,000 tetrahedra (issue 35:
// at most 1 ms and 5 ms a step on one core), at 10, 20 and 30 solver iterations, pressed at its
// top so that the rotations and the solve have work. The counters give the tetrahedra and the
// residual the iterations leave, the error a fixed iteration count trades for its fixed cost.
#include "IO/Mesh/MeshReader.h"
#include "IO/TissueMeshing/TissueMeshing.h"
#include "Tissue/ElasticSolid.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <string>

namespace proxima
{
namespace
{

const TetMesh& kidneyTets(double tetSize)
{
  static std::map<double, TetMesh> meshes;
  auto found = meshes.find(tetSize);
  if (found == meshes.end())
  {
    const std::string file = PROXIMA_SOURCE_DIR "/Data/Meshes/VH_M_Kidney_L.glb";
    TissueMeshingOptions options;
    options.tetSize = tetSize;
    found = meshes.emplace(tetSize, meshTissue(readMeshFile(file), options, file).tets).first;
  }
  return found->second;
}

void elasticStep(benchmark::State& state)
{
  const double tetSize = static_cast<double>(state.range(0)) * 1e-4;
  const TetMesh& mesh = kidneyTets(tetSize);
  ElasticSolidSettings settings;
  settings.timeStep = 0.005;
  settings.solverIterations = static_cast<int>(state.range(1));
  ElasticSolid solid(mesh, ElasticMaterial{3000.0, 0.45}, settings);
  // Held along its lowest centimetre, pressed down on its highest points.
  double low = mesh.points.front().z;
  double high = low;
  for (const Vec3& p : mesh.points)
  {
    low = std::min(low, p.z);
    high = std::max(high, p.z);
  }
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v)
  {
    if (mesh.points[v].z < low + 0.01)
    {
      solid.fixVertex(v);
    }
    else if (mesh.points[v].z > high - 0.005)
    {
      solid.setExternalForce(v, {0.0, 0.0, -0.02});
    }
  }
  for (int warm = 0; warm < 20; ++warm)
  {
    solid.step();
  }
  for (auto _ : state)
  {
    solid.step();
  }
  state.counters["tetrahedra"] = static_cast<double>(mesh.tets.size());
  state.counters["residual"] = solid.lastRelativeResidual();
}

// Tet sizes in 0.1 mm: 8 mm (about 2,000 tetrahedra) and 4.5 mm (about 10,000).
BENCHMARK(elasticStep)
  ->ArgsProduct({{80, 45}, {10, 20, 30}})
  ->Unit(benchmark::kMicrosecond)
  ->MinTime(0.5);

} // namespace
} // namespace proxima

BENCHMARK_MAIN();
