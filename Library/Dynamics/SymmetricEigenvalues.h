// The eigenvalues of a symmetric 3 x 3 matrix by the trigonometric closed form (no iteration):
// for the Dynamics layer's bounds on effective masses, from an inertia tensor (a body's least
// principal inertia) or from a point's mobility J M^-1 J^T (the largest).
#pragma once

#include "Core/Vec3.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace proxima
{

/// The eigenvalues of the symmetric matrix with rows `a`, least first.
inline std::array<double, 3> symmetricEigenvalues(const std::array<Vec3, 3>& a)
{
  const double offDiagonal = a[0].y * a[0].y + a[0].z * a[0].z + a[1].z * a[1].z;
  if (offDiagonal == 0.0)
  {
    std::array<double, 3> diagonal{a[0].x, a[1].y, a[2].z};
    std::sort(diagonal.begin(), diagonal.end());
    return diagonal;
  }
  const double mean = (a[0].x + a[1].y + a[2].z) / 3.0;
  const double spread =
    std::sqrt(((a[0].x - mean) * (a[0].x - mean) + (a[1].y - mean) * (a[1].y - mean) +
               (a[2].z - mean) * (a[2].z - mean) + 2.0 * offDiagonal) /
              6.0);
  std::array<Vec3, 3> b = a;
  for (int k = 0; k < 3; ++k)
  {
    b[k][k] -= mean;
    b[k] = b[k] / spread;
  }
  const double determinant = dot(b[0], cross(b[1], b[2]));
  const double angle = std::acos(std::clamp(determinant / 2.0, -1.0, 1.0)) / 3.0;
  // The roots are mean + 2 spread cos(angle + 2 pi k / 3): k = 1 the least, k = 0 the largest.
  return {mean + 2.0 * spread * std::cos(angle + 2.0 * M_PI / 3.0),
          mean + 2.0 * spread * std::cos(angle + 4.0 * M_PI / 3.0),
          mean + 2.0 * spread * std::cos(angle)};
}

} // namespace proxima
