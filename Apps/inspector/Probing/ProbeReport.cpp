#include "Probing/ProbeReport.h"

#include "IO/MeshInspection/InspectionReport.h"

namespace proxima::inspector
{

nlohmann::ordered_json probeMeasurementsJson(const ProbeMeasurements& m)
{
  nlohmann::ordered_json markers = nlohmann::ordered_json::array();
  for (const ProbeMarker& marker : m.markers)
  {
    markers.push_back({{"time", marker.time},
                       {"point", pointJson(marker.point)},
                       {"normal", pointJson(marker.normal)},
                       {"object", marker.object},
                       {"triangle", marker.triangle}});
  }
  nlohmann::ordered_json distances = nlohmann::ordered_json::array();
  for (const MarkerDistance& distance : m.distances)
  {
    distances.push_back({{"from", distance.from},
                         {"to", distance.to},
                         {"distance", distance.distance},
                         {"across", distance.across}});
  }
  nlohmann::ordered_json stops = nlohmann::ordered_json::array();
  for (const ProbeStop& stop : m.stops)
  {
    stops.push_back({{"start_time", stop.startTime},
                     {"end_time", stop.endTime},
                     {"proxy", pointJson(stop.proxy)},
                     {"finger", pointJson(stop.finger)},
                     {"depth", stop.depth}});
  }
  nlohmann::ordered_json json;
  json["ticks"] = m.ticks;
  json["markers"] = markers;
  json["marks_missed"] = m.marksMissed;
  json["distances"] = distances;
  if (m.narrowestGap)
  {
    json["narrowest_gap"] = {{"width", m.narrowestGap->width},
                             {"time", m.narrowestGap->time},
                             {"proxy", pointJson(m.narrowestGap->proxy)},
                             {"wall", pointJson(m.narrowestGap->wall)},
                             {"across", pointJson(m.narrowestGap->across)}};
  }
  else
  {
    json["narrowest_gap"] = nullptr;
  }
  json["stops"] = {{"count", m.stopCount}, {"first", stops}};
  json["deepest_press"] = m.deepestPress;
  return json;
}

} // namespace proxima::inspector
