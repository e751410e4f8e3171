#include "Dynamics/BodyWorld.h"

#include "Dynamics/SymmetricEigenvalues.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
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
    case JointType::Mechanism: return "mechanism";
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
        // The unit axis: MuJoCo normalises it by its plain norm, which overflows for
        // [1e300, 1e300, 0] and leaves a zero axis (a body that never moves).
        xml << " axis=\"" << triple(overflowSafeDirection(joint.axis)) << "\"";
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

// MuJoCo's own handlers print on standard output, where a command's JSON report goes, append to
// MUJOCO_LOG.TXT in the current folder, which is the user's, and exit on an error. Proxima's
// handlers, set once before the first model is read, say a warning in one line on standard error
// and turn an error into an exception the caller reports (an internal error, status 1).
void onMujocoWarning(const char* message)
{
  std::fprintf(stderr, "proxima: MuJoCo warning: %s\n", message);
}

[[noreturn]] void onMujocoError(const char* message)
{
  throw std::runtime_error(std::string("MuJoCo: ") + message);
}

void routeMujocoMessages()
{
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_warning = onMujocoWarning;
    mju_user_error = onMujocoError;
  });
}

void checkBody(const BodyDescription& body)
{
  const JointDescription& joint = body.joint;
  const bool axial = joint.type == JointType::Hinge || joint.type == JointType::Slide;
  check(!axial || isFinite(joint.axis), body, "the joint's axis is not finite");
  check(!axial || maxAbsComponent(joint.axis) > 0.0, body, "the joint's axis is zero");
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
  routeMujocoMessages();
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
  std::vector<int> ids;
  for (std::size_t i = 0; i < bodies.size(); ++i)
  {
    ids.push_back(static_cast<int>(i) + 1); // 0 is MuJoCo's world
  }
  start(ids);
}

namespace
{
// The joint type of a bound MJCF body: its own single joint's, or Mechanism.
JointType mechanismJointType(const mjModel* model, int body)
{
  if (model->body_jntnum[body] != 1)
  {
    return JointType::Mechanism;
  }
  switch (model->jnt_type[model->body_jntadr[body]])
  {
    case mjJNT_HINGE: return JointType::Hinge;
    case mjJNT_SLIDE: return JointType::Slide;
    case mjJNT_BALL: return JointType::Ball;
    case mjJNT_FREE: return JointType::Free;
    default: return JointType::Mechanism;
  }
}

// True when the body or one of its ancestors has a degree of freedom.
bool moves(const mjModel* model, int body)
{
  for (int b = body; b > 0; b = model->body_parentid[b])
  {
    if (model->body_dofnum[b] > 0)
    {
      return true;
    }
  }
  return false;
}
} // namespace

BodyWorld::BodyWorld(const std::string& mjcfFile, const std::vector<std::string>& boundBodies,
                     const DynamicsSettings& settings)
  : m_model(std::make_unique<Model>())
  , m_settings(settings)
{
  routeMujocoMessages();
  if (!(settings.timeStep > 0.0) || !std::isfinite(settings.timeStep))
  {
    throw std::invalid_argument("the dynamics time step must be above 0 s");
  }
  char error[1000] = "";
  m_model->model = mj_loadXML(mjcfFile.c_str(), nullptr, error, sizeof error);
  if (m_model->model == nullptr)
  {
    throw std::invalid_argument(std::string("MuJoCo refused it: ") + error);
  }
  mjModel* model = m_model->model;
  // The bodies step with the servo, whatever step the file chose for itself.
  model->opt.timestep = settings.timeStep;
  model->opt.enableflags |= mjENBL_ENERGY;
  m_settings.gravity = Vec3{model->opt.gravity[0], model->opt.gravity[1], model->opt.gravity[2]};
  std::vector<int> ids;
  for (std::size_t index = 0; index < boundBodies.size(); ++index)
  {
    const std::string& name = boundBodies[index];
    const int id = mj_name2id(model, mjOBJ_BODY, name.c_str());
    if (id <= 0)
    {
      std::string names;
      for (int b = 1; b < model->nbody; ++b)
      {
        const char* other = mj_id2name(model, mjOBJ_BODY, b);
        names += std::string(names.empty() ? "" : ", ") + (other != nullptr ? other : "(unnamed)");
      }
      throw MechanismBindingError(index, "no body named '" + name + "' (the file has: " +
                                           (names.empty() ? "none" : names) + ")");
    }
    if (!moves(model, id))
    {
      throw MechanismBindingError(
        index, "body '" + name + "' is fixed to the world (neither it nor a parent has a joint)");
    }
    ids.push_back(id);
    m_joints.push_back(mechanismJointType(model, id));
  }
  start(ids);
}

void BodyWorld::start(const std::vector<int>& bodyIds)
{
  m_model->data = mj_makeData(m_model->model);
  m_model->jacobian.resize(3 * static_cast<std::size_t>(m_model->model->nv));
  // The poses and Jacobian frames of the start (MuJoCo computes them at the beginning of each
  // step).
  mj_kinematics(m_model->model, m_model->data);
  mj_comPos(m_model->model, m_model->data);
  m_ids = bodyIds;
  m_start.clear();
  const mjData* data = m_model->data;
  for (const int b : m_ids)
  {
    BodyPose pose;
    const std::size_t at = static_cast<std::size_t>(b);
    pose.position = Vec3{data->xpos[3 * at], data->xpos[3 * at + 1], data->xpos[3 * at + 2]};
    for (std::size_t k = 0; k < 4; ++k)
    {
      pose.orientation[k] = data->xquat[4 * at + k];
    }
    m_start.push_back(pose);
  }
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
  mj_applyFT(m_model->model, m_model->data, f, torque, at, m_ids[body],
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
  const auto b = static_cast<std::size_t>(m_ids[body]);
  // Relative to the start: R = R_now R_start^T, t = x_now - R x_start (the start is the identity
  // for bodies declared on objects, whose frames are the world's at the start).
  const BodyPose& start = m_start[body];
  mjtNum inverseStart[4];
  mju_negQuat(inverseStart, start.orientation);
  BodyPose pose;
  mju_mulQuat(pose.orientation, data->xquat + 4 * b, inverseStart);
  const mjtNum from[3] = {start.position.x, start.position.y, start.position.z};
  mjtNum turned[3];
  mju_rotVecQuat(turned, from, pose.orientation);
  pose.position = Vec3{data->xpos[3 * b] - turned[0], data->xpos[3 * b + 1] - turned[1],
                       data->xpos[3 * b + 2] - turned[2]};
  return pose;
}

double BodyWorld::jointPosition(std::size_t body) const
{
  const JointType type = m_joints[body];
  if (type != JointType::Hinge && type != JointType::Slide)
  {
    // No single coordinate: the angle of the body's turn from where it started, the length of
    // its rotation vector, in [0, pi].
    const BodyPose turned = pose(body);
    const double* q = turned.orientation;
    return 2.0 * std::atan2(std::sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), std::fabs(q[0]));
  }
  const mjModel* model = m_model->model;
  const int joint = model->body_jntadr[m_ids[body]];
  return m_model->data->qpos[model->jnt_qposadr[joint]];
}

double BodyWorld::jointVelocity(std::size_t body) const
{
  const JointType type = m_joints[body];
  const mjModel* model = m_model->model;
  const mjData* data = m_model->data;
  if (type != JointType::Hinge && type != JointType::Slide)
  {
    // No single coordinate: the body's angular speed in the world, |J_r qdot|, from the
    // rotational Jacobian of the state's own frames.
    std::vector<mjtNum> rotational(static_cast<std::size_t>(3 * model->nv));
    const int b = m_ids[body];
    mj_jac(model, data, nullptr, rotational.data(), data->xpos + 3 * b, b);
    double w[3] = {0.0, 0.0, 0.0};
    for (int row = 0; row < 3; ++row)
    {
      for (int dof = 0; dof < model->nv; ++dof)
      {
        w[row] += rotational[static_cast<std::size_t>(row * model->nv + dof)] * data->qvel[dof];
      }
    }
    return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }
  const int joint = model->body_jntadr[m_ids[body]];
  return data->qvel[model->jnt_dofadr[joint]];
}

Vec3 BodyWorld::pointVelocity(std::size_t body, const Vec3& point) const
{
  const mjModel* model = m_model->model;
  const mjData* data = m_model->data;
  const mjtNum at[3] = {point.x, point.y, point.z};
  mjtNum* jacobian = m_model->jacobian.data();
  mj_jac(model, data, jacobian, nullptr, at, m_ids[body]);
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
  const int b = m_ids[body];
  // Kinetic: the body's own, from the velocity of its centre of mass and its angular velocity in
  // its principal frame (where MuJoCo keeps its inertia diagonal); the same for a body on its own
  // joint and for one link of a mechanism.
  mjtNum velocity[6];
  mj_objectVelocity(model, data, mjOBJ_BODY, b, velocity, 1);
  const mjtNum* inertia = model->body_inertia + 3 * b;
  BodyEnergy energy;
  energy.kinetic = 0.5 * model->body_mass[b] * mju_dot3(velocity + 3, velocity + 3);
  for (int k = 0; k < 3; ++k)
  {
    energy.kinetic += 0.5 * inertia[k] * velocity[k] * velocity[k];
  }
  // Potential: gravity's (zero at the world's origin, as MuJoCo counts it) and the springs of the
  // body's own joints.
  const mjtNum* g = model->opt.gravity;
  const mjtNum* c = data->xipos + 3 * b;
  energy.potential = -model->body_mass[b] * (g[0] * c[0] + g[1] * c[1] + g[2] * c[2]);
  for (int joint = model->body_jntadr[b];
       joint >= 0 && joint < model->body_jntadr[b] + model->body_jntnum[b]; ++joint)
  {
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

double BodyWorld::leastEffectiveMass(std::size_t body, const std::vector<Vec3>& points)
{
  const mjModel* model = m_model->model;
  mjData* data = m_model->data;
  // The mass matrix of the present state, factorised.
  mj_forward(model, data);
  const auto nv = static_cast<std::size_t>(model->nv);
  std::vector<mjtNum> jacobian(3 * nv);
  std::vector<mjtNum> solved(3 * nv);
  double least = std::numeric_limits<double>::infinity();
  for (const Vec3& point : points)
  {
    const mjtNum at[3] = {point.x, point.y, point.z};
    mj_jac(model, data, jacobian.data(), nullptr, at, m_ids[body]);
    // M^-1 J^T, a row per direction.
    mj_solveM(model, data, solved.data(), jacobian.data(), 3);
    std::array<Vec3, 3> mobility;
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        mobility[static_cast<std::size_t>(r)][c] =
          mju_dot(jacobian.data() + static_cast<std::size_t>(r) * nv,
                  solved.data() + static_cast<std::size_t>(c) * nv, model->nv);
      }
    }
    const double largest = symmetricEigenvalues(mobility)[2];
    if (largest > 0.0)
    {
      least = std::min(least, 1.0 / largest);
    }
  }
  return least;
}

} // namespace proxima
