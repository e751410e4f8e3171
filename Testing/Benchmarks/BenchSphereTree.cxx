// The sphere tree's build and its three queries (firstContact, nearest, gatherWithin) at haptic
// scale, beside CGAL's AABB tree on the same queries in the same run.
//
// Meshes: icospheres of 20k, 330k and 1.3M triangles (makeIcosphere 5, 7, 8) scaled so the median
// edge is 0.5 mm, and the 1.5M-triangle CT skull of the shared data (binary PLY, millimetres,
// scaled to metres). Queries (4096 per mesh, fixed seed, precomputed): a proxy of radius 1 mm
// starting 1 to 1.5 radii off a random point of the surface, moving up to 1 mm (half of them
// towards the surface); nearest queries at the same start points; gather queries (radius
// 1.01 mm, the constraint planes of the update stage) at 0.9 to 1 radius off the surface, where a
// move stage leaves the proxy.
//
// Besides Google Benchmark's mean time per query, each query benchmark reports the per-query
// median and 99th percentile (counters median_ns, p99_ns), timed one by one after the main loop
// with the clock's own overhead subtracted, and the work done (nodes visited, triangles tested).
//
// CGAL has no swept-sphere query. Its fairest equivalent here is CGAL as the broad phase and our
// exact per-triangle test as the narrow phase: the AABB tree returns every triangle meeting the
// bounding box of the capsule swept by the sphere, and sweepSphereTriangle picks the earliest
// contact among them, which is exactly what our tree does below its leaves. Likewise gather is
// all_intersected_primitives with the sphere's bounding box followed by the same distance filter,
// and nearest is CGAL's own closest_point_and_primitive (with its accelerating k-d tree).
#include "Geometry/ClosestPoint.h"
#include "Geometry/ProceduralMeshes.h"
#include "Geometry/SphereTree.h"
#include "Geometry/SweptSphere.h"
#include "Geometry/TriangleMesh.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#ifndef PROXIMA_SHARED_MESHES
#define PROXIMA_SHARED_MESHES "../shared/data/meshes"
#endif

namespace proxima
{
namespace
{

using Kernel = CGAL::Simple_cartesian<double>;
using CgalTriangles = std::vector<Kernel::Triangle_3>;
using CgalPrimitive = CGAL::AABB_triangle_primitive<Kernel, CgalTriangles::const_iterator>;
using CgalTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CgalPrimitive>>;

constexpr double kProxyRadius = 1e-3;  // 1 mm
constexpr double kMaxSegment = 1e-3;   // segments up to 1 mm per query
constexpr double kTargetEdge = 0.5e-3; // icosphere median edge
constexpr int kNumQueries = 4096;
constexpr std::uint64_t kSeed = 0xbe9c4001;

struct Dataset
{
  std::string name;
  TriangleMesh mesh;
  SphereTree tree;
  CgalTriangles cgalTriangles;
  std::unique_ptr<CgalTree> cgalTree;
  std::vector<SweepQuery> sweeps;
  std::vector<Vec3> points;       // nearest: where the proxy starts, 1 to 1.5 radii off
  std::vector<Vec3> gatherPoints; // gather: where a move stopped, 0.9 to 1 radius off
  std::string error;
};

double medianEdge(const TriangleSoup& soup)
{
  std::vector<double> edges;
  edges.reserve(soup.triangles.size() * 3);
  for (const auto& t : soup.triangles)
  {
    for (int i = 0; i < 3; ++i)
    {
      edges.push_back(distance(soup.points[t[i]], soup.points[t[(i + 1) % 3]]));
    }
  }
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  return edges[edges.size() / 2];
}

/// Binary little-endian PLY as VTK writes it: float x y z, then a face list of uchar/int.
bool readBinaryPly(const std::string& path, double scale, TriangleSoup& soup, std::string& error)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    error = "cannot open " + path;
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(file)),
                                std::istreambuf_iterator<char>());
  const std::string head(bytes.data(), std::min<std::size_t>(bytes.size(), 4096));
  const auto end = head.find("end_header\n");
  std::size_t numVertices = 0;
  std::size_t numFaces = 0;
  if (head.rfind("ply", 0) != 0 || end == std::string::npos ||
      head.find("format binary_little_endian 1.0") == std::string::npos ||
      std::sscanf(head.c_str() + head.find("element vertex"), "element vertex %zu", &numVertices) !=
        1 ||
      std::sscanf(head.c_str() + head.find("element face"), "element face %zu", &numFaces) != 1 ||
      head.find("property list uchar int vertex_indices") == std::string::npos)
  {
    error = path + ": not the binary PLY layout this reader handles";
    return false;
  }
  std::size_t offset = end + std::strlen("end_header\n");
  if (bytes.size() < offset + numVertices * 12)
  {
    error = path + ": truncated";
    return false;
  }
  soup.points.resize(numVertices);
  for (std::size_t v = 0; v < numVertices; ++v, offset += 12)
  {
    float xyz[3];
    std::memcpy(xyz, bytes.data() + offset, 12);
    soup.points[v] = Vec3{xyz[0], xyz[1], xyz[2]} * scale;
  }
  soup.triangles.reserve(numFaces);
  for (std::size_t f = 0; f < numFaces; ++f)
  {
    if (offset + 13 > bytes.size() || bytes[offset] != 3)
    {
      error = path + ": face " + std::to_string(f) + " is not a triangle or is truncated";
      return false;
    }
    std::uint32_t index[3];
    std::memcpy(index, bytes.data() + offset + 1, 12);
    offset += 13;
    soup.triangles.push_back({index[0], index[1], index[2]});
  }
  return true;
}

void makeQueries(Dataset& d)
{
  std::mt19937_64 engine(kSeed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss;
  auto direction = [&] {
    return normalizedOrZero(Vec3{gauss(engine), gauss(engine), gauss(engine)});
  };
  const Vec3 center = d.mesh.bounds().center();
  const bool closedSphere = d.name.rfind("icosphere", 0) == 0;
  std::uniform_int_distribution<std::uint32_t> pick(0, d.mesh.numTriangles() - 1);
  while (d.points.size() < kNumQueries)
  {
    const TriangleCorners& c = d.mesh.corners(pick(engine));
    Vec3 n = normalizedOrZero(cross(c.b - c.a, c.c - c.a));
    if (n == Vec3{})
    {
      continue;
    }
    double u = unit(engine);
    double v = unit(engine);
    if (u + v > 1.0)
    {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const Vec3 onSurface = c.a + (c.b - c.a) * u + (c.c - c.a) * v;
    // Outside the icospheres; either side of the open, thin-walled skull.
    if (closedSphere ? dot(n, onSurface - center) < 0.0 : unit(engine) < 0.5)
    {
      n = -n;
    }
    const Vec3 start = onSurface + n * (kProxyRadius * (1.0 + 0.5 * unit(engine)));
    Vec3 heading = direction();
    if (unit(engine) < 0.5)
    {
      heading = normalizedOrZero(heading - n * 1.5); // towards the surface, at a random slant
    }
    SweepQuery q;
    q.start = start;
    q.end = start + heading * (kMaxSegment * unit(engine));
    q.radius = kProxyRadius;
    d.sweeps.push_back(q);
    d.points.push_back(start);
    d.gatherPoints.push_back(onSurface + n * (kProxyRadius * (0.9 + 0.1 * unit(engine))));
  }
}

Dataset* loadDataset(const std::string& name)
{
  static std::map<std::string, std::unique_ptr<Dataset>> cache;
  auto& slot = cache[name];
  if (slot)
  {
    return slot.get();
  }
  slot = std::make_unique<Dataset>();
  Dataset& d = *slot;
  d.name = name;
  TriangleSoup soup;
  if (name == "skull")
  {
    if (!readBinaryPly(std::string(PROXIMA_SHARED_MESHES) + "/cranium_bone_iso075mm.ply", 1e-3,
                       soup, d.error))
    {
      return slot.get();
    }
  }
  else
  {
    const auto subdivisions = static_cast<std::uint32_t>(std::stoi(name.substr(name.size() - 1)));
    soup = makeIcosphere(subdivisions, 1.0);
    const double scale = kTargetEdge / medianEdge(soup);
    for (Vec3& p : soup.points)
    {
      p *= scale;
    }
  }
  MeshError error;
  if (!d.mesh.build(std::move(soup), error))
  {
    d.error = name + ": " + error.message;
    return slot.get();
  }
  d.tree.build(d.mesh);
  d.cgalTriangles.reserve(d.mesh.numTriangles());
  for (std::uint32_t t = 0; t < d.mesh.numTriangles(); ++t)
  {
    const TriangleCorners& c = d.mesh.corners(t);
    d.cgalTriangles.emplace_back(Kernel::Point_3(c.a.x, c.a.y, c.a.z),
                                 Kernel::Point_3(c.b.x, c.b.y, c.b.z),
                                 Kernel::Point_3(c.c.x, c.c.y, c.c.z));
  }
  d.cgalTree = std::make_unique<CgalTree>(d.cgalTriangles.begin(), d.cgalTriangles.end());
  d.cgalTree->build();
  d.cgalTree->accelerate_distance_queries();
  makeQueries(d);
  return slot.get();
}

/// Median and 99th percentile of per-query times, each query timed alone, minus the clock's own
/// median cost (measured the same way around nothing).
template <class Query>
void reportLatency(benchmark::State& state, std::size_t numQueries, Query&& query)
{
  using Clock = std::chrono::steady_clock;
  std::vector<double> emptyNs(numQueries);
  std::vector<double> queryNs(numQueries);
  for (int pass = 0; pass < 2; ++pass) // the first pass warms the caches as the main loop did
  {
    for (std::size_t i = 0; i < numQueries; ++i)
    {
      const auto t0 = Clock::now();
      const auto t1 = Clock::now();
      query(i);
      const auto t2 = Clock::now();
      emptyNs[i] = std::chrono::duration<double, std::nano>(t1 - t0).count();
      queryNs[i] = std::chrono::duration<double, std::nano>(t2 - t1).count();
    }
  }
  auto quantile = [](std::vector<double> v, double q) {
    const auto k = static_cast<std::ptrdiff_t>(q * double(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[static_cast<std::size_t>(k)];
  };
  const double clock = quantile(emptyNs, 0.5);
  state.counters["median_ns"] = std::max(0.0, quantile(queryNs, 0.5) - clock);
  state.counters["p99_ns"] = std::max(0.0, quantile(queryNs, 0.99) - clock);
}

Dataset* datasetOrSkip(benchmark::State& state, const std::string& name)
{
  Dataset* d = loadDataset(name);
  if (!d->error.empty())
  {
    state.SkipWithError(d->error.c_str());
    return nullptr;
  }
  return d;
}

// ---- build ----------------------------------------------------------------------------------

void buildSphereTree(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  for (auto _ : state)
  {
    SphereTree tree;
    tree.build(d->mesh);
    benchmark::DoNotOptimize(tree.numNodes());
  }
  state.counters["triangles"] = d->mesh.numTriangles();
  state.counters["bytes_per_triangle"] = double(d->tree.memoryBytes()) / d->mesh.numTriangles();
  state.counters["leaf_spheres"] = d->tree.numLeafSpheres();
  state.counters["depth"] = d->tree.depth();
}

// A deforming surface (issue 35): the tree built once with one sphere per triangle, then refit
// after each simulation step moves the points (target: at most 200 us for 20,000 triangles). The
// refit's margin is a tenth of a median edge, as a deforming object's (Proxy/DeformingObjects),
// except where every sphere is remade (0). Timed: the refit alone; `move_points_us` is
// TriangleMesh::movePoints, which a step pays as well.
// How the surface moves between two refits (the benchmark's first argument).
enum class RefitMotion
{
  // Every point two median edges back and forth: every sphere is made again.
  everySphereRemade = 0,
  // Every point a hundredth of an edge a step, along a direction that turns slowly: the whole
  // surface drifts, and each sphere's slack runs out in its turn.
  drift = 1,
  // A finger's press on an elastic body: a dent three edges wide whose depth swings between 0 and
  // six edges once every 200 steps (a second at a 200 Hz solid) while it slides a twentieth of an
  // edge a step round the sphere. Each point moves along the press by the dent's width over its
  // distance from the dent (the 1/r of Boussinesq's point load on a half-space), so the whole
  // surface moves a little every step and the spheres near the dent a lot.
  press = 2,
  // Nothing moves: a tissue at rest between its simulation steps.
  rest = 3,
};

void refitSphereTree(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  const auto motion = static_cast<RefitMotion>(state.range(0));
  TriangleMesh mesh = d->mesh;
  SphereTreeOptions options;
  options.leafSizeFactor = 0.0;
  SphereTree tree;
  tree.build(mesh, options);
  const std::vector<Vec3> rest = mesh.points();
  std::vector<Vec3> moved = rest;
  double edge = 0.0;
  {
    std::vector<double> edges;
    for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
    {
      edges.push_back(distance(mesh.corners(t).a, mesh.corners(t).b));
    }
    std::nth_element(edges.begin(), edges.begin() + std::ptrdiff_t(edges.size() / 2), edges.end());
    edge = edges[edges.size() / 2];
  }
  const Vec3 sphereCenter = mesh.bounds().center();
  const double sphereRadius = norm(rest.front() - sphereCenter);
  const double margin = motion == RefitMotion::everySphereRemade ? 0.0 : 0.1 * edge;
  double movingNs = 0.0;
  std::int64_t step = 0;
  for (auto _ : state)
  {
    state.PauseTiming();
    const auto before = std::chrono::steady_clock::now();
    ++step;
    if (motion == RefitMotion::everySphereRemade)
    {
      const Vec3 shift{(step % 2 == 0 ? 2.0 : -2.0) * edge, 0.0, 0.0};
      for (std::size_t i = 0; i < moved.size(); ++i)
      {
        moved[i] = rest[i] + shift;
      }
    }
    else if (motion == RefitMotion::drift)
    {
      const Vec3 shift =
        Vec3{std::cos(0.01 * double(step)), std::sin(0.01 * double(step)), 0.0} * (0.01 * edge);
      for (Vec3& point : moved)
      {
        point = point + shift;
      }
    }
    else if (motion == RefitMotion::press)
    {
      const double angle = 0.05 * edge / sphereRadius * double(step);
      const Vec3 along{std::cos(angle), std::sin(angle), 0.0};
      const Vec3 dent = sphereCenter + along * sphereRadius;
      const double width = 3.0 * edge;
      const double depth =
        3.0 * edge * (1.0 - std::cos(2.0 * std::numbers::pi * double(step) / 200.0));
      for (std::size_t i = 0; i < moved.size(); ++i)
      {
        moved[i] = rest[i] - along * (depth * width / std::max(distance(rest[i], dent), width));
      }
    }
    mesh.movePoints(moved.data(), moved.size());
    movingNs +=
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - before).count();
    state.ResumeTiming();
    tree.refit(mesh, margin);
    benchmark::DoNotOptimize(tree.nodes().data());
  }
  state.counters["triangles"] = mesh.numTriangles();
  state.counters["move_points_us"] = step > 0 ? movingNs / double(step) / 1e3 : 0.0;
}

void buildCgalTree(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  for (auto _ : state)
  {
    CgalTree tree(d->cgalTriangles.begin(), d->cgalTriangles.end());
    tree.build();
    tree.accelerate_distance_queries();
    benchmark::DoNotOptimize(tree.size());
  }
  state.counters["triangles"] = d->mesh.numTriangles();
}

// ---- firstContact -------------------------------------------------------------------------

void sweepSphereTree(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  auto scratch = std::make_unique<SphereTreeScratch>();
  QueryStats stats;
  std::size_t i = 0;
  std::size_t hits = 0;
  for (auto _ : state)
  {
    const SweepContact c = d->tree.firstContact(d->mesh, d->sweeps[i], *scratch, &stats);
    hits += c.hit ? 1 : 0;
    benchmark::DoNotOptimize(c);
    i = (i + 1) % d->sweeps.size();
  }
  const auto n = double(state.iterations());
  state.counters["nodes_visited"] = stats.nodesVisited / n;
  state.counters["triangles_tested"] = stats.trianglesTested / n;
  state.counters["hit_fraction"] = double(hits) / n;
  reportLatency(state, d->sweeps.size(), [&](std::size_t k) {
    benchmark::DoNotOptimize(d->tree.firstContact(d->mesh, d->sweeps[k], *scratch));
  });
}

/// CGAL broad phase (box of the swept capsule), our exact narrow phase; see the file comment.
SweepContact cgalFirstContact(const Dataset& d, const SweepQuery& q,
                              std::vector<CgalPrimitive::Id>& candidates)
{
  const double reach = q.radius + q.skin;
  const Vec3 lower = componentMin(q.start, q.end) - Vec3{reach, reach, reach};
  const Vec3 upper = componentMax(q.start, q.end) + Vec3{reach, reach, reach};
  candidates.clear();
  d.cgalTree->all_intersected_primitives(
    CGAL::Bbox_3(lower.x, lower.y, lower.z, upper.x, upper.y, upper.z),
    std::back_inserter(candidates));
  SweepContact best;
  const Vec3 motion = q.end - q.start;
  for (const auto& id : candidates)
  {
    const auto t = static_cast<std::uint32_t>(id - d.cgalTriangles.begin());
    const SweepResult r =
      sweepSphereTriangleWithSkin(q.start, motion, q.radius, q.skin, d.mesh.corners(t));
    if (r.hit && (!best.hit || r.t < best.t || (r.t == best.t && t < best.triangle)))
    {
      best.hit = true;
      best.t = r.t;
      best.triangle = t;
    }
  }
  return best;
}

void sweepCgal(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  std::vector<CgalPrimitive::Id> candidates;
  candidates.reserve(1024);
  // Same answers as the sphere tree, or the comparison means nothing.
  auto scratch = std::make_unique<SphereTreeScratch>();
  for (const SweepQuery& q : d->sweeps)
  {
    const SweepContact ours = d->tree.firstContact(d->mesh, q, *scratch);
    const SweepContact theirs = cgalFirstContact(*d, q, candidates);
    if (ours.hit != theirs.hit || ours.t != theirs.t)
    {
      state.SkipWithError("CGAL and the sphere tree disagree on a sweep");
      return;
    }
  }
  std::size_t i = 0;
  double numCandidates = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(cgalFirstContact(*d, d->sweeps[i], candidates));
    numCandidates += double(candidates.size());
    i = (i + 1) % d->sweeps.size();
  }
  state.counters["triangles_tested"] = numCandidates / double(state.iterations());
  reportLatency(state, d->sweeps.size(), [&](std::size_t k) {
    benchmark::DoNotOptimize(cgalFirstContact(*d, d->sweeps[k], candidates));
  });
}

// ---- nearest ------------------------------------------------------------------------------

void nearestSphereTree(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  auto scratch = std::make_unique<SphereTreeScratch>();
  QueryStats stats;
  const double unlimited = std::numeric_limits<double>::infinity();
  std::size_t i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(d->tree.nearest(d->mesh, d->points[i], unlimited, *scratch, &stats));
    i = (i + 1) % d->points.size();
  }
  const auto n = double(state.iterations());
  state.counters["nodes_visited"] = stats.nodesVisited / n;
  state.counters["triangles_tested"] = stats.trianglesTested / n;
  reportLatency(state, d->points.size(), [&](std::size_t k) {
    benchmark::DoNotOptimize(d->tree.nearest(d->mesh, d->points[k], unlimited, *scratch));
  });
}

void nearestCgal(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  auto query = [&](std::size_t k) {
    const Vec3& p = d->points[k];
    return d->cgalTree->closest_point_and_primitive(Kernel::Point_3(p.x, p.y, p.z));
  };
  auto scratch = std::make_unique<SphereTreeScratch>();
  for (std::size_t k = 0; k < d->points.size(); ++k)
  {
    const auto theirs = query(k);
    const NearestTriangle ours =
      d->tree.nearest(d->mesh, d->points[k], std::numeric_limits<double>::infinity(), *scratch);
    const Vec3 q{theirs.first.x(), theirs.first.y(), theirs.first.z()};
    if (std::fabs(distance(q, d->points[k]) - std::sqrt(ours.closest.squaredDistance)) >
        1e-12 + 1e-9 * kProxyRadius)
    {
      state.SkipWithError("CGAL and the sphere tree disagree on a nearest point");
      return;
    }
  }
  std::size_t i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(query(i));
    i = (i + 1) % d->points.size();
  }
  reportLatency(state, d->points.size(),
                [&](std::size_t k) { benchmark::DoNotOptimize(query(k)); });
}

// ---- gatherWithin -------------------------------------------------------------------------

constexpr double kGatherDistance = kProxyRadius * 1.01; // constraint planes within r + epsilon

std::uint32_t treeGather(const Dataset& d, const Vec3& p, std::vector<NearbyTriangle>& out,
                         SphereTreeScratch& scratch, QueryStats* stats)
{
  return d.tree.gatherWithin(d.mesh, p, kGatherDistance, out.data(),
                             static_cast<std::uint32_t>(out.size()), scratch, stats);
}

/// CGAL broad phase (the sphere's bounding box), the same exact distance filter as the tree.
std::uint32_t cgalGather(const Dataset& d, const Vec3& p,
                         std::vector<CgalPrimitive::Id>& candidates,
                         std::vector<NearbyTriangle>& out)
{
  const Vec3 reach{kGatherDistance, kGatherDistance, kGatherDistance};
  const Vec3 lower = p - reach;
  const Vec3 upper = p + reach;
  candidates.clear();
  d.cgalTree->all_intersected_primitives(
    CGAL::Bbox_3(lower.x, lower.y, lower.z, upper.x, upper.y, upper.z),
    std::back_inserter(candidates));
  std::uint32_t found = 0;
  const double limit = kGatherDistance * kGatherDistance;
  for (const auto& id : candidates)
  {
    const auto t = static_cast<std::uint32_t>(id - d.cgalTriangles.begin());
    const TriangleCorners& c = d.mesh.corners(t);
    const ClosestPointResult r = closestPointOnTriangle(p, c.a, c.b, c.c);
    if (r.squaredDistance <= limit)
    {
      if (found < out.size())
      {
        out[found] = NearbyTriangle{t, r};
      }
      ++found;
    }
  }
  return found;
}

void gatherSphereTree(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  auto scratch = std::make_unique<SphereTreeScratch>();
  std::vector<NearbyTriangle> out(4096);
  QueryStats stats;
  std::size_t i = 0;
  double found = 0;
  for (auto _ : state)
  {
    found += treeGather(*d, d->gatherPoints[i], out, *scratch, &stats);
    i = (i + 1) % d->gatherPoints.size();
  }
  const auto n = double(state.iterations());
  state.counters["nodes_visited"] = stats.nodesVisited / n;
  state.counters["triangles_tested"] = stats.trianglesTested / n;
  state.counters["found"] = found / n;
  reportLatency(state, d->gatherPoints.size(), [&](std::size_t k) {
    benchmark::DoNotOptimize(treeGather(*d, d->gatherPoints[k], out, *scratch, nullptr));
  });
}

void gatherCgal(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  std::vector<CgalPrimitive::Id> candidates;
  candidates.reserve(1024);
  std::vector<NearbyTriangle> out(4096);
  std::size_t i = 0;
  double numCandidates = 0;
  double found = 0;
  for (auto _ : state)
  {
    found += cgalGather(*d, d->gatherPoints[i], candidates, out);
    numCandidates += double(candidates.size());
    i = (i + 1) % d->gatherPoints.size();
  }
  const auto n = double(state.iterations());
  state.counters["triangles_tested"] = numCandidates / n;
  state.counters["found"] = found / n;
  reportLatency(state, d->gatherPoints.size(), [&](std::size_t k) {
    benchmark::DoNotOptimize(cgalGather(*d, d->gatherPoints[k], candidates, out));
  });
}

// ---- narrow phase alone ---------------------------------------------------------------------
// The per-triangle tests below the leaves, on the (query, triangle) pairs near each query (the
// CGAL box candidates): with triangles_tested above, this splits a query's time into the exact
// tests and the traversal.

struct NearPairs
{
  std::vector<std::uint32_t> query;
  std::vector<std::uint32_t> triangle;
};

NearPairs nearPairs(const Dataset& d)
{
  NearPairs pairs;
  std::vector<CgalPrimitive::Id> candidates;
  for (std::uint32_t k = 0; k < d.sweeps.size(); ++k)
  {
    cgalFirstContact(d, d.sweeps[k], candidates);
    for (const auto& id : candidates)
    {
      pairs.query.push_back(k);
      pairs.triangle.push_back(static_cast<std::uint32_t>(id - d.cgalTriangles.begin()));
    }
  }
  return pairs;
}

void narrowSweep(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  const NearPairs pairs = nearPairs(*d);
  std::size_t i = 0;
  for (auto _ : state)
  {
    const SweepQuery& q = d->sweeps[pairs.query[i]];
    benchmark::DoNotOptimize(sweepSphereTriangleWithSkin(q.start, q.end - q.start, q.radius, q.skin,
                                                         d->mesh.corners(pairs.triangle[i])));
    i = (i + 1) % pairs.query.size();
  }
}

void narrowClosest(benchmark::State& state, const std::string& name)
{
  Dataset* d = datasetOrSkip(state, name);
  if (d == nullptr)
  {
    return;
  }
  const NearPairs pairs = nearPairs(*d);
  std::size_t i = 0;
  for (auto _ : state)
  {
    const TriangleCorners& c = d->mesh.corners(pairs.triangle[i]);
    benchmark::DoNotOptimize(closestPointOnTriangle(d->points[pairs.query[i]], c.a, c.b, c.c));
    i = (i + 1) % pairs.query.size();
  }
}

} // namespace
} // namespace proxima

int main(int argc, char** argv)
{
  using namespace proxima;
  // Registration order is run order: every benchmark of one mesh before the next mesh, so at
  // most the meshes seen so far are in memory, and each pair (ours, CGAL) runs back to back.
  const char* meshes[] = {"icosphere5", "icosphere7", "icosphere8", "skull"};
  for (const char* mesh : meshes)
  {
    const std::string name(mesh);
    benchmark::RegisterBenchmark(("Build/SphereTree/" + name).c_str(), buildSphereTree, name)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(name == "icosphere5" ? 20 : 3);
    benchmark::RegisterBenchmark(("Build/CgalAabb/" + name).c_str(), buildCgalTree, name)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(name == "icosphere5" ? 20 : 3);
    if (name == "icosphere5")
    {
      benchmark::RegisterBenchmark(("Refit/SphereTree/" + name).c_str(), refitSphereTree, name)
        ->Unit(benchmark::kMicrosecond)
        ->ArgName("motion")
        ->DenseRange(0, 3);
    }
    benchmark::RegisterBenchmark(("FirstContact/SphereTree/" + name).c_str(), sweepSphereTree, name)
      ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("FirstContact/CgalAabb/" + name).c_str(), sweepCgal, name)
      ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("Nearest/SphereTree/" + name).c_str(), nearestSphereTree, name)
      ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("Nearest/CgalAabb/" + name).c_str(), nearestCgal, name)
      ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("GatherWithin/SphereTree/" + name).c_str(), gatherSphereTree,
                                 name)
      ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("GatherWithin/CgalAabb/" + name).c_str(), gatherCgal, name)
      ->Unit(benchmark::kNanosecond);
    if (name == "icosphere8")
    {
      benchmark::RegisterBenchmark(("NarrowPhase/SweepSphereTriangle/" + name).c_str(), narrowSweep,
                                   name)
        ->Unit(benchmark::kNanosecond);
      benchmark::RegisterBenchmark(("NarrowPhase/ClosestPointOnTriangle/" + name).c_str(),
                                   narrowClosest, name)
        ->Unit(benchmark::kNanosecond);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
