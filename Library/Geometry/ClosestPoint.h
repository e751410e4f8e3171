// Closest point on a triangle, a segment or a point to a query point, with the barycentric
// weights of the answer: the contact weights that shading and texture interpolate with.
#pragma once

#include "Core/Vec3.h"

#include <cstdint>

namespace proxima
{

/// Which part of a triangle holds the closest point: a vertex, an edge or the face interior.
enum class TriangleFeature : std::uint8_t
{
  VertexA,
  VertexB,
  VertexC,
  EdgeAB,
  EdgeBC,
  EdgeCA,
  Face
};

/// The point of a triangle nearest a query point, where it lies on the triangle and how far it
/// is: what closestPointOnTriangle() returns.
struct ClosestPointResult
{
  /// The nearest point of the triangle, in the frame of its corners.
  Vec3 point;
  /// point = weights[0] * a + weights[1] * b + weights[2] * c; weights >= 0, sum 1.
  double weights[3] = {1.0, 0.0, 0.0};
  /// Squared distance from the query point to `point`.
  double squaredDistance = 0.0;
  /// The vertex, edge or face interior that holds `point`.
  TriangleFeature feature = TriangleFeature::VertexA;
};

/// Closest point of segment [a, b] to p, as the weight of b (0 at a, 1 at b).
double closestParameterOnSegment(const Vec3& p, const Vec3& a, const Vec3& b);

/// Closest point of triangle (a, b, c) to p. Follows the Voronoi-region method of Ericson,
/// "Real-Time Collision Detection" 5.1.5; a degenerate triangle (zero area, collinear or
/// coincident corners) is answered by its nearest edge, never by a division by zero.
ClosestPointResult closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c);

} // namespace proxima
