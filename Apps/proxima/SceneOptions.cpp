#include "SceneOptions.h"

#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Scene/SceneFile.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace proxima::cli
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
SceneDescription sceneFromFlags(const SceneOptions& options)
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

void addSceneOptionsThroughPath(CLI::App& app, SceneOptions& options)
{
  CLI::Option* mesh = app.add_option("--mesh", options.mesh,
                                     "Mesh file (STL, OBJ, PLY, VTP, OFF, glTF/GLB); or --scene");
  CLI::Option* scene = app.add_option(
    "--scene", options.scene,
    "Scene file (JSON: objects with meshes, poses and materials; Documentation/SceneFiles.md); "
    "the surface options below are then the file's, per object");
  mesh->excludes(scene);
  app.add_option("--radius", options.radius, "Proxy radius in metres (default 0.001)")
    ->check(numberIn(kProxyRadiusRange));
  app.add_option("--stiffness", options.stiffness, "Spring stiffness kp in N/m (default 1000)")
    ->check(numberIn(kStiffnessRange));
  app.add_option("--path", options.path, "Finger path CSV (t,x,y,z)")->required();
}

void addSceneOptionsAfterPath(CLI::App& app, SceneOptions& options)
{
  app.add_option("--rate", options.rate, "Servo rate in Hz (default 1000)")
    ->check(numberIn(kScriptedRateRange));
  app.add_option("--max-force", options.maxForce, "Force clamp in newtons (default 10)")
    ->check(numberIn(kMaxForceRange));
  app
    .add_option("--max-iterations", options.maxIterations,
                "Move/update iterations per tick (default 256)")
    ->check(CLI::Range(1, 1000));
  app
    .add_option("--skin", options.skin,
                "Contact skin in metres (default: from the scene, see Documentation/Epsilons.md)")
    ->check(numberIn(kSkinRange));

  // The mesh's scale and surface: for --mesh only (a scene file gives them per object).
  const std::string meshOnly = "With --mesh only. ";
  std::vector<CLI::Option*> surface;
  surface.push_back(
    app.add_option("--scale", options.scale, meshOnly + "File units to metres (default 1)")
      ->check(numberIn(kMeshScaleRange)));
  surface.push_back(app
                      .add_option("--shading", options.shading,
                                  meshOnly +
                                    "Force shading from the mesh's point normals: off, on or auto "
                                    "(default off)")
                      ->check(CLI::IsMember({"off", "on", "auto"})));
  surface.push_back(
    app
      .add_option("--feature-angle", options.featureAngle,
                  meshOnly + "With --shading on and a mesh without normals: edges sharper than "
                             "this many degrees stay sharp (default 30)")
      ->check(numberIn(kFeatureAngleRange)));
  surface.push_back(app
                      .add_option("--static-friction", options.staticFriction,
                                  meshOnly + "Static friction coefficient mu_s (default 0: none)")
                      ->check(numberIn(kFrictionRange)));
  surface.push_back(
    app
      .add_option("--dynamic-friction", options.dynamicFriction,
                  meshOnly + "Dynamic friction coefficient mu_d, at most mu_s (default 0: none)")
      ->check(numberIn(kFrictionRange)));
  surface.push_back(app
                      .add_option("--viscosity", options.viscosity,
                                  meshOnly + "Viscous friction b in N s/m (default 0: none)")
                      ->check(numberIn(kViscosityRange)));
  CLI::Option* texture = app.add_option(
    "--texture", options.texture,
    meshOnly + "Texture image (PNG, JPEG, TIFF, OpenEXR) mapped by the mesh's texture "
               "coordinates; needs --texture-role");
  CLI::Option* role =
    app
      .add_option("--texture-role", options.textureRole,
                  meshOnly + "What --texture modulates: bump (height), friction or viscosity "
                             "(scales those coefficients)")
      ->check(CLI::IsMember({"bump", "friction", "viscosity", "stiffness"}));
  CLI::Option* amplitude =
    app
      .add_option("--texture-amplitude", options.textureAmplitude,
                  meshOnly + "Bump maps: metres of height per unit of image value (required "
                             "for bump, not 0)")
      ->check(CLI::Validator(
        [](std::string& input) -> std::string {
          double value = 0.0;
          return parsePlainNumber(input, value) && value != 0.0 && std::abs(value) <= 1.0
                   ? std::string()
                   : "must be a number other than 0, from -1 to 1 m, not " + input;
        },
        "NONZERO"));
  CLI::Option* channel =
    app
      .add_option("--texture-channel", options.textureChannel,
                  meshOnly + "Which value of each pixel --texture takes: luminance, red, green, "
                             "blue or alpha (default luminance)")
      ->check(CLI::IsMember({"luminance", "red", "green", "blue", "alpha"}));
  texture->needs(role);
  role->needs(texture);
  amplitude->needs(texture);
  channel->needs(texture);
  for (CLI::Option* option : {texture, role, amplitude, channel})
  {
    surface.push_back(option);
  }
  CLI::Option* scene = app.get_option("--scene");
  for (CLI::Option* option : surface)
  {
    scene->excludes(option);
  }
}

void addTickBudgetOption(CLI::App& app, SceneOptions& options, const std::string& defaults)
{
  app
    .add_option("--tick-budget", options.tickBudget,
                "Work budget of one proxy tick: <N>us of wall time, <N>it move/update "
                "iterations, both (50us,40it), or none. A tick that reaches it stops with the "
                "proxy where it is (always feasible) and the next tick goes on from there. " +
                  defaults)
    ->check(tickBudgetValue());
}

TickWorkBudget tickBudget(const SceneOptions& options, const TickWorkBudget& byDefault)
{
  if (options.tickBudget.empty())
  {
    return byDefault;
  }
  TickWorkBudget budget;
  const std::string refused = parseTickBudget(options.tickBudget, budget);
  if (!refused.empty())
  {
    // The option's check refuses this before any command runs; this is for a caller that
    // filled SceneOptions by itself.
    throw InputError("--tick-budget", refused);
  }
  return budget;
}

void checkSceneOptions(const SceneOptions& options, const CLI::App& app)
{
  if (options.mesh.empty() && options.scene.empty())
  {
    throw CLI::RequiredError("--mesh or --scene");
  }
  const std::string friction =
    frictionPairError(options.staticFriction, options.dynamicFriction, "--static-friction");
  if (!friction.empty())
  {
    throw CLI::ValidationError("--dynamic-friction", friction);
  }
  if (options.skin >= options.radius)
  {
    throw CLI::ValidationError("--skin", shortNumber(options.skin) +
                                           " m is not smaller than --radius " +
                                           shortNumber(options.radius) + " m");
  }
  if (options.texture.empty())
  {
    return;
  }
  const bool amplitudeGiven = app.get_option("--texture-amplitude")->count() > 0;
  if (options.textureRole == "bump")
  {
    if (!amplitudeGiven)
    {
      throw CLI::ValidationError("--texture-role", "bump needs --texture-amplitude (metres of "
                                                   "height per unit of image value)");
    }
  }
  else if (amplitudeGiven)
  {
    throw CLI::ValidationError("--texture-amplitude", "is for bump maps only: a " +
                                                        options.textureRole +
                                                        " map scales the surface's coefficient");
  }
  // A property map scales a coefficient; on a coefficient of 0 it would do nothing, which is
  // more likely a misunderstanding than intended (as in scene files).
  if (options.textureRole == "friction" && options.staticFriction == 0.0 &&
      options.dynamicFriction == 0.0)
  {
    throw CLI::ValidationError("--texture-role", "a friction map scales --static-friction and "
                                                 "--dynamic-friction, but neither is above 0");
  }
  if (options.textureRole == "viscosity" && options.viscosity == 0.0)
  {
    throw CLI::ValidationError("--texture-role",
                               "a viscosity map scales --viscosity, but it is not above 0");
  }
}

LoadedScene loadScene(const SceneOptions& options)
{
  return options.scene.empty() ? buildScene(sceneFromFlags(options)) : loadSceneFile(options.scene);
}

ProxyParameters proxyParameters(const SceneOptions& options)
{
  ProxyParameters parameters;
  parameters.radius = options.radius;
  parameters.skin = options.skin;
  parameters.maxIterations = options.maxIterations;
  parameters.stiffness = options.stiffness;
  parameters.timeStep = 1.0 / options.rate;
  return parameters;
}

ServoParameters servoParameters(const SceneOptions& options)
{
  ServoParameters servo;
  servo.stiffness = options.stiffness;
  servo.maxForce = options.maxForce;
  return servo;
}

void checkRadiusAgainstScene(const SceneOptions& options, const LoadedScene& loaded)
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

void checkPathStart(const SceneOptions& options, const LoadedScene& loaded,
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

} // namespace proxima::cli
