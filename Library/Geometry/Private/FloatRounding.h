// Rounding doubles to the floats the sphere tree stores, in the direction that keeps a stored
// sphere holding what the exact one held (SphereTree.cpp builds with them, SphereTreeRefit.cpp
// refits with them).
#pragma once

#include "Core/Vec3.h"

#include <cmath>
#include <limits>

namespace proxima::detail
{
/// `value` rounded up to the next float that is not smaller.
inline float roundUpToFloat(double value)
{
  float f = static_cast<float>(value);
  if (static_cast<double>(f) < value)
  {
    f = std::nextafter(f, std::numeric_limits<float>::infinity());
  }
  return f;
}

/// A float not smaller than `value` (positive, normal or zero), without a branch: at most two
/// float ulps above it. `value` raised by 2^-23 of itself is at least half an ulp above it, so its
/// nearest float is above `value`. For loops over many spheres, where roundUpToFloat's branch
/// goes either way at random and its mispredictions cost more than the arithmetic.
inline float roundUpToFloatWithoutBranch(double value)
{
  return static_cast<float>(value * (1.0 + 0x1p-23));
}

/// One coordinate rounded to the nearest float, widened back. Kept out of line on purpose: GCC
/// 12.2 at -O2/-O3 vectorises the three conversions of a Vec3 and then folds the
/// narrowing-widening pair of the vector away, returning x and y unrounded (seen in the generated
/// code; the tree's containment test caught it). A scalar call per coordinate cannot be combined
/// that way.
[[gnu::noinline]] inline double roundToFloat(double value)
{
  return static_cast<double>(static_cast<float>(value));
}

/// Each coordinate of `v` rounded to the nearest float (roundToFloat).
inline Vec3 roundToFloatPrecision(const Vec3& v)
{
  return {roundToFloat(v.x), roundToFloat(v.y), roundToFloat(v.z)};
}
} // namespace proxima::detail
