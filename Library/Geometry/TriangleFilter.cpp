#include "Geometry/TriangleFilter.h"

#include <algorithm>
#include <cmath>

namespace proxima
{

TriangleFilter makeTriangleFilter(const TriangleCorners& c)
{
  TriangleFilter filter;
  filter.centroid = (c.a + c.b + c.c) / 3.0;
  const double radius = std::sqrt(
    std::max({squaredDistance(filter.centroid, c.a), squaredDistance(filter.centroid, c.b),
              squaredDistance(filter.centroid, c.c)}));
  // A hair larger, so that the double rounding of the rejection tests never drops a triangle
  // that touches exactly.
  filter.radius = radius * (1.0 + 1e-12) + 1e-300;
  const Vec3 normalCross = cross(c.b - c.a, c.c - c.a);
  const double normalLength = norm(normalCross);
  filter.normal = normalLength > 0.0 ? normalCross / normalLength : Vec3{};
  filter.offset = dot(filter.normal, filter.centroid);
  const double off = std::max({std::fabs(dot(filter.normal, c.a) - filter.offset),
                               std::fabs(dot(filter.normal, c.b) - filter.offset),
                               std::fabs(dot(filter.normal, c.c) - filter.offset)});
  // The corners' rounding off the plane, and the rounding of a height measured at any point
  // near the triangle (coordinates up to |centroid| + radius): generous, as it only widens a
  // filter that the exact test follows.
  filter.planeSlack = 2.0 * off + 1e-12 * (maxAbsComponent(filter.centroid) + radius);
  return filter;
}

std::vector<TriangleFilter> makeTriangleFilters(const TriangleMesh& mesh)
{
  std::vector<TriangleFilter> filters(mesh.numTriangles());
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    filters[t] = makeTriangleFilter(mesh.corners(t));
  }
  return filters;
}

} // namespace proxima
