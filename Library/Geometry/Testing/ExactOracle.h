// CGAL's exact kernel as the oracle of the closest-point and sweep tests: the distance from a
// double point to a double triangle, computed exactly and rounded once.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleMesh.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <cmath>

namespace proxima::test
{

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;

inline ExactKernel::Point_3 toExact(const Vec3& v)
{
  return {v.x, v.y, v.z};
}

/// Exact squared distance from p to triangle (a, b, c) (degenerate triangles included: CGAL
/// then takes the nearest of the three segments), rounded to double once.
inline double exactSquaredDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const auto squared =
    CGAL::squared_distance(toExact(p), ExactKernel::Triangle_3(toExact(a), toExact(b), toExact(c)));
  // exact() forces the rational value, so the double is the rational rounded once, not the
  // midpoint of a lazily evaluated interval.
  return CGAL::to_double(CGAL::exact(squared));
}

inline double exactDistance(const Vec3& p, const TriangleCorners& t)
{
  return std::sqrt(exactSquaredDistance(p, t.a, t.b, t.c));
}

} // namespace proxima::test
