// An axis-aligned bounding box, used while building trees and for scale-aware tolerances.
#pragma once

#include "Core/Vec3.h"

#include <limits>

namespace proxima
{

struct Aabb
{
  Vec3 lower{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity()};
  Vec3 upper{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
             -std::numeric_limits<double>::infinity()};

  bool isEmpty() const { return lower.x > upper.x; }
  void expand(const Vec3& p)
  {
    lower = componentMin(lower, p);
    upper = componentMax(upper, p);
  }
  void expand(const Vec3& center, double radius)
  {
    expand(center - Vec3{radius, radius, radius});
    expand(center + Vec3{radius, radius, radius});
  }
  Vec3 center() const { return (lower + upper) * 0.5; }
  Vec3 extent() const { return upper - lower; }
  double diagonal() const { return isEmpty() ? 0.0 : norm(upper - lower); }
  /// 0, 1 or 2: the axis along which the box is longest.
  int longestAxis() const
  {
    const Vec3 e = extent();
    return e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
  }
};

} // namespace proxima
