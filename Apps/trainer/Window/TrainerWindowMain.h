// proxima-trainer without --path: the trainer's window. It opens the exercise given, or asks
// which of the shipped ones (Data/Exercises, configured into the build) to open; File > Open an
// exercise replaces the window with one on another exercise.
#pragma once

#include <string>

namespace proxima::trainer
{

struct TrainerWindowOptions
{
  /// Empty: a list of the shipped exercises to pick from.
  std::string exercise;
  /// mouse (default), spacemouse, falcon or replay:FILE.
  std::string device = "mouse";
  std::string falconFirmware;
  int width = 1024;
  int height = 720;
};

/// Runs the window until it is closed; the exit status (0, or 2 after a one-line error on
/// standard error for an exercise that cannot be used or no display). Throws InputError for the
/// exercise given on the command line.
int runTrainerWindow(const TrainerWindowOptions& options, int argc, char** argv);

/// The folder of the shipped exercises: PROXIMA_EXERCISE_DIR, else the build's; empty if neither.
std::string shippedExerciseFolder();

} // namespace proxima::trainer
