// `proxima run`: plays a scripted finger path through a mesh or a scene file in lockstep mode and
// writes the trace (DESIGN.md section 3) and a summary of per-tick solve times and iterations.
#include "Command.h"
#include "DeviceChoice.h"

#include "IO/FingerPathFile.h"
#include "IO/InputError.h"
#include "IO/SceneBuilder.h"
#include "IO/SceneFile.h"
#include "IO/TraceWriter.h"
#include "Proxy/ProxySolver.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/RunSummary.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace proxima::cli
{
namespace
{
struct RunOptions
{
  std::string mesh;
  std::string scene;
  double scale = 1.0;
  double radius = 0.001;
  double stiffness = 1000.0;
  std::string path;
  std::string out;
  std::string summary;
  double rate = 1000.0;
  double maxForce = 10.0;
  int maxIterations = 256;
  double skin = 0.0;
  std::string shading = "off";
  double featureAngle = 30.0;
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
  double viscosity = 0.0;
  std::string texture;
  std::string textureRole;
  double textureAmplitude = 0.0;
  std::string textureChannel = "luminance";
  DeviceChoiceOptions device;
};

SceneShading shadingFrom(const std::string& name)
{
  return name == "on"   ? SceneShading::On
         : name == "auto" ? SceneShading::Auto
                          : SceneShading::Off;
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
  for (TextureChannel channel : {TextureChannel::Red, TextureChannel::Green, TextureChannel::Blue,
                                 TextureChannel::Alpha})
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
SceneDescription sceneFromFlags(const RunOptions& options)
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

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

// Progress on standard error, only for a person watching a terminal.
class Progress
{
public:
  explicit Progress(std::uint64_t total) : m_total(total), m_enabled(isatty(STDERR_FILENO) != 0) {}
  void update(std::uint64_t done)
  {
    if (!m_enabled || m_total == 0)
    {
      return;
    }
    const auto percent = static_cast<int>(100 * done / m_total);
    if (percent != m_lastPercent)
    {
      m_lastPercent = percent;
      std::fprintf(stderr, "\rproxima run: %3d%% (%llu of %llu ticks)", percent,
                   static_cast<unsigned long long>(done), static_cast<unsigned long long>(m_total));
      std::fflush(stderr);
    }
  }
  void finish()
  {
    if (m_enabled && m_total > 0)
    {
      std::fprintf(stderr, "\n");
    }
  }

private:
  std::uint64_t m_total;
  bool m_enabled;
  int m_lastPercent = -1;
};

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

// The surface keys of the summary, for a one-mesh run and for each object of a scene alike.
void addSurfaceKeys(nlohmann::ordered_json& json, const LoadedObject& object,
                    const SurfaceMaterial& material)
{
  json["shading"] = object.shaded;
  json["point_normals"] = normalsSourceName(object.normals);
  if (object.normals == NormalsSource::Computed)
  {
    json["feature_angle_deg"] = object.featureAngleDegrees;
  }
  json["static_friction"] = material.staticFriction;
  json["dynamic_friction"] = material.dynamicFriction;
  json["viscosity_N_s_per_m"] = material.viscosity;
}

int run(const RunOptions& options)
{
  const auto readStart = std::chrono::steady_clock::now();
  const LoadedScene loaded =
    options.scene.empty() ? buildScene(sceneFromFlags(options)) : loadSceneFile(options.scene);
  const FingerPath fingerPath = readFingerPathFile(options.path);
  const double readMilliseconds = millisecondsSince(readStart) - loaded.treeBuildMilliseconds;
  const CollisionScene& scene = *loaded.scene;

  ProxyParameters parameters;
  parameters.radius = options.radius;
  parameters.skin = options.skin;
  parameters.maxIterations = options.maxIterations;
  parameters.stiffness = options.stiffness;
  parameters.timeStep = 1.0 / options.rate;
  ProxySolver solver;
  solver.setScene(&scene, parameters);

  // The proxy starts at the first finger sample, which must leave room for the proxy sphere
  // against every object: a proxy that starts overlapping a surface has no free side to be
  // pushed back to.
  const Vec3 start = fingerPath.positions.front();
  const auto [nearest, distance] = nearestObject(scene, start, options.radius);
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
  solver.resetProxy(start);

  LockstepSettings settings;
  settings.rate = options.rate;
  settings.startTime = fingerPath.startTime();
  settings.numTicks = ticksCovering(fingerPath.startTime(), fingerPath.endTime(), options.rate);
  ServoParameters servo;
  servo.stiffness = options.stiffness;
  servo.maxForce = options.maxForce;

  RunDevice device(options.device, fingerPath, settings.numTicks);
  TraceWriter trace(options.out);
  RunSummary summary;
  Progress progress(settings.numTicks);
  const auto runStart = std::chrono::steady_clock::now();
  runLockstep(settings, solver, device.device(), servo, [&](const TickRecord& record) {
    trace.write(record);
    summary.add(record);
    if ((record.tick & 1023u) == 0)
    {
      progress.update(record.tick);
    }
  });
  progress.update(settings.numTicks);
  progress.finish();
  trace.close();
  device.finish();
  const double runMilliseconds = millisecondsSince(runStart);

  std::uint64_t numTriangles = 0;
  std::uint64_t numDegenerate = 0;
  for (const LoadedObject& object : loaded.objects)
  {
    numTriangles += object.numTriangles;
    numDegenerate += object.numDegenerateTriangles;
  }
  nlohmann::ordered_json json;
  if (options.scene.empty())
  {
    json["mesh"] = options.mesh;
  }
  else
  {
    json["scene"] = options.scene;
  }
  json["path"] = options.path;
  json["device"] = options.device.device;
  json["trace"] = options.out;
  json["triangles"] = numTriangles;
  json["degenerate_triangles"] = numDegenerate;
  json["radius_m"] = options.radius;
  json["skin_m"] = solver.skin();
  json["stiffness_N_per_m"] = options.stiffness;
  json["rate_hz"] = options.rate;
  if (options.scene.empty())
  {
    // The keys of a one-mesh run, as before scene files.
    const LoadedObject& object = loaded.objects.front();
    const SurfaceMaterial& material = scene.objects.front().material;
    addSurfaceKeys(json, object, material);
    if (!options.texture.empty())
    {
      nlohmann::ordered_json texture;
      texture["image"] = options.texture;
      texture["role"] = options.textureRole;
      if (material.textures.front().role == TextureRole::Bump)
      {
        texture["amplitude_m"] = material.textures.front().amplitude;
      }
      texture["channel"] = options.textureChannel;
      json["texture"] = std::move(texture);
    }
  }
  else
  {
    nlohmann::ordered_json objects = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < loaded.objects.size(); ++i)
    {
      const LoadedObject& object = loaded.objects[i];
      const SurfaceMaterial& material = scene.objects[i].material;
      nlohmann::ordered_json entry;
      entry["mesh"] = object.mesh;
      entry["triangles"] = object.numTriangles;
      entry["degenerate_triangles"] = object.numDegenerateTriangles;
      addSurfaceKeys(entry, object, material);
      entry["textures"] = material.textures.size();
      objects.push_back(std::move(entry));
    }
    json["objects"] = std::move(objects);
  }
  json["ticks"] = summary.ticks();
  json["contact_ticks"] = summary.contactTicks();
  json["iterations"] = {
    {"total", summary.totalIterations()},
    {"mean", summary.ticks() > 0 ? static_cast<double>(summary.totalIterations()) /
                                     static_cast<double>(summary.ticks())
                                 : 0.0},
    {"max", summary.maxIterations()},
    {"cap", options.maxIterations},
    {"ticks_at_cap", summary.iterationCapTicks()}};
  json["refused_finger_ticks"] = summary.refusedTicks();
  json["contact_overflow_ticks"] = summary.overflowTicks();
  json["clamped_force_ticks"] = summary.clampedTicks();
  json["fading_force_ticks"] = summary.fadingTicks();
  json["device_lost_ticks"] = summary.deviceLostTicks();
  json["stuck_ticks"] = summary.stuckTicks();
  json["friction_limited_ticks"] = summary.frictionLimitedTicks();
  json["max_force_N"] = summary.maxForce();
  json["solve_ns"] = {{"median", summary.solveNanosecondsQuantile(0.5)},
                      {"p99", summary.solveNanosecondsQuantile(0.99)},
                      {"p99.9", summary.solveNanosecondsQuantile(0.999)},
                      {"max", summary.solveNanosecondsQuantile(1.0)}};
  json["triangles_tested_per_tick"] = summary.meanTrianglesTested();
  json["read_ms"] = readMilliseconds;
  json["tree_build_ms"] = loaded.treeBuildMilliseconds;
  json["run_ms"] = runMilliseconds;

  const std::string text = json.dump(2);
  if (!options.summary.empty())
  {
    std::ofstream file(options.summary);
    file << text << "\n";
    if (!file)
    {
      throw InputError(options.summary, "cannot write the file");
    }
  }
  std::cout << text << "\n";
  return kExitOk;
}

// Checks between options that CLI11 cannot say by itself, as usage errors (status 2).
void checkCombinations(const RunOptions& options, const CLI::App& app)
{
  if (options.mesh.empty() && options.scene.empty())
  {
    throw CLI::RequiredError("--mesh or --scene");
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
} // namespace

Command addRunCommand(CLI::App& parent)
{
  auto options = std::make_shared<RunOptions>();
  CLI::App* app = parent.add_subcommand(
    "run", "Play a finger path through a mesh or a scene in lockstep mode; write the trace and a "
           "summary");
  CLI::Option* mesh = app->add_option(
    "--mesh", options->mesh, "Mesh file (STL, OBJ, PLY, VTP, OFF, glTF/GLB); or --scene");
  CLI::Option* scene = app->add_option(
    "--scene", options->scene,
    "Scene file (JSON: objects with meshes, poses and materials; Documentation/SceneFiles.md); "
    "the surface options below are then the file's, per object");
  mesh->excludes(scene);
  app->add_option("--radius", options->radius, "Proxy radius in metres (default 0.001)")
    ->check(CLI::PositiveNumber);
  app->add_option("--stiffness", options->stiffness, "Spring stiffness kp in N/m (default 1000)")
    ->check(CLI::PositiveNumber);
  app->add_option("--path", options->path, "Finger path CSV (t,x,y,z)")->required();
  app->add_option("--out", options->out, "Trace CSV to write (trace v1)")->required();
  app->add_option("--summary", options->summary, "Also write the summary JSON to this file");
  addDeviceOptions(*app, options->device);
  app->add_option("--rate", options->rate, "Servo rate in Hz (default 1000)")
    ->check(CLI::PositiveNumber);
  app->add_option("--max-force", options->maxForce, "Force clamp in newtons (default 10)")
    ->check(CLI::PositiveNumber);
  app->add_option("--max-iterations", options->maxIterations,
                  "Move/update iterations per tick (default 256)")
    ->check(CLI::Range(1, 1000));
  app->add_option("--skin", options->skin,
                  "Contact skin in metres (default: from the scene, see Documentation/Epsilons.md)")
    ->check(CLI::NonNegativeNumber);

  // The mesh's scale and surface: for --mesh only (a scene file gives them per object).
  const std::string meshOnly = "With --mesh only. ";
  std::vector<CLI::Option*> surface;
  surface.push_back(
    app->add_option("--scale", options->scale, meshOnly + "File units to metres (default 1)")
      ->check(CLI::PositiveNumber));
  surface.push_back(
    app->add_option("--shading", options->shading,
                    meshOnly + "Force shading from the mesh's point normals: off, on or auto "
                               "(default off)")
      ->check(CLI::IsMember({"off", "on", "auto"})));
  surface.push_back(
    app->add_option("--feature-angle", options->featureAngle,
                    meshOnly + "With --shading on and a mesh without normals: edges sharper than "
                               "this many degrees stay sharp (default 30)")
      ->check(CLI::Range(0.0, 180.0)));
  surface.push_back(app->add_option("--static-friction", options->staticFriction,
                                    meshOnly + "Static friction coefficient mu_s (default 0: none)")
                      ->check(CLI::NonNegativeNumber));
  surface.push_back(
    app->add_option("--dynamic-friction", options->dynamicFriction,
                    meshOnly + "Dynamic friction coefficient mu_d (default 0: none)")
      ->check(CLI::NonNegativeNumber));
  surface.push_back(app->add_option("--viscosity", options->viscosity,
                                    meshOnly + "Viscous friction b in N s/m (default 0: none)")
                      ->check(CLI::NonNegativeNumber));
  CLI::Option* texture = app->add_option(
    "--texture", options->texture,
    meshOnly + "Texture image (PNG, JPEG, TIFF, OpenEXR) mapped by the mesh's texture "
               "coordinates; needs --texture-role");
  CLI::Option* role =
    app->add_option("--texture-role", options->textureRole,
                    meshOnly + "What --texture modulates: bump (height), friction or viscosity "
                               "(scales those coefficients)")
      ->check(CLI::IsMember({"bump", "friction", "viscosity", "stiffness"}));
  CLI::Option* amplitude =
    app->add_option("--texture-amplitude", options->textureAmplitude,
                    meshOnly + "Bump maps: metres of height per unit of image value (required "
                               "for bump, not 0)")
      ->check(CLI::Validator(
        [](std::string& input) -> std::string {
          std::size_t used = 0;
          double value = 0.0;
          try
          {
            value = std::stod(input, &used);
          }
          catch (const std::exception&)
          {
            used = 0;
          }
          return used == input.size() && std::isfinite(value) && value != 0.0
                   ? std::string()
                   : "must be a finite number other than 0, not " + input;
        },
        "NONZERO"));
  CLI::Option* channel =
    app->add_option("--texture-channel", options->textureChannel,
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
  for (CLI::Option* option : surface)
  {
    scene->excludes(option);
  }
  app->callback([options, app] { checkCombinations(*options, *app); });
  return Command{app, [options] { return run(*options); }};
}

} // namespace proxima::cli
