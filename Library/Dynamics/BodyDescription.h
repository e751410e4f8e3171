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

/// How a body is held to the world.
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

/// The one joint that holds a body to the world, in the world frame at the start.
struct JointDescription
{
  /// The kind of joint; `axis`, `range` and the units of q follow from it.
  JointType type = JointType::Hinge;
  /// Unit or not (normalised); not used by ball and free joints.
  Vec3 axis{0.0, 0.0, 1.0};
  /// A point on the axis (hinge, slide: where the joint is drawn) or the ball's centre, world
  /// frame, metres.
  Vec3 anchor;
  /// Whether q is kept within `range` (hinge and slide only; other joints have no range).
  bool limited = false;
  /// Lower and upper limits of q when `limited` (radians for a hinge, metres for a slide);
  /// low < high.
  double range[2] = {0.0, 0.0};
  /// Stiffness of a spring toward q = 0 (N m/rad or N/m), not negative.
  double stiffness = 0.0;
  /// Viscous damping of the joint (N m s/rad or N s/m), not negative.
  double damping = 0.0;
};

/// A rigid body of a scene as its dynamics needs it: a name, a joint, and mass properties.
struct BodyDescription
{
  /// Names the body in messages and in MuJoCo's model.
  std::string name;
  /// The joint that holds the body to the world.
  JointDescription joint;
  /// Mass, centre of mass and inertia in the world frame at the start.
  SolidMassProperties mass;
};

/// The settings of the bodies' world, shared by all its bodies (an MJCF mechanism takes only
/// `timeStep`, and keeps its file's gravity).
struct DynamicsSettings
{
  /// The integration step: the haptic servo's period.
  double timeStep = 1e-3;
  /// m/s^2, world frame (a scene has no "up" of its own: zero unless the scene gives it).
  Vec3 gravity;
};

} // namespace proxima
