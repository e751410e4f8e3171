// The picture of a scripted session at one moment (proxima-trainer --screenshot S --at T): the
// scene, the proxy, finger, contacts and force as proxima view draws them, the exercise's targets
// (touched grey, next yellow, the rest green) and trace lines, the trainee's last palpation mark,
// a HUD with the exercise's name, the force, what is touched and each task's progress, and the
// force plot of the seconds before. The
// hidden nodule is not drawn. The camera looks down -z (the shipped scenes' up) at the targets
// and lines with the proxy, or at the whole scene when the exercise has none.
#pragma once

#include "Exercises/Exercise.h"
#include "ForcePlot.h"
#include "Exercises/ExerciseScorer.h"
#include "Proxy/CollisionScene.h"
#include "Runtime/HapticState.h"

#include <string>

namespace proxima::trainer
{

struct ScreenshotSize
{
  int width = 800;
  int height = 600;
};

/// Renders offscreen and returns the PNG; throws OutputError naming `path` if VTK gives nothing.
std::string exerciseScreenshot(const Exercise& exercise, const CollisionScene& scene,
                               const HapticState& state, const ExerciseScore& score,
                               shell::ForcePlot& forcePlot, const ScreenshotSize& size,
                               const std::string& path);

} // namespace proxima::trainer
