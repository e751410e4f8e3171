#include "Dynamics/BodyCoupling.h"

#include "Dynamics/SymmetricEigenvalues.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace proxima
{

namespace
{
std::vector<std::string> boundNames(const std::vector<MechanismBinding>& bindings)
{
  std::vector<std::string> names;
  for (const MechanismBinding& binding : bindings)
  {
    names.push_back(binding.body);
  }
  return names;
}

std::vector<BodyDescription> descriptions(const std::vector<CoupledBody>& bodies)
{
  std::vector<BodyDescription> list;
  list.reserve(bodies.size());
  for (const CoupledBody& body : bodies)
  {
    list.push_back(body.description);
  }
  return list;
}

// The inertia tensor (about the centre of mass) as a matrix.
std::array<Vec3, 3> inertiaRows(const SolidMassProperties& mass)
{
  const double* i = mass.inertia;
  return {Vec3{i[0], i[3], i[4]}, Vec3{i[3], i[1], i[5]}, Vec3{i[4], i[5], i[2]}};
}

std::string figure(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}
} // namespace

std::string couplingStabilityDefect(const BodyDescription& body, const TriangleMesh& mesh,
                                    double kp, double timeStep)
{
  const JointDescription& joint = body.joint;
  const SolidMassProperties& mass = body.mass;
  const Vec3 axis = overflowSafeDirection(joint.axis);
  double effectiveMass = mass.mass;
  std::string where = "its mass";
  if (joint.type == JointType::Hinge)
  {
    // I about the hinge's axis: about the parallel axis through the centre of mass, plus m d^2.
    const std::array<Vec3, 3> inertia = inertiaRows(mass);
    const Vec3 offset = mass.centroid - joint.anchor;
    const Vec3 across = offset - axis * dot(offset, axis);
    const double axial =
      dot(axis, Vec3{dot(inertia[0], axis), dot(inertia[1], axis), dot(inertia[2], axis)}) +
      mass.mass * squaredNorm(across);
    double farthest = 0.0;
    for (const Vec3& point : mesh.points())
    {
      const Vec3 toPoint = point - joint.anchor;
      farthest = std::max(farthest, squaredNorm(toPoint - axis * dot(toPoint, axis)));
    }
    effectiveMass = farthest > 0.0 ? axial / farthest : mass.mass;
    where = "its inertia about the hinge over the square of its reach from the axis";
  }
  else if (joint.type == JointType::Ball || joint.type == JointType::Free)
  {
    // A push at r from the centre of rotation moves the point as a mass m_eff with
    // 1 / m_eff <= 1 / m + |r|^2 / I_min (for a ball: m is infinite, I about the anchor).
    std::array<Vec3, 3> inertia = inertiaRows(mass);
    const Vec3 centre = joint.type == JointType::Ball ? joint.anchor : mass.centroid;
    if (joint.type == JointType::Ball)
    {
      const Vec3 d = mass.centroid - joint.anchor;
      // The parallel-axis theorem: I_anchor = I_c + m (|d|^2 E - d d^T).
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          inertia[r][c] += mass.mass * ((r == c ? squaredNorm(d) : 0.0) - d[r] * d[c]);
        }
      }
    }
    double farthest = 0.0;
    for (const Vec3& point : mesh.points())
    {
      farthest = std::max(farthest, squaredNorm(point - centre));
    }
    const double least = symmetricEigenvalues(inertia)[0];
    const double inverse =
      (joint.type == JointType::Free ? 1.0 / mass.mass : 0.0) + farthest / std::max(least, 1e-300);
    effectiveMass = 1.0 / inverse;
    where = "its least principal inertia and its reach";
  }
  return couplingStabilityDefect(effectiveMass, where, kp, timeStep);
}

std::string couplingStabilityDefect(double effectiveMass, const std::string& where, double kp,
                                    double timeStep)
{
  const double needed = kp * timeStep * timeStep;
  if (effectiveMass >= needed)
  {
    return {};
  }
  return "too light to touch stably: at kp " + figure(kp) + " N/m and " + figure(1.0 / timeStep) +
         " Hz a push anywhere on it needs an effective mass of at least " + figure(needed) +
         " kg, and it has " + figure(effectiveMass) + " kg (from " + where +
         "; make it heavier, or use a softer kp or a faster rate)";
}

BodyCoupling::BodyCoupling(const std::vector<CoupledBody>& bodies, const DynamicsSettings& settings)
  : m_world(descriptions(bodies), settings)
{
  std::vector<std::uint32_t> objects;
  for (const CoupledBody& body : bodies)
  {
    m_names.push_back(body.description.name);
    objects.push_back(body.object);
  }
  bind(objects);
}

BodyCoupling::BodyCoupling(const std::string& mjcfFile,
                           const std::vector<MechanismBinding>& bindings,
                           const DynamicsSettings& settings)
  : m_world(mjcfFile, boundNames(bindings), settings)
{
  std::vector<std::uint32_t> objects;
  for (const MechanismBinding& binding : bindings)
  {
    m_names.push_back(binding.body);
    objects.push_back(binding.object);
  }
  bind(objects);
}

void BodyCoupling::bind(const std::vector<std::uint32_t>& objects)
{
  m_objects = objects;
  std::uint32_t largest = 0;
  for (const std::uint32_t object : objects)
  {
    largest = std::max(largest, object);
  }
  m_bodyOfObject.assign(objects.empty() ? 0 : largest + 1, -1);
  for (std::size_t i = 0; i < objects.size(); ++i)
  {
    m_bodyOfObject[objects[i]] = static_cast<int>(i);
  }
  m_work.assign(objects.size(), 0.0);
  m_leftBoundsAt.assign(objects.size(), -1.0);
}

void BodyCoupling::watchBounds(const Vec3& lower, const Vec3& upper,
                               const std::vector<Vec3>& references)
{
  m_watchingBounds = references.size() == m_objects.size();
  m_lower = lower;
  m_upper = upper;
  m_references = references;
}

RigidTransform BodyCoupling::transform(std::size_t body) const
{
  const BodyPose pose = m_world.pose(body);
  return RigidTransform::fromQuaternion(pose.orientation[0], pose.orientation[1],
                                        pose.orientation[2], pose.orientation[3], pose.position);
}

void BodyCoupling::placeBodies(ProxySolver& solver) const
{
  for (std::size_t body = 0; body < m_objects.size(); ++body)
  {
    solver.setObjectPose(m_objects[body], transform(body));
  }
}

void BodyCoupling::poses(BodyPoses& out) const
{
  const std::size_t count =
    std::min(m_objects.size(), static_cast<std::size_t>(BodyPoses::kCapacity));
  out.count = static_cast<int>(count);
  for (std::size_t body = 0; body < count; ++body)
  {
    out.objects[body] = m_objects[body];
    out.poses[body] = transform(body);
  }
}

void BodyCoupling::step(HapticState& state, ProxySolver& solver)
{
  const auto begin = std::chrono::steady_clock::now();
  // The contacts share the force on the finger by how deep the spring presses into each (their
  // goal multipliers); a contact on a static object passes its share to the world.
  double totalDepth = 0.0;
  for (int i = 0; i < state.numContacts; ++i)
  {
    totalDepth += state.contacts[i].depth;
  }
  struct Push
  {
    int body;
    Vec3 point;
    Vec3 force;
  };
  Push pushes[3];
  int numPushes = 0;
  const Vec3 onBodies = -state.force;
  for (int i = 0; i < state.numContacts; ++i)
  {
    const ContactSnapshot& contact = state.contacts[i];
    const int body = bodyOfObject(contact.object);
    if (body < 0 || !(squaredNorm(onBodies) > 0.0))
    {
      continue;
    }
    const double share =
      totalDepth > 0.0 ? contact.depth / totalDepth : 1.0 / static_cast<double>(state.numContacts);
    if (!(share > 0.0))
    {
      continue;
    }
    pushes[numPushes] = Push{body, contact.point, onBodies * share};
    m_world.applyForce(static_cast<std::size_t>(body), contact.point, pushes[numPushes].force);
    ++numPushes;
  }
  m_world.step();
  for (std::size_t body = 0; body < m_objects.size(); ++body)
  {
    const RigidTransform after = transform(body);
    const RigidTransform& before = solver.objectPose(m_objects[body]);
    for (int i = 0; i < numPushes; ++i)
    {
      // Work: the force times how far the material point it pushed moved over the step.
      if (static_cast<std::size_t>(pushes[i].body) == body)
      {
        const Vec3 moved = after.apply(before.applyInverse(pushes[i].point)) - pushes[i].point;
        m_work[body] += dot(pushes[i].force, moved);
      }
    }
    solver.setObjectPose(m_objects[body], after);
    if (m_watchingBounds && m_leftBoundsAt[body] < 0.0)
    {
      const Vec3 where = after.apply(m_references[body]);
      for (int axis = 0; axis < 3; ++axis)
      {
        if (!(where[axis] >= m_lower[axis] && where[axis] <= m_upper[axis]))
        {
          m_leftBoundsAt[body] = m_world.time();
          break;
        }
      }
    }
  }
  const auto end = std::chrono::steady_clock::now();
  state.dynamicsNanoseconds =
    std::chrono::duration_cast<std::chrono::nanoseconds>(end - begin).count();
}

} // namespace proxima
