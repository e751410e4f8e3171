// `proxima tissue`: an organ's surface made into the tetrahedra of a soft-tissue model. Reads a
// mesh (a soup as organ files are), wraps it into a closed surface and fills that with
// tetrahedra of --tet-size (IO/TissueMeshing), writes them as a .vtu file and prints a report as
// JSON: the counts, the smallest dihedral angle, the volume against the wrapped surface's, and
// the seconds each part took (Documentation/Tissue.md).
#include "Command.h"
#include "MeshFileOptions.h"
#include "OutputChecks.h"
#include "Validators.h"

#include "IO/Mesh/MeshReader.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/StandardOutput.h"
#include "IO/TissueMeshing/TetMeshFile.h"
#include "IO/TissueMeshing/TissueMeshing.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <memory>
#include <string>

namespace proxima::cli
{
namespace
{
struct TissueArguments
{
  std::string mesh;
  double scale = 1.0;
  TissueMeshingOptions meshing;
  std::string out;
  std::string report;
};

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int runTissue(const TissueArguments& arguments)
{
  refuseOverlappingFiles({{arguments.out, "--out"}, {arguments.report, "--report"}},
                         {{arguments.mesh, "--mesh"}});
  const auto readStart = std::chrono::steady_clock::now();
  const TriangleSoup surface = readMeshFile(arguments.mesh, arguments.scale);
  const double readSeconds = secondsSince(readStart);
  const TissueMeshingResult result = meshTissue(surface, arguments.meshing, arguments.mesh);
  const double volume = totalVolume(result.tets);

  nlohmann::ordered_json report;
  report["mesh"] = arguments.mesh;
  report["scale"] = arguments.scale;
  report["surface_triangles"] = surface.triangles.size();
  report["tet_size_m"] = arguments.meshing.tetSize;
  report["tetrahedra"] = result.tets.tets.size();
  report["vertices"] = result.tets.points.size();
  report["min_dihedral_angle_deg"] = minDihedralAngle(result.tets);
  report["inverted_tetrahedra"] = countInvertedTets(result.tets);
  report["volume_m3"] = volume;
  report["wrapped_volume_m3"] = result.wrappedVolume;
  report["volume_over_wrapped"] = volume / result.wrappedVolume;
  report["wrapped_triangles"] = result.wrapped.triangles.size();
  report["seconds"] = {
    {"read", readSeconds}, {"wrap", result.wrapSeconds}, {"fill", result.fillSeconds}};
  report["out"] = arguments.out;
  const std::string text = report.dump(2) + "\n";
  // The tetrahedra first, then the report: a report never describes a file that is not there.
  writeTetMeshFile(arguments.out, result.tets);
  if (!arguments.report.empty())
  {
    writeFileAtomically(arguments.report, text);
  }
  writeStandardOutput(text);
  return kExitOk;
}
} // namespace

Command addTissueCommand(CLI::App& parent)
{
  auto arguments = std::make_shared<TissueArguments>();
  CLI::App* app = parent.add_subcommand(kTissueSummary.name, kTissueSummary.description);
  addMeshFileOptions(*app, arguments->mesh, arguments->scale);
  app
    ->add_option("--tet-size", arguments->meshing.tetSize,
                 "The tetrahedra's edge size in metres (and the wrap's detail: nothing finer is "
                 "kept); at most the object's smallest extent")
    ->check(numberIn(kTetSizeRange))
    ->capture_default_str();
  app->add_option("--out", arguments->out, "The tetrahedra to write (.vtu, VTK's XML grid)")
    ->required();
  app->add_option("--report", arguments->report, "Also write the JSON report to this file");
  return Command{app, [arguments] { return runTissue(*arguments); }};
}

} // namespace proxima::cli
