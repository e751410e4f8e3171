// Self-intersecting triangle pairs: CGAL's box intersection (the broad phase its Polygon Mesh
// Processing uses) finds the pairs whose bounding boxes meet, and its exact predicates decide
// whether the triangles do. Kept apart from MeshInspection.cpp, so that only this file compiles
// CGAL.
#include "IO/MeshInspection/MeshInspection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <utility>

namespace proxima
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;

Point pointOf(const Vec3& p)
{
  return {p.x, p.y, p.z};
}
} // namespace

DefectCount findSelfIntersections(const TriangleSoup& soup,
                                  const std::vector<std::uint32_t>& vertexOfPoint,
                                  std::size_t locationsKept)
{
  std::vector<Triangle> triangles(soup.triangles.size());
  std::vector<Box> boxes;
  boxes.reserve(soup.triangles.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const auto& c = soup.triangles[t];
    const Point a = pointOf(soup.points[c[0]]);
    const Point b = pointOf(soup.points[c[1]]);
    const Point d = pointOf(soup.points[c[2]]);
    // Collapsed and collinear triangles (exactly) have no inside to meet another with.
    if (CGAL::collinear(a, b, d))
    {
      continue;
    }
    triangles[t] = Triangle(a, b, d);
    boxes.emplace_back(triangles[t].bbox(), static_cast<std::uint32_t>(t));
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const auto sharesVertex = [&](std::uint32_t s, std::uint32_t t) {
    for (const std::uint32_t i : soup.triangles[s])
    {
      for (const std::uint32_t j : soup.triangles[t])
      {
        if (vertexOfPoint[i] == vertexOfPoint[j])
        {
          return true;
        }
      }
    }
    return false;
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& p, const Box& q) {
    const std::uint32_t s = std::min(p.info(), q.info());
    const std::uint32_t t = std::max(p.info(), q.info());
    if (!sharesVertex(s, t) && CGAL::do_intersect(triangles[s], triangles[t]))
    {
      pairs.emplace_back(s, t);
    }
  });
  std::sort(pairs.begin(), pairs.end());
  DefectCount found;
  found.count = pairs.size();
  for (std::size_t i = 0; i < pairs.size() && i < locationsKept; ++i)
  {
    const auto& c = soup.triangles[pairs[i].first];
    const Vec3 centroid = (soup.points[c[0]] + soup.points[c[1]] + soup.points[c[2]]) / 3.0;
    found.first.push_back({pairs[i].first, centroid, pairs[i].second});
  }
  return found;
}

} // namespace proxima
