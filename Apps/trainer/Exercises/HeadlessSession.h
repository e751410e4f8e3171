// A scripted training session without a window: the exercise's scene loaded with its proxy
// settings, a finger path played through it in lockstep (IO/ScriptedRun, the same steps as the
// threaded runtime on a virtual clock), the marks applied at their times, and the ticks scored.
// What `proxima-trainer --exercise E --path P --report R` runs, and its tests.
#pragma once

#include "Exercises/Exercise.h"
#include "Exercises/ExerciseScorer.h"
#include "Runtime/FingerPath.h"

#include <functional>
#include <string>
#include <vector>

namespace proxima
{
class TissueDynamics;
}

namespace proxima::trainer
{

/// Called after each tick is scored, with the scene the session plays in and, for a scene with
/// tissue, its tissues as that tick left them (null otherwise): a picture draws the scene as
/// deformed (Tissue/DeformedScene.h).
using SessionObserver = std::function<void(const HapticState&, const ExerciseScorer&,
                                           const CollisionScene&, const TissueDynamics*)>;

/// Plays `path` (named `pathName` in messages) through the exercise's scene and scores it; a mark
/// at time t marks the contact of the last tick at or before t. Throws InputError for a scene,
/// path or exercise reference that cannot be used.
ExerciseScore playHeadlessSession(const Exercise& exercise, const FingerPath& path,
                                  const std::string& pathName, const std::vector<double>& markTimes,
                                  const SessionObserver& observer = {});

} // namespace proxima::trainer
