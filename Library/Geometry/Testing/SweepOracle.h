// The brute-force oracle of the swept-sphere tests. Along the line p(t) = start + t * motion the
// distance to a triangle is convex in t (the distance to a convex set is convex, and p is affine),
// so its minimum over [0, 1] is found by golden-section search, and the first t at which it comes
// within a radius by bisection on [0, argmin], where it only decreases. Distances come from the
// extended-precision closest point of GeometryTestSupport.h: nothing here shares code with the
// kernel's swept-volume construction (offset faces, edge cylinders, corner spheres).
#pragma once

#include "GeometryTestSupport.h"

#include <cmath>

namespace proxima::test
{

template <class T>
class SweepOracle
{
public:
  /// Golden-section steps and bisection steps enough to reach T's precision on [0, 1].
  static constexpr int kGoldenSteps = sizeof(T) > 12 ? 165 : 100;
  static constexpr int kBisectionSteps = sizeof(T) > 12 ? 115 : 66;

  SweepOracle(const Vec3& start, const Vec3& motion, const TriangleCorners& triangle)
    : m_start(extend<T>(start))
    , m_motion(extend<T>(motion))
    , m_a(extend<T>(triangle.a))
    , m_b(extend<T>(triangle.b))
    , m_c(extend<T>(triangle.c))
  {
    findMinimum();
  }

  T squaredDistanceAt(T t) const { return closestAt(t).squaredDistance; }
  long double distanceAt(T t) const
  {
    return std::sqrt(static_cast<long double>(squaredDistanceAt(t)));
  }
  /// The smallest distance over [0, upTo] (convexity: at the argmin, or at upTo before it).
  long double minDistanceUpTo(T upTo) const
  {
    return distanceAt(m_argmin < upTo ? m_argmin : upTo);
  }
  long double minDistance() const { return distanceAt(m_argmin); }
  T argmin() const { return m_argmin; }

  /// Rate of change of the distance with t at `t` (envelope theorem: the gradient of the
  /// distance to a convex set is the unit vector from the nearest point).
  long double slopeAt(T t) const
  {
    const OracleClosest<T> closest = closestAt(t);
    const ExtVec<T> away = pointAt(t) - closest.point;
    const long double length = std::sqrt(static_cast<long double>(dotExt(away, away)));
    return length > 0 ? static_cast<long double>(dotExt(away, m_motion)) / length : 0.0L;
  }

  /// Cosine between the motion and the direction away from the triangle at the start (0 when the
  /// start is on the triangle or there is no motion).
  long double startCosine() const
  {
    const OracleClosest<T> closest = closestAt(T(0));
    const ExtVec<T> away = m_start - closest.point;
    const long double product = std::sqrt(static_cast<long double>(dotExt(away, away)) *
                                          static_cast<long double>(dotExt(m_motion, m_motion)));
    return product > 0 ? static_cast<long double>(dotExt(away, m_motion)) / product : 0.0L;
  }

  struct Entry
  {
    bool hit = false;
    T t = 1;
  };
  /// First t in [0, 1] at which the distance is at most `radius` (the start may already be).
  Entry firstEntry(long double radius) const
  {
    const T radiusSquared = static_cast<T>(radius) * static_cast<T>(radius);
    Entry entry;
    if (squaredDistanceAt(T(0)) <= radiusSquared)
    {
      entry.hit = true;
      entry.t = 0;
      return entry;
    }
    if (squaredDistanceAt(m_argmin) > radiusSquared)
    {
      return entry;
    }
    T outside = 0;
    T inside = m_argmin;
    for (int i = 0; i < kBisectionSteps; ++i)
    {
      const T middle = (outside + inside) / 2;
      if (squaredDistanceAt(middle) <= radiusSquared)
      {
        inside = middle;
      }
      else
      {
        outside = middle;
      }
    }
    entry.hit = true;
    entry.t = inside;
    return entry;
  }

private:
  ExtVec<T> pointAt(T t) const { return m_start + m_motion * t; }
  OracleClosest<T> closestAt(T t) const
  {
    return oracleClosestOnTriangle(pointAt(t), m_a, m_b, m_c);
  }

  void findMinimum()
  {
    // Golden-section search; with ties (a plateau) either side holds a minimiser.
    const T ratio = static_cast<T>(0.6180339887498948482045868343656381L);
    T lower = 0;
    T upper = 1;
    T x1 = upper - (upper - lower) * ratio;
    T x2 = lower + (upper - lower) * ratio;
    T f1 = squaredDistanceAt(x1);
    T f2 = squaredDistanceAt(x2);
    for (int i = 0; i < kGoldenSteps; ++i)
    {
      if (f1 < f2)
      {
        upper = x2;
        x2 = x1;
        f2 = f1;
        x1 = upper - (upper - lower) * ratio;
        f1 = squaredDistanceAt(x1);
      }
      else
      {
        lower = x1;
        x1 = x2;
        f1 = f2;
        x2 = lower + (upper - lower) * ratio;
        f2 = squaredDistanceAt(x2);
      }
    }
    // The ends are candidates too (the search never evaluates them).
    m_argmin = f1 < f2 ? x1 : x2;
    T best = f1 < f2 ? f1 : f2;
    if (squaredDistanceAt(T(0)) <= best)
    {
      best = squaredDistanceAt(T(0));
      m_argmin = 0;
    }
    if (squaredDistanceAt(T(1)) < best)
    {
      m_argmin = 1;
    }
  }

  ExtVec<T> m_start;
  ExtVec<T> m_motion;
  ExtVec<T> m_a;
  ExtVec<T> m_b;
  ExtVec<T> m_c;
  T m_argmin = 0;
};

} // namespace proxima::test
