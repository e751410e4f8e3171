#include "SceneOptions.h"

#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "Runtime/ServoRate.h"

namespace proxima::cli
{

static_assert(kRealtimeRateRange.low == kMinServoRate && kRealtimeRateRange.high == kMaxServoRate,
              "the real-time rate's range is the servo loop's rule");

void addSceneOptionsThroughPath(CLI::App& app, SceneOptions& options, bool pathRequired)
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
  CLI::Option* path = app.add_option("--path", options.path, "Finger path CSV (t,x,y,z)");
  if (pathRequired)
  {
    path->required();
  }
}

void addSceneOptionsAfterPath(CLI::App& app, SceneOptions& options, const ParameterRange& rateRange)
{
  app.add_option("--rate", options.rate, "Servo rate in Hz (default 1000)")
    ->check(numberIn(rateRange));
  app.add_option("--max-force", options.maxForce, "Force clamp in newtons (default 10)")
    ->check(numberIn(kMaxForceRange));
  app
    .add_option("--max-iterations", options.maxIterations,
                "Move/update iterations per tick (default 256)")
    ->check(wholeNumberIn(kMaxIterationsRange));
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
                "iterations, both (50us,40it), default (the real-time default: " +
                  std::to_string(kDefaultTickBudgetIterations) +
                  "it, deterministic, with a wall-time safety cap in real time only) or none. A "
                  "tick that reaches it stops with the "
                  "proxy where it is (always feasible) and the next tick goes on from there. " +
                  defaults)
    ->check(tickBudgetValue());
}

void checkSceneOptions(const SceneOptions& options, const CLI::App& /*app*/)
{
  if (options.mesh.empty() && options.scene.empty())
  {
    throw CLI::RequiredError("--mesh or --scene");
  }
  // The values' own ranges are the options' validators'; what is left are the rules between
  // options, which the library words the same way for every caller (a usage error here).
  try
  {
    checkScriptedRunSettings(options);
  }
  catch (const InputError& error)
  {
    throw CLI::ValidationError(error.path(), error.defect());
  }
}

} // namespace proxima::cli
