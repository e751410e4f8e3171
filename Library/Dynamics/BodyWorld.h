// The bodies of a scene and their integration (paper section 6) on MuJoCo, whose headers stay in
// BodyWorld.cpp. Each haptic tick: applyForce for the touched body (the force the device renders,
// equal and opposite, at the contact point: J^T f_c, eqs. 23-24), then step(), then pose() moves
// each body's object for the next proxy update. MuJoCo's messages are Proxima's once a world
// is made: a warning is one line on standard error (`proxima: MuJoCo warning: ...`), an error a
// std::runtime_error thrown from the call that met it; neither reaches standard output, and no
// MUJOCO_LOG.TXT is written.
#pragma once

#include "Core/Vec3.h"
#include "Dynamics/BodyDescription.h"

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace proxima
{

/// A rigid transform: a point p of the object as placed goes to position + rotate(p).
struct BodyPose
{
  /// Translation (m, world frame), applied after the rotation.
  Vec3 position;
  /// Unit quaternion w, x, y, z.
  double orientation[4] = {1.0, 0.0, 0.0, 0.0};

  /// Where the point `point` of the object as placed is under this pose (world frame, m).
  Vec3 apply(const Vec3& point) const;
};

/// The mechanical energy of the bodies (or of one body), for reports and tests.
struct BodyEnergy
{
  /// Joules: the bodies' kinetic energy.
  double kinetic = 0.0;
  /// Joules: the bodies' potential energy in gravity and joint springs (zero at the start pose
  /// for the springs; gravity's zero is the world origin).
  double potential = 0.0;
};

/// An MJCF file's bodies could not be bound as asked: `binding` is the index, in the names
/// given, of the one that failed.
struct MechanismBindingError : std::invalid_argument
{
  /// An error about the binding `index`, with the message `what`.
  MechanismBindingError(std::size_t index, const std::string& what)
    : std::invalid_argument(what)
    , binding(index)
  {}
  /// Index, in the body names given, of the binding that failed.
  std::size_t binding;
};

/// The bodies of a scene on MuJoCo: builds the model, applies the finger's forces and steps it
/// at the haptic rate. Body i is the i-th BodyDescription (or bound MJCF body) given. Not
/// thread-safe: one thread at a time drives it, the one that steps the proxy.
class BodyWorld
{
public:
  /// Builds MuJoCo's model of `bodies`. Throws std::invalid_argument naming the body and the
  /// defect (a zero axis, a mass or inertia that is not positive, a range that is empty, a
  /// negative stiffness or damping, a time step that is not positive) or MuJoCo's complaint.
  BodyWorld(const std::vector<BodyDescription>& bodies, const DynamicsSettings& settings);
  /// Loads the MJCF file `mjcfFile` (a mechanism: bodies on joints, nested, as MuJoCo reads them)
  /// and binds its bodies named in `boundBodies`, in that order, as this world's bodies 0, 1, ...
  /// (a name may come more than once). Its time step becomes `settings.timeStep` (the servo's
  /// period); its gravity and everything else stay the file's. Throws std::invalid_argument with
  /// MuJoCo's complaint, or MechanismBindingError for a name the file has not or a body fixed
  /// to the world.
  BodyWorld(const std::string& mjcfFile, const std::vector<std::string>& boundBodies,
            const DynamicsSettings& settings);
  ~BodyWorld();
  BodyWorld(const BodyWorld&) = delete;
  BodyWorld& operator=(const BodyWorld&) = delete;

  /// How many bodies the world has bound (those given, in order).
  std::size_t numBodies() const;
  /// Seconds of simulated time since the world was made (0 at the start; step() adds one time
  /// step).
  double time() const;
  /// The settings the world was made with.
  const DynamicsSettings& settings() const { return m_settings; }

  /// Adds `force` (N, world frame) at `point` (world) on `body` for the next step only.
  void applyForce(std::size_t body, const Vec3& point, const Vec3& force);
  /// One time step; forces applied before it are then cleared.
  void step();

  /// Where the body is now, relative to where it started.
  BodyPose pose(std::size_t body) const;
  /// The joint coordinate q and its rate (hinge: radians and rad/s; slide: metres and m/s). Ball,
  /// free and mechanism bodies have no single coordinate: q is the angle of their turn from where
  /// they started (the length of the rotation vector of pose(), radians in [0, pi]) and its rate
  /// their angular speed in the world (rad/s, never negative).
  double jointPosition(std::size_t body) const;
  /// The rate of jointPosition() (see there for units and for bodies with no single coordinate).
  double jointVelocity(std::size_t body) const;
  /// Velocity (m/s) of the body's material point now at `point` (world).
  Vec3 pointVelocity(std::size_t body, const Vec3& point) const;
  /// The energies of the present state (computes the model forward: for reports and tests, not
  /// for the haptic loop).
  BodyEnergy energy();
  /// The same energies for one body: its own kinetic energy (1/2 m v^2 + 1/2 w^T I w at its
  /// centre of mass), its weight's potential and its own joints' springs'. For reports and tests.
  BodyEnergy bodyEnergy(std::size_t body);
  /// The joint of body `body`: its description's type; for a bound MJCF body, the type of its one
  /// joint, or Mechanism when it has none or several.
  JointType jointType(std::size_t body) const { return m_joints[body]; }
  /// The least effective mass (kg) of the body at any of `points` (world, where the body is now)
  /// in any direction: 1 / the largest eigenvalue of J M^-1 J^T, with J the points' translational
  /// Jacobian. What a push there moves, through every joint of the mechanism (for the coupling's
  /// stability check of MJCF bodies; O(points nv^2)).
  double leastEffectiveMass(std::size_t body, const std::vector<Vec3>& points);

private:
  struct Model;
  void start(const std::vector<int>& bodyIds);

  std::unique_ptr<Model> m_model;
  DynamicsSettings m_settings;
  std::vector<JointType> m_joints;
  /// MuJoCo's id of each body, and where it was at the start (poses are relative to it).
  std::vector<int> m_ids;
  std::vector<BodyPose> m_start;
};

} // namespace proxima
