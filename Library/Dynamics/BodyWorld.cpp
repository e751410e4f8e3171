#include "Dynamics/BodyWorld.h"

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace proxima
{

const char* jointTypeName(JointType type)
{
  switch (type)
  {
    case JointType::Hinge: return "hinge";
    case JointType::Slide: return "slide";
    case JointType::Ball: return "ball";
    case JointType::Free: return "free";
  }
  return "hinge";
}

Vec3 BodyPose::apply(const Vec3& point) const
{
  // p' = q p q* for the unit quaternion q = (w, v): p + 2 w (v x p) + 2 v x (v x p).
  const double w = orientation[0];
  const Vec3 v{orientation[1], orientation[2], orientation[3]};
  const Vec3 t = cross(v, point) * 2.0;
  return position + point + t * w + cross(v, t);
}

namespace
{
// Every digit: the model MuJoCo reads holds the doubles given.
std::string number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string triple(const Vec3& v)
{
  return number(v.x) + " " + number(v.y) + " " + number(v.z);
}

void check(bool ok, const BodyDescription& body, const std::string& defect)
{
  if (!ok)
  {
    throw std::invalid_argument("body '" + body.name + "': " + defect);
  }
}

// The MJCF of the bodies: each a child of the world at the origin with no rotation (its frame is
// the world's at the start), its joint at the anchor, its inertial at the centre of mass.
std::string modelXml(const std::vector<BodyDescription>& bodies, const DynamicsSettings& settings)
{
  std::ostringstream xml;
  xml << "<mujoco model=\"proxima\">\n"
      << "  <compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" "
         "boundinertia=\"0\"/>\n"
      // Semi-implicit Euler with implicit joint damping, at the haptic rate; no MuJoCo contacts
      // (the proxy is the only contact, and there are no geoms).
      << "  <option timestep=\"" << number(settings.timeStep) << "\" gravity=\""
      << triple(settings.gravity) << "\" integrator=\"Euler\">\n"
      << "    <flag contact=\"disable\" energy=\"enable\"/>\n"
      << "  </option>\n"
      << "  <worldbody>\n";
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    const BodyDescription& body = bodies[i];
    const JointDescription& joint = body.joint;
    const SolidMassProperties& mass = body.mass;
    xml << "    <body name=\"body" << i << "\" pos=\"0 0 0\">\n";
    if (joint.type == JointType::Free)
    {
      xml << "      <freejoint name=\"joint" << i << "\"/>\n";
    }
    else
    {
      xml << "      <joint name=\"joint" << i << "\" type=\"" << jointTypeName(joint.type)
          << "\" pos=\"" << triple(joint.anchor) << "\"";
      if (joint.type != JointType::Ball)
      {
        xml << " axis=\"" << triple(joint.axis) << "\"";
      }
      xml << " stiffness=\"" << number(joint.stiffness) << "\" damping=\"" << number(joint.damping)
          << "\"";
      if (joint.limited)
      {
        xml << " limited=\"true\" range=\"" << number(joint.range[0]) << " "
            << number(joint.range[1]) << "\"";
      }
      xml << "/>\n";
    }
    xml << "      <inertial pos=\"" << triple(mass.centroid) << "\" mass=\"" << number(mass.mass)
        << "\" fullinertia=\"" << number(mass.inertia[0]) << " " << number(mass.inertia[1]) << " "
        << number(mass.inertia[2]) << " " << number(mass.inertia[3]) << " "
        << number(mass.inertia[4]) << " " << number(mass.inertia[5]) << "\"/>\n"
        << "    </body>\n";
  }
  xml << "  </worldbody>\n</mujoco>\n";
  return xml.str();
}

void checkBody(const BodyDescription& body)
{
  const JointDescription& joint = body.joint;
  const bool axial = joint.type == JointType::Hinge || joint.type == JointType::Slide;
  check(!axial || norm(joint.axis) > 0.0, body, "the joint's axis is zero");
  check(std::isfinite(joint.anchor.x) && std::isfinite(joint.anchor.y) &&
          std::isfinite(joint.anchor.z),
        body, "the joint's anchor is not finite");
  check(!joint.limited || (axial && joint.range[0] < joint.range[1]), body,
        axial ? "the joint's range is empty (give [low, high] with low < high)"
              : std::string("a ") + jointTypeName(joint.type) + " joint has no range");
  check(joint.stiffness >= 0.0 && std::isfinite(joint.stiffness), body,
        "the joint's stiffness is negative or not finite");
  check(joint.damping >= 0.0 && std::isfinite(joint.damping), body,
        "the joint's damping is negative or not finite");
  check(body.mass.mass > 0.0 && std::isfinite(body.mass.mass), body, "the mass is not positive");
  check(body.mass.inertia[0] > 0.0 && body.mass.inertia[1] > 0.0 && body.mass.inertia[2] > 0.0,
        body, "the inertia is not positive definite");
}
} // namespace

struct BodyWorld::Model
{
  mjModel* model = nullptr;
  mjData* data = nullptr;
  /// The translational Jacobian of a point, scratch for pointVelocity (3 x nv).
  mutable std::vector<mjtNum> jacobian;

  ~Model()
  {
    if (data != nullptr)
    {
      mj_deleteData(data);
    }
    if (model != nullptr)
    {
      mj_deleteModel(model);
    }
  }
};

BodyWorld::BodyWorld(const std::vector<BodyDescription>& bodies, const DynamicsSettings& settings)
  : m_model(std::make_unique<Model>())
  , m_settings(settings)
{
  if (!(settings.timeStep > 0.0) || !std::isfinite(settings.timeStep))
  {
    throw std::invalid_argument("the dynamics time step must be above 0 s");
  }
  for (const BodyDescription& body : bodies)
  {
    checkBody(body);
    m_joints.push_back(body.joint.type);
  }
  // MuJoCo reads models from files: this one is a file in memory (its virtual file system, too
  // large for the stack).
  const std::string xml = modelXml(bodies, settings);
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "proxima-bodies.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0)
  {
    throw std::runtime_error("MuJoCo's virtual file system refused the model");
  }
  const int file = mj_findFileVFS(vfs.get(), name);
  std::memcpy(vfs->filedata[file], xml.data(), xml.size());
  char error[1000] = "";
  m_model->model = mj_loadXML(name, vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (m_model->model == nullptr)
  {
    throw std::invalid_argument(std::string("MuJoCo refused the bodies: ") + error);
  }
  m_model->data = mj_makeData(m_model->model);
  m_model->jacobian.resize(3 * static_cast<std::size_t>(m_model->model->nv));
  // The poses and Jacobian frames of the start (MuJoCo computes them at the beginning of each
  // step).
  mj_kinematics(m_model->model, m_model->data);
  mj_comPos(m_model->model, m_model->data);
}

BodyWorld::~BodyWorld() = default;

std::size_t BodyWorld::numBodies() const
{
  return m_joints.size();
}

double BodyWorld::time() const
{
  return m_model->data->time;
}

void BodyWorld::applyForce(std::size_t body, const Vec3& point, const Vec3& force)
{
  const mjtNum f[3] = {force.x, force.y, force.z};
  const mjtNum torque[3] = {0.0, 0.0, 0.0};
  mjtNum at[3] = {point.x, point.y, point.z};
  // J^T f into the generalised applied forces (eqs. 23-24); body 0 is MuJoCo's world.
  mj_applyFT(m_model->model, m_model->data, f, torque, at, static_cast<int>(body) + 1,
             m_model->data->qfrc_applied);
}

void BodyWorld::step()
{
  mjModel* model = m_model->model;
  mjData* data = m_model->data;
  mj_step(model, data);
  mju_zero(data->qfrc_applied, model->nv);
  // mj_step leaves the poses of the state it started from: bring them, and the frames the
  // Jacobians of applyForce and pointVelocity use, to the new state.
  mj_kinematics(model, data);
  mj_comPos(model, data);
}

BodyPose BodyWorld::pose(std::size_t body) const
{
  const mjData* data = m_model->data;
  const std::size_t b = body + 1;
  BodyPose pose;
  pose.position = Vec3{data->xpos[3 * b], data->xpos[3 * b + 1], data->xpos[3 * b + 2]};
  for (int k = 0; k < 4; ++k)
  {
    pose.orientation[k] = data->xquat[4 * b + static_cast<std::size_t>(k)];
  }
  return pose;
}

double BodyWorld::jointPosition(std::size_t body) const
{
  const JointType type = m_joints[body];
  if (type != JointType::Hinge && type != JointType::Slide)
  {
    return 0.0;
  }
  const mjModel* model = m_model->model;
  const int joint = model->body_jntadr[body + 1];
  return m_model->data->qpos[model->jnt_qposadr[joint]];
}

double BodyWorld::jointVelocity(std::size_t body) const
{
  const JointType type = m_joints[body];
  if (type != JointType::Hinge && type != JointType::Slide)
  {
    return 0.0;
  }
  const mjModel* model = m_model->model;
  const int joint = model->body_jntadr[body + 1];
  return m_model->data->qvel[model->jnt_dofadr[joint]];
}

Vec3 BodyWorld::pointVelocity(std::size_t body, const Vec3& point) const
{
  const mjModel* model = m_model->model;
  const mjData* data = m_model->data;
  const mjtNum at[3] = {point.x, point.y, point.z};
  mjtNum* jacobian = m_model->jacobian.data();
  mj_jac(model, data, jacobian, nullptr, at, static_cast<int>(body) + 1);
  double v[3] = {0.0, 0.0, 0.0};
  for (int row = 0; row < 3; ++row)
  {
    for (int dof = 0; dof < model->nv; ++dof)
    {
      v[row] += jacobian[row * model->nv + dof] * data->qvel[dof];
    }
  }
  return Vec3{v[0], v[1], v[2]};
}

BodyEnergy BodyWorld::energy()
{
  mjModel* model = m_model->model;
  mjData* data = m_model->data;
  // Forward dynamics computes both energies (the energy flag is on) without moving the state.
  mj_forward(model, data);
  return BodyEnergy{data->energy[1], data->energy[0]};
}

BodyEnergy BodyWorld::bodyEnergy(std::size_t body)
{
  mjModel* model = m_model->model;
  mjData* data = m_model->data;
  mj_forward(model, data);
  const int b = static_cast<int>(body) + 1;
  const int firstDof = model->body_dofadr[b];
  const int numDofs = model->body_dofnum[b];
  // Kinetic: 1/2 v^T M v with the velocities of this body's joint only (M is block diagonal, a
  // block per body, as every body hangs from the world).
  std::vector<mjtNum> velocity(static_cast<std::size_t>(model->nv), 0.0);
  std::vector<mjtNum> momentum(static_cast<std::size_t>(model->nv), 0.0);
  for (int dof = firstDof; dof < firstDof + numDofs; ++dof)
  {
    velocity[static_cast<std::size_t>(dof)] = data->qvel[dof];
  }
  mj_mulM(model, data, momentum.data(), velocity.data());
  BodyEnergy energy;
  for (int dof = firstDof; dof < firstDof + numDofs; ++dof)
  {
    energy.kinetic +=
      0.5 * velocity[static_cast<std::size_t>(dof)] * momentum[static_cast<std::size_t>(dof)];
  }
  // Potential: gravity's (zero at the world's origin, as MuJoCo counts it) and the joint spring's.
  const mjtNum* g = model->opt.gravity;
  const mjtNum* c = data->xipos + 3 * b;
  energy.potential = -model->body_mass[b] * (g[0] * c[0] + g[1] * c[1] + g[2] * c[2]);
  if (model->body_jntnum[b] > 0)
  {
    const int joint = model->body_jntadr[b];
    const double k = model->jnt_stiffness[joint];
    const int at = model->jnt_qposadr[joint];
    if (model->jnt_type[joint] == mjJNT_HINGE || model->jnt_type[joint] == mjJNT_SLIDE)
    {
      const double q = data->qpos[at] - model->qpos_spring[at];
      energy.potential += 0.5 * k * q * q;
    }
    else if (model->jnt_type[joint] == mjJNT_BALL)
    {
      // The angle between the pose and the spring's rest pose (the start).
      mjtNum difference[3];
      mju_subQuat(difference, data->qpos + at, model->qpos_spring + at);
      energy.potential += 0.5 * k * mju_dot3(difference, difference);
    }
  }
  return energy;
}

} // namespace proxima
