// A 3-vector of doubles in SI units: the one vector type of the real-time kernel.
#pragma once

#include <cmath>

namespace proxima
{

/// A point or a vector in 3-D space, in SI units (metres for positions); zero by default.
struct Vec3
{
  double x = 0.0; ///< Component along the x axis.
  double y = 0.0; ///< Component along the y axis.
  double z = 0.0; ///< Component along the z axis.

  constexpr Vec3() = default;
  /// The vector (xValue, yValue, zValue).
  constexpr Vec3(double xValue, double yValue, double zValue)
    : x(xValue)
    , y(yValue)
    , z(zValue)
  {}

  /// The component along `axis`: 0 is x, 1 is y, any other value z.
  constexpr double operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  /// The component along `axis`, writable: 0 is x, 1 is y, any other value z.
  constexpr double& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }

  /// The component-wise sum.
  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  /// The component-wise difference.
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  /// The opposite vector.
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  /// The vector scaled by `s`.
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  /// The vector divided by `s` (no check for zero).
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  /// Adds `o`, component by component.
  constexpr Vec3& operator+=(const Vec3& o)
  {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  /// Subtracts `o`, component by component.
  constexpr Vec3& operator-=(const Vec3& o)
  {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  /// Scales the vector by `s`.
  constexpr Vec3& operator*=(double s)
  {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  /// True when all three components are exactly equal.
  constexpr bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
  /// True when any component differs.
  constexpr bool operator!=(const Vec3& o) const { return !(*this == o); }
};

/// `v` scaled by `s`.
constexpr Vec3 operator*(double s, const Vec3& v)
{
  return v * s;
}
/// The dot product of `a` and `b`.
constexpr double dot(const Vec3& a, const Vec3& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
/// The cross product a x b (right-handed).
constexpr Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// |v|^2, without the square root.
constexpr double squaredNorm(const Vec3& v)
{
  return dot(v, v);
}
/// |v|, the Euclidean length (overflows to infinity beyond about 1e154; see overflowSafeNorm()).
inline double norm(const Vec3& v)
{
  return std::sqrt(dot(v, v));
}
/// The Euclidean distance between points `a` and `b`.
inline double distance(const Vec3& a, const Vec3& b)
{
  return norm(a - b);
}
/// The squared distance between points `a` and `b`.
constexpr double squaredDistance(const Vec3& a, const Vec3& b)
{
  return squaredNorm(a - b);
}
/// The largest absolute value of the components of `v` (a NaN component may or may not come
/// out as the result).
constexpr double maxAbsComponent(const Vec3& v)
{
  const double ax = v.x < 0 ? -v.x : v.x;
  const double ay = v.y < 0 ? -v.y : v.y;
  const double az = v.z < 0 ? -v.z : v.z;
  return ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
}
/// True when no component of `v` is infinite or NaN.
inline bool isFinite(const Vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
/// |v| computed on v scaled by its largest component, so that the squares neither overflow nor
/// underflow: norm() of (1e155, 0, 0) is infinity, this is 1e155. Infinity when a component is.
inline double overflowSafeNorm(const Vec3& v)
{
  const double largest = maxAbsComponent(v);
  if (!(largest > 0.0) || !std::isfinite(largest))
  {
    return largest;
  }
  const Vec3 scaled{v.x / largest, v.y / largest, v.z / largest};
  return largest * std::sqrt(dot(scaled, scaled));
}
/// The unit vector along v for any v with a direction, even one with infinite components (their
/// directions, the finite ones then 0); the zero vector for the zero vector.
inline Vec3 overflowSafeDirection(const Vec3& v)
{
  const double largest = maxAbsComponent(v);
  if (!(largest > 0.0))
  {
    return {};
  }
  Vec3 scaled;
  if (std::isfinite(largest))
  {
    scaled = {v.x / largest, v.y / largest, v.z / largest};
  }
  else
  {
    scaled = {std::isinf(v.x) ? std::copysign(1.0, v.x) : 0.0,
              std::isinf(v.y) ? std::copysign(1.0, v.y) : 0.0,
              std::isinf(v.z) ? std::copysign(1.0, v.z) : 0.0};
  }
  return scaled / std::sqrt(dot(scaled, scaled));
}
/// The unit vector along v, or the zero vector when v has no usable length.
inline Vec3 normalizedOrZero(const Vec3& v)
{
  const double length = norm(v);
  return length > 0.0 && std::isfinite(length) ? v / length : Vec3{};
}
/// The smaller of `a` and `b` on each axis.
constexpr Vec3 componentMin(const Vec3& a, const Vec3& b)
{
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
/// The larger of `a` and `b` on each axis.
constexpr Vec3 componentMax(const Vec3& a, const Vec3& b)
{
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}

} // namespace proxima
