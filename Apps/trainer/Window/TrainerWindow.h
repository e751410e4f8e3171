// The surgical trainer's window (Documentation/SurgicalTrainer.md): the applications' Qt shell
// (HapticWindow) with an exercise in it. Every servo tick the runtime streams is scored live by
// the same ExerciseScorer the headless sessions use; the exercise's targets, lines and marks are
// drawn over the scene and its progress is written in the HUD. The Session menu marks the spot
// touched (M), finishes the attempt with its score and report (F), or starts it again; a device
// change starts a new attempt, since the runtime's clock starts again at 0.
#pragma once

#include "Exercises/Exercise.h"
#include "Exercises/ExerciseScorer.h"
#include "HapticWindow.h"

#include <memory>
#include <string>

namespace proxima::trainer
{

class ExerciseOverlay;

class TrainerWindow : public shell::HapticWindow
{
  Q_OBJECT

public:
  /// `scene` is the exercise's, loaded; `settings` take its proxy and servo values.
  TrainerWindow(const Exercise& exercise, const shell::HapticWindowSettings& settings,
                QWidget* parent = nullptr);
  ~TrainerWindow() override;

  /// Marks the spot touched now (the palpation's answer).
  void mark();
  /// The attempt's score so far.
  ExerciseScore score() const;
  /// Writes the attempt's report (the headless report's format) atomically to `path`; false with
  /// `error`.
  bool writeReport(const std::string& path, std::string& error) const;
  /// Starts the attempt again: the scorer forgets every tick and mark.
  void restartExercise();
  const Exercise& exercise() const { return m_exercise; }

signals:
  /// File > Open an exercise: the program replaces this window with one on `path`.
  void exerciseRequested(const QString& path);

protected:
  void ticksArrived(const std::vector<HapticState>& ticks) override;
  std::string hudLines(const HapticState& state) const override;
  void sessionRestarted() override;

private:
  void finishAttempt();
  void openExercise();

  Exercise m_exercise;
  std::unique_ptr<ExerciseScorer> m_scorer;
  std::unique_ptr<ExerciseOverlay> m_overlay;
  /// The last tick scored: a mark belongs to its contact.
  bool m_ticked = false;
};

} // namespace proxima::trainer
