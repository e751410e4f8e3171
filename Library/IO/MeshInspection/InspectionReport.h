// The JSON of a mesh inspection and of a tool's reach, as `proxima inspect` writes them and the
// inspector window exports them (Documentation/CadInspector.md has the format).
#pragma once

#include "IO/MeshInspection/MeshInspection.h"
#include "IO/MeshInspection/ToolReach.h"

#include <nlohmann/json.hpp>

namespace proxima
{

/// Counts, closedness and the places of the first few of each defect.
nlohmann::ordered_json meshInspectionJson(const MeshInspection& inspection);

/// The tool's radius, the sides probed, the sampled and unreachable areas and the regions.
nlohmann::ordered_json toolReachJson(const ToolReach& reach);

/// A point as a JSON array [x, y, z].
nlohmann::ordered_json pointJson(const Vec3& point);

} // namespace proxima
