// What an exercise adds to the picture, in the window and in headless screenshots alike: its
// targets as spheres (done grey, the next one yellow, the rest green), its trace lines as blue
// tubes, the trainee's palpation mark as a red ball; and the HUD's lines on the exercise's
// progress (the tissue touched, damage events, each task's state).
#pragma once

#include "Exercises/Exercise.h"
#include "Exercises/ExerciseScorer.h"
#include "Runtime/HapticState.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkActor;
class vtkRenderer;

namespace proxima::trainer
{

class ExerciseOverlay
{
public:
  /// Adds the exercise's targets and lines to `renderer`.
  ExerciseOverlay(const Exercise& exercise, vtkRenderer* renderer);
  /// Colours the targets and places the marks for the score so far.
  void update(const ExerciseScore& score);
  /// The box around the targets and lines with a centimetre's margin; false when there are none.
  bool bounds(double box[6]) const;

private:
  const Exercise& m_exercise;
  vtkRenderer* m_renderer;
  /// Per task, its targets' spheres (empty for the other kinds).
  std::vector<std::vector<vtkSmartPointer<vtkActor>>> m_targets;
  /// Per task, its palpation mark (null until marked, and for the other kinds).
  std::vector<vtkSmartPointer<vtkActor>> m_marks;
  double m_box[6] = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  bool m_framed = false;
};

/// Grows `box` (x min, x max, y min, ...) to hold `p` with `margin` around it.
void expandBox(double box[6], const Vec3& p, double margin);

/// The tissue touched at `state` by name ("touching liver"), or "touching object N", or "free".
std::string touchedText(const Exercise& exercise, const HapticState& state);

/// One line per task: marks made, targets touched and the next one, the line's coverage.
std::string taskLines(const Exercise& exercise, const ExerciseScore& score);

} // namespace proxima::trainer
