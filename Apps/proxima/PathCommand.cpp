// `proxima path`: writes a scripted finger path of a given kind, placed from the bounds of a mesh
// or of a scene file's objects as placed.
#include "Command.h"

#include "IO/FingerPathFile.h"
#include "IO/MeshReader.h"
#include "IO/SceneBuilder.h"
#include "Runtime/PathGenerators.h"

#include <iostream>
#include <memory>

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
  std::string out;
};

int writePath(const PathOptions& options)
{
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
    for (const CollisionObject& object : loaded.scene->objects)
    {
      bounds.expand(object.mesh.bounds().lower);
      bounds.expand(object.mesh.bounds().upper);
    }
  }
  const FingerPath path = makeDefaultPath(options.kind, bounds, options.radius, options.rate);
  writeFingerPathFile(options.out, path);
  std::cout << options.out << ": " << path.size() << " rows, " << path.endTime() - path.startTime()
            << " s\n";
  return kExitOk;
}
} // namespace

Command addPathCommand(CLI::App& parent)
{
  auto options = std::make_shared<PathOptions>();
  CLI::App* app = parent.add_subcommand(
    "path",
    "Write a scripted finger path (slide, press-stroke, circle, jab, wander) for a mesh or a "
    "scene");
  app->add_option("kind", options->kind, "Path kind")
    ->required()
    ->check(CLI::IsMember(defaultPathKinds()));
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
