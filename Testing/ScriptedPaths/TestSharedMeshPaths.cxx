// Scripted finger paths on every real mesh of the shared folder (../shared/data/meshes,
// PROVENANCE.md), scaled to metres, with the oracle on every tick. Each test skips, saying so,
// when the shared folder or the file is absent.
//
// Scales (file units to metres; diagonals from PROVENANCE.md): bunny 0.25 m (scale 1), teapot
// 8.2 -> 0.164 m (0.02), spot 2.6 -> 0.13 m (0.05), abc 0.135 m (1), fandisk 1.45 -> 0.145 m (0.1),
// screw 15.2 mm -> 15.2 mm (0.001), featuretype 5.8 -> 0.174 m (0.03), liver 0.33 m (1), angel
// 412 -> 0.206 m (0.0005), cranium 349 mm -> 0.349 m (0.001). Proxy radius 1 mm (0.3-0.8% of those
// diagonals) except the screw: 0.1 mm (0.7% of its 15 mm), so that it feels the threads.
// Paths from makeDefaultPath: press-stroke, jab and wander (straight through the object) on every
// mesh, all five kinds on the bunny, the teapot and the fandisk (a scan with holes, a soup whose
// spout and handle pass into the body, a CAD part with sharp feature edges).
#include "ScriptedHarness.h"

#include "IO/Mesh/MeshReader.h"
#include "Paths/PathGenerators.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

namespace proxima
{
namespace
{
struct SharedMeshCase
{
  const char* file;
  double scale;
  double radius;
  std::vector<std::string> kinds;
};

std::ostream& operator<<(std::ostream& out, const SharedMeshCase& c)
{
  return out << c.file;
}

const std::vector<std::string> kAllKinds = {"press-stroke", "jab", "wander", "slide", "circle"};
const std::vector<std::string> kPressJabWander = {"press-stroke", "jab", "wander"};

class SharedMeshPaths : public testing::TestWithParam<SharedMeshCase>
{};

TEST_P(SharedMeshPaths, InvariantsHoldOnEveryTick)
{
  const SharedMeshCase& mesh = GetParam();
  const std::string path = std::string(PROXIMA_SHARED_MESHES) + "/" + mesh.file;
  if (!std::filesystem::exists(path))
  {
    GTEST_SKIP() << "shared mesh not found: " << path
                 << " (set the CMake cache variable PROXIMA_SHARED_DATA)";
  }
  const auto begin = std::chrono::steady_clock::now();
  auto scene = std::make_unique<CollisionScene>();
  scene->addObject(loadTriangleMesh(path, mesh.scale));
  const auto loaded = std::chrono::steady_clock::now();
  const oracle::MeshOracle oracle(*scene);
  const auto indexed = std::chrono::steady_clock::now();
  const TriangleMesh& triangles = scene->objects.front().mesh;
  std::cout << "[mesh] " << mesh.file << ": " << triangles.numTriangles() << " triangles ("
            << triangles.numDegenerateTriangles() << " zero-area), diagonal "
            << triangles.diagonal() << " m, radius " << mesh.radius << " m; load + sphere tree "
            << std::chrono::duration<double>(loaded - begin).count() << " s, oracle index "
            << std::chrono::duration<double>(indexed - loaded).count() << " s\n";
  for (const std::string& kind : mesh.kinds)
  {
    scripted::ScriptedCase c;
    c.name = std::string(mesh.file) + "/" + kind;
    c.scene = scene.get();
    c.oracle = &oracle;
    c.proxy.radius = mesh.radius;
    c.path = makeDefaultPath(kind, triangles.bounds(), mesh.radius, 1000.0);
    const scripted::ScriptedOutcome outcome = scripted::runScriptedCase(c);
    scripted::expectInvariants(c.name, outcome);
  }
}

INSTANTIATE_TEST_SUITE_P(
  Provenance, SharedMeshPaths,
  testing::Values(SharedMeshCase{"stanford-bunny.obj", 1.0, 0.001, kAllKinds},
                  SharedMeshCase{"teapot.obj", 0.02, 0.001, kAllKinds},
                  SharedMeshCase{"spot_triangulated.obj", 0.05, 0.001, kPressJabWander},
                  SharedMeshCase{"abc_00000050_trimesh_000.stl", 1.0, 0.001, kPressJabWander},
                  SharedMeshCase{"fandisk.off", 0.1, 0.001, kAllKinds},
                  SharedMeshCase{"M3x10_screw.stl", 0.001, 0.0001, kPressJabWander},
                  SharedMeshCase{"featuretype.STL", 0.03, 0.001, kPressJabWander},
                  SharedMeshCase{"VH_M_Liver.glb", 1.0, 0.001, kPressJabWander},
                  SharedMeshCase{"Angel_decimated.vtp", 0.0005, 0.001, kPressJabWander},
                  SharedMeshCase{"cranium_bone_iso075mm.ply", 0.001, 0.001, kPressJabWander}),
  [](const testing::TestParamInfo<SharedMeshCase>& info) {
    std::string name = info.param.file;
    for (char& ch : name)
    {
      ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    }
    return name;
  });

} // namespace
} // namespace proxima
