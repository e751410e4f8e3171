#include "Geometry/WindingNumber.h"

#include <cmath>

namespace proxima
{

double triangleSolidAngle(const Vec3& point, const Vec3& a, const Vec3& b, const Vec3& c)
{
  // van Oosterom and Strackee: tan(omega / 2) = det[a b c] / (|a||b||c| + (a.b)|c| + (a.c)|b| +
  // (b.c)|a|) with the corners relative to the point. atan2 keeps the quadrant that a plain atan
  // loses when the denominator is negative (a large triangle seen from close by).
  const Vec3 ra = a - point;
  const Vec3 rb = b - point;
  const Vec3 rc = c - point;
  const double la = norm(ra);
  const double lb = norm(rb);
  const double lc = norm(rc);
  const double numerator = dot(ra, cross(rb, rc));
  const double denominator = la * lb * lc + dot(ra, rb) * lc + dot(ra, rc) * lb + dot(rb, rc) * la;
  if (numerator == 0.0)
  {
    // In the triangle's plane: outside the triangle it subtends nothing; inside it (or on its
    // edge) the two sides are a whole hemisphere each, and either answer is as right: take none,
    // so that a point on a surface sits halfway, as the header says, whatever the orientation.
    return 0.0;
  }
  return 2.0 * std::atan2(numerator, denominator);
}

double windingNumber(const TriangleMesh& mesh, const Vec3& point)
{
  constexpr double kFourPi = 4.0 * 3.14159265358979323846;
  double total = 0.0;
  const std::uint32_t numTriangles = mesh.numTriangles();
  for (std::uint32_t triangle = 0; triangle < numTriangles; ++triangle)
  {
    const TriangleCorners& corners = mesh.corners(triangle);
    total += triangleSolidAngle(point, corners.a, corners.b, corners.c);
  }
  return total / kFourPi;
}

} // namespace proxima
