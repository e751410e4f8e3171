// Shared by the geometry tests: seeded random inputs, failure messages that carry the seed and
// every input to 17 digits, and an extended-precision brute-force closest-point oracle written
// independently of the kernel (plane projection with an explicit normal, else the three edges),
// so that a test never checks the kernel against itself.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/TriangleMesh.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

namespace proxima::test
{

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

/// 128-bit binary floating point (113-bit significand): a product of two doubles is exact in it,
/// which is what makes the oracle trustworthy on slivers where long double loses the normal.
__extension__ typedef __float128 Quad;

inline std::string str(double value)
{
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

inline std::string str(const Vec3& v)
{
  return "{" + str(v.x) + ", " + str(v.y) + ", " + str(v.z) + "}";
}

inline std::string str(const TriangleCorners& t)
{
  return "{" + str(t.a) + ", " + str(t.b) + ", " + str(t.c) + "}";
}

/// A seeded engine and the draws the tests need; the seed is printed with every failure.
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : m_engine(seed)
  {}

  double uniform(double lower, double upper)
  {
    return std::uniform_real_distribution<double>(lower, upper)(m_engine);
  }
  int integer(int lower, int upper)
  {
    return std::uniform_int_distribution<int>(lower, upper)(m_engine);
  }
  bool chance(double probability) { return uniform(0.0, 1.0) < probability; }
  Vec3 inCube(double halfSide)
  {
    return {uniform(-halfSide, halfSide), uniform(-halfSide, halfSide),
            uniform(-halfSide, halfSide)};
  }
  /// Uniform on the unit sphere (normalised Gaussian vector).
  Vec3 direction()
  {
    std::normal_distribution<double> gauss;
    for (;;)
    {
      const Vec3 v{gauss(m_engine), gauss(m_engine), gauss(m_engine)};
      const double length = norm(v);
      if (length > 1e-3)
      {
        return v / length;
      }
    }
  }
  /// 10^uniform(lowerExponent, upperExponent): spreads magnitudes over many decades.
  double logUniform(double lowerExponent, double upperExponent)
  {
    return std::pow(10.0, uniform(lowerExponent, upperExponent));
  }
  std::mt19937_64& engine() { return m_engine; }

private:
  std::mt19937_64 m_engine;
};

/// A 3-vector in an extended precision T (long double or Quad), for the oracles only.
template <class T>
struct ExtVec
{
  T x{};
  T y{};
  T z{};
};

template <class T>
ExtVec<T> extend(const Vec3& v)
{
  return {static_cast<T>(v.x), static_cast<T>(v.y), static_cast<T>(v.z)};
}
template <class T>
ExtVec<T> operator+(const ExtVec<T>& a, const ExtVec<T>& b)
{
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
ExtVec<T> operator-(const ExtVec<T>& a, const ExtVec<T>& b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
ExtVec<T> operator*(const ExtVec<T>& a, T s)
{
  return {a.x * s, a.y * s, a.z * s};
}
template <class T>
T dotExt(const ExtVec<T>& a, const ExtVec<T>& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
ExtVec<T> crossExt(const ExtVec<T>& a, const ExtVec<T>& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class T>
struct OracleClosest
{
  T squaredDistance{};
  ExtVec<T> point;
};

template <class T>
OracleClosest<T> oracleClosestOnSegment(const ExtVec<T>& p, const ExtVec<T>& a, const ExtVec<T>& b)
{
  const ExtVec<T> ab = b - a;
  const T lengthSquared = dotExt(ab, ab);
  T s = 0;
  if (lengthSquared > 0)
  {
    s = dotExt(p - a, ab) / lengthSquared;
    s = s < 0 ? T(0) : (s > 1 ? T(1) : s);
  }
  OracleClosest<T> r;
  r.point = a + ab * s;
  const ExtVec<T> d = p - r.point;
  r.squaredDistance = dotExt(d, d);
  return r;
}

/// Closest point of triangle (a, b, c) to p in precision T: the foot of the perpendicular when it
/// falls inside all three edge planes, else the nearest of the three edges. Degenerate triangles
/// (zero normal in T) are their edges.
template <class T>
OracleClosest<T> oracleClosestOnTriangle(const ExtVec<T>& p, const ExtVec<T>& a, const ExtVec<T>& b,
                                         const ExtVec<T>& c)
{
  const ExtVec<T> n = crossExt(b - a, c - a);
  const T nn = dotExt(n, n);
  if (nn > 0)
  {
    const bool insideAB = dotExt(crossExt(b - a, p - a), n) >= 0;
    const bool insideBC = dotExt(crossExt(c - b, p - b), n) >= 0;
    const bool insideCA = dotExt(crossExt(a - c, p - c), n) >= 0;
    if (insideAB && insideBC && insideCA)
    {
      const T h = dotExt(p - a, n);
      OracleClosest<T> r;
      r.point = p - n * (h / nn);
      r.squaredDistance = h * h / nn;
      return r;
    }
  }
  OracleClosest<T> best = oracleClosestOnSegment(p, a, b);
  const OracleClosest<T> bc = oracleClosestOnSegment(p, b, c);
  if (bc.squaredDistance < best.squaredDistance)
  {
    best = bc;
  }
  const OracleClosest<T> ca = oracleClosestOnSegment(p, c, a);
  if (ca.squaredDistance < best.squaredDistance)
  {
    best = ca;
  }
  return best;
}

template <class T>
OracleClosest<T> oracleClosestOnTriangle(const ExtVec<T>& p, const TriangleCorners& t)
{
  return oracleClosestOnTriangle(p, extend<T>(t.a), extend<T>(t.b), extend<T>(t.c));
}

/// Longest distance between any two of the given points: the length scale of one query.
inline double spread(std::initializer_list<Vec3> points)
{
  double longest = 0.0;
  for (const Vec3& p : points)
  {
    for (const Vec3& q : points)
    {
      longest = std::fmax(longest, distance(p, q));
    }
  }
  return longest;
}

/// Largest absolute coordinate: positions near it are rounded to about kEpsilon times it.
inline double magnitude(std::initializer_list<Vec3> points)
{
  double largest = 0.0;
  for (const Vec3& p : points)
  {
    largest = std::fmax(largest, maxAbsComponent(p));
  }
  return largest;
}

/// Keeps one failing test from printing thousands of messages: the first few tell the story.
class FailureBudget
{
public:
  explicit FailureBudget(int allowed = 8)
    : m_remaining(allowed)
  {}
  bool spend() { return m_remaining-- > 0; }

private:
  int m_remaining;
};

/// The triangle shapes the kernel must survive: well-shaped, needles (one edge 1/aspect of the
/// others), caps (one angle near 180 degrees, height 1/aspect of the longest edge), exactly
/// collinear corners, and coincident corners.
enum class TriangleShape
{
  Fat,
  Needle,
  Cap,
  Collinear,
  Coincident,
  SinglePoint
};

inline const char* name(TriangleShape shape)
{
  switch (shape)
  {
    case TriangleShape::Fat: return "fat";
    case TriangleShape::Needle: return "needle";
    case TriangleShape::Cap: return "cap";
    case TriangleShape::Collinear: return "collinear";
    case TriangleShape::Coincident: return "coincident";
    case TriangleShape::SinglePoint: return "single point";
  }
  return "?";
}

/// A unit vector orthogonal to `v` (v non-zero).
inline Vec3 perpendicular(const Vec3& v, Random& random)
{
  for (;;)
  {
    const Vec3 p = cross(v, random.direction());
    const double length = norm(p);
    if (length > 1e-3 * norm(v))
    {
      return p / length;
    }
  }
}

/// A triangle of the given shape, about `size` across, near `offset`. `aspect` (>= 1) sets how
/// thin needles and caps are.
inline TriangleCorners makeTriangle(Random& random, TriangleShape shape, double size,
                                    const Vec3& offset, double aspect)
{
  TriangleCorners t;
  t.a = offset + random.inCube(size);
  t.b = offset + random.inCube(size);
  switch (shape)
  {
    case TriangleShape::Fat: t.c = offset + random.inCube(size); break;
    case TriangleShape::Needle: t.c = t.a + random.direction() * (size / aspect); break;
    case TriangleShape::Cap:
    {
      const Vec3 ab = t.b - t.a;
      t.c = t.a + ab * random.uniform(0.05, 0.95) + perpendicular(ab, random) * (norm(ab) / aspect);
      break;
    }
    case TriangleShape::Collinear:
    {
      // Exactly collinear in double: corners on a grid fine enough for the size and coarse
      // enough that every sum below is exact, along a direction of small integers.
      const double grid = std::exp2(
        std::floor(std::log2(std::fmax(size * 0x1p-20, maxAbsComponent(offset) * 0x1p-45))));
      const Vec3 base = offset + random.inCube(size);
      t.a = {std::round(base.x / grid) * grid, std::round(base.y / grid) * grid,
             std::round(base.z / grid) * grid};
      Vec3 direction;
      while (direction == Vec3{})
      {
        direction = {double(random.integer(-7, 7)), double(random.integer(-7, 7)),
                     double(random.integer(-7, 7))};
      }
      const Vec3 step = direction * (grid * std::exp2(std::floor(std::log2(size / grid)) - 4));
      t.b = t.a + step * double(random.integer(-8, 8));
      t.c = t.a + step * double(random.integer(-8, 8));
      break;
    }
    case TriangleShape::Coincident:
      if (random.chance(0.5))
      {
        t.c = t.a;
      }
      else
      {
        t.c = offset + random.inCube(size);
        t.b = t.c;
      }
      break;
    case TriangleShape::SinglePoint:
      t.b = t.a;
      t.c = t.a;
      break;
  }
  // Rotate the corner order so that no shape always puts its defect on the same corner.
  const int rotation = random.integer(0, 2);
  for (int i = 0; i < rotation; ++i)
  {
    t = TriangleCorners{t.b, t.c, t.a};
  }
  return t;
}

/// A point on the triangle: a random convex combination of the corners (rounded to double).
inline Vec3 pointOnTriangle(Random& random, const TriangleCorners& t)
{
  double u = random.uniform(0.0, 1.0);
  double v = random.uniform(0.0, 1.0);
  if (u + v > 1.0)
  {
    u = 1.0 - u;
    v = 1.0 - v;
  }
  return t.a + (t.b - t.a) * u + (t.c - t.a) * v;
}

} // namespace proxima::test
