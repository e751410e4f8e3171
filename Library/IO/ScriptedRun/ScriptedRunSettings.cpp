#include "IO/ScriptedRun/ScriptedRunSettings.h"

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "IO/ScriptedRun/RunSettingTable.h"
#include "IO/Scene/SceneFile.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{
SceneShading shadingFrom(const std::string& name)
{
  return name == "on" ? SceneShading::On : name == "auto" ? SceneShading::Auto : SceneShading::Off;
}

TextureRole roleFrom(const std::string& name)
{
  if (name == "stiffness")
  {
    return TextureRole::Stiffness;
  }
  return name == "friction" ? TextureRole::Friction
                            : (name == "viscosity" ? TextureRole::Viscosity : TextureRole::Bump);
}

TextureChannel channelFrom(const std::string& name)
{
  for (TextureChannel channel :
       {TextureChannel::Red, TextureChannel::Green, TextureChannel::Blue, TextureChannel::Alpha})
  {
    if (name == textureChannelName(channel))
    {
      return channel;
    }
  }
  return TextureChannel::Luminance;
}

// A --mesh run is the scene of one object, at rest, whose material the flags spell out: --shading
// on gives a mesh whose file has no point normals normals computed with --feature-angle (sharp
// CAD edges stay sharp), auto shades exactly when the file has them, off never.
SceneDescription sceneFromFlags(const ScriptedRunSettings& options)
{
  SceneObject object;
  object.mesh = options.mesh;
  object.scale = options.scale;
  object.material.shading = shadingFrom(options.shading);
  object.material.featureAngleDegrees = options.featureAngle;
  object.material.staticFriction = options.staticFriction;
  object.material.dynamicFriction = options.dynamicFriction;
  object.material.viscosity = options.viscosity;
  if (!options.texture.empty())
  {
    const TextureRole role = roleFrom(options.textureRole);
    const double amplitude = role == TextureRole::Bump ? options.textureAmplitude : 0.0;
    object.material.textures.push_back(
      SceneTexture{options.texture, role, amplitude, channelFrom(options.textureChannel)});
  }
  SceneDescription scene;
  scene.objects.push_back(std::move(object));
  return scene;
}

// The nearest object to `point` within `radius`: its index and distance (infinity if none).
std::pair<std::size_t, double> nearestObject(const CollisionScene& scene, const Vec3& point,
                                             double radius)
{
  std::pair<std::size_t, double> nearest{0, std::numeric_limits<double>::infinity()};
  SphereTreeScratch scratch;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
  {
    const CollisionObject& object = scene.objects[i];
    const NearestTriangle near = object.tree.nearest(object.mesh, point, radius, scratch);
    if (near.found && std::sqrt(near.closest.squaredDistance) < nearest.second)
    {
      nearest = {i, std::sqrt(near.closest.squaredDistance)};
    }
  }
  return nearest;
}

} // namespace

void checkScriptedRunSettings(const ScriptedRunSettings& settings)
{
  if (settings.mesh.empty() == settings.scene.empty())
  {
    throw InputError("--mesh", "give a mesh or a scene file, one of the two");
  }
  // Each knob on its own, by its row of the settings table. A scene file gives its objects'
  // scale and surface; the mesh's knobs then stay at their defaults (the command line refuses
  // them beside --scene), so only a --mesh run's are checked.
  for (const RunSetting& setting : runSettings())
  {
    if (setting.scope == RunSettingScope::Surface && !settings.scene.empty())
    {
      continue;
    }
    const std::string refused = setting.refusal(settings);
    if (!refused.empty())
    {
      throw InputError(setting.flag(), refused);
    }
  }
  // Then the rules between knobs.
  if (settings.skin >= settings.radius)
  {
    throw InputError("--skin", shortNumber(settings.skin) + " m is not smaller than --radius " +
                                 shortNumber(settings.radius) + " m");
  }
  if (!settings.scene.empty())
  {
    return;
  }
  const std::string friction =
    frictionPairError(settings.staticFriction, settings.dynamicFriction, "--static-friction");
  if (!friction.empty())
  {
    throw InputError("--dynamic-friction", friction);
  }
  if (settings.texture.empty())
  {
    if (!settings.textureRole.empty())
    {
      throw InputError("--texture-role", "needs --texture");
    }
    return;
  }
  if (settings.textureRole.empty())
  {
    throw InputError("--texture", "requires --texture-role (bump, friction, viscosity or "
                                  "stiffness)");
  }
  const bool amplitudeGiven = settings.textureAmplitude != 0.0;
  if (settings.textureRole == "bump")
  {
    if (!amplitudeGiven)
    {
      throw InputError("--texture-role", "bump needs --texture-amplitude (metres of height per "
                                         "unit of image value)");
    }
  }
  else if (amplitudeGiven)
  {
    throw InputError("--texture-amplitude", "is for bump maps only: a " + settings.textureRole +
                                              " map scales the surface's coefficient");
  }
  // A property map scales a coefficient; on a coefficient of 0 it would do nothing, which is
  // more likely a misunderstanding than intended (as in scene files).
  if (settings.textureRole == "friction" && settings.staticFriction == 0.0 &&
      settings.dynamicFriction == 0.0)
  {
    throw InputError("--texture-role", "a friction map scales --static-friction and "
                                       "--dynamic-friction, but neither is above 0");
  }
  if (settings.textureRole == "viscosity" && settings.viscosity == 0.0)
  {
    throw InputError("--texture-role", "a viscosity map scales --viscosity, but it is not above 0");
  }
}

TickWorkBudget tickBudget(const ScriptedRunSettings& options, const TickWorkBudget& byDefault)
{
  if (options.tickBudget.empty())
  {
    return byDefault;
  }
  TickWorkBudget budget;
  const std::string refused = parseTickBudget(options.tickBudget, budget);
  if (!refused.empty())
  {
    // The command line's option check refuses this before any command runs; this is for a
    // caller that filled the settings by itself.
    throw InputError("--tick-budget", refused);
  }
  return budget;
}

LoadedScene loadScene(const ScriptedRunSettings& options)
{
  return options.scene.empty() ? buildScene(sceneFromFlags(options)) : loadSceneFile(options.scene);
}

ProxyParameters proxyParameters(const ScriptedRunSettings& options)
{
  ProxyParameters parameters;
  parameters.radius = options.radius;
  parameters.skin = options.skin;
  parameters.maxIterations = options.maxIterations;
  parameters.stiffness = options.stiffness;
  parameters.timeStep = 1.0 / options.rate;
  return parameters;
}

ServoParameters servoParameters(const ScriptedRunSettings& options)
{
  ServoParameters servo;
  servo.stiffness = options.stiffness;
  servo.maxForce = options.maxForce;
  return servo;
}

void refuseSceneBodies(const LoadedScene& loaded, const std::string& who)
{
  if (loaded.description.hasBodies())
  {
    throw InputError(loaded.description.path,
                     "the scene has bodies, which " + who +
                       " does not move yet (proxima run and proxima view play them, "
                       "Documentation/Dynamics.md)");
  }
}

void refuseSceneTissue(const LoadedScene& loaded, const std::string& who)
{
  if (loaded.description.hasTissue())
  {
    throw InputError(loaded.description.path,
                     "the scene has tissue, which " + who +
                       " does not deform yet (proxima run plays it, in lockstep or "
                       "--realtime, Documentation/Tissue.md)");
  }
}

void checkRadiusAgainstScene(const ScriptedRunSettings& options, const LoadedScene& loaded)
{
  Aabb bounds;
  for (const CollisionObject& object : loaded.scene->objects)
  {
    bounds.expand(object.mesh.bounds().lower);
    bounds.expand(object.mesh.bounds().upper);
  }
  const double diagonal = norm(bounds.upper - bounds.lower);
  // A proxy larger than the whole scene touches it everywhere at once: a unit slip (--radius
  // in millimetres on a scene in metres), not a finger.
  if (options.radius > diagonal)
  {
    throw InputError("--radius", shortNumber(options.radius) +
                                   " m is larger than the whole scene (its bounding box's "
                                   "diagonal is " +
                                   shortNumber(diagonal) + " m): give the radius in metres");
  }
}

void checkPathStart(const ScriptedRunSettings& options, const LoadedScene& loaded,
                    const FingerPath& fingerPath)
{
  const Vec3 start = fingerPath.positions.front();
  const auto [nearest, distance] = nearestObject(*loaded.scene, start, options.radius);
  if (distance < options.radius)
  {
    std::ostringstream defect;
    defect << "the path starts " << distance << " m from ";
    if (options.scene.empty())
    {
      defect << "the mesh";
    }
    else
    {
      defect << "objects[" << nearest << "] (" << loaded.objects[nearest].mesh << ")";
    }
    defect << ", closer than the proxy radius " << options.radius
           << " m: start the path in free space";
    throw InputError(options.path, defect.str());
  }
}

} // namespace proxima
