#include "IO/Scene/ScenePose.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace proxima
{
namespace
{
// The rotation matrix of a unit quaternion, computed once per soup rather than per point.
using Matrix3 = std::array<Vec3, 3>; // rows

Matrix3 rotationMatrix(const UnitQuaternion& q)
{
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  return {Vec3{1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)},
          Vec3{2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)},
          Vec3{2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)}};
}

Vec3 times(const Matrix3& m, const Vec3& v)
{
  return {dot(m[0], v), dot(m[1], v), dot(m[2], v)};
}
} // namespace

UnitQuaternion UnitQuaternion::fromAxisAngle(const Vec3& axis, double degrees)
{
  if (!isFinite(axis) || !std::isfinite(degrees))
  {
    throw std::invalid_argument("axis-angle rotation with a number that is not finite");
  }
  // Scaled by its largest component first: an axis of 1e300 or 1e-300 keeps its direction.
  const Vec3 unit = overflowSafeDirection(axis);
  if (!(maxAbsComponent(unit) > 0.0))
  {
    throw std::invalid_argument("axis-angle rotation about an axis without direction");
  }
  // Reduce the angle first so that a whole number of turns gives the identity exactly.
  const double half = std::remainder(degrees, 360.0) * std::numbers::pi / 360.0;
  const double s = std::sin(half);
  return {std::cos(half), unit.x * s, unit.y * s, unit.z * s};
}

UnitQuaternion UnitQuaternion::normalized(double w, double x, double y, double z)
{
  const double length = std::sqrt(w * w + x * x + y * y + z * z);
  if (!std::isfinite(length) || !(length > 0.0))
  {
    throw std::invalid_argument("quaternion of zero or non-finite norm");
  }
  return {w / length, x / length, y / length, z / length};
}

Vec3 rotate(const UnitQuaternion& rotation, const Vec3& v)
{
  return times(rotationMatrix(rotation), v);
}

TriangleSoup posed(TriangleSoup soup, const ScenePose& pose)
{
  if (pose.isIdentity())
  {
    return soup;
  }
  const Matrix3 r = rotationMatrix(pose.rotation);
  for (Vec3& point : soup.points)
  {
    point = times(r, point) + pose.translation;
  }
  for (Vec3& normal : soup.pointNormals)
  {
    normal = times(r, normal);
  }
  return soup;
}

} // namespace proxima
