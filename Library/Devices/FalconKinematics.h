// The Falcon as a rotary delta robot: three motors on a base triangle, each turning an upper arm
// by an angle theta; parallelogram lower arms of one length carry the grip, which only
// translates. Forward kinematics solves the grip position from the three angles (the
// intersection of three spheres), inverse kinematics each angle from a position, and the
// Jacobian J = d(position)/d(angles) maps a force on the grip to motor torques, tau = J^T F.
// The geometry is the Falcon's size, not its exact linkage (Documentation/Devices.md).
#pragma once

#include "Core/Vec3.h"

#include <array>
#include <optional>

namespace proxima
{

struct DeltaGeometry
{
  /// Distance from the base centre to each motor axis, and from the grip centre to each lower
  /// arm's attachment, in metres.
  double baseRadius = 0.055;
  double effectorRadius = 0.015;
  /// Upper (motor) arm and lower (parallelogram) arm lengths in metres.
  double upperArm = 0.060;
  double lowerArm = 0.1025;
};

using JointAngles = std::array<double, 3>;
/// Row-major 3x3: jacobian[row][column], row = position axis, column = joint.
using Matrix3 = std::array<std::array<double, 3>, 3>;

class DeltaKinematics
{
public:
  explicit DeltaKinematics(const DeltaGeometry& geometry = DeltaGeometry{});

  /// Grip position for the three upper-arm angles (radians, 0 = arm horizontal, positive =
  /// down); the solution below the base. nullopt where the arms cannot meet.
  std::optional<Vec3> forward(const JointAngles& angles) const;
  /// Angles that put the grip at `position`, elbows out; nullopt outside the reachable space.
  std::optional<JointAngles> inverse(const Vec3& position) const;
  /// d(position)/d(angles) at `angles`; nullopt at a singular pose.
  std::optional<Matrix3> jacobian(const JointAngles& angles) const;
  /// Motor torques (N m) that balance `force` (N) on the grip: tau = J^T F. Zero at a singular
  /// pose, where no finite torques would do.
  JointAngles torques(const JointAngles& angles, const Vec3& force) const;

  const DeltaGeometry& geometry() const { return m_geometry; }

private:
  /// Centre of the sphere the grip centre must lie on for arm i at angle theta (the elbow,
  /// shifted in by the effector radius), and its derivative in theta.
  Vec3 sphereCentre(int arm, double theta) const;
  Vec3 sphereCentreDerivative(int arm, double theta) const;

  DeltaGeometry m_geometry;
  std::array<double, 3> m_cos{};
  std::array<double, 3> m_sin{};
};

} // namespace proxima
