// proxima-trainer: the surgical trainer (Documentation/SurgicalTrainer.md). Without --path it opens
// the trainer's window, where a trainee feels the exercise with the mouse or a device and is
// scored live:
//   proxima-trainer [--exercise E.json] [--device mouse|spacemouse|falcon|replay:FILE]
// Headless, it plays a scripted finger path through an exercise in lockstep and writes the score
// report, and with --screenshot the picture of the session at --at seconds:
//   proxima-trainer --exercise E.json --path P.csv [--marks M.csv] --report R.json
//                   [--screenshot S.png [--at T] [--width W] [--height H]]
// Exit statuses as the proxima command line's (DESIGN.md section 3): 0 when the session ran
// (whether or not the trainee passed: the report says), 2 for bad input or an output that cannot
// be written (one line naming the file and the defect), 1 for an internal error.
#include "DisplayCheck.h"
#include "ExerciseScreenshot.h"
#include "NumberOptions.h"
#include "ProgramMain.h"
#include "Exercises/ExerciseFile.h"
#include "Exercises/ExerciseReport.h"
#include "Exercises/HeadlessSession.h"
#include "IO/PathAndTrace/MarkTimesFile.h"
#if PROXIMA_TRAINER_WINDOW
#include "Window/TrainerWindowMain.h"
#endif

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Tissue/DeformedScene.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

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
  std::string screenshot;
  double at = -1.0;
  ScreenshotSize size;
  std::string device;
  std::string falconFirmware;
};

// The options of one mode given in the other: a window takes no report, a scripted session no
// device.
void checkMode(const TrainerOptions& options)
{
  if (options.path.empty())
  {
    for (const auto& [value, name] :
         {std::pair{options.report, "--report"}, std::pair{options.marks, "--marks"},
          std::pair{options.screenshot, "--screenshot"}})
    {
      if (!value.empty())
      {
        throw InputError(name, "belongs to a scripted session: give --path too (the window's "
                               "Session menu marks, scores and saves the report)");
      }
    }
    return;
  }
  if (!options.device.empty())
  {
    throw InputError("--device", "moves the finger in the window: leave out --path for it");
  }
  if (options.exercise.empty())
  {
    throw InputError("--exercise", "is required with --path");
  }
  if (options.report.empty())
  {
    throw InputError("--report", "is required with --path");
  }
}

// The checks of the screenshot's options that need the path: --at within it, .png, a display.
void checkScreenshot(const TrainerOptions& options, const FingerPath& path)
{
  if (options.screenshot.empty())
  {
    if (options.at >= 0.0)
    {
      throw InputError("--at", "is the moment of --screenshot, which is not given");
    }
    return;
  }
  const std::string extension = std::filesystem::path(options.screenshot).extension().string();
  if (!extension.empty() && extension != ".png" && extension != ".PNG")
  {
    throw InputError(options.screenshot, "a screenshot is a PNG file: name it .png");
  }
  if (options.at > path.endTime())
  {
    throw InputError("--at", std::to_string(options.at) + " s is after the end of the path (" +
                               std::to_string(path.endTime()) + " s)");
  }
  const std::string noDisplay = shell::displayProblem("proxima-trainer");
  if (!noDisplay.empty())
  {
    throw InputError("--screenshot", noDisplay);
  }
}

int runHeadless(const TrainerOptions& options)
{
  const Exercise exercise = readExerciseFile(options.exercise);
  const FingerPath path = readFingerPathFile(options.path);
  const std::vector<double> marks =
    options.marks.empty() ? std::vector<double>{} : readMarkTimesFile(options.marks);
  checkScreenshot(options, path);
  refuseOverlappingFiles({{options.report, "--report"}, {options.screenshot, "--screenshot"}},
                         {{options.exercise, "--exercise"},
                          {options.path, "--path"},
                          {options.marks, "--marks"},
                          {exercise.scene, "the exercise's scene"}});
  // The report's temporary before the session: an unwritable report fails before the run.
  AtomicOutputFile report(options.report);
  std::optional<AtomicOutputFile> screenshot;
  std::string picture;
  SessionObserver observer;
  if (!options.screenshot.empty())
  {
    screenshot.emplace(options.screenshot);
    // The first tick at or after --at (default: the path's end, the last tick).
    const double at = options.at >= 0.0 ? options.at : path.endTime();
    // `at` by value: it ends with this block, the observer runs after it (ASan found it read
    // out of scope); the rest outlives the session.
    observer = [&exercise, &options, &picture, at,
                forcePlot = std::make_shared<shell::ForcePlot>(5.0, exercise.maxForce)](
                 const HapticState& state, const ExerciseScorer& scorer,
                 const CollisionScene& scene, const TissueDynamics* tissue) {
      if (!picture.empty())
      {
        return;
      }
      forcePlot->add(state.time, norm(state.force));
      if (state.time >= at - 1e-9)
      {
        // A soft organ as the press has deformed it at this tick, not at rest.
        const CollisionScene drawn = tissue != nullptr ? deformedScene(scene, *tissue) : scene;
        picture = exerciseScreenshot(exercise, drawn, state, scorer.score(), *forcePlot,
                                     options.size, options.screenshot);
      }
    };
  }
  const ExerciseScore score = playHeadlessSession(exercise, path, options.path, marks, observer);
  report.write(exerciseReportJson(exercise, score, ReportContext{options.path, options.marks}));
  if (screenshot)
  {
    // Both finished before either is put in place: one failing leaves neither.
    screenshot->write(picture);
    screenshot->finish();
    report.finish();
    screenshot->commit();
  }
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
  CLI::App app{"proxima-trainer: palpation and probing exercises on anatomy, scored "
               "(Documentation/SurgicalTrainer.md)",
               "proxima-trainer"};
  TrainerOptions options;
  app.add_option("--exercise", options.exercise,
                 "Exercise file (JSON); in the window, default: a list of the shipped ones");
  app.add_option("--path", options.path,
                 "Finger path CSV (t,x,y,z) played in lockstep, headless; without it the "
                 "trainer's window opens");
  shell::addWindowDeviceOptions(app, options.device, options.falconFirmware);
  app.add_option("--marks", options.marks,
                 "The trainee's marks: CSV with the header t, one time in seconds per row");
  app.add_option("--report", options.report, "The score report to write (JSON; with --path)");
  app.add_option("--screenshot", options.screenshot,
                 "Also render the session at --at offscreen to this PNG (needs a display: "
                 "xvfb-run -a without one)");
  app.add_option("--at", options.at, "With --screenshot: seconds into the path (default its end)")
    ->check(cli::numberIn(kScreenshotTimeRange));
  app
    .add_option("--width", options.size.width,
                "Screenshot width in pixels (default 800; the window's 1024)")
    ->check(cli::wholeNumberIn(kWindowSizeRange));
  app
    .add_option("--height", options.size.height,
                "Screenshot height in pixels (default 600; the window's 720)")
    ->check(cli::wholeNumberIn(kWindowSizeRange));
  return shell::runProgram(app, "proxima-trainer", argc, argv, [&] {
    checkMode(options);
    if (options.path.empty())
    {
#if PROXIMA_TRAINER_WINDOW
      TrainerWindowOptions window;
      window.exercise = options.exercise;
      window.device = options.device.empty() ? "mouse" : options.device;
      window.falconFirmware = options.falconFirmware;
      window.width = app.count("--width") > 0 ? options.size.width : window.width;
      window.height = app.count("--height") > 0 ? options.size.height : window.height;
      return runTrainerWindow(window, argc, argv);
#else
      throw InputError("--path", "is required: this build has no window (PROXIMA_BUILD_QT=OFF)");
#endif
    }
    const int status = runHeadless(options);
    finishStandardOutput();
    return status;
  });
}
