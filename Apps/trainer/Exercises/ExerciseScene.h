// The scene an exercise is played in, loaded with the exercise's proxy and servo settings, and
// checked (the radius against the scene): shared by the headless sessions and the window.
#pragma once

#include "Exercises/Exercise.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"

namespace proxima::trainer
{

/// The settings of a run of `exercise` with the finger path `pathName` (empty for a device).
ScriptedRunSettings exerciseRunSettings(const Exercise& exercise, const std::string& pathName);

/// Loads the scene of an exercise's settings and checks the radius against it; throws InputError
/// naming the scene file and the defect.
LoadedScene loadExerciseScene(const ScriptedRunSettings& settings);

} // namespace proxima::trainer
