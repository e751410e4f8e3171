// One typed suite for the two structures that answer the proxy's collision queries over a scene:
// the sphere trees (one per object, combined in object order as ProxySolver::sweep does) and the
// candidate cache, which promises the trees' answers. Each runs the same seeded queries against
// a brute force over every triangle of every object, with the same per-triangle routines
// (sweepSphereTriangleWithSkin, closestPointOnTriangle), so answers agree to the last bit:
// - first contact of a sweep: hit, t, object and triangle; ties in t to the lowest object, then
//   the lowest triangle (scenes with duplicated triangles and duplicated objects make ties);
// - triangles near a point (a segment of zero length; the proxy's gathers): the same set;
// - nearest point: triangle, object and squared distance, ties to the lowest as above.
// The cache holds the neighbourhood of one centre: its adapter rebuilds it around each query and
// counts a query it cannot cover (more than CandidateCache::kCapacity triangles) as unanswered;
// it has no nearest query of its own, so its adapter takes the nearest of its gather.
#include "Geometry/ProceduralMeshes.h"
#include "Geometry/SweptSphere.h"
#include "Proxy/CandidateCache.h"
#include "Proxy/CollisionScene.h"

#if PROXIMA_WITH_MESH_IO
#include "IO/Mesh/MeshReader.h"
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{
using ObjectTriangle = std::pair<std::uint32_t, std::uint32_t>;

struct SceneNearest
{
  bool found = false;
  std::uint32_t object = 0;
  std::uint32_t triangle = 0;
  double squaredDistance = 0.0;
};

// Lexicographic (object, triangle): the tie rule of every query here.
bool lowerThan(std::uint32_t object, std::uint32_t triangle, std::uint32_t bestObject,
               std::uint32_t bestTriangle)
{
  return object < bestObject || (object == bestObject && triangle < bestTriangle);
}

struct NamedScene
{
  std::string name;
  std::unique_ptr<CollisionScene> scene;
  /// The queries' length scale: proxy radius, sweep lengths and gather distances follow it.
  double radius = 0.0;
};

bool addSoup(CollisionScene& scene, TriangleSoup soup)
{
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(std::move(soup), error))
  {
    return false;
  }
  scene.addObject(std::move(mesh));
  return true;
}

// Every triangle twice (the copy after all the originals): equal contact times everywhere.
TriangleSoup doubled(TriangleSoup soup)
{
  const std::size_t n = soup.triangles.size();
  for (std::size_t t = 0; t < n; ++t)
  {
    soup.triangles.push_back(soup.triangles[t]);
  }
  return soup;
}

TriangleSoup scaled(TriangleSoup soup, double scale)
{
  for (Vec3& p : soup.points)
  {
    p = p * scale;
  }
  return soup;
}

/// A real mesh of the test data (PROXIMA_SHARED_MESHES) at `scale`, read through the IO layer's
/// readers when that layer is built (PROXIMA_BUILD_IO), as a scene of its own with a proxy of a
/// few triangles' size (so that the cache's neighbourhoods fit its capacity). Returns why it
/// could not be read, or an empty string.
std::string addRealScene(std::vector<NamedScene>& made, const char* file, double scale)
{
#if PROXIMA_WITH_MESH_IO
  TriangleSoup soup;
  try
  {
    soup = readMeshFile(std::string(PROXIMA_SHARED_MESHES) + "/" + file);
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  auto scene = std::make_unique<CollisionScene>();
  if (!addSoup(*scene, scaled(std::move(soup), scale)))
  {
    ADD_FAILURE() << file << ": mesh refused";
    return {};
  }
  const double radius = 0.003 * scene->diagonal();
  made.push_back(NamedScene{file, std::move(scene), radius});
  return {};
#else
  (void)made;
  (void)scale;
  return std::string(file) + ": the IO layer is not built";
#endif
}

/// The procedural scenes and the shipped bunny (Data/Meshes: a bunny that cannot be read fails).
const std::vector<NamedScene>& scenes()
{
  static const std::vector<NamedScene> all = [] {
    std::vector<NamedScene> made;
    auto add = [&](const std::string& name, std::vector<TriangleSoup> soups, double radius) {
      auto scene = std::make_unique<CollisionScene>();
      for (TriangleSoup& soup : soups)
      {
        if (!addSoup(*scene, std::move(soup)))
        {
          ADD_FAILURE() << name << ": mesh refused";
          return;
        }
      }
      made.push_back(NamedScene{name, std::move(scene), radius});
    };
    add("icosphere", {makeIcosphere(3, 0.05)}, 0.004);
    add("box-and-grid", {makeBox({0.02, 0.02, 0.01}, {0.0, 0.0, 0.012}), makeGrid(0.1, 40)}, 0.003);
    add("doubled-icosphere", {doubled(makeIcosphere(2, 0.05))}, 0.005);
    add("two-identical-objects", {makeIcosphere(2, 0.05), makeIcosphere(2, 0.05)}, 0.005);
    // CAD slivers: each cap a fan of 62 from one rim point, each side two slivers 10 cm long.
    add("sliver-cylinder", {makeSliverCylinder(64, 0.02, 0.1)}, 0.003);
#if PROXIMA_WITH_MESH_IO
    const std::string missing = addRealScene(made, "stanford-bunny.obj", 0.4);
    if (!missing.empty())
    {
      ADD_FAILURE() << "the bunny is shipped in Data/Meshes: " << missing;
    }
#endif
    return made;
  }();
  return all;
}

/// The shared screw (PROXIMA_SHARED_DATA only: it may not ship), or nothing and why.
const std::vector<NamedScene>& sharedScenes(std::string& missing)
{
  static std::string why;
  static const std::vector<NamedScene> all = [] {
    std::vector<NamedScene> made;
    why = addRealScene(made, "M3x10_screw.stl", 0.005);
    return made;
  }();
  missing = why;
  return all;
}

// Brute force over every triangle of every object. A triangle's bounding box farther than the
// query's reach (with a 1e-6 relative margin) skips the exact test: that changes no answer.
class BruteForce
{
public:
  explicit BruteForce(const CollisionScene& scene)
    : m_scene(scene)
  {
    for (const CollisionObject& object : scene.objects)
    {
      std::vector<Aabb>& boxes = m_boxes.emplace_back();
      for (std::uint32_t t = 0; t < object.mesh.numTriangles(); ++t)
      {
        const TriangleCorners& c = object.mesh.corners(t);
        Aabb& box = boxes.emplace_back();
        box.expand(c.a);
        box.expand(c.b);
        box.expand(c.c);
      }
    }
  }

  SceneContact firstContact(const SweepQuery& q) const
  {
    Aabb reach;
    reach.expand(q.start);
    reach.expand(q.end);
    const double margin = (q.radius + q.skin) * (1.0 + 1e-6) + 1e-12;
    reach.expand(reach.lower, margin);
    reach.expand(reach.upper, margin);
    SceneContact best;
    for (std::uint32_t o = 0; o < m_scene.objects.size(); ++o)
    {
      const TriangleMesh& mesh = m_scene.objects[o].mesh;
      for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
      {
        if (disjoint(m_boxes[o][t], reach))
        {
          continue;
        }
        const SweepResult r =
          sweepSphereTriangleWithSkin(q.start, q.end - q.start, q.radius, q.skin, mesh.corners(t));
        if (r.hit && (!best.hit || r.t < best.t ||
                      (r.t == best.t && lowerThan(o, t, best.object, best.triangle))))
        {
          best = SceneContact{true, r.t, o, t};
        }
      }
    }
    return best;
  }

  std::vector<ObjectTriangle> within(const Vec3& p, double maxDistance) const
  {
    std::vector<ObjectTriangle> found;
    const double limit = maxDistance * maxDistance;
    forEachNear(p, limit, [&](std::uint32_t o, std::uint32_t t, double d2) {
      if (d2 <= limit)
      {
        found.emplace_back(o, t);
      }
    });
    return found;
  }

  SceneNearest nearest(const Vec3& p, double maxDistance) const
  {
    SceneNearest best;
    forEachNear(p, maxDistance * maxDistance, [&](std::uint32_t o, std::uint32_t t, double d2) {
      if (d2 <= maxDistance * maxDistance &&
          (!best.found || d2 < best.squaredDistance ||
           (d2 == best.squaredDistance && lowerThan(o, t, best.object, best.triangle))))
      {
        best = SceneNearest{true, o, t, d2};
      }
    });
    return best;
  }

private:
  template <typename Visit>
  void forEachNear(const Vec3& p, double limitSquared, Visit&& visit) const
  {
    for (std::uint32_t o = 0; o < m_scene.objects.size(); ++o)
    {
      const TriangleMesh& mesh = m_scene.objects[o].mesh;
      for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
      {
        if (boxDistanceSquared(m_boxes[o][t], p) > limitSquared * (1.0 + 1e-6) + 1e-300)
        {
          continue;
        }
        const TriangleCorners& c = mesh.corners(t);
        visit(o, t, closestPointOnTriangle(p, c.a, c.b, c.c).squaredDistance);
      }
    }
  }

  static double boxDistanceSquared(const Aabb& box, const Vec3& p)
  {
    double sum = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double below = box.lower[axis] - p[axis];
      const double above = p[axis] - box.upper[axis];
      const double gap = std::max({0.0, below, above});
      sum += gap * gap;
    }
    return sum;
  }

  static bool disjoint(const Aabb& a, const Aabb& b)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (a.upper[axis] < b.lower[axis] || b.upper[axis] < a.lower[axis])
      {
        return true;
      }
    }
    return false;
  }

  const CollisionScene& m_scene;
  std::vector<std::vector<Aabb>> m_boxes;
};

/// The trees of the scene's objects, queried one object after the other.
class TreeQueries
{
public:
  explicit TreeQueries(const CollisionScene& scene)
    : m_scene(scene)
    , m_scratch(std::make_unique<SphereTreeScratch>())
  {}

  bool firstContact(const SweepQuery& q, SceneContact& out)
  {
    out = SceneContact{};
    for (std::uint32_t o = 0; o < m_scene.objects.size(); ++o)
    {
      const CollisionObject& object = m_scene.objects[o];
      const SweepContact c = object.tree.firstContact(object.mesh, q, *m_scratch);
      // Objects in order, a later one only when strictly earlier: ties stay with the lower.
      if (c.hit && (!out.hit || c.t < out.t))
      {
        out = SceneContact{true, c.t, o, c.triangle};
      }
    }
    return true;
  }

  bool within(const Vec3& p, double maxDistance, std::vector<ObjectTriangle>& out)
  {
    out.clear();
    for (std::uint32_t o = 0; o < m_scene.objects.size(); ++o)
    {
      const CollisionObject& object = m_scene.objects[o];
      NearbyTriangle buffer[CandidateCache::kCapacity];
      const std::uint32_t found = object.tree.gatherWithin(object.mesh, p, maxDistance, buffer,
                                                           CandidateCache::kCapacity, *m_scratch);
      EXPECT_LE(found, CandidateCache::kCapacity);
      for (std::uint32_t i = 0; i < std::min<std::uint32_t>(found, CandidateCache::kCapacity); ++i)
      {
        out.emplace_back(o, buffer[i].triangle);
      }
    }
    return true;
  }

  bool nearest(const Vec3& p, double maxDistance, SceneNearest& out)
  {
    out = SceneNearest{};
    for (std::uint32_t o = 0; o < m_scene.objects.size(); ++o)
    {
      const CollisionObject& object = m_scene.objects[o];
      const NearestTriangle n = object.tree.nearest(object.mesh, p, maxDistance, *m_scratch);
      if (n.found && (!out.found || n.closest.squaredDistance < out.squaredDistance))
      {
        out = SceneNearest{true, o, n.triangle, n.closest.squaredDistance};
      }
    }
    return true;
  }

private:
  const CollisionScene& m_scene;
  std::unique_ptr<SphereTreeScratch> m_scratch;
};

/// The candidate cache, rebuilt around each query with a margin of one radius. With
/// `gatherFirst`, each query first gathers near its point, as the solver's update stage does
/// before its move stage and before the next update stage: a gather a little away keeps
/// separating planes the query may skip triangles by, and for every other sweep a gather at its
/// start keeps the closest points it takes (CandidateCache::gatherWithin, firstContact).
class CacheQueries
{
public:
  explicit CacheQueries(const CollisionScene& scene, bool gatherFirst = false)
    : m_scene(scene)
    , m_scratch(std::make_unique<SphereTreeScratch>())
    , m_cache(std::make_unique<CandidateCache>())
    , m_gatherFirst(gatherFirst)
  {}

  bool firstContact(const SweepQuery& q, SceneContact& out)
  {
    const double sweepReach = q.radius + q.skin;
    const Vec3 middle = (q.start + q.end) * 0.5;
    if (!rebuild(middle, 0.5 * norm(q.end - q.start) + sweepReach + q.radius))
    {
      return false;
    }
    const double covered = m_cache->coveredFraction(q.start, q.end, sweepReach);
    EXPECT_EQ(covered, 1.0);
    if (m_gatherFirst)
    {
      // Within the ball the rebuild covers round the start (a hair inside, for rounding).
      gatherNear(q.start, 0.5 * q.radius, sweepReach + 0.49 * q.radius);
      if (++m_sweeps % 2 == 0)
      {
        gather(q.start, sweepReach + 0.99 * q.radius);
      }
    }
    out = m_cache->firstContact(m_scene, q, covered, m_stats);
    // Again, now that the first answer's triangle is the hint that is tested first: the order
    // must change nothing.
    const SceneContact again = m_cache->firstContact(m_scene, q, covered, m_stats);
    EXPECT_EQ(again.hit, out.hit);
    EXPECT_EQ(again.t, out.t);
    EXPECT_EQ(again.object, out.object);
    EXPECT_EQ(again.triangle, out.triangle);
    return true;
  }

  bool within(const Vec3& p, double maxDistance, std::vector<ObjectTriangle>& out)
  {
    out.clear();
    if (!rebuild(p, 1.5 * maxDistance))
    {
      return false;
    }
    EXPECT_TRUE(m_cache->coversBall(p, maxDistance));
    if (m_gatherFirst)
    {
      gatherNear(p, 0.25 * maxDistance, 1.2 * maxDistance);
    }
    NearbyTriangle buffer[CandidateCache::kCapacity];
    std::uint32_t objects[CandidateCache::kCapacity];
    const std::uint32_t found = m_cache->gatherWithin(m_scene, p, maxDistance, buffer, objects,
                                                      CandidateCache::kCapacity, m_stats);
    EXPECT_LE(found, CandidateCache::kCapacity);
    for (std::uint32_t i = 0; i < std::min<std::uint32_t>(found, CandidateCache::kCapacity); ++i)
    {
      out.emplace_back(objects[i], buffer[i].triangle);
    }
    return true;
  }

  bool nearest(const Vec3& p, double maxDistance, SceneNearest& out)
  {
    out = SceneNearest{};
    if (!rebuild(p, 1.5 * maxDistance))
    {
      return false;
    }
    if (m_gatherFirst)
    {
      gatherNear(p, 0.25 * maxDistance, 1.2 * maxDistance);
    }
    NearbyTriangle buffer[CandidateCache::kCapacity];
    std::uint32_t objects[CandidateCache::kCapacity];
    const std::uint32_t found = m_cache->gatherWithin(m_scene, p, maxDistance, buffer, objects,
                                                      CandidateCache::kCapacity, m_stats);
    for (std::uint32_t i = 0; i < std::min<std::uint32_t>(found, CandidateCache::kCapacity); ++i)
    {
      const double d2 = buffer[i].closest.squaredDistance;
      if (!out.found || d2 < out.squaredDistance ||
          (d2 == out.squaredDistance &&
           lowerThan(objects[i], buffer[i].triangle, out.object, out.triangle)))
      {
        out = SceneNearest{true, objects[i], buffer[i].triangle, d2};
      }
    }
    return true;
  }

private:
  bool rebuild(const Vec3& center, double reach)
  {
    m_cache->rebuild(m_scene, center, reach, *m_scratch, m_stats);
    return m_cache->valid();
  }

  void gather(const Vec3& point, double reach)
  {
    EXPECT_TRUE(m_cache->coversBall(point, reach));
    NearbyTriangle buffer[CandidateCache::kCapacity];
    std::uint32_t objects[CandidateCache::kCapacity];
    m_cache->gatherWithin(m_scene, point, reach, buffer, objects, CandidateCache::kCapacity,
                          m_stats);
  }

  /// A gather within `reach` of a seeded point at most `offset` from `point`.
  void gatherNear(const Vec3& point, double offset, double reach)
  {
    std::normal_distribution<double> gauss;
    const Vec3 direction{gauss(m_random), gauss(m_random), gauss(m_random)};
    const double length = norm(direction);
    const double away = offset * std::uniform_real_distribution<double>(0.0, 1.0)(m_random);
    gather(length > 0.0 ? point + direction * (away / length) : point, reach);
  }

  const CollisionScene& m_scene;
  std::unique_ptr<SphereTreeScratch> m_scratch;
  std::unique_ptr<CandidateCache> m_cache;
  bool m_gatherFirst = false;
  int m_sweeps = 0;
  std::mt19937 m_random{2207};
  QueryStats m_stats;
};

/// The candidate cache with gathers before each query (CacheQueries).
class GatheredCacheQueries : public CacheQueries
{
public:
  explicit GatheredCacheQueries(const CollisionScene& scene)
    : CacheQueries(scene, true)
  {}
};

// Seeded query points: a random point of a random triangle, moved off it in a random direction
// by up to three radii (inside and outside closed meshes alike).
class QueryPoints
{
public:
  QueryPoints(const CollisionScene& scene, double radius, unsigned seed)
    : m_scene(scene)
    , m_radius(radius)
    , m_random(seed)
  {}

  Vec3 point()
  {
    std::uniform_int_distribution<std::uint32_t> pickObject(
      0, static_cast<std::uint32_t>(m_scene.objects.size() - 1));
    const TriangleMesh& mesh = m_scene.objects[pickObject(m_random)].mesh;
    std::uniform_int_distribution<std::uint32_t> pickTriangle(0, mesh.numTriangles() - 1);
    const TriangleCorners& c = mesh.corners(pickTriangle(m_random));
    double u = m_unit(m_random);
    double v = m_unit(m_random);
    if (u + v > 1.0)
    {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const Vec3 onSurface = c.a + (c.b - c.a) * u + (c.c - c.a) * v;
    return onSurface + direction() * (3.0 * m_radius * m_unit(m_random));
  }

  Vec3 direction()
  {
    std::normal_distribution<double> gauss;
    Vec3 d{gauss(m_random), gauss(m_random), gauss(m_random)};
    const double length = norm(d);
    return length > 0.0 ? d / length : Vec3{1.0, 0.0, 0.0};
  }

  double unit() { return m_unit(m_random); }

private:
  const CollisionScene& m_scene;
  double m_radius;
  std::mt19937 m_random;
  std::uniform_real_distribution<double> m_unit{0.0, 1.0};
};

constexpr int kQueriesPerScene = 300;

std::string describe(const SceneContact& c)
{
  return c.hit ? "t " + std::to_string(c.t) + " object " + std::to_string(c.object) + " triangle " +
                   std::to_string(c.triangle)
               : "no hit";
}

template <typename Queries>
class SceneQueries : public ::testing::Test
{};

class ImplementationNames
{
public:
  template <typename T>
  static std::string GetName(int)
  {
    if (std::is_same_v<T, TreeQueries>)
    {
      return "SphereTrees";
    }
    return std::is_same_v<T, GatheredCacheQueries> ? "CandidateCacheAfterGathers"
                                                   : "CandidateCache";
  }
};

using Implementations = ::testing::Types<TreeQueries, CacheQueries, GatheredCacheQueries>;
TYPED_TEST_SUITE(SceneQueries, Implementations, ImplementationNames);

template <typename TypeParam>
void expectFirstContactsMatchBruteForce(const std::vector<NamedScene>& all)
{
  for (const NamedScene& named : all)
  {
    const CollisionScene& scene = *named.scene;
    const BruteForce brute(scene);
    TypeParam queries(scene);
    QueryPoints random(scene, named.radius, 1401);
    int answered = 0;
    int hits = 0;
    int ties = 0;
    for (int i = 0; i < kQueriesPerScene; ++i)
    {
      SweepQuery q;
      q.start = random.point();
      q.end = q.start + random.direction() * (4.0 * named.radius * random.unit());
      q.radius = named.radius * (0.25 + random.unit());
      q.skin = i % 3 == 0 ? 0.0 : 1e-6 * q.radius;
      SceneContact got;
      if (!queries.firstContact(q, got))
      {
        continue;
      }
      ++answered;
      const SceneContact expected = brute.firstContact(q);
      hits += expected.hit ? 1 : 0;
      // A tie: the same contact time on another triangle (a duplicate, or a second object).
      ties +=
        expected.hit && (named.name == "doubled-icosphere" || named.name == "two-identical-objects")
          ? 1
          : 0;
      EXPECT_TRUE(got.hit == expected.hit && got.t == expected.t && got.object == expected.object &&
                  got.triangle == expected.triangle)
        << named.name << " sweep " << i << ": got " << describe(got) << ", brute force "
        << describe(expected);
    }
    std::printf("[ %-8s ] %s: %d of %d answered, %d hits, %d equal-time ties\n", "sweeps",
                named.name.c_str(), answered, kQueriesPerScene, hits, ties);
    EXPECT_GE(answered, kQueriesPerScene / 2) << named.name;
    EXPECT_GT(hits, 0) << named.name;
  }
}

TYPED_TEST(SceneQueries, FirstContactOfASweepMatchesBruteForce)
{
  expectFirstContactsMatchBruteForce<TypeParam>(scenes());
}

TYPED_TEST(SceneQueries, FirstContactOfASweepMatchesBruteForceOnTheSharedScrew)
{
  std::string missing;
  const std::vector<NamedScene>& shared = sharedScenes(missing);
  if (shared.empty())
  {
    GTEST_SKIP() << missing << " (the shared meshes, PROXIMA_SHARED_DATA)";
  }
  expectFirstContactsMatchBruteForce<TypeParam>(shared);
}

template <typename TypeParam>
void expectTrianglesNearAPointMatchBruteForce(const std::vector<NamedScene>& all)
{
  for (const NamedScene& named : all)
  {
    const CollisionScene& scene = *named.scene;
    const BruteForce brute(scene);
    TypeParam queries(scene);
    QueryPoints random(scene, named.radius, 1402);
    int answered = 0;
    int nonEmpty = 0;
    for (int i = 0; i < kQueriesPerScene; ++i)
    {
      const Vec3 p = random.point();
      const double maxDistance = named.radius * (0.5 + 1.5 * random.unit());
      std::vector<ObjectTriangle> got;
      if (!queries.within(p, maxDistance, got))
      {
        continue;
      }
      ++answered;
      std::vector<ObjectTriangle> expected = brute.within(p, maxDistance);
      nonEmpty += expected.empty() ? 0 : 1;
      std::sort(got.begin(), got.end());
      std::sort(expected.begin(), expected.end());
      EXPECT_TRUE(std::adjacent_find(got.begin(), got.end()) == got.end())
        << named.name << " point " << i << ": a triangle listed twice";
      EXPECT_EQ(got, expected) << named.name << " point " << i << ": " << got.size()
                               << " triangles, brute force " << expected.size();
    }
    std::printf("[ %-8s ] %s: %d of %d answered, %d with triangles in reach\n", "gathers",
                named.name.c_str(), answered, kQueriesPerScene, nonEmpty);
    EXPECT_GE(answered, kQueriesPerScene / 2) << named.name;
    EXPECT_GT(nonEmpty, 0) << named.name;
  }
}

TYPED_TEST(SceneQueries, TrianglesNearAPointMatchBruteForce)
{
  expectTrianglesNearAPointMatchBruteForce<TypeParam>(scenes());
}

TYPED_TEST(SceneQueries, TrianglesNearAPointMatchBruteForceOnTheSharedScrew)
{
  std::string missing;
  const std::vector<NamedScene>& shared = sharedScenes(missing);
  if (shared.empty())
  {
    GTEST_SKIP() << missing << " (the shared meshes, PROXIMA_SHARED_DATA)";
  }
  expectTrianglesNearAPointMatchBruteForce<TypeParam>(shared);
}

template <typename TypeParam>
void expectNearestPointsMatchBruteForce(const std::vector<NamedScene>& all)
{
  for (const NamedScene& named : all)
  {
    const CollisionScene& scene = *named.scene;
    const BruteForce brute(scene);
    TypeParam queries(scene);
    QueryPoints random(scene, named.radius, 1403);
    int answered = 0;
    int found = 0;
    for (int i = 0; i < kQueriesPerScene; ++i)
    {
      const Vec3 p = random.point();
      const double maxDistance = named.radius * (0.5 + 2.5 * random.unit());
      SceneNearest got;
      if (!queries.nearest(p, maxDistance, got))
      {
        continue;
      }
      ++answered;
      const SceneNearest expected = brute.nearest(p, maxDistance);
      found += expected.found ? 1 : 0;
      EXPECT_TRUE(got.found == expected.found && got.object == expected.object &&
                  got.triangle == expected.triangle &&
                  got.squaredDistance == expected.squaredDistance)
        << named.name << " point " << i << ": got object " << got.object << " triangle "
        << got.triangle << " at " << std::sqrt(got.squaredDistance) << ", brute force object "
        << expected.object << " triangle " << expected.triangle << " at "
        << std::sqrt(expected.squaredDistance);
    }
    std::printf("[ %-8s ] %s: %d of %d answered, %d found\n", "nearest", named.name.c_str(),
                answered, kQueriesPerScene, found);
    EXPECT_GE(answered, kQueriesPerScene / 2) << named.name;
    EXPECT_GT(found, 0) << named.name;
  }
}

TYPED_TEST(SceneQueries, NearestPointMatchesBruteForce)
{
  expectNearestPointsMatchBruteForce<TypeParam>(scenes());
}

TYPED_TEST(SceneQueries, NearestPointMatchesBruteForceOnTheSharedScrew)
{
  std::string missing;
  const std::vector<NamedScene>& shared = sharedScenes(missing);
  if (shared.empty())
  {
    GTEST_SKIP() << missing << " (the shared meshes, PROXIMA_SHARED_DATA)";
  }
  expectNearestPointsMatchBruteForce<TypeParam>(shared);
}

} // namespace
} // namespace proxima

namespace proxima
{
namespace
{
// The candidate cache reads each triangle's filter record made when the object was built
// (TriangleFilter.h). A record must bound its triangle, and a cache over an object without
// records (made then from the corners) must answer every sweep the same, bit for bit.
TEST(TriangleFilterRecords, BoundTheirTrianglesAndAnswerAsRecordsMadeFromTheCorners)
{
  CollisionScene recorded;
  ASSERT_TRUE(addSoup(recorded, makeSliverCylinder(48, 0.01, 0.05)));
  const CollisionObject& object = recorded.objects.front();
  ASSERT_EQ(object.filters.size(), object.mesh.numTriangles());
  for (std::uint32_t t = 0; t < object.mesh.numTriangles(); ++t)
  {
    const TriangleFilter& filter = object.filters[t];
    const TriangleCorners& c = object.mesh.corners(t);
    for (const Vec3& corner : {c.a, c.b, c.c})
    {
      EXPECT_LE(distance(corner, filter.centroid), filter.radius);
      EXPECT_LE(std::fabs(dot(filter.normal, corner) - filter.offset), filter.planeSlack);
    }
  }
  auto bare = std::make_shared<CollisionObject>(object);
  bare->filters.clear();
  CollisionScene computed;
  computed.addObject(bare);

  std::mt19937 random(7);
  std::uniform_real_distribution<double> along(-0.03, 0.03);
  QueryStats stats;
  SphereTreeScratch scratch;
  auto withRecords = std::make_unique<CandidateCache>();
  auto withoutRecords = std::make_unique<CandidateCache>();
  int hits = 0;
  for (int k = 0; k < 400; ++k)
  {
    const Vec3 center{along(random) * 0.5, along(random) * 0.5, along(random)};
    withRecords->rebuild(recorded, center, 0.006, scratch, stats);
    withoutRecords->rebuild(computed, center, 0.006, scratch, stats);
    ASSERT_EQ(withRecords->valid(), withoutRecords->valid());
    ASSERT_EQ(withRecords->size(), withoutRecords->size());
    if (!withRecords->valid())
    {
      continue;
    }
    SweepQuery query;
    query.start = center;
    query.end = center + Vec3{along(random), along(random), along(random)} * 0.1;
    query.radius = 0.002;
    query.skin = 1e-7;
    const double covered = withRecords->coveredFraction(query.start, query.end, 0.0021);
    if (covered <= 0.0)
    {
      continue;
    }
    const SceneContact a = withRecords->firstContact(recorded, query, covered, stats);
    const SceneContact b = withoutRecords->firstContact(computed, query, covered, stats);
    EXPECT_EQ(a.hit, b.hit);
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.triangle, b.triangle);
    hits += a.hit ? 1 : 0;
  }
  EXPECT_GT(hits, 10); // the sweeps met the cylinder, not only empty space
}
} // namespace
} // namespace proxima
