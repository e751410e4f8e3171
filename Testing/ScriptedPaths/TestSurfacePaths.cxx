// The paths of `proxima path KIND` (makeSurfacePath) do what their names say on every real mesh of
// the shared folder and at any scale (issue 13): each kind, run through the kernel in lockstep
// at the command line's defaults (1000 N/m, a 10 N clamp), touches the surface for the share of
// ticks its name promises, and the pressing kinds never reach the clamp. Before, `slide` touched
// nothing on 5 of 7 meshes, `press-stroke` saturated the clamp on 6 of 7, and every kind took z
// as up (the bunny and spot are y-up). The oracle of "touching" is the kernel's own contact
// count, whose exactness the oracle suites check; what is tested here is the paths.
#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshReader.h"
#include "Runtime/LockstepRuntime.h"
#include "Paths/PathGenerators.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace proxima
{
namespace
{
struct SurfacePathCase
{
  const char* file;
  double scale;
  double radius;
};

std::ostream& operator<<(std::ostream& out, const SurfacePathCase& c)
{
  return out << c.file;
}

/// The least share of ticks in contact each kind promises (jab: five quick pokes from close by;
/// the others spend most of their time on the surface).
const std::map<std::string, double> kLeastContactShare = {
  {"press-stroke", 0.4}, {"slide", 0.4}, {"circle", 0.4}, {"jab", 0.1}, {"wander", 0.5}};

struct RunOutcome
{
  double contactShare = 0.0;
  std::size_t clampedTicks = 0;
  double maxForce = 0.0;
  double startClearance = 0.0;
};

RunOutcome runThroughKernel(const CollisionScene& scene, const FingerPath& path, double radius)
{
  ProxyParameters parameters;
  parameters.radius = radius;
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(&scene, parameters);
  solver->resetProxy(path.positions.front());
  SimulatedDevice device(path);
  ServoParameters servo; // 1000 N/m and 10 N, as `proxima run`
  LockstepSettings settings;
  settings.rate = 1000.0;
  settings.startTime = path.startTime();
  settings.numTicks = ticksCovering(path.startTime(), path.endTime(), settings.rate);
  std::size_t contacts = 0;
  std::size_t ticks = 0;
  RunOutcome outcome;
  runLockstep(settings, *solver, device, servo, [&](const HapticState& state) {
    ++ticks;
    contacts += state.numContacts > 0 ? 1 : 0;
    outcome.clampedTicks += state.conditions.has(TickCondition::forceClamped) ? 1 : 0;
    outcome.maxForce = std::max(outcome.maxForce, norm(state.force));
  });
  outcome.contactShare = ticks > 0 ? static_cast<double>(contacts) / static_cast<double>(ticks) : 0;
  SphereTreeScratch scratch;
  const CollisionObject& object = scene.objects.front();
  const NearestTriangle near =
    object.tree.nearest(object.mesh, path.positions.front(), 1.0, scratch);
  outcome.startClearance = near.found ? std::sqrt(near.closest.squaredDistance) : 1.0;
  return outcome;
}

void expectNamedBehaviour(const std::string& name, const std::string& kind,
                          const RunOutcome& outcome, double radius)
{
  EXPECT_GE(outcome.contactShare, kLeastContactShare.at(kind)) << name;
  // `proxima run` refuses a path that starts within a radius of the surface.
  EXPECT_GT(outcome.startClearance, radius) << name;
  if (kind != "wander") // a wander goes through the object: its force saturates by design
  {
    EXPECT_EQ(outcome.clampedTicks, 0u) << name << ": max force " << outcome.maxForce << " N";
    EXPECT_LT(outcome.maxForce, 6.0) << name;
  }
}

class SurfacePaths : public testing::TestWithParam<SurfacePathCase>
{};

TEST_P(SurfacePaths, EveryKindDoesWhatItsNameSays)
{
  const SurfacePathCase& mesh = GetParam();
  const std::string file = std::string(PROXIMA_SHARED_MESHES) + "/" + mesh.file;
  if (!std::filesystem::exists(file))
  {
    GTEST_SKIP() << "shared mesh not found: " << file
                 << " (set the CMake cache variable PROXIMA_SHARED_DATA)";
  }
  CollisionScene scene;
  scene.addObject(loadTriangleMesh(file, mesh.scale));
  const CollisionObject& object = scene.objects.front();
  for (const std::string& kind : defaultPathKinds())
  {
    SurfacePathOptions options;
    options.radius = mesh.radius;
    const FingerPath path =
      makeSurfacePath(kind, {ProbeSurface{&object.mesh, &object.tree}}, options);
    const RunOutcome outcome = runThroughKernel(scene, path, mesh.radius);
    RecordProperty(kind + "_contact_percent", static_cast<int>(100.0 * outcome.contactShare));
    expectNamedBehaviour(std::string(mesh.file) + "/" + kind, kind, outcome, mesh.radius);
  }
}

INSTANTIATE_TEST_SUITE_P(
  Provenance, SurfacePaths,
  testing::Values(
    SurfacePathCase{"stanford-bunny.obj", 1.0, 0.001}, SurfacePathCase{"teapot.obj", 0.02, 0.001},
    SurfacePathCase{"spot_triangulated.obj", 0.05, 0.001},
    SurfacePathCase{"abc_00000050_trimesh_000.stl", 1.0, 0.001},
    SurfacePathCase{"fandisk.off", 0.1, 0.001}, SurfacePathCase{"M3x10_screw.stl", 0.001, 0.0001},
    SurfacePathCase{"featuretype.STL", 0.03, 0.001}, SurfacePathCase{"VH_M_Liver.glb", 1.0, 0.001},
    SurfacePathCase{"Angel_decimated.vtp", 0.0005, 0.001},
    SurfacePathCase{"cranium_bone_iso075mm.ply", 0.001, 0.001}),
  [](const testing::TestParamInfo<SurfacePathCase>& info) {
    std::string name = info.param.file;
    for (char& ch : name)
    {
      ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    }
    return name;
  });

TEST(SurfacePathScales, TheBunnyFromCentimetresToHundredsOfMetresAcross)
{
  const std::string file = std::string(PROXIMA_SHARED_MESHES) + "/stanford-bunny.obj";
  if (!std::filesystem::exists(file))
  {
    GTEST_SKIP() << "shared mesh not found: " << file;
  }
  // At scale 1 it is 0.25 m across: 25 mm to 250 m. (At 2.5 mm across, scale 0.01, the paths
  // are made as well, but the 1 mm proxy then covers the whole bunny and every tick tests all
  // of its triangles, which takes minutes: issue 12's territory, not the paths'.)
  for (const double scale : {0.1, 10.0, 1000.0})
  {
    CollisionScene scene;
    scene.addObject(loadTriangleMesh(file, scale));
    const CollisionObject& object = scene.objects.front();
    for (const std::string kind : {"press-stroke", "slide", "circle", "jab"})
    {
      const FingerPath path =
        makeSurfacePath(kind, {ProbeSurface{&object.mesh, &object.tree}}, SurfacePathOptions{});
      expectNamedBehaviour("scale " + std::to_string(scale) + "/" + kind, kind,
                           runThroughKernel(scene, path, 0.001), 0.001);
    }
  }
}

TEST(SurfacePathRefusals, ASurfaceWithNoPatchToSlideOnIsSaidSo)
{
  // Dust: 400 triangles of 0.1 mm, 2 mm apart in a plane. No stroke of the slide's length
  // (centimetres) stays on the surface; each ends at its triangle's edge.
  TriangleSoup dust;
  for (std::uint32_t i = 0; i < 20; ++i)
  {
    for (std::uint32_t j = 0; j < 20; ++j)
    {
      const Vec3 corner{0.002 * i, 0.002 * j, 0.0};
      const auto first = static_cast<std::uint32_t>(dust.points.size());
      dust.points.push_back(corner);
      dust.points.push_back(corner + Vec3{0.0001, 0.0, 0.0});
      dust.points.push_back(corner + Vec3{0.0, 0.0001, 0.0});
      dust.triangles.push_back({first, first + 1, first + 2});
    }
  }
  TriangleMesh mesh;
  MeshError error;
  ASSERT_TRUE(mesh.build(dust, error));
  SphereTree tree;
  tree.build(mesh);
  SurfacePathOptions options;
  options.radius = 0.001;
  try
  {
    (void)makeSurfacePath("slide", {ProbeSurface{&mesh, &tree}}, options);
    ADD_FAILURE() << "a slide was made on dust";
  }
  catch (const std::runtime_error& refusal)
  {
    EXPECT_NE(std::string(refusal.what()).find("no place on the surface where a slide of"),
              std::string::npos)
      << refusal.what();
  }
  EXPECT_THROW((void)makeSurfacePath("zigzag", {ProbeSurface{&mesh, &tree}}, options),
               std::invalid_argument);
}

} // namespace
} // namespace proxima
