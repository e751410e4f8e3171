#include "IO/MeshInspection/InspectionReport.h"

#include <utility>

namespace proxima
{
namespace
{
nlohmann::ordered_json defectJson(const DefectCount& defect, const char* placeKind)
{
  nlohmann::ordered_json places = nlohmann::ordered_json::array();
  for (const DefectLocation& place : defect.first)
  {
    places.push_back({{"triangle", place.triangle}, {placeKind, pointJson(place.point)}});
  }
  return {{"count", defect.count}, {"first", places}};
}
} // namespace

nlohmann::ordered_json pointJson(const Vec3& point)
{
  return nlohmann::ordered_json::array({point.x, point.y, point.z});
}

nlohmann::ordered_json meshInspectionJson(const MeshInspection& r)
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
  json["folds"] = defectJson(r.folds, "centroid");
  const std::pair<const char*, const DefectCount*> pairKinds[] = {
    {"self_intersections", &r.selfIntersections}, {"folds", &r.folds}};
  for (const auto& [key, pairs] : pairKinds)
  {
    for (std::size_t i = 0; i < pairs->first.size(); ++i)
    {
      json[key]["first"][i]["other_triangle"] = pairs->first[i].other;
    }
  }
  return json;
}

nlohmann::ordered_json toolReachJson(const ToolReach& reach)
{
  nlohmann::ordered_json regions = nlohmann::ordered_json::array();
  for (const UnreachableRegion& region : reach.regions)
  {
    regions.push_back({{"triangle", region.triangle},
                       {"triangles", region.triangles},
                       {"area", region.area},
                       {"deepest", pointJson(region.point)},
                       {"largest_reaching_radius", region.largestReachingRadius}});
  }
  nlohmann::ordered_json json;
  json["tool_radius"] = reach.toolRadius;
  json["sides"] = reach.outsideOnly ? "outside" : "both";
  json["samples"] = reach.samples;
  json["unreachable_samples"] = reach.unreachableSamples;
  json["area"] = reach.area;
  json["unreachable_area"] = reach.unreachableArea;
  json["unreachable_triangles"] = reach.unreachableTriangles.size();
  json["regions"] = {{"count", reach.regionCount}, {"first", regions}};
  return json;
}

} // namespace proxima
