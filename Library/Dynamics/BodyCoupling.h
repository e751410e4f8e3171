// The coupling of the proxy and the bodies of a scene (paper section 6), each haptic tick after
// the force stage: the force the device renders on the finger, equal and opposite, on the bodies
// touched at the tick's contacts (J^T f_c, eqs. 23-24, shared among the contacts by how far the
// spring presses into each), one step of the bodies at the haptic rate, and their new poses into
// the proxy solver, which sweeps the proxy against their motion at its next update. The sphere
// trees stay in the frames the objects were placed in: nothing is rebuilt when a body moves.
#pragma once

#include "Core/RigidTransform.h"
#include "Dynamics/BodyWorld.h"
#include "Runtime/TickDynamics.h"

#include <cstdint>
#include <string>
#include <vector>

namespace proxima
{

/// A body and the scene object that is its surface.
struct CoupledBody
{
  /// The body: its name, joint and mass properties.
  BodyDescription description;
  /// Index of the scene object that moves with the body.
  std::uint32_t object = 0;
};

/// A scene object bound to a body of an MJCF mechanism by the body's name.
struct MechanismBinding
{
  /// Index of the scene object that moves with the body.
  std::uint32_t object = 0;
  /// Name of the body in the MJCF file.
  std::string body;
};

/// Why a body of `mesh` (its surface, as placed) is too light to couple stably to the servo's
/// spring `kp` (N/m) at the step `timeStep` (s), or empty when it is not. The coupled spring and
/// mass, integrated by semi-implicit Euler, stay stable while kp dt^2 / m < 4; the check asks for
/// kp dt^2 / m <= 1 with m the body's smallest effective mass at any point of its surface (for a
/// hinge I / d^2 at the farthest point from the axis, a slide its mass, a ball or free body a
/// bound from its least principal inertia), so that a push anywhere on it stays well inside.
std::string couplingStabilityDefect(const BodyDescription& body, const TriangleMesh& mesh,
                                    double kp, double timeStep);
/// The same rule for a body whose least effective mass is known (`from` says where it comes
/// from, for the message).
std::string couplingStabilityDefect(double effectiveMass, const std::string& from, double kp,
                                    double timeStep);

/// The TickDynamics of a scene with bodies, on a BodyWorld (MuJoCo): pushes the touched bodies
/// with the force the device renders, steps them at the haptic rate and moves their objects in
/// the proxy solver. Body i moves scene object `object(i)`.
class BodyCoupling final : public TickDynamics
{
public:
  /// Builds the bodies' world (BodyWorld's errors, naming the body).
  BodyCoupling(const std::vector<CoupledBody>& bodies, const DynamicsSettings& settings);
  /// The bodies of the MJCF file `mjcfFile` that `bindings` name, each moving its object
  /// (BodyWorld's errors).
  BodyCoupling(const std::string& mjcfFile, const std::vector<MechanismBinding>& bindings,
               const DynamicsSettings& settings);

  // TickDynamics.
  std::vector<std::uint32_t> movingObjects() const override { return m_objects; }
  void placeBodies(ProxySolver& solver) const override;
  void step(HapticState& state, ProxySolver& solver) override;
  void poses(BodyPoses& out) const override;

  /// How many bodies move: one per CoupledBody or MechanismBinding given.
  std::size_t numBodies() const { return m_objects.size(); }
  /// The name of body `body` (its description's, or the MJCF body's bound).
  const std::string& name(std::size_t body) const { return m_names[body]; }
  /// The scene object that body `body` moves.
  std::uint32_t object(std::size_t body) const { return m_objects[body]; }
  /// The body of scene object `object`, or -1 for a static object.
  int bodyOfObject(std::uint32_t object) const
  {
    return object < m_bodyOfObject.size() ? m_bodyOfObject[object] : -1;
  }
  /// Where body `body` is now, relative to where it was placed.
  RigidTransform transform(std::size_t body) const;
  /// The bodies' world, owned by the coupling.
  BodyWorld& world() { return m_world; }
  /// The bodies' world, read only.
  const BodyWorld& world() const { return m_world; }
  /// Watches the bodies leave the scene: from now on, the first time the point `references[b]`
  /// of body b's object (as placed) goes outside the box [lower, upper] is kept
  /// (leftBoundsAt). O(1) per body per step.
  void watchBounds(const Vec3& lower, const Vec3& upper, const std::vector<Vec3>& references);
  /// Seconds of the bodies' clock at which `body` first left the bounds, or -1 while it has not
  /// (or no bounds are watched).
  double leftBoundsAt(std::size_t body) const { return m_leftBoundsAt[body]; }
  /// Joules the finger has done on `body` so far: each step's force on it times the displacement
  /// over that step of the material point it pushed.
  double work(std::size_t body) const { return m_work[body]; }

private:
  void bind(const std::vector<std::uint32_t>& objects);

  BodyWorld m_world;
  std::vector<std::string> m_names;
  std::vector<std::uint32_t> m_objects;
  std::vector<int> m_bodyOfObject;
  std::vector<double> m_work;
  bool m_watchingBounds = false;
  Vec3 m_lower;
  Vec3 m_upper;
  std::vector<Vec3> m_references;
  std::vector<double> m_leftBoundsAt;
};

} // namespace proxima
