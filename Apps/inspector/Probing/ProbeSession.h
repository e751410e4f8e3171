// A scripted probing session without a window: the part loaded as a scene with the proxy at the
// tool's radius, a finger path played through it in lockstep (IO/ScriptedRun, the same steps as
// the threaded runtime on a virtual clock), the markers dropped at their times and every tick
// measured (ProbeMeter). What `proxima-inspector --path P --report R` runs, and its tests.
#pragma once

#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Probing/ProbeMeter.h"
#include "Runtime/FingerPath.h"

#include <vector>

namespace proxima::inspector
{

/// Plays `path` through the settings' mesh with the proxy at settings.radius; a marker at time t
/// is the touched point of the last tick at or before t. Throws InputError for a mesh or a path
/// that cannot be used (named by settings.mesh and settings.path).
ProbeMeasurements playProbeSession(const ScriptedRunSettings& settings, const FingerPath& path,
                                   const std::vector<double>& markTimes,
                                   const ProbeMeterSettings& meterSettings);

} // namespace proxima::inspector
