// The score report of a session as JSON (Documentation/SurgicalTrainer.md, "The report"): what
// proxima-trainer writes with --report, and what the window exports.
#pragma once

#include "Exercises/Exercise.h"
#include "Exercises/ExerciseScorer.h"

#include <string>

namespace proxima::trainer
{

struct ReportContext
{
  /// The finger path played (headless), or empty for a live session.
  std::string path;
  /// The marks file read (headless), or empty.
  std::string marks;
};

/// The report: indented by two, ending in a newline.
std::string exerciseReportJson(const Exercise& exercise, const ExerciseScore& score,
                               const ReportContext& context);

} // namespace proxima::trainer
