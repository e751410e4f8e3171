// The JSON of a probing session's measurements (Documentation/CadInspector.md has the format): the
// headless session's report and the "probe" part of the window's export.
#pragma once

#include "Probing/ProbeMeter.h"

#include <nlohmann/json.hpp>

namespace proxima::inspector
{

nlohmann::ordered_json probeMeasurementsJson(const ProbeMeasurements& measurements);

} // namespace proxima::inspector
