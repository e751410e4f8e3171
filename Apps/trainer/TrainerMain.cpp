// proxima-trainer: the surgical trainer (Documentation/SurgicalTrainer.md). Headless, it plays a
// scripted finger path through an exercise in lockstep and writes the score report:
//   proxima-trainer --exercise E.json --path P.csv [--marks M.csv] --report R.json
// Exit statuses as the proxima command line's (DESIGN.md section 3): 0 when the session ran
// (whether or not the trainee passed: the report says), 2 for bad input or an output that cannot
// be written (one line naming the file and the defect), 1 for an internal error.
#include "Exercises/ExerciseFile.h"
#include "Exercises/ExerciseReport.h"
#include "Exercises/HeadlessSession.h"
#include "Exercises/MarkTimesFile.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>

namespace
{
using namespace proxima;
using namespace proxima::trainer;

struct TrainerOptions
{
  std::string exercise;
  std::string path;
  std::string marks;
  std::string report;
};

int runHeadless(const TrainerOptions& options)
{
  const Exercise exercise = readExerciseFile(options.exercise);
  const FingerPath path = readFingerPathFile(options.path);
  const std::vector<double> marks =
    options.marks.empty() ? std::vector<double>{} : readMarkTimesFile(options.marks);
  refuseOverlappingFiles({{options.report, "--report"}},
                         {{options.exercise, "--exercise"},
                          {options.path, "--path"},
                          {options.marks, "--marks"},
                          {exercise.scene, "the exercise's scene"}});
  // The report's temporary before the session: an unwritable report fails before the run.
  AtomicOutputFile report(options.report);
  const ExerciseScore score = playHeadlessSession(exercise, path, options.path, marks);
  report.write(exerciseReportJson(exercise, score, ReportContext{options.path, options.marks}));
  report.commit();
  int tasksPassed = 0;
  for (const TaskScore& task : score.tasks)
  {
    tasksPassed += task.passed ? 1 : 0;
  }
  char line[256];
  std::snprintf(
    line, sizeof line, "%s: %s (%d of %zu tasks, %zu damage events, peak force %.2f N, %.2f s)\n",
    options.report.c_str(), score.passed ? "passed" : "not passed", tasksPassed, score.tasks.size(),
    score.damage.size(), score.peakForce, score.endTime - score.startTime);
  writeStandardOutput(line);
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  // A file-size limit fails a write with EFBIG, reported like a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"proxima-trainer: palpation and probing exercises on anatomy, scored "
               "(Documentation/SurgicalTrainer.md)",
               "proxima-trainer"};
  TrainerOptions options;
  app.add_option("--exercise", options.exercise, "Exercise file (JSON)")->required();
  app.add_option("--path", options.path, "Finger path CSV (t,x,y,z) played in lockstep")
    ->required();
  app.add_option("--marks", options.marks,
                 "The trainee's marks: CSV with the header t, one time in seconds per row");
  app.add_option("--report", options.report, "The score report to write (JSON)")->required();
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& error)
  {
    return app.exit(error) == 0 ? 0 : 2;
  }
  try
  {
    const int status = runHeadless(options);
    finishStandardOutput();
    return status;
  }
  catch (const InputError& error)
  {
    std::cerr << "proxima-trainer: " << error.what() << "\n";
    return 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << "proxima-trainer: internal error: " << error.what() << "\n";
    return 1;
  }
}
