#include "Devices/FalconKinematics.h"

#include <cmath>
#include <numbers>

namespace proxima
{
namespace
{
double determinant(const Matrix3& m)
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
} // namespace

DeltaKinematics::DeltaKinematics(const DeltaGeometry& geometry) : m_geometry(geometry)
{
  // Arm i sits at 120 i degrees around the base's z axis.
  for (int i = 0; i < 3; ++i)
  {
    const double phi = 2.0 * std::numbers::pi * i / 3.0;
    m_cos[static_cast<std::size_t>(i)] = std::cos(phi);
    m_sin[static_cast<std::size_t>(i)] = std::sin(phi);
  }
}

Vec3 DeltaKinematics::sphereCentre(int arm, double theta) const
{
  const double radial =
    m_geometry.baseRadius - m_geometry.effectorRadius + m_geometry.upperArm * std::cos(theta);
  const auto i = static_cast<std::size_t>(arm);
  return {radial * m_cos[i], radial * m_sin[i], -m_geometry.upperArm * std::sin(theta)};
}

Vec3 DeltaKinematics::sphereCentreDerivative(int arm, double theta) const
{
  const double radial = -m_geometry.upperArm * std::sin(theta);
  const auto i = static_cast<std::size_t>(arm);
  return {radial * m_cos[i], radial * m_sin[i], -m_geometry.upperArm * std::cos(theta)};
}

std::optional<Vec3> DeltaKinematics::forward(const JointAngles& angles) const
{
  // Trilateration of three spheres of equal radius (the lower arm) about c1, c2, c3.
  const Vec3 c1 = sphereCentre(0, angles[0]);
  const Vec3 c2 = sphereCentre(1, angles[1]);
  const Vec3 c3 = sphereCentre(2, angles[2]);
  const double d = distance(c1, c2);
  if (!(d > 0.0))
  {
    return std::nullopt;
  }
  const Vec3 ex = (c2 - c1) / d;
  const double i = dot(ex, c3 - c1);
  const Vec3 inPlane = c3 - c1 - ex * i;
  const double j = norm(inPlane);
  if (!(j > 1e-12))
  {
    return std::nullopt;
  }
  const Vec3 ey = inPlane / j;
  const Vec3 ez = cross(ex, ey);
  const double x = 0.5 * d;
  const double y = (i * i + j * j - 2.0 * i * x) / (2.0 * j);
  const double b = m_geometry.lowerArm;
  const double zSquared = b * b - x * x - y * y;
  if (!(zSquared >= 0.0))
  {
    return std::nullopt;
  }
  const double z = std::sqrt(zSquared);
  const Vec3 base = c1 + ex * x + ey * y;
  const Vec3 a = base + ez * z;
  const Vec3 other = base - ez * z;
  return a.z < other.z ? a : other;
}

std::optional<JointAngles> DeltaKinematics::inverse(const Vec3& position) const
{
  // In arm i's frame (x outward, z up) the grip is at (px, py, pz); the sphere centre is at
  // (k + a cos t, 0, -a sin t) with k = base - effector radius. |p - c|^2 = b^2 gives
  // d cos t + pz sin t = K with d = k - px, which is rho cos(t - alpha) = K.
  JointAngles angles{};
  const double a = m_geometry.upperArm;
  const double b = m_geometry.lowerArm;
  const double k = m_geometry.baseRadius - m_geometry.effectorRadius;
  for (std::size_t arm = 0; arm < 3; ++arm)
  {
    const double px = m_cos[arm] * position.x + m_sin[arm] * position.y;
    const double py = -m_sin[arm] * position.x + m_cos[arm] * position.y;
    const double pz = position.z;
    const double d = k - px;
    const double bigK = (b * b - py * py - d * d - a * a - pz * pz) / (2.0 * a);
    const double rho = std::hypot(d, pz);
    if (!(rho > 0.0) || std::abs(bigK) > rho)
    {
      return std::nullopt;
    }
    const double alpha = std::atan2(pz, d);
    // Of the two elbow poses, the one with the elbow outward (the larger angle from the
    // horizontal toward the grip below) is how the Falcon is built.
    const double t1 = alpha + std::acos(bigK / rho);
    const double t2 = alpha - std::acos(bigK / rho);
    const double outward1 = std::cos(t1);
    const double outward2 = std::cos(t2);
    angles[arm] = outward1 >= outward2 ? t1 : t2;
    // Keep the angle in (-pi, pi].
    angles[arm] = std::remainder(angles[arm], 2.0 * std::numbers::pi);
  }
  return angles;
}

std::optional<Matrix3> DeltaKinematics::jacobian(const JointAngles& angles) const
{
  // Each arm's constraint g_i = |p - c_i(t_i)|^2 - b^2 = 0 differentiates to
  // (p - c_i) . dp = (p - c_i) . c_i' dt_i, so A dp = B dt with A's rows (p - c_i) and B
  // diagonal: J = A^-1 B.
  const auto position = forward(angles);
  if (!position)
  {
    return std::nullopt;
  }
  Matrix3 rows{};
  std::array<double, 3> diagonal{};
  for (int arm = 0; arm < 3; ++arm)
  {
    const auto i = static_cast<std::size_t>(arm);
    const Vec3 r = *position - sphereCentre(arm, angles[i]);
    rows[i] = {r.x, r.y, r.z};
    diagonal[i] = dot(r, sphereCentreDerivative(arm, angles[i]));
  }
  const double det = determinant(rows);
  const double scale = m_geometry.lowerArm * m_geometry.lowerArm * m_geometry.lowerArm;
  if (!(std::abs(det) > 1e-9 * scale))
  {
    return std::nullopt;
  }
  // The inverse of A by cofactors, then J = A^-1 B (column j of A^-1 scaled by B_jj).
  Matrix3 inverse{};
  for (std::size_t r = 0; r < 3; ++r)
  {
    for (std::size_t c = 0; c < 3; ++c)
    {
      const std::size_t r1 = (c + 1) % 3;
      const std::size_t r2 = (c + 2) % 3;
      const std::size_t c1 = (r + 1) % 3;
      const std::size_t c2 = (r + 2) % 3;
      inverse[r][c] = (rows[r1][c1] * rows[r2][c2] - rows[r1][c2] * rows[r2][c1]) / det;
    }
  }
  Matrix3 result{};
  for (std::size_t r = 0; r < 3; ++r)
  {
    for (std::size_t c = 0; c < 3; ++c)
    {
      result[r][c] = inverse[r][c] * diagonal[c];
    }
  }
  return result;
}

JointAngles DeltaKinematics::torques(const JointAngles& angles, const Vec3& force) const
{
  const auto j = jacobian(angles);
  if (!j)
  {
    return {0.0, 0.0, 0.0};
  }
  JointAngles tau{};
  for (std::size_t c = 0; c < 3; ++c)
  {
    tau[c] = (*j)[0][c] * force.x + (*j)[1][c] * force.y + (*j)[2][c] * force.z;
  }
  return tau;
}

} // namespace proxima
