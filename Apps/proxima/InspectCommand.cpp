// `proxima inspect`: the defect report of a mesh (Documentation/CadInspector.md): is it
// closed, its holes, non-manifold and misoriented edges, degenerate and duplicate triangles and
// pieces, each counted with the places of the first few, written as JSON. Counts are of the file's
// own geometry: corners merge only where their coordinates are identical. With a tool radius, also
// where a ball of that radius cannot touch it (IO/MeshInspection/ToolReach.h).
#include "Command.h"
#include "MeshFileOptions.h"
#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/MeshInspection/InspectionReport.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

namespace proxima::cli
{
namespace
{
struct InspectArguments
{
  std::string mesh;
  double scale = 1.0;
  std::string report;
  std::size_t locations = 10;
  double sliverAngle = 1.0;
  double weld = 0.0;
  /// 0: not given (a given radius is above 0).
  double toolRadius = 0.0;
};

// Progress on a terminal only: a pipe or a log gets the result alone. `phase` names the work.
std::function<void(double)> terminalProgress(const char* phase)
{
  if (isatty(STDERR_FILENO) == 0)
  {
    return nullptr;
  }
  return [phase](double done) {
    std::fprintf(stderr, "\rproxima inspect: %s %3.0f%%", phase, 100.0 * done);
    if (done >= 1.0)
    {
      std::fprintf(stderr, "\n");
    }
  };
}

int runInspect(const InspectArguments& arguments)
{
  refuseOverlappingFiles({{arguments.report, "--report"}}, {{arguments.mesh, "--mesh"}});
  // The report's temporary first: an unwritable report fails before the work.
  AtomicOutputFile report(arguments.report);
  const auto start = std::chrono::steady_clock::now();
  const TriangleSoup soup = readMeshFile(arguments.mesh, arguments.scale);
  MeshInspectionOptions options;
  options.locationsKept = arguments.locations;
  options.sliverAngleDegrees = arguments.sliverAngle;
  options.progress = terminalProgress("defects");
  const MeshInspection r = inspectMesh(soup, options);

  nlohmann::ordered_json json;
  json["format"] = "proxima-mesh-inspection";
  json["version"] = 1;
  json["mesh"] = arguments.mesh;
  json["scale"] = arguments.scale;
  json["vertex_merging"] = "identical coordinates";
  json["sliver_angle_degrees"] = arguments.sliverAngle;
  json.update(meshInspectionJson(r));
  if (arguments.weld > 0.0)
  {
    // The same counts after corners closer than the tolerance are made one: reported apart, so
    // that the file's own defects are never hidden by the welding.
    MeshInspectionOptions quiet = options;
    quiet.progress = nullptr;
    const MeshInspection welded = inspectMesh(weldCorners(soup, arguments.weld), quiet);
    nlohmann::ordered_json weldedJson;
    weldedJson["tolerance"] = arguments.weld;
    weldedJson.update(meshInspectionJson(welded));
    json["welded"] = weldedJson;
  }
  std::string reachLine;
  if (arguments.toolRadius > 0.0)
  {
    ToolReachOptions reachOptions;
    reachOptions.toolRadius = arguments.toolRadius;
    reachOptions.locationsKept = arguments.locations;
    reachOptions.progress = terminalProgress("tool reach");
    const ToolReach reach =
      findToolReach(soup, r.closed && r.misorientedEdges.count == 0, reachOptions);
    json["tool_reach"] = toolReachJson(reach);
    char text[256];
    std::snprintf(
      text, sizeof text, "a %g m tool cannot touch %.2f%% of the area, in %zu regions\n",
      arguments.toolRadius, reach.area > 0.0 ? 100.0 * reach.unreachableArea / reach.area : 0.0,
      reach.regionCount);
    reachLine = text;
  }
  json["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.write(json.dump(2) + "\n");
  report.commit();

  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %s, %zu triangles, %zu components, %zu boundary edges in %zu loops, %zu "
                "non-manifold, %zu misoriented, %zu degenerate, %zu slivers, %zu duplicate, %zu "
                "self-intersecting pairs, %zu folds\n",
                arguments.report.c_str(), r.closed ? "closed" : "open", r.triangles, r.components,
                r.boundaryEdges.count, r.boundaryLoops.count, r.nonManifoldEdges.count,
                r.misorientedEdges.count, r.collapsedTriangles.count + r.zeroAreaTriangles.count,
                r.sliverTriangles.count, r.duplicateTriangles.count, r.selfIntersections.count,
                r.folds.count);
  writeStandardOutput(line + reachLine);
  return kExitOk;
}
} // namespace

Command addInspectCommand(CLI::App& parent)
{
  auto arguments = std::make_shared<InspectArguments>();
  CLI::App* app = parent.add_subcommand(kInspectSummary.name, kInspectSummary.description);
  addMeshFileOptions(*app, arguments->mesh, arguments->scale);
  app->add_option("--report", arguments->report, "The report to write (JSON)")->required();
  app
    ->add_option("--locations", arguments->locations,
                 "Places listed per kind of defect (the first in the file's triangle order)")
    ->check(wholeNumberIn(kDefectLocationsRange))
    ->capture_default_str();
  app
    ->add_option("--sliver-angle", arguments->sliverAngle,
                 "Degrees: a triangle with a smaller angle (and not degenerate) is a sliver")
    ->check(numberIn(kSliverAngleRange))
    ->capture_default_str();
  app
    ->add_option("--weld", arguments->weld,
                 "Also report the counts after welding corners closer than this (metres, after "
                 "--scale), apart from the file's own")
    ->check(numberIn(kWeldDistanceRange));
  app
    ->add_option("--tool-radius", arguments->toolRadius,
                 "Also report where a ball tool of this radius cannot touch the surface (metres, "
                 "after --scale)")
    ->check(numberIn(kProxyRadiusRange));
  return Command{app, [arguments] { return runInspect(*arguments); }};
}

} // namespace proxima::cli
