// An axis-aligned bounding box, used while building trees and for scale-aware tolerances.
#pragma once

#include "Core/Vec3.h"

#include <limits>

namespace proxima
{

/// An axis-aligned box given by its lower and upper corners (m). It starts empty (lower above
/// upper on every axis), so that the first expand() sets both corners.
struct Aabb
{
  /// The corner with the smallest coordinates; +infinity on every axis while the box is empty.
  Vec3 lower{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity()};
  /// The corner with the largest coordinates; -infinity on every axis while the box is empty.
  Vec3 upper{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
             -std::numeric_limits<double>::infinity()};

  /// True while the box holds no point (nothing was added since it was made).
  bool isEmpty() const { return lower.x > upper.x; }
  /// Grows the box to hold point `p`.
  void expand(const Vec3& p)
  {
    lower = componentMin(lower, p);
    upper = componentMax(upper, p);
  }
  /// Grows the box to hold the sphere at `center` of radius `radius` (m).
  void expand(const Vec3& center, double radius)
  {
    expand(center - Vec3{radius, radius, radius});
    expand(center + Vec3{radius, radius, radius});
  }
  /// The midpoint of the box (NaN while it is empty).
  Vec3 center() const { return (lower + upper) * 0.5; }
  /// The box's size along each axis (m): upper minus lower (-infinity while it is empty).
  Vec3 extent() const { return upper - lower; }
  /// The length of the box's diagonal (m); 0 for an empty box.
  double diagonal() const { return isEmpty() ? 0.0 : norm(upper - lower); }
  /// 0, 1 or 2: the axis along which the box is longest.
  int longestAxis() const
  {
    const Vec3 e = extent();
    return e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
  }
};

} // namespace proxima
