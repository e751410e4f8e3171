// `proxima path`: writes a scripted finger path of a given kind, placed from the bounds of a mesh
// or of a scene file's objects as placed; or, for `probe`, a seeded person-like probing session
// placed by the surface itself.
#include "Command.h"
#include "OutputChecks.h"

#include "IO/Mesh/MeshReader.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/Scene/SceneBuilder.h"
#include "Runtime/PathGenerators.h"

#include <cstdint>
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

FingerPath probePath(const PathOptions& options)
{
  ProbeOptions probe;
  probe.seed = options.seed;
  probe.duration = options.duration;
  probe.rate = options.rate;
  if (options.scene.empty())
  {
    return makeProbePath(loadTriangleMesh(options.mesh, options.scale), probe);
  }
  const LoadedScene loaded = loadSceneFile(options.scene);
  refuseOverlappingFiles({{options.out, "--out"}}, sceneMeshInputs(loaded));
  std::vector<ProbeSurface> surfaces;
  for (const CollisionObject& object : loaded.scene->objects)
  {
    surfaces.push_back({&object.mesh, &object.tree});
  }
  return makeProbePath(surfaces, probe);
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
    const FingerPath path = probePath(options);
    writeFingerPathFile(options.out, path);
    writeStandardOutput(report(options, path.size(), path.endTime()));
    return kExitOk;
  }
  Aabb bounds;
  if (options.scene.empty())
  {
    bounds = loadTriangleMesh(options.mesh, options.scale).bounds();
  }
  else
  {
    // The whole scene is built (trees and images too) so that its bounds are exactly those the
    // run will see; for a path, once, that cost does not matter.
    const LoadedScene loaded = loadSceneFile(options.scene);
    refuseOverlappingFiles({{options.out, "--out"}}, sceneMeshInputs(loaded));
    for (const CollisionObject& object : loaded.scene->objects)
    {
      bounds.expand(object.mesh.bounds().lower);
      bounds.expand(object.mesh.bounds().upper);
    }
  }
  const FingerPath path = makeDefaultPath(options.kind, bounds, options.radius, options.rate);
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
      ->check(CLI::PositiveNumber);
  mesh->excludes(scene);
  scene->excludes(scale);
  app->add_option("--radius", options->radius, "Proxy radius in metres (default 0.001)")
    ->check(CLI::PositiveNumber);
  app->add_option("--rate", options->rate, "Samples per second (default 1000)")
    ->check(CLI::PositiveNumber);
  app->add_option("--seed", options->seed, "probe only: random seed (default 1)");
  app
    ->add_option("--duration", options->duration,
                 "probe only: seconds of probing, at least (default 8; the last episode is "
                 "finished)")
    ->check(CLI::NonNegativeNumber);
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
