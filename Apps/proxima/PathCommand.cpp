// `proxima path`: writes a scripted finger path of a given kind, placed from a mesh's bounds.
#include "Command.h"

#include "IO/FingerPathFile.h"
#include "IO/MeshReader.h"
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
  double scale = 1.0;
  double radius = 0.001;
  double rate = 1000.0;
  std::string out;
};

int writePath(const PathOptions& options)
{
  const TriangleMesh mesh = loadTriangleMesh(options.mesh, options.scale);
  const FingerPath path =
    makeDefaultPath(options.kind, mesh.bounds(), options.radius, options.rate);
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
    "path", "Write a scripted finger path (slide, press-stroke, circle, jab, wander) for a mesh");
  app->add_option("kind", options->kind, "Path kind")
    ->required()
    ->check(CLI::IsMember(defaultPathKinds()));
  app->add_option("--mesh", options->mesh, "Mesh whose bounds place the path")->required();
  app->add_option("--scale", options->scale, "File units to metres (default 1)")
    ->check(CLI::PositiveNumber);
  app->add_option("--radius", options->radius, "Proxy radius in metres (default 0.001)")
    ->check(CLI::PositiveNumber);
  app->add_option("--rate", options->rate, "Samples per second (default 1000)")
    ->check(CLI::PositiveNumber);
  app->add_option("--out", options->out, "Path CSV to write")->required();
  return Command{app, [options] { return writePath(*options); }};
}

} // namespace proxima::cli
