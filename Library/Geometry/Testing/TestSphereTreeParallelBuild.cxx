// The parallel tree build against the serial one: the same nodes and leaf spheres bit for bit
// (compared as bytes), the same depth, for every thread count, on meshes that take each path of
// the build (leaf pieces of long triangles, coincident triangles, median fallbacks, one or many
// leaf spheres per node). And the parallel-for it runs on: fixed chunks whatever the thread
// count, Initialize on every thread, Reduce once, exceptions carried to the caller.
#include "Geometry/Private/ParallelFor.h"
#include "Geometry/ProceduralMeshes.h"
#include "Geometry/SphereTree.h"

#include "GeometryTestSupport.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace proxima::test
{
namespace
{

TriangleMesh buildMesh(TriangleSoup soup)
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(std::move(soup), error)) << error.message;
  return mesh;
}

// Small triangles with some long slivers among them (split into pieces by the leaf size rule),
// a cluster of exact duplicates (a split with one side empty) and a far outlier.
TriangleSoup makeMixedSoup(std::uint64_t seed, int numTriangles)
{
  Random random(seed);
  TriangleSoup soup;
  auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    const auto first = static_cast<std::uint32_t>(soup.points.size());
    soup.points.insert(soup.points.end(), {a, b, c});
    soup.triangles.push_back({first, first + 1, first + 2});
  };
  for (int i = 0; i < numTriangles; ++i)
  {
    const Vec3 corner = random.inCube(1.0);
    const double size = random.chance(0.05) ? 0.5 : 0.01;
    add(corner, corner + random.direction() * size, corner + random.direction() * 0.01);
  }
  const Vec3 p{0.25, 0.25, 0.25};
  for (int i = 0; i < 2000; ++i)
  {
    add(p, p + Vec3{0.001, 0.0, 0.0}, p + Vec3{0.0, 0.001, 0.0});
  }
  add(Vec3{50.0, 0.0, 0.0}, Vec3{50.1, 0.0, 0.0}, Vec3{50.0, 0.1, 0.0});
  return soup;
}

void expectSameTree(const SphereTree& parallel, const SphereTree& serial, const std::string& what)
{
  SCOPED_TRACE(what);
  EXPECT_EQ(parallel.depth(), serial.depth());
  EXPECT_EQ(parallel.numTriangles(), serial.numTriangles());
  EXPECT_EQ(std::memcmp(&parallel.origin(), &serial.origin(), sizeof(Vec3)), 0);
  ASSERT_EQ(parallel.numNodes(), serial.numNodes());
  ASSERT_EQ(parallel.numLeafSpheres(), serial.numLeafSpheres());
  EXPECT_EQ(std::memcmp(parallel.nodes().data(), serial.nodes().data(),
                        serial.nodes().size() * sizeof(SphereTreeNode)),
            0);
  EXPECT_EQ(std::memcmp(parallel.leafSpheres().data(), serial.leafSpheres().data(),
                        serial.leafSpheres().size() * sizeof(LeafSphere)),
            0);
}

static_assert(sizeof(SphereTreeNode) == 6 * 4 && sizeof(LeafSphere) == 5 * 4,
              "the byte comparison needs nodes and leaf spheres without padding");

TEST(SphereTreeParallelBuild, EqualsTheSerialBuildForEveryThreadCount)
{
  struct Case
  {
    std::string name;
    TriangleMesh mesh;
  };
  std::vector<Case> cases;
  cases.push_back({"icosphere 6", buildMesh(makeIcosphere(6, 0.1, Vec3{0.3, -0.2, 0.1}))});
  cases.push_back({"mixed soup", buildMesh(makeMixedSoup(14, 40000))});
  cases.push_back({"grid 120", buildMesh(makeGrid(1.0, 120, 0.2))});
  std::vector<std::pair<std::string, SphereTreeOptions>> settings;
  settings.push_back({"defaults", SphereTreeOptions{}});
  SphereTreeOptions paper;
  paper.leafSizeFactor = 0.0;
  paper.maxLeafSpheresPerNode = 1;
  settings.push_back({"one sphere per triangle and per leaf", paper});
  SphereTreeOptions fine;
  fine.leafSizeFactor = 0.7;
  fine.maxLeafSpheresPerNode = 16;
  settings.push_back({"pieces, 16 per leaf", fine});

  for (const Case& c : cases)
  {
    for (const auto& [settingName, options] : settings)
    {
      SphereTree serial;
      serial.build(c.mesh, options);
      for (const unsigned threads : {2u, 3u, 8u, 0u})
      {
        SphereTreeOptions parallelOptions = options;
        parallelOptions.numBuildThreads = threads;
        SphereTree parallel;
        parallel.build(c.mesh, parallelOptions);
        expectSameTree(parallel, serial,
                       c.name + ", " + settingName + ", " + std::to_string(threads) + " threads");
      }
    }
  }
}

TEST(SphereTreeParallelBuild, EqualsTheSerialBuildOnASharedMesh)
{
  const std::string path = std::string(PROXIMA_SHARED_MESHES) + "/stanford-bunny.obj";
  TriangleSoup soup;
  {
    // The OBJ's vertices and faces only: enough for a tree, and no reader outside this layer.
    std::FILE* file = std::fopen(path.c_str(), "r");
    if (file == nullptr)
    {
      GTEST_SKIP() << "no shared mesh at " << path;
    }
    char line[512];
    while (std::fgets(line, sizeof line, file))
    {
      double x, y, z;
      unsigned a, b, c;
      if (std::sscanf(line, "v %lf %lf %lf", &x, &y, &z) == 3)
      {
        soup.points.push_back({x, y, z});
      }
      else if (std::sscanf(line, "f %u%*[^ ] %u%*[^ ] %u", &a, &b, &c) == 3 ||
               std::sscanf(line, "f %u %u %u", &a, &b, &c) == 3)
      {
        soup.triangles.push_back({a - 1, b - 1, c - 1});
      }
    }
    std::fclose(file);
  }
  ASSERT_GT(soup.triangles.size(), 10000u);
  const TriangleMesh mesh = buildMesh(std::move(soup));
  SphereTree serial;
  serial.build(mesh);
  SphereTreeOptions options;
  options.numBuildThreads = 4;
  SphereTree parallel;
  parallel.build(mesh, options);
  expectSameTree(parallel, serial, "stanford bunny");
}

TEST(ParallelFor, RunsFixedChunksInitializeOnEachThreadAndReduceOnce)
{
  for (const unsigned threads : {1u, 2u, 5u})
  {
    struct Chunks
    {
      std::mutex mutex;
      std::set<std::pair<std::size_t, std::size_t>> seen;
      std::atomic<int> initialized{0};
      int reduced = 0;
      void Initialize() { ++initialized; }
      void operator()(std::size_t begin, std::size_t end)
      {
        const std::lock_guard<std::mutex> lock(mutex);
        seen.insert({begin, end});
      }
      void Reduce() { ++reduced; }
    } chunks;
    detail::parallelFor(3, 40, 10, chunks, threads);
    const std::set<std::pair<std::size_t, std::size_t>> expected{
      {3, 13}, {13, 23}, {23, 33}, {33, 40}};
    EXPECT_EQ(chunks.seen, expected) << threads << " threads";
    EXPECT_EQ(chunks.reduced, 1);
    EXPECT_GE(chunks.initialized.load(), 1);
    EXPECT_LE(chunks.initialized.load(), static_cast<int>(threads));
  }
}

TEST(ParallelFor, WorkerLocalSumsAgreeAndAnExceptionReachesTheCaller)
{
  struct Sum
  {
    detail::WorkerLocal<long> partial{4};
    long total = 0;
    void operator()(std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        partial.local() += static_cast<long>(i);
      }
    }
    void Reduce()
    {
      for (const long value : partial.all())
      {
        total += value;
      }
    }
  } sum;
  detail::parallelFor(0, 100000, 1000, sum, 4);
  EXPECT_EQ(sum.total, 99999L * 100000L / 2);

  auto throwing = [](std::size_t begin, std::size_t) {
    if (begin == 500)
    {
      throw std::runtime_error("chunk 5");
    }
  };
  EXPECT_THROW(detail::parallelFor(0, 1000, 100, throwing, 3), std::runtime_error);
  int nothing = 0;
  auto never = [&](std::size_t, std::size_t) { ++nothing; };
  detail::parallelFor(7, 7, 10, never, 3);
  EXPECT_EQ(nothing, 0);
}

} // namespace
} // namespace proxima::test
