#include "IO/Scene/SceneBodies.h"

#include "Core/Aabb.h"
#include "IO/InputChecks/InputError.h"

#include <algorithm>
#include <stdexcept>

namespace proxima
{

namespace
{
JointType jointType(SceneJoint joint)
{
  switch (joint)
  {
    case SceneJoint::Hinge: return JointType::Hinge;
    case SceneJoint::Slide: return JointType::Slide;
    case SceneJoint::Ball: return JointType::Ball;
    case SceneJoint::Free: return JointType::Free;
  }
  return JointType::Hinge;
}
} // namespace

BodyDescription bodyDescription(const SceneBody& body, const std::string& name,
                                const TriangleMesh& placedMesh)
{
  BodyDescription description;
  description.name = name;
  description.joint.type = jointType(body.joint);
  description.joint.axis = body.axis;
  description.joint.anchor = body.anchor;
  description.joint.limited = body.limited;
  description.joint.range[0] = body.range[0];
  description.joint.range[1] = body.range[1];
  description.joint.stiffness = body.stiffness;
  description.joint.damping = body.damping;
  description.mass = body.density > 0.0 ? solidMassProperties(placedMesh, body.density)
                                        : solidMassPropertiesWithMass(placedMesh, body.mass);
  return description;
}

namespace
{
std::string objectBody(std::size_t object)
{
  return "objects[" + std::to_string(object) + "].body";
}

// The bodies bound by name to the scene's MJCF file, each checked heavy enough where its
// object's surface is (through every joint of the mechanism).
std::unique_ptr<BodyCoupling> buildMechanism(const LoadedScene& loaded, const std::string& file,
                                             double kp, const DynamicsSettings& settings)
{
  const SceneDescription& description = loaded.description;
  std::vector<MechanismBinding> bindings;
  for (std::size_t i = 0; i < description.objects.size(); ++i)
  {
    if (description.objects[i].hasBody)
    {
      bindings.push_back(
        MechanismBinding{static_cast<std::uint32_t>(i), description.objects[i].body.mjcfBody});
    }
  }
  std::unique_ptr<BodyCoupling> coupling;
  try
  {
    coupling = std::make_unique<BodyCoupling>(description.mjcf, bindings, settings);
  }
  catch (const MechanismBindingError& error)
  {
    throw InputError(file, objectBody(bindings[error.binding].object) +
                             ".name: " + description.mjcf + ": " + error.what());
  }
  catch (const std::invalid_argument& error)
  {
    throw InputError(description.mjcf, error.what());
  }
  for (std::size_t body = 0; body < coupling->numBodies(); ++body)
  {
    const std::uint32_t object = coupling->object(body);
    const double effectiveMass =
      coupling->world().leastEffectiveMass(body, loaded.scene->objects[object].mesh.points());
    const std::string unstable = couplingStabilityDefect(
      effectiveMass, "the mechanism's least effective mass at its surface", kp, settings.timeStep);
    if (!unstable.empty())
    {
      throw InputError(file, objectBody(object) + ": " + unstable);
    }
  }
  return coupling;
}

// The scene's bounds: the box around every object as placed, grown on every side by its largest
// side; each body is watched by the centre of its object's box.
void watchSceneBounds(const LoadedScene& loaded, BodyCoupling& bodies)
{
  Aabb scene;
  for (const auto& object : loaded.scene->objects)
  {
    scene.expand(object.mesh.bounds().lower);
    scene.expand(object.mesh.bounds().upper);
  }
  const Vec3 size = scene.extent();
  const double margin = std::max({size.x, size.y, size.z});
  std::vector<Vec3> references;
  for (std::size_t body = 0; body < bodies.numBodies(); ++body)
  {
    references.push_back(loaded.scene->objects[bodies.object(body)].mesh.bounds().center());
  }
  bodies.watchBounds(scene.lower - Vec3{margin, margin, margin},
                     scene.upper + Vec3{margin, margin, margin}, references);
}

std::unique_ptr<BodyCoupling> buildSceneBodiesUnwatched(const LoadedScene& loaded, double kp,
                                                        double rate)
{
  const SceneDescription& description = loaded.description;
  if (!description.hasBodies())
  {
    return nullptr;
  }
  const std::string file = description.path.empty() ? "scene" : description.path;
  std::vector<CoupledBody> bodies;
  DynamicsSettings settings;
  settings.timeStep = 1.0 / rate;
  settings.gravity = description.gravity;
  if (!description.mjcf.empty())
  {
    return buildMechanism(loaded, file, kp, settings);
  }
  for (std::size_t i = 0; i < description.objects.size(); ++i)
  {
    const SceneObject& object = description.objects[i];
    if (!object.hasBody)
    {
      continue;
    }
    const std::string where = objectBody(i);
    const TriangleMesh& mesh = loaded.scene->objects[i].mesh;
    CoupledBody body;
    body.object = static_cast<std::uint32_t>(i);
    try
    {
      body.description = bodyDescription(object.body, "objects[" + std::to_string(i) + "]", mesh);
    }
    catch (const std::invalid_argument& error)
    {
      throw InputError(file, where + ": " + error.what());
    }
    const std::string unstable =
      couplingStabilityDefect(body.description, mesh, kp, settings.timeStep);
    if (!unstable.empty())
    {
      throw InputError(file, where + ": " + unstable);
    }
    bodies.push_back(std::move(body));
  }
  try
  {
    return std::make_unique<BodyCoupling>(bodies, settings);
  }
  catch (const std::invalid_argument& error)
  {
    // BodyWorld names the body by its object ("body 'objects[1]': ...").
    throw InputError(file, error.what());
  }
}

} // namespace

std::unique_ptr<BodyCoupling> buildSceneBodies(const LoadedScene& loaded, double kp, double rate)
{
  std::unique_ptr<BodyCoupling> bodies = buildSceneBodiesUnwatched(loaded, kp, rate);
  if (bodies != nullptr)
  {
    watchSceneBounds(loaded, *bodies);
  }
  return bodies;
}

} // namespace proxima
