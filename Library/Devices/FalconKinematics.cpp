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

/// The point at distance `radius` from c1, c2 and c3 on the +z side (the grip's side of the
/// knees); nullopt where the spheres do not meet or the centres are in a line.
std::optional<Vec3> trilaterate(const Vec3& c1, const Vec3& c2, const Vec3& c3, double radius)
{
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
  // Equal radii: the point is on the plane halfway between c1 and c2, and equally far from c1
  // and c3.
  const double x = 0.5 * d;
  const double y = (i * i + j * j - 2.0 * i * x) / (2.0 * j);
  const double zSquared = radius * radius - x * x - y * y;
  if (!(zSquared >= 0.0))
  {
    return std::nullopt;
  }
  const double z = std::sqrt(zSquared);
  const Vec3 base = c1 + ex * x + ey * y;
  const Vec3 a = base + ez * z;
  const Vec3 other = base - ez * z;
  return a.z > other.z ? a : other;
}

// Forward kinematics stops when a trilateration moves the guess less than this (metres), and
// gives up after this many. The sphere touches the torus, so a guess off by e gives spheres off
// by about e^2 / (b + d + e): three or four steps reach the tolerance from the first guess.
constexpr double kForwardTolerance = 1e-13;
constexpr int kForwardMaxSteps = 64;
// A solution must meet every arm's torus within this (metres).
constexpr double kConstraintTolerance = 1e-9;
} // namespace

DeltaKinematics::DeltaKinematics(const DeltaGeometry& geometry)
  : m_geometry(geometry)
{
  for (std::size_t i = 0; i < 3; ++i)
  {
    const double phi = geometry.armAngles[i];
    ArmFrame& arm = m_arms[i];
    arm.u = {std::cos(phi), std::sin(phi), 0.0};
    arm.v = {-std::sin(phi), std::cos(phi), 0.0};
    arm.hip = arm.u * geometry.hipRadial + arm.v * geometry.hipAlongAxis;
    arm.effectorOffset = arm.u * geometry.effectorRadial + arm.v * geometry.effectorAlongAxis;
  }
}

Vec3 DeltaKinematics::knee(int arm, double theta) const
{
  const ArmFrame& frame = m_arms[static_cast<std::size_t>(arm)];
  const double a = m_geometry.upperArm;
  return frame.hip + frame.u * (a * std::cos(theta)) + Vec3{0.0, 0.0, a * std::sin(theta)};
}

Vec3 DeltaKinematics::kneeDerivative(int arm, double theta) const
{
  const ArmFrame& frame = m_arms[static_cast<std::size_t>(arm)];
  const double a = m_geometry.upperArm;
  return frame.u * (-a * std::sin(theta)) + Vec3{0.0, 0.0, a * std::cos(theta)};
}

Vec3 DeltaKinematics::sphereCentre(int arm, const Vec3& kneePoint, const Vec3& position) const
{
  const ArmFrame& frame = m_arms[static_cast<std::size_t>(arm)];
  const Vec3 shin = position + frame.effectorOffset - kneePoint;
  const Vec3 lean = shin - frame.v * dot(frame.v, shin);
  const double length = norm(lean);
  // A shin exactly along the motor axis has no lean; the links then point along +z, an
  // arbitrary choice at a pose the Falcon cannot reach.
  const Vec3 direction = length > 1e-12 ? lean / length : Vec3{0.0, 0.0, 1.0};
  const double links = m_geometry.kneeLink + m_geometry.effectorLink;
  return kneePoint + direction * links - frame.effectorOffset;
}

double DeltaKinematics::constraintError(int arm, double theta, const Vec3& position) const
{
  const ArmFrame& frame = m_arms[static_cast<std::size_t>(arm)];
  const Vec3 shin = position + frame.effectorOffset - knee(arm, theta);
  const double along = dot(frame.v, shin);
  const double rho = norm(shin - frame.v * along);
  const double links = m_geometry.kneeLink + m_geometry.effectorLink;
  if (rho < links)
  {
    // The other assembly mode (the shin folded back across the links): not the Falcon's.
    return links - rho + m_geometry.lowerArm;
  }
  return std::hypot(rho - links, along) - m_geometry.lowerArm;
}

std::optional<Vec3> DeltaKinematics::forward(const JointAngles& angles) const
{
  const std::array<Vec3, 3> knees{knee(0, angles[0]), knee(1, angles[1]), knee(2, angles[2])};
  // First guess: each shin straight out of its knee, links and shin in one line of length
  // b + d + e (exact where the shins lie in their arms' u-w planes).
  const double links = m_geometry.kneeLink + m_geometry.effectorLink;
  std::optional<Vec3> position =
    trilaterate(knees[0] - m_arms[0].effectorOffset, knees[1] - m_arms[1].effectorOffset,
                knees[2] - m_arms[2].effectorOffset, m_geometry.lowerArm + links);
  for (int step = 0; position && step < kForwardMaxSteps; ++step)
  {
    const auto next =
      trilaterate(sphereCentre(0, knees[0], *position), sphereCentre(1, knees[1], *position),
                  sphereCentre(2, knees[2], *position), m_geometry.lowerArm);
    if (!next)
    {
      return std::nullopt;
    }
    const double moved = distance(*next, *position);
    position = next;
    if (moved < kForwardTolerance)
    {
      break;
    }
  }
  if (!position)
  {
    return std::nullopt;
  }
  for (int arm = 0; arm < 3; ++arm)
  {
    if (!(std::abs(constraintError(arm, angles[static_cast<std::size_t>(arm)], *position)) <
          kConstraintTolerance))
    {
      return std::nullopt;
    }
  }
  return position;
}

std::optional<JointAngles> DeltaKinematics::inverse(const Vec3& position) const
{
  // In arm i's frame the shin's grip end is at q = Q - H = (qu, qv, qw). Its component along
  // the motor axis fixes how far the shin leans out of the u-w plane, hence the length
  // L = d + e + sqrt(b^2 - qv^2) it spans in that plane; the knee must then be at distance L
  // from (qu, qw): (qu - a cos t)^2 + (qw - a sin t)^2 = L^2, that is
  // qu cos t + qw sin t = K with K = (qu^2 + qw^2 + a^2 - L^2) / (2 a), or rho cos(t - alpha) = K.
  JointAngles angles{};
  const double a = m_geometry.upperArm;
  const double b = m_geometry.lowerArm;
  const double links = m_geometry.kneeLink + m_geometry.effectorLink;
  for (std::size_t arm = 0; arm < 3; ++arm)
  {
    const ArmFrame& frame = m_arms[arm];
    const Vec3 q = position + frame.effectorOffset - frame.hip;
    const double qu = dot(frame.u, q);
    const double qv = dot(frame.v, q);
    const double qw = q.z;
    if (!(std::abs(qv) <= b))
    {
      return std::nullopt;
    }
    const double span = links + std::sqrt(b * b - qv * qv);
    const double bigK = (qu * qu + qw * qw + a * a - span * span) / (2.0 * a);
    const double rho = std::hypot(qu, qw);
    if (!(rho > 0.0) || std::abs(bigK) > rho)
    {
      return std::nullopt;
    }
    const double alpha = std::atan2(qw, qu);
    // Of the two knee poses, the Falcon's is the one with the knee out, away from the base
    // axis (the larger u).
    const double t1 = alpha + std::acos(bigK / rho);
    const double t2 = alpha - std::acos(bigK / rho);
    const double theta = std::cos(t1) >= std::cos(t2) ? t1 : t2;
    // Keep the angle in (-pi, pi].
    angles[arm] = std::remainder(theta, 2.0 * std::numbers::pi);
  }
  return angles;
}

std::optional<Matrix3> DeltaKinematics::jacobian(const JointAngles& angles) const
{
  // Each arm's constraint g_i = |P - S_i|^2 - b^2 = 0, with S_i the sphere centre of
  // sphereCentre(), differentiates to (P - S_i) . dP = (P - S_i) . K_i' dt_i: S_i moves with the
  // knee, and its turn with the shin's lean is perpendicular to P - S_i, so it drops out. So
  // A dP = B dt with A's rows (P - S_i) and B diagonal: J = A^-1 B.
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
    const Vec3 kneePoint = knee(arm, angles[i]);
    const Vec3 r = *position - sphereCentre(arm, kneePoint, *position);
    rows[i] = {r.x, r.y, r.z};
    diagonal[i] = dot(r, kneeDerivative(arm, angles[i]));
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
