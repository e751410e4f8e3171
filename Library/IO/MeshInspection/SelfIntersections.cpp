// Self-intersecting and folded triangle pairs: CGAL's box intersection (the broad phase its Polygon
// Mesh Processing uses) finds the pairs whose bounding boxes meet, and its exact predicates decide
// whether the triangles do. Pairs that share no vertex meet or not (do_intersect); neighbours
// meet at what they share, and are folds when they meet anywhere else:
//   - sharing an edge uw, triangles (u, w, a) and (u, w, b) meet beyond it exactly when b lies in
//     the plane of the first and on a's side of the line uw (they overlap, folded onto each other);
//   - sharing a vertex v, two triangles meet elsewhere exactly when their common part holds a
//     point other than v; that part is convex, so one of its corners other than v is then on an
//     edge of one triangle and inside the other: the edge opposite v crosses the other triangle,
//     or an edge from v runs into the other triangle (in its plane and within its angle at v).
// Kept apart from MeshInspection.cpp, so that only this file compiles CGAL.
#include "IO/MeshInspection/MeshInspection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <utility>

namespace proxima
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;

using Segment = Kernel::Segment_3;

Point pointOf(const Vec3& p)
{
  return {p.x, p.y, p.z};
}

// Whether the direction from v to x lies within the angle of the triangle (v, b, c) at v, in its
// plane (on its edges included).
bool withinAngle(const Point& v, const Point& b, const Point& c, const Point& x)
{
  return CGAL::coplanar(v, b, c, x) && CGAL::coplanar_orientation(v, b, c, x) != CGAL::NEGATIVE &&
         CGAL::coplanar_orientation(v, c, b, x) != CGAL::NEGATIVE;
}

// Neighbours s and t (sharing one vertex or one edge) that meet beyond what they share.
bool folded(const Triangle& s, const std::array<std::uint32_t, 3>& sVertices, const Triangle& t,
            const std::array<std::uint32_t, 3>& tVertices)
{
  // Each triangle's corners rotated so that the shared ones come first.
  int sharedInS[3];
  int sharedInT[3];
  int shared = 0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (sVertices[i] == tVertices[j])
      {
        sharedInS[shared] = i;
        sharedInT[shared] = j;
        ++shared;
      }
    }
  }
  if (shared == 2)
  {
    const Point& u = s.vertex(sharedInS[0]);
    const Point& w = s.vertex(sharedInS[1]);
    const Point& a = s.vertex(3 - sharedInS[0] - sharedInS[1]);
    const Point& b = t.vertex(3 - sharedInT[0] - sharedInT[1]);
    return CGAL::coplanar(u, w, a, b) && CGAL::coplanar_orientation(u, w, a, b) == CGAL::POSITIVE;
  }
  const Point& v = s.vertex(sharedInS[0]);
  const Point& s1 = s.vertex((sharedInS[0] + 1) % 3);
  const Point& s2 = s.vertex((sharedInS[0] + 2) % 3);
  const Point& t1 = t.vertex((sharedInT[0] + 1) % 3);
  const Point& t2 = t.vertex((sharedInT[0] + 2) % 3);
  return CGAL::do_intersect(Segment(s1, s2), t) || CGAL::do_intersect(Segment(t1, t2), s) ||
         withinAngle(v, t1, t2, s1) || withinAngle(v, t1, t2, s2) || withinAngle(v, s1, s2, t1) ||
         withinAngle(v, s1, s2, t2);
}

DefectCount listed(std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                   const TriangleSoup& soup, std::size_t locationsKept)
{
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
} // namespace

CrossingPairs findCrossingPairs(const TriangleSoup& soup,
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
  const auto verticesOf = [&](std::uint32_t t) {
    const auto& c = soup.triangles[t];
    return std::array<std::uint32_t, 3>{vertexOfPoint[c[0]], vertexOfPoint[c[1]],
                                        vertexOfPoint[c[2]]};
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> crossing;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> folds;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& p, const Box& q) {
    const std::uint32_t s = std::min(p.info(), q.info());
    const std::uint32_t t = std::max(p.info(), q.info());
    const std::array<std::uint32_t, 3> sVertices = verticesOf(s);
    const std::array<std::uint32_t, 3> tVertices = verticesOf(t);
    int shared = 0;
    for (const std::uint32_t i : sVertices)
    {
      shared += std::count(tVertices.begin(), tVertices.end(), i) > 0 ? 1 : 0;
    }
    if (shared == 0)
    {
      if (CGAL::do_intersect(triangles[s], triangles[t]))
      {
        crossing.emplace_back(s, t);
      }
    }
    // Three shared vertices: a duplicate triangle, reported as one.
    else if (shared < 3 && folded(triangles[s], sVertices, triangles[t], tVertices))
    {
      folds.emplace_back(s, t);
    }
  });
  return {listed(crossing, soup, locationsKept), listed(folds, soup, locationsKept)};
}

} // namespace proxima
