// The Falcon's linkage as libnifalcon measures it (FalconSpecification.h), in our own
// derivation. Three motors turn upper arms by angles theta; each upper arm carries, through a
// short knee link, a parallelogram shin whose far end joins the grip through another short link;
// the grip only translates.
//
// Arm i has its own frame: u = (cos phi_i, sin phi_i, 0), v = (-sin phi_i, cos phi_i, 0) (the
// motor axis), w = z. Its hip is at H = r u + s v, its knee at K(theta) = H + a (cos theta u +
// sin theta w), and the shin reaches the grip centre P at the joint Q = P + c u + f v. The two
// short links (lengths d, e) turn about axes parallel to v, so they stay in the u-w plane and
// point the way the shin leans in that plane. Writing D = Q - K, with D_v its component along v
// and rho the length of the rest, the shin of length b requires
//   (rho - (d + e))^2 + D_v^2 = b^2,  rho >= d + e:
// Q lies on a torus about K, not a sphere, so the three arms are not a plain trilateration.
// Forward kinematics solves it by repeated trilateration: for a guess of P, each torus touches
// the sphere of radius b about K + (d + e) n (n: the unit u-w direction of D), and the three
// spheres' intersection is the next guess; at the fixed point the torus equations hold exactly.
// The inverse is closed-form per arm, and the Jacobian J = d(position)/d(angles) maps a force on
// the grip to motor torques, tau = J^T F.
#pragma once

#include "Core/Vec3.h"
#include "Devices/FalconSpecification.h"

#include <array>
#include <optional>

namespace proxima
{

/// The linkage dimensions in metres and the arms' directions in radians; libnifalcon's letters
/// in brackets.
struct DeltaGeometry
{
  /// [a] Upper arm: hip (motor axis) to knee.
  double upperArm = falcon::kUpperArm;
  /// [b] Lower arm: the length of the shin parallelogram's sides.
  double lowerArm = falcon::kLowerArm;
  /// [e] Short link from the knee to the shin.
  double kneeLink = falcon::kKneeLink;
  /// [d] Short link from the shin to the grip's joint; only kneeLink + effectorLink matters.
  double effectorLink = falcon::kEffectorLink;
  /// [c] The grip's joint of each arm relative to the grip centre, along the arm's u.
  double effectorRadial = falcon::kEffectorRadial;
  /// [f] The grip's joint of each arm relative to the grip centre, along the arm's motor axis v.
  double effectorAlongAxis = falcon::kEffectorAlongAxis;
  /// [r] The hip relative to the base centre, along the arm's u.
  double hipRadial = falcon::kHipRadial;
  /// [s] The hip relative to the base centre, along the arm's motor axis v.
  double hipAlongAxis = falcon::kHipAlongAxis;
  /// [phy] Direction phi_i of each arm's u axis about the base's z axis (rad).
  std::array<double, 3> armAngles{falcon::kArmAngles[0], falcon::kArmAngles[1],
                                  falcon::kArmAngles[2]};
};

/// One value per arm, arm 1 to 3: angles (rad) or, from torques(), torques (N m).
using JointAngles = std::array<double, 3>;
/// Row-major 3x3: jacobian[row][column], row = position axis, column = joint.
using Matrix3 = std::array<std::array<double, 3>, 3>;

/// Forward and inverse kinematics and the Jacobian of the Falcon's delta linkage, for one
/// DeltaGeometry.
class DeltaKinematics
{
public:
  /// Precomputes each arm's frame, hip and grip joint from `geometry`.
  explicit DeltaKinematics(const DeltaGeometry& geometry = DeltaGeometry{});

  /// Grip centre for the three arm angles (radians, from each arm's u axis toward +z, the side
  /// the grip is on), in the base frame (z along the delta axis, toward the user). nullopt where
  /// the arms cannot meet.
  std::optional<Vec3> forward(const JointAngles& angles) const;
  /// Angles that put the grip centre at `position`, knees out; nullopt outside the reachable
  /// space.
  std::optional<JointAngles> inverse(const Vec3& position) const;
  /// d(position)/d(angles) at `angles`; nullopt at a singular pose.
  std::optional<Matrix3> jacobian(const JointAngles& angles) const;
  /// Motor torques (N m, toward larger angles) that balance `force` (N) on the grip:
  /// tau = J^T F. Zero at a singular pose, where no finite torques would do.
  JointAngles torques(const JointAngles& angles, const Vec3& force) const;

  /// The linkage this instance was built for.
  const DeltaGeometry& geometry() const { return m_geometry; }

private:
  struct ArmFrame
  {
    Vec3 u;
    Vec3 v;
    Vec3 hip;
    /// Q - P: where the shin joins the grip, relative to the grip centre.
    Vec3 effectorOffset;
  };

  Vec3 knee(int arm, double theta) const;
  Vec3 kneeDerivative(int arm, double theta) const;
  /// Centre of the sphere of radius b that touches arm `arm`'s torus where the grip centre
  /// `position` is (the knee, moved out along the shin's lean by the two short links, and back
  /// by the effector offset).
  Vec3 sphereCentre(int arm, const Vec3& kneePoint, const Vec3& position) const;
  /// Distance of `position` from arm `arm`'s torus constraint (zero on it), in metres.
  double constraintError(int arm, double theta, const Vec3& position) const;

  DeltaGeometry m_geometry;
  std::array<ArmFrame, 3> m_arms{};
};

} // namespace proxima
