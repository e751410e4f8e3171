// `proxima run`: plays a scripted finger path through a mesh in lockstep mode and writes the
// trace (DESIGN.md section 3) and a summary of per-tick solve times and iterations.
#include "Command.h"

#include "IO/FingerPathFile.h"
#include "IO/InputError.h"
#include "IO/MeshReader.h"
#include "IO/PointNormals.h"
#include "IO/TraceWriter.h"
#include "Proxy/ProxySolver.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/RunSummary.h"
#include "Runtime/SimulatedDevice.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
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
};

// The mesh as the run shades it: --shading on gives a mesh whose file has no point normals
// normals computed with --feature-angle (sharp CAD edges stay sharp); auto and off keep the file's.
TriangleMesh meshFor(const RunOptions& options, std::string& normals)
{
  TriangleSoup soup = readMeshFile(options.mesh, options.scale);
  normals = soup.pointNormals.empty() ? "none" : "file";
  if (options.shading == "on" && soup.pointNormals.empty())
  {
    soup = withFeatureAngleNormals(soup, options.featureAngle);
    normals = "computed";
  }
  return buildTriangleMesh(std::move(soup), options.mesh);
}

// --shading: on shades (with the file's normals or computed ones), auto shades exactly when the
// file has normals, off never.
SurfaceMaterial materialFor(const RunOptions& options, const TriangleMesh& mesh)
{
  SurfaceMaterial material;
  material.shading = options.shading == "on" || (options.shading == "auto" && mesh.hasPointNormals());
  material.staticFriction = options.staticFriction;
  material.dynamicFriction = options.dynamicFriction;
  material.viscosity = options.viscosity;
  return material;
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

int run(const RunOptions& options)
{
  const auto readStart = std::chrono::steady_clock::now();
  CollisionScene scene;
  std::string normals;
  const TriangleMesh mesh = meshFor(options, normals);
  const FingerPath fingerPath = readFingerPathFile(options.path);
  const double readMilliseconds = millisecondsSince(readStart);

  const std::uint32_t numTriangles = mesh.numTriangles();
  const std::uint32_t numDegenerate = mesh.numDegenerateTriangles();
  const SurfaceMaterial material = materialFor(options, mesh);
  const auto buildStart = std::chrono::steady_clock::now();
  scene.addObject(mesh, SphereTreeOptions{}, material);
  const double buildMilliseconds = millisecondsSince(buildStart);

  ProxyParameters parameters;
  parameters.radius = options.radius;
  parameters.skin = options.skin;
  parameters.maxIterations = options.maxIterations;
  parameters.stiffness = options.stiffness;
  parameters.timeStep = 1.0 / options.rate;
  ProxySolver solver;
  solver.setScene(&scene, parameters);

  // The proxy starts at the first finger sample, which must leave room for the proxy sphere:
  // a proxy that starts overlapping the surface has no free side to be pushed back to.
  const Vec3 start = fingerPath.positions.front();
  const CollisionObject& object = scene.objects.front();
  SphereTreeScratch scratch;
  const NearestTriangle nearest = object.tree.nearest(object.mesh, start, options.radius, scratch);
  if (nearest.found && std::sqrt(nearest.closest.squaredDistance) < options.radius)
  {
    std::ostringstream defect;
    defect << "the path starts " << std::sqrt(nearest.closest.squaredDistance)
           << " m from the mesh, closer than the proxy radius " << options.radius
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

  SimulatedDevice device(fingerPath);
  TraceWriter trace(options.out);
  RunSummary summary;
  Progress progress(settings.numTicks);
  const auto runStart = std::chrono::steady_clock::now();
  runLockstep(settings, solver, device, servo, [&](const TickRecord& record) {
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
  const double runMilliseconds = millisecondsSince(runStart);

  nlohmann::ordered_json json;
  json["mesh"] = options.mesh;
  json["path"] = options.path;
  json["trace"] = options.out;
  json["triangles"] = numTriangles;
  json["degenerate_triangles"] = numDegenerate;
  json["radius_m"] = options.radius;
  json["skin_m"] = solver.skin();
  json["stiffness_N_per_m"] = options.stiffness;
  json["rate_hz"] = options.rate;
  json["shading"] = material.shading;
  json["point_normals"] = normals;
  if (normals == "computed")
  {
    json["feature_angle_deg"] = options.featureAngle;
  }
  json["static_friction"] = material.staticFriction;
  json["dynamic_friction"] = material.dynamicFriction;
  json["viscosity_N_s_per_m"] = material.viscosity;
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
  json["stuck_ticks"] = summary.stuckTicks();
  json["friction_limited_ticks"] = summary.frictionLimitedTicks();
  json["max_force_N"] = summary.maxForce();
  json["solve_ns"] = {{"median", summary.solveNanosecondsQuantile(0.5)},
                      {"p99", summary.solveNanosecondsQuantile(0.99)},
                      {"p99.9", summary.solveNanosecondsQuantile(0.999)},
                      {"max", summary.solveNanosecondsQuantile(1.0)}};
  json["triangles_tested_per_tick"] = summary.meanTrianglesTested();
  json["read_ms"] = readMilliseconds;
  json["tree_build_ms"] = buildMilliseconds;
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
} // namespace

Command addRunCommand(CLI::App& parent)
{
  auto options = std::make_shared<RunOptions>();
  CLI::App* app = parent.add_subcommand(
    "run", "Play a finger path through a mesh in lockstep mode; write the trace and a summary");
  app->add_option("--mesh", options->mesh, "Mesh file (STL, OBJ, PLY, VTP, OFF, glTF/GLB)")
    ->required();
  app->add_option("--scale", options->scale, "File units to metres (default 1)")
    ->check(CLI::PositiveNumber);
  app->add_option("--radius", options->radius, "Proxy radius in metres (default 0.001)")
    ->check(CLI::PositiveNumber);
  app->add_option("--stiffness", options->stiffness, "Spring stiffness kp in N/m (default 1000)")
    ->check(CLI::PositiveNumber);
  app->add_option("--path", options->path, "Finger path CSV (t,x,y,z)")->required();
  app->add_option("--out", options->out, "Trace CSV to write (trace v1)")->required();
  app->add_option("--summary", options->summary, "Also write the summary JSON to this file");
  app->add_option("--rate", options->rate, "Servo rate in Hz (default 1000)")
    ->check(CLI::PositiveNumber);
  app->add_option("--max-force", options->maxForce, "Force clamp in newtons (default 10)")
    ->check(CLI::PositiveNumber);
  app->add_option("--max-iterations", options->maxIterations,
                  "Move/update iterations per tick (default 256)")
    ->check(CLI::Range(1, 1000));
  app->add_option("--shading", options->shading,
                  "Force shading from the mesh's point normals: off, on or auto (default off)")
    ->check(CLI::IsMember({"off", "on", "auto"}));
  app->add_option("--feature-angle", options->featureAngle,
                  "With --shading on and a mesh without normals: edges sharper than this many "
                  "degrees stay sharp (default 30)")
    ->check(CLI::Range(0.0, 180.0));
  app->add_option("--static-friction", options->staticFriction,
                  "Static friction coefficient mu_s (default 0: none)")
    ->check(CLI::NonNegativeNumber);
  app->add_option("--dynamic-friction", options->dynamicFriction,
                  "Dynamic friction coefficient mu_d (default 0: none)")
    ->check(CLI::NonNegativeNumber);
  app->add_option("--viscosity", options->viscosity,
                  "Viscous friction b in N s/m (default 0: none)")
    ->check(CLI::NonNegativeNumber);
  app->add_option("--skin", options->skin,
                  "Contact skin in metres (default: from the scene, see Documentation/Epsilons.md)")
    ->check(CLI::NonNegativeNumber);
  return Command{app, [options] { return run(*options); }};
}

} // namespace proxima::cli
