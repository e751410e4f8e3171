// `proxima tree`: reads a mesh, builds its sphere tree and reports sizes and times as JSON, so
// that a script (or a person choosing leaf sizes) sees what a mesh costs before running it.
#include "Command.h"
#include "MeshFileOptions.h"
#include "Validators.h"

#include "Geometry/SphereTree.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/Output/StandardOutput.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <memory>
#include <string>

namespace proxima::cli
{
namespace
{
struct TreeArguments
{
  std::string mesh;
  double scale = 1.0;
  SphereTreeOptions tree;
};

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

nlohmann::ordered_json toJson(const Vec3& v)
{
  return nlohmann::ordered_json::array({v.x, v.y, v.z});
}

int runTree(const TreeArguments& arguments)
{
  const auto readStart = std::chrono::steady_clock::now();
  const TriangleMesh mesh = loadTriangleMesh(arguments.mesh, arguments.scale);
  const double readMs = millisecondsSince(readStart);

  SphereTree tree;
  const auto buildStart = std::chrono::steady_clock::now();
  tree.build(mesh, arguments.tree);
  const double buildMs = millisecondsSince(buildStart);

  nlohmann::ordered_json report;
  report["mesh"] = arguments.mesh;
  report["scale"] = arguments.scale;
  report["triangles"] = mesh.numTriangles();
  report["degenerate_triangles"] = mesh.numDegenerateTriangles();
  report["points"] = mesh.numPoints();
  report["point_normals"] = mesh.hasPointNormals();
  report["texture_coordinates"] = mesh.hasTexCoords();
  report["leaf_spheres"] = tree.numLeafSpheres();
  report["nodes"] = tree.numNodes();
  report["depth"] = tree.depth();
  report["build_ms"] = buildMs;
  report["tree_bytes"] = tree.memoryBytes();
  report["bytes_per_triangle"] =
    static_cast<double>(tree.memoryBytes()) / static_cast<double>(mesh.numTriangles());
  report["mesh_bytes"] = mesh.memoryBytes();
  report["read_ms"] = readMs;
  report["bounds"] = {{"min", toJson(mesh.bounds().lower)}, {"max", toJson(mesh.bounds().upper)}};
  report["diagonal"] = mesh.diagonal();
  report["options"] = {{"leaf_size_factor", arguments.tree.leafSizeFactor},
                       {"leaf_spheres_per_node", arguments.tree.maxLeafSpheresPerNode},
                       {"max_pieces_per_triangle", arguments.tree.maxPiecesPerTriangle}};
  writeStandardOutput(report.dump(2) + "\n");
  return kExitOk;
}
} // namespace

Command addTreeCommand(CLI::App& parent)
{
  // Shared with the run callback: CLI11 writes the parsed values here.
  auto arguments = std::make_shared<TreeArguments>();
  CLI::App* app = parent.add_subcommand(kTreeSummary.name, kTreeSummary.description);
  addMeshFileOptions(*app, arguments->mesh, arguments->scale);
  app
    ->add_option("--leaf-size-factor", arguments->tree.leafSizeFactor,
                 "Split triangles longer than this many median edge lengths into several leaf "
                 "spheres; 0 gives one leaf sphere per triangle")
    ->check(numberIn(kLeafSizeFactorRange))
    ->capture_default_str();
  app
    ->add_option("--leaf-spheres-per-node", arguments->tree.maxLeafSpheresPerNode,
                 "Leaf spheres grouped under one leaf node (1 is the paper's tree)")
    ->check(wholeNumberIn(kLeafSpheresPerNodeRange))
    ->capture_default_str();
  app
    ->add_option("--max-pieces-per-triangle", arguments->tree.maxPiecesPerTriangle,
                 "Upper bound on the leaf spheres of one triangle")
    ->check(wholeNumberIn(kPiecesPerTriangleRange))
    ->capture_default_str();
  return Command{app, [arguments] { return runTree(*arguments); }};
}

} // namespace proxima::cli
