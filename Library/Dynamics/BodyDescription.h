// What moves in a scene with dynamics (paper section 6; DESIGN.md section 3, "Bodies"): a rigid
// body per moving object, held to the world by one joint, with the mass properties of its solid.
// Every body starts at rest in the pose its object was placed in: the body's frame is the world
// frame at the start, so that a pose maps the object's points as placed to where they are now.
#pragma once

#include "Core/Vec3.h"
#include "Dynamics/SolidMassProperties.h"

#include <string>
#include <vector>

namespace proxima
{

enum class JointType
{
  /// Rotation about `axis` through `anchor`; q in radians.
  Hinge,
  /// Translation along `axis`; q in metres.
  Slide,
  /// Rotation about `anchor` in every direction; no single coordinate.
  Ball,
  /// No joint: six degrees of freedom.
  Free,
  /// A body of an MJCF mechanism without one joint of its own to the world: several joints, or
  /// none (welded to a parent that moves); no single coordinate.
  Mechanism,
};

/// "hinge", "slide", "ball", "free", "mechanism".
const char* jointTypeName(JointType type);

struct JointDescription
{
  JointType type = JointType::Hinge;
  /// Unit or not (normalised); not used by ball and free joints.
  Vec3 axis{0.0, 0.0, 1.0};
  /// A point on the axis (hinge, slide: where the joint is drawn) or the ball's centre, world
  /// frame, metres.
  Vec3 anchor;
  /// Limits of q (hinge, slide) when `limited`.
  bool limited = false;
  double range[2] = {0.0, 0.0};
  /// Spring toward q = 0 (N m/rad or N/m) and viscous damping (N m s/rad or N s/m).
  double stiffness = 0.0;
  double damping = 0.0;
};

struct BodyDescription
{
  /// Names the body in messages and in MuJoCo's model.
  std::string name;
  JointDescription joint;
  /// Mass, centre of mass and inertia in the world frame at the start.
  SolidMassProperties mass;
};

struct DynamicsSettings
{
  /// The integration step: the haptic servo's period.
  double timeStep = 1e-3;
  /// m/s^2, world frame (a scene has no "up" of its own: zero unless the scene gives it).
  Vec3 gravity;
};

} // namespace proxima
