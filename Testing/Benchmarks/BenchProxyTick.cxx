// Per-tick cost of the whole proxy update (all move/update iterations of a tick) in sliding
// contact: press-and-stroke paths on icospheres of 20k, 320k and 1.3M triangles with 0.5 mm edges
// and on the 1.5M-triangle skull, proxy radius 1 mm, at 1 kHz. Each benchmark iteration plays the
// whole path once; the per-tick distribution (median, p99, p99.9, max) and the work per tick
// (iterations, triangles tested) are reported as counters, because a mean hides the tail that
// matters to a servo loop.
#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshReader.h"
#include "Proxy/ProxySolver.h"
#include "Proxy/SurfaceMaterial.h"
#include "Proxy/TextureImage.h"
#include "Paths/PathGenerators.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace
{
using namespace proxima;

constexpr double kRadius = 0.001;
constexpr double kEdge = 0.0005;
constexpr double kRate = 1000.0;

struct Workload
{
  CollisionScene scene;
  FingerPath path;
  std::uint32_t triangles = 0;
};

// A press into the top of the object and a stroke across it at 5 cm/s: sliding contact for most
// of the path. The press starts over the surface point nearest the top of the bounding box (on
// the skull the box's top centre is over a hole), and the stroke is 2 cm long.
FingerPath slidingPath(const CollisionObject& object)
{
  const Aabb& bounds = object.mesh.bounds();
  const Vec3 c = bounds.center();
  SphereTreeScratch scratch;
  const NearestTriangle top =
    object.tree.nearest(object.mesh, Vec3{c.x, c.y, bounds.upper.z}, bounds.diagonal(), scratch);
  PressAndStroke p;
  p.strokeDirection = Vec3{1, 0, 0};
  p.strokeLength = 0.02;
  p.surfacePoint =
    Vec3{top.closest.point.x - 0.5 * p.strokeLength, top.closest.point.y, top.closest.point.z};
  p.approachHeight = 3.0 * kRadius;
  p.depth = 2.0 * kRadius;
  p.speed = 0.05;
  return makePressAndStrokePath(p, kRate);
}

const Workload& icosphereWorkload(std::uint32_t subdivisions)
{
  static std::map<std::uint32_t, std::unique_ptr<Workload>> cache;
  auto& slot = cache[subdivisions];
  if (!slot)
  {
    slot = std::make_unique<Workload>();
    // Edge of an icosphere of radius R after s subdivisions is about 1.05 R / 2^s.
    const double radius = kEdge * std::ldexp(1.0, static_cast<int>(subdivisions)) / 1.05;
    TriangleMesh mesh;
    MeshError error;
    mesh.build(makeIcosphere(subdivisions, radius), error);
    slot->triangles = mesh.numTriangles();
    slot->scene.addObject(std::move(mesh));
    slot->path = slidingPath(slot->scene.objects.front());
  }
  return *slot;
}

const Workload* skullWorkload()
{
  static std::unique_ptr<Workload> workload;
  static bool tried = false;
  if (!tried)
  {
    tried = true;
    const std::string file = std::string(PROXIMA_SHARED_MESHES) + "/cranium_bone_iso075mm.ply";
    if (std::filesystem::exists(file))
    {
      workload = std::make_unique<Workload>();
      TriangleMesh mesh = loadTriangleMesh(file, 0.001);
      workload->triangles = mesh.numTriangles();
      workload->scene.addObject(std::move(mesh));
      workload->path = slidingPath(workload->scene.objects.front());
    }
  }
  return workload.get();
}

void playPath(benchmark::State& state, const Workload& workload)
{
  ProxyParameters parameters;
  parameters.radius = kRadius;
  ProxySolver solver;
  solver.setScene(&workload.scene, parameters);
  // Every tick of every pass (the first pass meets the mesh's memory cold, as a real session
  // does once), and apart the ticks that end in contact: the sliding contact of the targets.
  std::vector<double> nanoseconds;
  std::vector<double> contactNanoseconds;
  nanoseconds.reserve(workload.path.size() * 8);
  contactNanoseconds.reserve(workload.path.size() * 8);
  double iterations = 0.0;
  double trianglesTested = 0.0;
  double contactTicks = 0.0;
  for (auto _ : state)
  {
    solver.resetProxy(workload.path.positions.front());
    for (const Vec3& finger : workload.path.positions)
    {
      const auto begin = std::chrono::steady_clock::now();
      const ProxyTickResult result = solver.update(finger);
      const auto end = std::chrono::steady_clock::now();
      const double ns = std::chrono::duration<double, std::nano>(end - begin).count();
      nanoseconds.push_back(ns);
      if (result.numContacts > 0)
      {
        contactNanoseconds.push_back(ns);
      }
      iterations += result.iterations;
      trianglesTested += result.queries.trianglesTested;
      contactTicks += result.numContacts > 0 ? 1.0 : 0.0;
      benchmark::DoNotOptimize(result.proxy);
    }
  }
  auto quantile = [](std::vector<double>& values, double q) {
    if (values.empty())
    {
      return 0.0;
    }
    std::sort(values.begin(), values.end());
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
    return values[rank == 0 ? 0 : rank - 1];
  };
  const double ticks =
    static_cast<double>(state.iterations()) * static_cast<double>(workload.path.size());
  state.counters["triangles"] = workload.triangles;
  state.counters["tick_median_ns"] = quantile(nanoseconds, 0.5);
  state.counters["tick_p99_ns"] = quantile(nanoseconds, 0.99);
  state.counters["tick_p999_ns"] = quantile(nanoseconds, 0.999);
  state.counters["tick_max_ns"] = nanoseconds.back();
  state.counters["contact_median_ns"] = quantile(contactNanoseconds, 0.5);
  state.counters["contact_p99_ns"] = quantile(contactNanoseconds, 0.99);
  state.counters["contact_p999_ns"] = quantile(contactNanoseconds, 0.999);
  state.counters["iterations_per_tick"] = iterations / ticks;
  state.counters["triangles_tested_per_tick"] = trianglesTested / ticks;
  state.counters["contact_fraction"] = contactTicks / ticks;
  state.SetItemsProcessed(static_cast<std::int64_t>(ticks));
}

void BM_ProxyTickIcosphere(benchmark::State& state)
{
  playPath(state, icosphereWorkload(static_cast<std::uint32_t>(state.range(0))));
}
BENCHMARK(BM_ProxyTickIcosphere)
  ->Arg(5)
  ->Arg(7)
  ->Arg(8)
  ->Unit(benchmark::kMillisecond)
  ->Iterations(5);

// Pay for what you use (issue: surface effects): the same press and stroke on the 1.3M-triangle
// icosphere with each surface effect on alone, and with shading asked for on a copy of the mesh
// without normals (which must cost what the plain surface costs). The bump map is a 1024 x 1024
// sinusoidal height of 20 um on texture coordinates projected from above.
enum SurfaceEffects : int
{
  kPlain,
  kShadingWithoutNormals,
  kShading,
  kFriction,
  kBump,
  kEverything,
  kNumEffects
};

const char* effectName(int effects)
{
  static const char* names[kNumEffects] = {
    "plain", "shading asked, no normals", "shading", "friction", "bump texture", "all"};
  return names[effects];
}

std::shared_ptr<const TextureImage> bumpImage()
{
  const std::uint32_t size = 1024;
  std::vector<float> values(size * size);
  for (std::uint32_t j = 0; j < size; ++j)
  {
    for (std::uint32_t i = 0; i < size; ++i)
    {
      values[j * size + i] =
        static_cast<float>(0.5 + 0.25 * std::sin(0.2 * i) + 0.25 * std::sin(0.2 * j));
    }
  }
  return std::make_shared<const TextureImage>(size, size, std::move(values));
}

const Workload& effectsWorkload(int effects)
{
  static std::map<int, std::unique_ptr<Workload>> cache;
  auto& slot = cache[effects];
  if (!slot)
  {
    slot = std::make_unique<Workload>();
    const std::uint32_t subdivisions = 8;
    const double radius = kEdge * std::ldexp(1.0, static_cast<int>(subdivisions)) / 1.05;
    TriangleSoup soup = makeIcosphere(subdivisions, radius);
    if (effects == kShadingWithoutNormals)
    {
      soup.pointNormals.clear();
    }
    for (const Vec3& p : soup.points)
    {
      soup.texCoords.push_back({p.x / (2.0 * radius) + 0.5, p.y / (2.0 * radius) + 0.5});
    }
    SurfaceMaterial material;
    material.shading =
      effects == kShadingWithoutNormals || effects == kShading || effects == kEverything;
    if (effects == kFriction || effects == kEverything)
    {
      material.staticFriction = 0.5;
      material.dynamicFriction = 0.3;
      material.viscosity = 1.0;
    }
    if (effects == kBump || effects == kEverything)
    {
      material.textures.push_back(TextureMap{bumpImage(), TextureRole::Bump, 2e-5});
    }
    TriangleMesh mesh;
    MeshError error;
    mesh.build(std::move(soup), error);
    slot->triangles = mesh.numTriangles();
    slot->scene.addObject(std::move(mesh), SphereTreeOptions{}, material);
    slot->path = slidingPath(slot->scene.objects.front());
  }
  return *slot;
}

void BM_ProxyTickSurfaceEffects(benchmark::State& state)
{
  const int effects = static_cast<int>(state.range(0));
  state.SetLabel(effectName(effects));
  playPath(state, effectsWorkload(effects));
}
BENCHMARK(BM_ProxyTickSurfaceEffects)
  ->DenseRange(0, kNumEffects - 1)
  ->Unit(benchmark::kMillisecond)
  ->Iterations(5);

void BM_ProxyTickSkull(benchmark::State& state)
{
  const Workload* workload = skullWorkload();
  if (workload == nullptr)
  {
    state.SkipWithError("the shared skull mesh is absent (PROXIMA_SHARED_DATA)");
    return;
  }
  playPath(state, *workload);
}
BENCHMARK(BM_ProxyTickSkull)->Unit(benchmark::kMillisecond)->Iterations(5);
} // namespace

BENCHMARK_MAIN();
