#include "IO/MeshInspection/MeshInspection.h"

#include "IO/MeshInspection/Private/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstring>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace proxima
{
namespace
{
struct PositionKey
{
  std::uint64_t bits[3];
  bool operator==(const PositionKey& other) const
  {
    return bits[0] == other.bits[0] && bits[1] == other.bits[1] && bits[2] == other.bits[2];
  }
};

struct PositionHash
{
  std::size_t operator()(const PositionKey& key) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint64_t word : key.bits)
    {
      h = (h ^ word) * 1099511628211ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }
};

// Identical coordinates, with -0 and +0 the same.
PositionKey keyOf(const Vec3& p)
{
  PositionKey key{};
  const double coordinates[3] = {p.x == 0.0 ? 0.0 : p.x, p.y == 0.0 ? 0.0 : p.y,
                                 p.z == 0.0 ? 0.0 : p.z};
  std::memcpy(key.bits, coordinates, sizeof coordinates);
  return key;
}

struct EdgeUse
{
  std::uint32_t count = 0;
  /// +1 for each use from the smaller vertex to the larger, -1 for the other way.
  int direction = 0;
  bool reported = false;
};

// The angle at `a` between the edges to `b` and `c`, in degrees.
double angleDegrees(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 u = b - a;
  const Vec3 v = c - a;
  constexpr double kDegrees = 57.29577951308232;
  return std::atan2(norm(cross(u, v)), dot(u, v)) * kDegrees;
}

double smallestAngleDegrees(const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
  return std::min({angleDegrees(p0, p1, p2), angleDegrees(p1, p2, p0), angleDegrees(p2, p0, p1)});
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b)
{
  return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}

void note(DefectCount& defect, std::uint32_t triangle, const Vec3& point, std::size_t kept)
{
  ++defect.count;
  if (defect.first.size() < kept)
  {
    defect.first.push_back({triangle, point});
  }
}

void noteEdge(DefectCount& defect, std::uint32_t triangle, const Vec3& a, const Vec3& b,
              std::size_t kept)
{
  ++defect.count;
  if (defect.first.size() < kept)
  {
    defect.first.push_back({triangle, (a + b) * 0.5, 0, a, b});
  }
}
} // namespace

std::vector<std::uint32_t> mergeIdenticalCorners(const TriangleSoup& soup, std::size_t& vertexCount)
{
  std::unordered_map<PositionKey, std::uint32_t, PositionHash> vertexOf;
  vertexOf.reserve(soup.points.size());
  std::vector<std::uint32_t> vertexOfPoint(soup.points.size());
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    const auto [it, added] =
      vertexOf.try_emplace(keyOf(soup.points[i]), static_cast<std::uint32_t>(vertexOf.size()));
    vertexOfPoint[i] = it->second;
  }
  vertexCount = vertexOf.size();
  return vertexOfPoint;
}

MeshInspection inspectMesh(const TriangleSoup& soup, const MeshInspectionOptions& options)
{
  const auto progress = [&options](double done) {
    if (options.progress)
    {
      options.progress(done);
    }
  };
  const std::size_t kept = options.locationsKept;
  MeshInspection report;
  report.triangles = soup.triangles.size();

  // Corners on identical coordinates are one vertex.
  std::size_t vertexCount = 0;
  const std::vector<std::uint32_t> vertexOfPoint = mergeIdenticalCorners(soup, vertexCount);
  std::vector<Vec3> vertexPosition(vertexCount);
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    vertexPosition[vertexOfPoint[i]] = soup.points[i];
  }
  progress(0.2);

  std::vector<std::array<std::uint32_t, 3>> corners(soup.triangles.size());
  std::vector<bool> used(vertexPosition.size(), false);
  std::vector<bool> collapsed(soup.triangles.size(), false);
  // The same three vertices in any order: the sorted triple, compared whole.
  std::unordered_set<PositionKey, PositionHash> triples;
  triples.reserve(soup.triangles.size());
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(soup.triangles.size() * 2);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const auto triangle = static_cast<std::uint32_t>(t);
    std::array<std::uint32_t, 3> c{};
    for (int k = 0; k < 3; ++k)
    {
      c[k] = vertexOfPoint[soup.triangles[t][k]];
    }
    corners[t] = c;
    const Vec3& p0 = vertexPosition[c[0]];
    const Vec3& p1 = vertexPosition[c[1]];
    const Vec3& p2 = vertexPosition[c[2]];
    const Vec3 centroid = (p0 + p1 + p2) / 3.0;
    std::array<std::uint32_t, 3> sorted = c;
    std::sort(sorted.begin(), sorted.end());
    if (!triples.insert(PositionKey{{sorted[0], sorted[1], sorted[2]}}).second)
    {
      note(report.duplicateTriangles, triangle, centroid, kept);
    }
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
    {
      // Two corners on one vertex: a collapsed triangle has no edges and joins nothing.
      collapsed[t] = true;
      note(report.collapsedTriangles, triangle, centroid, kept);
      continue;
    }
    if (norm(cross(p1 - p0, p2 - p0)) == 0.0)
    {
      note(report.zeroAreaTriangles, triangle, centroid, kept);
    }
    else if (smallestAngleDegrees(p0, p1, p2) < options.sliverAngleDegrees)
    {
      note(report.sliverTriangles, triangle, centroid, kept);
    }
    for (int k = 0; k < 3; ++k)
    {
      used[c[k]] = true;
      const std::uint32_t a = c[k];
      const std::uint32_t b = c[(k + 1) % 3];
      EdgeUse& use = edges[edgeKey(a, b)];
      ++use.count;
      use.direction += a < b ? 1 : -1;
    }
  }
  report.edges = edges.size();
  progress(0.6);

  // Edge defects, found in the order of the triangles that use them (the same order on every
  // machine, whatever the hash map's).
  DisjointSets boundaryGroups(vertexPosition.size());
  DisjointSets pieces(vertexPosition.size());
  for (std::size_t t = 0; t < corners.size(); ++t)
  {
    if (collapsed[t])
    {
      continue;
    }
    const auto triangle = static_cast<std::uint32_t>(t);
    const auto& c = corners[t];
    pieces.unite(c[0], c[1]);
    pieces.unite(c[1], c[2]);
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = c[k];
      const std::uint32_t b = c[(k + 1) % 3];
      EdgeUse& use = edges[edgeKey(a, b)];
      if (use.count == 1)
      {
        boundaryGroups.unite(a, b);
      }
      if (use.reported)
      {
        continue;
      }
      use.reported = true;
      if (use.count == 1)
      {
        noteEdge(report.boundaryEdges, triangle, vertexPosition[a], vertexPosition[b], kept);
      }
      else if (use.count > 2)
      {
        noteEdge(report.nonManifoldEdges, triangle, vertexPosition[a], vertexPosition[b], kept);
      }
      else if (use.direction != 0)
      {
        noteEdge(report.misorientedEdges, triangle, vertexPosition[a], vertexPosition[b], kept);
      }
    }
  }
  progress(0.8);

  // Loops: the groups of boundary edges, each named by its first edge in triangle order.
  std::unordered_map<std::uint32_t, std::size_t> loopOfRoot;
  for (std::size_t t = 0; t < corners.size(); ++t)
  {
    if (collapsed[t])
    {
      continue;
    }
    const auto& c = corners[t];
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = c[k];
      const std::uint32_t b = c[(k + 1) % 3];
      if (edges[edgeKey(a, b)].count != 1)
      {
        continue;
      }
      const std::uint32_t root = boundaryGroups.find(a);
      const auto [it, added] = loopOfRoot.try_emplace(root, report.boundaryLoopEdges.size());
      if (added)
      {
        note(report.boundaryLoops, static_cast<std::uint32_t>(t),
             (vertexPosition[a] + vertexPosition[b]) * 0.5, kept);
        report.boundaryLoopEdges.push_back(0);
      }
      ++report.boundaryLoopEdges[it->second];
    }
  }

  std::unordered_set<std::uint32_t> roots;
  for (std::uint32_t v = 0; v < vertexPosition.size(); ++v)
  {
    if (used[v])
    {
      roots.insert(pieces.find(v));
    }
  }
  progress(0.85);
  CrossingPairs crossing = findCrossingPairs(soup, vertexOfPoint, kept);
  report.selfIntersections = std::move(crossing.selfIntersections);
  report.folds = std::move(crossing.folds);
  report.vertices = vertexPosition.size();
  report.components = roots.size();
  report.closed = report.triangles > report.collapsedTriangles.count &&
                  report.boundaryEdges.count == 0 && report.nonManifoldEdges.count == 0;
  progress(1.0);
  return report;
}

TriangleSoup weldCorners(const TriangleSoup& soup, double tolerance)
{
  TriangleSoup welded = soup;
  if (!(tolerance > 0.0) || soup.points.empty())
  {
    return welded;
  }
  // A grid of cells one tolerance wide: corners within the tolerance are in the same or
  // neighbouring cells.
  struct Cell
  {
    std::int64_t i, j, k;
    bool operator==(const Cell& o) const { return i == o.i && j == o.j && k == o.k; }
  };
  struct CellHash
  {
    std::size_t operator()(const Cell& c) const
    {
      return static_cast<std::size_t>((c.i * 73856093) ^ (c.j * 19349663) ^ (c.k * 83492791));
    }
  };
  const auto cellOf = [tolerance](const Vec3& p) {
    return Cell{static_cast<std::int64_t>(std::floor(p.x / tolerance)),
                static_cast<std::int64_t>(std::floor(p.y / tolerance)),
                static_cast<std::int64_t>(std::floor(p.z / tolerance))};
  };
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> cells;
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    cells[cellOf(soup.points[i])].push_back(static_cast<std::uint32_t>(i));
  }
  DisjointSets groups(soup.points.size());
  const double squared = tolerance * tolerance;
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    const Vec3& p = soup.points[i];
    const Cell c = cellOf(p);
    for (std::int64_t di = -1; di <= 1; ++di)
    {
      for (std::int64_t dj = -1; dj <= 1; ++dj)
      {
        for (std::int64_t dk = -1; dk <= 1; ++dk)
        {
          const auto found = cells.find(Cell{c.i + di, c.j + dj, c.k + dk});
          if (found == cells.end())
          {
            continue;
          }
          for (const std::uint32_t other : found->second)
          {
            if (other > i && squaredDistance(soup.points[other], p) < squared)
            {
              groups.unite(static_cast<std::uint32_t>(i), other);
            }
          }
        }
      }
    }
  }
  // Each group takes the position of its first corner in the file.
  std::vector<std::int64_t> firstOfGroup(soup.points.size(), -1);
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    std::int64_t& first = firstOfGroup[groups.find(static_cast<std::uint32_t>(i))];
    if (first < 0)
    {
      first = static_cast<std::int64_t>(i);
    }
    welded.points[i] = soup.points[static_cast<std::size_t>(first)];
  }
  return welded;
}

} // namespace proxima
