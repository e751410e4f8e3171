// `proxima inspect`: the defect report of a mesh (issue 18; Documentation/CadInspector.md): is it
// closed, its holes, non-manifold and misoriented edges, degenerate and duplicate triangles and
// pieces, each counted with the places of the first few, written as JSON. Counts are of the file's
// own geometry: corners merge only where their coordinates are identical.
#include "Command.h"
#include "MeshFileOptions.h"
#include "Validators.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"
#include "IO/MeshInspection/MeshInspection.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
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
};

nlohmann::ordered_json defectJson(const DefectCount& defect, const char* placeKind)
{
  nlohmann::ordered_json places = nlohmann::ordered_json::array();
  for (const DefectLocation& place : defect.first)
  {
    places.push_back(
      {{"triangle", place.triangle}, {placeKind, {place.point.x, place.point.y, place.point.z}}});
  }
  return {{"count", defect.count}, {"first", places}};
}

nlohmann::ordered_json countsJson(const MeshInspection& r)
{
  nlohmann::ordered_json json;
  json["triangles"] = r.triangles;
  json["vertices"] = r.vertices;
  json["edges"] = r.edges;
  json["closed"] = r.closed;
  json["components"] = r.components;
  json["boundary_edges"] = defectJson(r.boundaryEdges, "midpoint");
  json["boundary_loops"] = defectJson(r.boundaryLoops, "midpoint");
  json["boundary_loops"]["edges"] = r.boundaryLoopEdges;
  json["non_manifold_edges"] = defectJson(r.nonManifoldEdges, "midpoint");
  json["misoriented_edges"] = defectJson(r.misorientedEdges, "midpoint");
  json["collapsed_triangles"] = defectJson(r.collapsedTriangles, "centroid");
  json["zero_area_triangles"] = defectJson(r.zeroAreaTriangles, "centroid");
  json["sliver_triangles"] = defectJson(r.sliverTriangles, "centroid");
  json["duplicate_triangles"] = defectJson(r.duplicateTriangles, "centroid");
  json["self_intersections"] = defectJson(r.selfIntersections, "centroid");
  for (std::size_t i = 0; i < r.selfIntersections.first.size(); ++i)
  {
    json["self_intersections"]["first"][i]["other_triangle"] = r.selfIntersections.first[i].other;
  }
  return json;
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
  // Progress on a terminal only: a pipe or a log gets the result alone.
  if (isatty(STDERR_FILENO) != 0)
  {
    options.progress = [](double done) {
      std::fprintf(stderr, "\rproxima inspect: %3.0f%%", 100.0 * done);
      if (done >= 1.0)
      {
        std::fprintf(stderr, "\n");
      }
    };
  }
  const MeshInspection r = inspectMesh(soup, options);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  nlohmann::ordered_json json;
  json["format"] = "proxima-mesh-inspection";
  json["version"] = 1;
  json["mesh"] = arguments.mesh;
  json["scale"] = arguments.scale;
  json["vertex_merging"] = "identical coordinates";
  json["sliver_angle_degrees"] = arguments.sliverAngle;
  json.update(countsJson(r));
  if (arguments.weld > 0.0)
  {
    // The same counts after corners closer than the tolerance are made one: reported apart, so
    // that the file's own defects are never hidden by the welding.
    MeshInspectionOptions quiet = options;
    quiet.progress = nullptr;
    const MeshInspection welded = inspectMesh(weldCorners(soup, arguments.weld), quiet);
    nlohmann::ordered_json weldedJson;
    weldedJson["tolerance"] = arguments.weld;
    weldedJson.update(countsJson(welded));
    json["welded"] = weldedJson;
  }
  json["seconds"] = seconds;
  report.write(json.dump(2) + "\n");
  report.commit();

  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %s, %zu triangles, %zu components, %zu boundary edges in %zu loops, %zu "
                "non-manifold, %zu misoriented, %zu degenerate, %zu slivers, %zu duplicate, %zu "
                "self-intersecting pairs\n",
                arguments.report.c_str(), r.closed ? "closed" : "open", r.triangles, r.components,
                r.boundaryEdges.count, r.boundaryLoops.count, r.nonManifoldEdges.count,
                r.misorientedEdges.count, r.collapsedTriangles.count + r.zeroAreaTriangles.count,
                r.sliverTriangles.count, r.duplicateTriangles.count, r.selfIntersections.count);
  writeStandardOutput(line);
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
    ->check(CLI::Range(0, 100000))
    ->capture_default_str();
  app
    ->add_option("--sliver-angle", arguments->sliverAngle,
                 "Degrees: a triangle with a smaller angle (and not degenerate) is a sliver")
    ->check(numberIn(ParameterRange{0.0, false, 60.0, " degrees"}))
    ->capture_default_str();
  app
    ->add_option("--weld", arguments->weld,
                 "Also report the counts after welding corners closer than this (metres, after "
                 "--scale), apart from the file's own")
    ->check(numberIn(ParameterRange{0.0, true, 1e6, " m"}));
  return Command{app, [arguments] { return runInspect(*arguments); }};
}

} // namespace proxima::cli
