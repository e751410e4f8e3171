// `proxima path`: writes a scripted finger path of a given kind (press-stroke, slide, circle,
// jab, wander, or `probe`, a seeded person-like probing session), placed by the surface of a mesh
// or of a scene file's objects as placed, with no axis taken as up.
#include "Command.h"
#include "OutputChecks.h"
#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/Scene/SceneBuilder.h"
#include "Paths/PathGenerators.h"

#include <cstdint>
#include <stdexcept>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace proxima::cli
{
namespace
{
struct PathOptions
{
  std::string kind;
  std::string mesh;
  std::string scene;
  double scale = 1.0;
  double radius = 0.001;
  double rate = 1000.0;
  std::uint64_t seed = 1;
  double duration = ProbeOptions{}.duration;
  double stretch = 0.0;
  double maxTicks = kDefaultMaxTicks;
  std::string out;
};

// The default kinds and `probe`, which needs the surface, not only the bounds.
const std::vector<std::string>& pathKinds()
{
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> all = defaultPathKinds();
    all.push_back("probe");
    return all;
  }();
  return kinds;
}

// The surfaces a path is placed on: the mesh with a tree of its own, or the scene's objects as
// placed (whose trees the scene built).
struct PathSurfaces
{
  std::vector<ProbeSurface> surfaces;
  TriangleMesh mesh;
  SphereTree tree;
  LoadedScene scene;
};

void loadSurfaces(const PathOptions& options, PathSurfaces& loaded)
{
  if (options.scene.empty())
  {
    loaded.mesh = loadTriangleMesh(options.mesh, options.scale);
    loaded.tree.build(loaded.mesh);
    loaded.surfaces.push_back({&loaded.mesh, &loaded.tree});
    return;
  }
  loaded.scene = loadSceneFile(options.scene);
  refuseOverlappingFiles({{options.out, "--out"}}, sceneMeshInputs(loaded.scene));
  for (const CollisionObject& object : loaded.scene.scene->objects)
  {
    loaded.surfaces.push_back({&object.mesh, &object.tree});
  }
}

std::string report(const PathOptions& options, std::size_t numRows, double seconds)
{
  std::ostringstream text;
  text << options.out << ": " << numRows << " rows, " << seconds << " s\n";
  return text.str();
}

int writePath(const PathOptions& options)
{
  // The path must not replace the mesh or scene it is made for.
  refuseOverlappingFiles({{options.out, "--out"}},
                         {{options.mesh, "--mesh"}, {options.scene, "--scene"}});
  if (options.kind == "probe")
  {
    // Refused before anything is loaded: an hour at 100 kHz would not fit in memory.
    checkTickCount(options.duration * options.rate, options.rate, options.maxTicks,
                   "--duration " + shortNumber(options.duration) + " s");
  }
  PathSurfaces loaded;
  loadSurfaces(options, loaded);
  FingerPath path;
  if (options.kind == "probe")
  {
    ProbeOptions probe;
    probe.seed = options.seed;
    probe.duration = options.duration;
    probe.rate = options.rate;
    path = makeProbePath(loaded.surfaces, probe);
  }
  else
  {
    SurfacePathOptions surface;
    surface.radius = options.radius;
    surface.rate = options.rate;
    surface.seed = options.seed;
    surface.stretch = options.stretch;
    try
    {
      path = makeSurfacePath(options.kind, loaded.surfaces, surface);
    }
    catch (const std::runtime_error& error)
    {
      throw InputError(options.scene.empty() ? options.mesh : options.scene,
                       options.kind + ": " + error.what());
    }
  }
  writeFingerPathFile(options.out, path);
  writeStandardOutput(report(options, path.size(), path.endTime() - path.startTime()));
  return kExitOk;
}
} // namespace

Command addPathCommand(CLI::App& parent)
{
  auto options = std::make_shared<PathOptions>();
  CLI::App* app = parent.add_subcommand(kPathSummary.name, kPathSummary.description);
  app->add_option("kind", options->kind, "Path kind")
    ->required()
    ->check(CLI::IsMember(pathKinds()));
  CLI::Option* mesh =
    app->add_option("--mesh", options->mesh, "Mesh whose bounds place the path; or --scene");
  CLI::Option* scene = app->add_option(
    "--scene", options->scene, "Scene file whose objects' bounds, as placed, place the path");
  CLI::Option* scale =
    app->add_option("--scale", options->scale, "With --mesh only. File units to metres (default 1)")
      ->check(numberIn(kMeshScaleRange));
  mesh->excludes(scene);
  scene->excludes(scale);
  app->add_option("--radius", options->radius, "Proxy radius in metres (default 0.001)")
    ->check(numberIn(kProxyRadiusRange));
  app->add_option("--rate", options->rate, "Samples per second (default 1000)")
    ->check(numberIn(kScriptedRateRange));
  app->add_option("--seed", options->seed, "Random seed of the surface points (default 1)");
  app
    ->add_option("--stretch", options->stretch,
                 "press-stroke, circle, jab: the spring's stretch while pressing, in metres "
                 "(default min(3 mm, 5 % of the object): 3 N at 1000 N/m)")
    ->check(numberIn(ParameterRange{0.0, true, 0.1, " m"}));
  app
    ->add_option("--duration", options->duration,
                 "probe only: seconds of probing, at least (default 8; the last episode is "
                 "finished)")
    ->check(numberIn(kPathDurationRange));
  app
    ->add_option("--max-ticks", options->maxTicks,
                 "The most rows the path may have (default 1e7): a longer one is refused")
    ->check(tickCount());
  app->add_option("--out", options->out, "Path CSV to write")->required();
  app->callback([options] {
    if (options->mesh.empty() && options->scene.empty())
    {
      throw CLI::RequiredError("--mesh or --scene");
    }
  });
  return Command{app, [options] { return writePath(*options); }};
}

} // namespace proxima::cli
