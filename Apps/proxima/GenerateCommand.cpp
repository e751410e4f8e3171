// `proxima generate <shape>`: writes one of the project's procedural meshes to a file, which is
// how Data/Meshes is made (see Data/README.md).
#include "Command.h"
#include "Validators.h"

#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshWriter.h"
#include "IO/Output/StandardOutput.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

namespace proxima::cli
{
namespace
{
struct GenerateArguments
{
  std::string out;
  std::vector<double> center{0.0, 0.0, 0.0};
  // icosphere
  std::uint32_t subdivisions = 4;
  double radius = 0.05;
  // box
  std::vector<double> halfExtents{0.05, 0.05, 0.05};
  // grid
  double size = 0.2;
  std::uint32_t cells = 16;
  double height = 0.0;
  // prism
  std::uint32_t sides = 10;
  double prismHeight = 0.1;
};

Vec3 toVec3(const std::vector<double>& values)
{
  return Vec3{values.at(0), values.at(1), values.at(2)};
}

int writeAndReport(const std::string& shape, const TriangleSoup& soup, const std::string& out)
{
  writeMeshFile(out, soup);
  nlohmann::ordered_json report;
  report["shape"] = shape;
  report["out"] = out;
  report["triangles"] = soup.triangles.size();
  report["points"] = soup.points.size();
  report["point_normals"] = !soup.pointNormals.empty();
  writeStandardOutput(report.dump(2) + "\n");
  return kExitOk;
}

void addOut(CLI::App* app, GenerateArguments& arguments)
{
  // The format is checked with the other options, before a shape of millions of triangles is
  // made only to be refused.
  app->add_option("--out", arguments.out, "Mesh file to write: .obj, .stl, .ply or .vtp")
    ->required()
    ->check(CLI::Validator(
      [](std::string& input) -> std::string {
        return isWritableMeshFormat(input) ? std::string()
                                           : input + ": " + kWritableMeshFormatsMessage;
      },
      "MESH"));
}

void addCenter(CLI::App* app, GenerateArguments& arguments)
{
  app->add_option("--center", arguments.center, "Centre in metres: X Y Z")
    ->expected(3)
    ->check(numberIn(kGeneratedPlaceRange))
    ->capture_default_str();
}
} // namespace

Command addGenerateCommand(CLI::App& parent)
{
  auto arguments = std::make_shared<GenerateArguments>();
  CLI::App* generate = parent.add_subcommand(kGenerateSummary.name, kGenerateSummary.description);
  generate->require_subcommand(1);

  CLI::App* icosphere = generate->add_subcommand(
    "icosphere", "Subdivided icosahedron: 20 * 4^N triangles, unit normals per point.");
  icosphere->add_option("--subdivisions", arguments->subdivisions, "Subdivision levels N")
    ->check(wholeNumberIn(kIcosphereSubdivisionsRange))
    ->capture_default_str();
  icosphere->add_option("--radius", arguments->radius, "Radius in metres")
    ->check(numberIn(kGeneratedSizeRange))
    ->capture_default_str();
  addCenter(icosphere, *arguments);
  addOut(icosphere, *arguments);

  CLI::App* box = generate->add_subcommand("box", "Axis-aligned box, 12 triangles.");
  box->add_option("--half-extents", arguments->halfExtents, "Half the box's size: X Y Z")
    ->expected(3)
    ->check(numberIn(kGeneratedSizeRange))
    ->capture_default_str();
  addCenter(box, *arguments);
  addOut(box, *arguments);

  CLI::App* grid =
    generate->add_subcommand("grid", "Square sheet in a plane z = height: 2 * cells^2 triangles.");
  grid->add_option("--size", arguments->size, "Side length in metres")
    ->check(numberIn(kGeneratedSizeRange))
    ->capture_default_str();
  grid->add_option("--cells", arguments->cells, "Cells along each side")
    ->check(wholeNumberIn(kGridCellsRange))
    ->capture_default_str();
  grid->add_option("--height", arguments->height, "The plane's z in metres")
    ->check(numberIn(kGeneratedPlaceRange))
    ->capture_default_str();
  addOut(grid, *arguments);

  CLI::App* prism = generate->add_subcommand(
    "prism", "Sides of a regular prism about z (open tube), radial normals per point: Figure 6.");
  prism->add_option("--sides", arguments->sides, "Number of sides")
    ->check(wholeNumberIn(kPrismSidesRange))
    ->capture_default_str();
  prism->add_option("--radius", arguments->radius, "Distance of the corners from the axis")
    ->check(numberIn(kGeneratedSizeRange))
    ->capture_default_str();
  prism->add_option("--height", arguments->prismHeight, "Length along z in metres")
    ->check(numberIn(kGeneratedSizeRange))
    ->capture_default_str();
  addCenter(prism, *arguments);
  addOut(prism, *arguments);

  auto run = [arguments, icosphere, box, grid, prism]() -> int {
    const GenerateArguments& a = *arguments;
    if (icosphere->parsed())
    {
      return writeAndReport("icosphere", makeIcosphere(a.subdivisions, a.radius, toVec3(a.center)),
                            a.out);
    }
    if (box->parsed())
    {
      return writeAndReport("box", makeBox(toVec3(a.halfExtents), toVec3(a.center)), a.out);
    }
    if (grid->parsed())
    {
      return writeAndReport("grid", makeGrid(a.size, a.cells, a.height), a.out);
    }
    if (prism->parsed())
    {
      return writeAndReport("prism", makePrism(a.sides, a.radius, a.prismHeight, toVec3(a.center)),
                            a.out);
    }
    return kExitBadInput;
  };
  return Command{generate, run};
}

} // namespace proxima::cli
