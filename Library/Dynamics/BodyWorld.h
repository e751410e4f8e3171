// The bodies of a scene and their integration (paper section 6) on MuJoCo, whose headers stay in
// BodyWorld.cpp. Each haptic tick: applyForce for the touched body (the force the device renders,
// equal and opposite, at the contact point: J^T f_c, eqs. 23-24), then step(), then pose() moves
// each body's object for the next proxy update.
#pragma once

#include "Core/Vec3.h"
#include "Dynamics/BodyDescription.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace proxima
{

/// A rigid transform: a point p of the object as placed goes to position + rotate(p).
struct BodyPose
{
  Vec3 position;
  /// Unit quaternion w, x, y, z.
  double orientation[4] = {1.0, 0.0, 0.0, 0.0};

  Vec3 apply(const Vec3& point) const;
};

struct BodyEnergy
{
  /// Joules: the bodies' kinetic energy, and their potential energy in gravity and joint springs
  /// (zero at the start pose for the springs; gravity's zero is the world origin).
  double kinetic = 0.0;
  double potential = 0.0;
};

class BodyWorld
{
public:
  /// Builds MuJoCo's model of `bodies`. Throws std::invalid_argument naming the body and the
  /// defect (a zero axis, a mass or inertia that is not positive, a range that is empty, a
  /// negative stiffness or damping, a time step that is not positive) or MuJoCo's complaint.
  BodyWorld(const std::vector<BodyDescription>& bodies, const DynamicsSettings& settings);
  ~BodyWorld();
  BodyWorld(const BodyWorld&) = delete;
  BodyWorld& operator=(const BodyWorld&) = delete;

  std::size_t numBodies() const;
  double time() const;
  const DynamicsSettings& settings() const { return m_settings; }

  /// Adds `force` (N, world frame) at `point` (world) on `body` for the next step only.
  void applyForce(std::size_t body, const Vec3& point, const Vec3& force);
  /// One time step; forces applied before it are then cleared.
  void step();

  /// Where the body is now, relative to where it started.
  BodyPose pose(std::size_t body) const;
  /// The joint coordinate q and its rate (hinge: radians; slide: metres); 0 for ball and free.
  double jointPosition(std::size_t body) const;
  double jointVelocity(std::size_t body) const;
  /// Velocity (m/s) of the body's material point now at `point` (world).
  Vec3 pointVelocity(std::size_t body, const Vec3& point) const;
  /// The energies of the present state (computes the model forward: for reports and tests, not
  /// for the haptic loop).
  BodyEnergy energy();
  /// The same energies for one body (each body hangs from the world by its own joint, so the
  /// bodies' kinetic energies add up to the whole; the potentials are gravity's and its joint
  /// spring's). For reports and tests.
  BodyEnergy bodyEnergy(std::size_t body);
  JointType jointType(std::size_t body) const { return m_joints[body]; }

private:
  struct Model;
  std::unique_ptr<Model> m_model;
  DynamicsSettings m_settings;
  std::vector<JointType> m_joints;
};

} // namespace proxima
