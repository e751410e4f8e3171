// Exercise files (Documentation/SurgicalTrainer.md, "Exercise files"): JSON, versioned, checked
// like scene files. Every defect is one InputError naming the file and the place in it
// (`tasks[1].targets[0].radius: must be a number above 0 and at most 1 m, got 0`). References
// into the scene (an object, a stiffness region) are checked when the scene is loaded
// (ExerciseScorer), where its contents are known.
#pragma once

#include "Exercises/Exercise.h"

#include <string>

namespace proxima::trainer
{

/// The exercise file version this program reads.
inline constexpr int kExerciseFileVersion = 1;

/// Reads and checks the exercise file `path`; the scene is resolved against its folder.
Exercise readExerciseFile(const std::string& path);

} // namespace proxima::trainer
