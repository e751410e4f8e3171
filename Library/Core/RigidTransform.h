// A rigid motion of space: a rotation (an orthonormal matrix) then a translation. Where a moving
// body is now (paper section 6): a point p of its object as placed goes to R p + t. Plain C++ for
// the real-time kernel; the Dynamics layer fills it from its bodies' quaternions.
#pragma once

#include "Core/Vec3.h"

namespace proxima
{

/// A rotation R (orthonormal, stored by rows) followed by a translation t: a point p goes to
/// R p + t. The default is the identity.
struct RigidTransform
{
  /// Rows of R.
  Vec3 row[3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  /// t (m), applied after the rotation.
  Vec3 translation;

  /// R p + t.
  Vec3 apply(const Vec3& point) const { return rotate(point) + translation; }
  /// R v: a direction or a normal (R is orthonormal, so normals need no inverse transpose).
  Vec3 rotate(const Vec3& vector) const
  {
    return {dot(row[0], vector), dot(row[1], vector), dot(row[2], vector)};
  }
  /// R^T (p - t): the point of the object as placed that is now at `point`.
  Vec3 applyInverse(const Vec3& point) const { return rotateInverse(point - translation); }
  /// R^T v.
  Vec3 rotateInverse(const Vec3& vector) const
  {
    return row[0] * vector.x + row[1] * vector.y + row[2] * vector.z;
  }
  /// True when both rotations and translations are exactly equal, component by component.
  bool operator==(const RigidTransform& other) const
  {
    return row[0] == other.row[0] && row[1] == other.row[1] && row[2] == other.row[2] &&
           translation == other.translation;
  }
  /// True when any component of the rotation or translation differs.
  bool operator!=(const RigidTransform& other) const { return !(*this == other); }

  /// The rotation of the unit quaternion (w, x, y, z) (normalised here), then `offset`.
  static RigidTransform fromQuaternion(double w, double x, double y, double z, const Vec3& offset)
  {
    const double length = std::sqrt(w * w + x * x + y * y + z * z);
    RigidTransform transform;
    if (length > 0.0)
    {
      w /= length;
      x /= length;
      y /= length;
      z /= length;
      transform.row[0] = {1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z),
                          2.0 * (x * z + w * y)};
      transform.row[1] = {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z),
                          2.0 * (y * z - w * x)};
      transform.row[2] = {2.0 * (x * z - w * y), 2.0 * (y * z + w * x),
                          1.0 - 2.0 * (x * x + y * y)};
    }
    transform.translation = offset;
    return transform;
  }
};

} // namespace proxima
