#include "IO/MeshInspection/ToolReach.h"

#include "Geometry/SphereTree.h"
#include "IO/MeshInspection/Private/DisjointSets.h"
#include "Geometry/TriangleMesh.h"
#include "IO/MeshInspection/MeshInspection.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <unordered_map>

namespace proxima
{
namespace
{
// A ball this much smaller than the tool decides reach, so that the face the ball is tangent to
// (at exactly R, up to rounding) and coplanar neighbours do not count as overlaps.
constexpr double kTangentSlack = 1e-6;

struct TangentBallTest
{
  const TriangleMesh& mesh;
  const SphereTree& tree;
  SphereTreeScratch& scratch;

  /// The distance from the centre of the ball of `radius` tangent at `point` on `side` to the
  /// surface, when the ball (less the slack) overlaps it; -1 when it is empty.
  double overlap(const Vec3& point, const Vec3& side, double radius) const
  {
    const Vec3 centre = point + side * radius;
    const NearestTriangle hit = tree.nearest(mesh, centre, radius * (1.0 - kTangentSlack), scratch);
    return hit.found ? std::sqrt(hit.closest.squaredDistance) : -1.0;
  }

  /// The largest radius up to `radius` whose tangent ball at `point` on `side` is empty.
  double largestEmpty(const Vec3& point, const Vec3& side, double radius) const
  {
    double empty = 0.0;
    double full = radius;
    while (full - empty > 1e-9 * radius)
    {
      const double middle = 0.5 * (empty + full);
      (overlap(point, side, middle) < 0.0 ? empty : full) = middle;
    }
    return empty;
  }
};

double signedVolume(const TriangleSoup& soup)
{
  double volume = 0.0;
  for (const auto& t : soup.triangles)
  {
    volume += dot(soup.points[t[0]], cross(soup.points[t[1]], soup.points[t[2]]));
  }
  return volume / 6.0;
}

} // namespace

ToolReach findToolReach(const TriangleSoup& soup, bool closedAndOriented,
                        const ToolReachOptions& options)
{
  TriangleMesh mesh;
  MeshError error;
  if (!mesh.build(soup, error))
  {
    throw std::invalid_argument(error.message);
  }
  auto tree = std::make_unique<SphereTree>();
  tree->build(mesh);
  return findToolReach(soup, mesh, *tree, closedAndOriented, options);
}

ToolReach findToolReach(const TriangleSoup& soup, const TriangleMesh& mesh, const SphereTree& tree,
                        bool closedAndOriented, const ToolReachOptions& options)
{
  const double radius = options.toolRadius;
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    throw std::invalid_argument("the tool radius must be above 0");
  }
  const auto progress = [&options](double done) {
    if (options.progress)
    {
      options.progress(done);
    }
  };
  auto scratch = std::make_unique<SphereTreeScratch>();
  const TangentBallTest test{mesh, tree, *scratch};
  progress(0.1);

  ToolReach reach;
  reach.toolRadius = radius;
  reach.outsideOnly = closedAndOriented;
  const double outward = signedVolume(soup) < 0.0 ? -1.0 : 1.0;

  // Per unreachable triangle: its deepest sample (the smallest centre-to-surface distance) and the
  // area of its unreachable samples.
  struct Deepest
  {
    double distance;
    Vec3 point;
    Vec3 side;
  };
  struct Unreachable
  {
    Deepest deepest;
    double area = 0.0;
  };
  std::unordered_map<std::uint32_t, Unreachable> unreachableOf;
  const std::size_t count = soup.triangles.size();
  for (std::size_t t = 0; t < count; ++t)
  {
    const auto triangle = static_cast<std::uint32_t>(t);
    const Vec3& a = soup.points[soup.triangles[t][0]];
    const Vec3& b = soup.points[soup.triangles[t][1]];
    const Vec3& c = soup.points[soup.triangles[t][2]];
    const Vec3 areaVector = cross(b - a, c - a);
    const double twiceArea = norm(areaVector);
    if (!(twiceArea > 0.0))
    {
      continue;
    }
    const Vec3 normal = areaVector / twiceArea * outward;
    const double longest = std::max({norm(b - a), norm(c - b), norm(a - c)});
    const int split =
      std::clamp(static_cast<int>(std::ceil(longest / radius)), 1, std::max(options.maxSplit, 1));
    const double sampleArea = 0.5 * twiceArea / (split * split);
    const Vec3 u = (b - a) / split;
    const Vec3 v = (c - a) / split;
    bool triangleUnreachable = false;
    // The centroids of the split's upward (i + j <= k - 1) and downward (i + j <= k - 2)
    // triangles, in barycentric steps of 1/k.
    for (int i = 0; i < split; ++i)
    {
      for (int j = 0; i + j < split; ++j)
      {
        for (int down = 0; down < 2; ++down)
        {
          if (down == 1 && i + j > split - 2)
          {
            continue;
          }
          const double shift = down == 1 ? 2.0 / 3.0 : 1.0 / 3.0;
          const Vec3 point = a + u * (i + shift) + v * (j + shift);
          double depth = test.overlap(point, normal, radius);
          Vec3 side = normal;
          if (depth >= 0.0 && !closedAndOriented)
          {
            const double other = test.overlap(point, -normal, radius);
            if (other < 0.0 || other > depth)
            {
              side = -normal;
              depth = other;
            }
          }
          const bool reachable = depth < 0.0;
          ++reach.samples;
          reach.area += sampleArea;
          if (!reachable)
          {
            ++reach.unreachableSamples;
            reach.unreachableArea += sampleArea;
            triangleUnreachable = true;
            auto [it, added] =
              unreachableOf.try_emplace(triangle, Unreachable{{depth, point, side}, 0.0});
            if (!added && depth < it->second.deepest.distance)
            {
              it->second.deepest = Deepest{depth, point, side};
            }
            it->second.area += sampleArea;
          }
          if (options.keepSamples)
          {
            reach.sampleList.push_back({triangle, point, side, sampleArea, reachable});
          }
        }
      }
    }
    if (triangleUnreachable)
    {
      reach.unreachableTriangles.push_back(triangle);
    }
    if ((t & 0xffff) == 0)
    {
      progress(0.1 + 0.8 * static_cast<double>(t) / static_cast<double>(count));
    }
  }

  // Regions: unreachable triangles joined through vertices on identical coordinates.
  std::size_t vertexCount = 0;
  const std::vector<std::uint32_t> vertexOfPoint = mergeIdenticalCorners(soup, vertexCount);
  DisjointSets joined(vertexCount);
  for (const std::uint32_t t : reach.unreachableTriangles)
  {
    const auto& corners = soup.triangles[t];
    joined.unite(vertexOfPoint[corners[0]], vertexOfPoint[corners[1]]);
    joined.unite(vertexOfPoint[corners[1]], vertexOfPoint[corners[2]]);
  }
  std::unordered_map<std::uint32_t, std::size_t> regionOfRoot;
  std::vector<Deepest> regionDeepest;
  for (const std::uint32_t t : reach.unreachableTriangles)
  {
    const std::uint32_t root = joined.find(vertexOfPoint[soup.triangles[t][0]]);
    const auto [it, added] = regionOfRoot.try_emplace(root, reach.regionCount);
    const Unreachable& unreachable = unreachableOf.at(t);
    const Deepest& deepest = unreachable.deepest;
    if (added)
    {
      ++reach.regionCount;
      regionDeepest.push_back(deepest);
      if (reach.regions.size() < options.locationsKept)
      {
        reach.regions.push_back({t, 0, 0.0, deepest.point, 0.0});
      }
    }
    else if (deepest.distance < regionDeepest[it->second].distance)
    {
      regionDeepest[it->second] = deepest;
    }
    if (it->second < reach.regions.size())
    {
      UnreachableRegion& region = reach.regions[it->second];
      ++region.triangles;
      region.area += unreachable.area;
    }
  }
  for (std::size_t r = 0; r < reach.regions.size(); ++r)
  {
    const Deepest& deepest = regionDeepest[r];
    reach.regions[r].point = deepest.point;
    reach.regions[r].largestReachingRadius = test.largestEmpty(deepest.point, deepest.side, radius);
  }
  progress(1.0);
  return reach;
}

} // namespace proxima
