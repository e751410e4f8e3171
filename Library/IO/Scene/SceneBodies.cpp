#include "IO/Scene/SceneBodies.h"

#include "IO/InputChecks/InputError.h"

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

std::unique_ptr<BodyCoupling> buildSceneBodies(const LoadedScene& loaded, double kp, double rate)
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
  for (std::size_t i = 0; i < description.objects.size(); ++i)
  {
    const SceneObject& object = description.objects[i];
    if (!object.hasBody)
    {
      continue;
    }
    const std::string where = "objects[" + std::to_string(i) + "].body";
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

} // namespace proxima
