#include "TrainerWindow.h"

#include "ExerciseOverlay.h"
#include "Exercises/ExerciseReport.h"

#include "IO/Output/AtomicOutputFile.h"

#include <QAction>
#include <QFileDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>

#include <cstdio>
#include <exception>

namespace proxima::trainer
{
namespace
{
// The attempt's result in a few lines, for the dialog and the status bar.
std::string scoreSummary(const Exercise& exercise, const ExerciseScore& score)
{
  int passed = 0;
  for (const TaskScore& task : score.tasks)
  {
    passed += task.passed ? 1 : 0;
  }
  char text[400];
  std::snprintf(text, sizeof text,
                "%s: %s\n%d of %zu tasks passed, %zu damage events\npeak force %.2f N, finger "
                "path %.0f mm, %.1f s",
                exercise.name.c_str(), score.passed ? "passed" : "not passed", passed,
                score.tasks.size(), score.damage.size(), score.peakForce,
                score.fingerPathLength * 1000.0, score.endTime - score.startTime);
  return std::string(text) + "\n" + taskLines(exercise, score);
}
} // namespace

TrainerWindow::TrainerWindow(const Exercise& exercise, const shell::HapticWindowSettings& settings,
                             QWidget* parent)
  : shell::HapticWindow(settings, parent)
  , m_exercise(exercise)
  , m_scorer(std::make_unique<ExerciseScorer>(m_exercise, *settings.scene))
  , m_overlay(std::make_unique<ExerciseOverlay>(m_exercise, renderer()))
{
  m_overlay->update(m_scorer->score());

  QMenu* session = sessionMenu();
  session->addSeparator();
  QAction* markAction = session->addAction(tr("&Mark the spot touched"));
  markAction->setObjectName("markSpot");
  markAction->setShortcut(QKeySequence(Qt::Key_M));
  connect(markAction, &QAction::triggered, this, &TrainerWindow::mark);
  QAction* finish = session->addAction(tr("&Finish: score and report..."));
  finish->setObjectName("finishAttempt");
  finish->setShortcut(QKeySequence(Qt::Key_F));
  connect(finish, &QAction::triggered, this, &TrainerWindow::finishAttempt);
  QAction* again = session->addAction(tr("Start the exercise &again"));
  connect(again, &QAction::triggered, this, &TrainerWindow::restartExercise);

  QMenu* file = menuBar()->actions().front()->menu();
  QAction* open = new QAction(tr("&Open an exercise..."), this);
  open->setShortcut(QKeySequence("Ctrl+O"));
  connect(open, &QAction::triggered, this, &TrainerWindow::openExercise);
  file->insertAction(file->actions().front(), open);

  statusBar()->showMessage(QString::fromStdString(m_exercise.instructions), 30000);
}

TrainerWindow::~TrainerWindow() = default;

void TrainerWindow::ticksArrived(const std::vector<HapticState>& ticks)
{
  for (const HapticState& tick : ticks)
  {
    m_scorer->addTick(tick);
    m_ticked = true;
  }
  if (!ticks.empty())
  {
    m_overlay->update(m_scorer->score());
  }
}

void TrainerWindow::mark()
{
  if (!m_ticked)
  {
    return;
  }
  m_scorer->mark();
  m_overlay->update(m_scorer->score());
}

ExerciseScore TrainerWindow::score() const
{
  return m_scorer->score();
}

bool TrainerWindow::writeReport(const std::string& path, std::string& error) const
{
  try
  {
    writeFileAtomically(path, exerciseReportJson(m_exercise, m_scorer->score(), ReportContext{}));
    return true;
  }
  catch (const std::exception& failure)
  {
    error = failure.what();
    return false;
  }
}

void TrainerWindow::restartExercise()
{
  m_scorer = std::make_unique<ExerciseScorer>(m_exercise, *settings().scene);
  m_ticked = false;
  m_overlay->update(m_scorer->score());
}

void TrainerWindow::sessionRestarted()
{
  // The runtime's clock starts again at 0: a new attempt (the scorer's ticks run forward).
  if (m_scorer)
  {
    restartExercise();
  }
}

std::string TrainerWindow::hudLines(const HapticState& state) const
{
  const ExerciseScore score = m_scorer->score();
  char line[256];
  std::snprintf(line, sizeof line, "%s   %s   damage events %zu", m_exercise.name.c_str(),
                touchedText(m_exercise, state).c_str(), score.damage.size());
  return std::string(line) + "\n" + taskLines(m_exercise, score);
}

void TrainerWindow::finishAttempt()
{
  const ExerciseScore result = m_scorer->score();
  const std::string summary = scoreSummary(m_exercise, result);
  statusBar()->showMessage(QString::fromStdString(summary).section('\n', 0, 0), 30000);
  QMessageBox box(this);
  box.setWindowTitle(tr("Score"));
  box.setText(QString::fromStdString(summary));
  box.setStandardButtons(QMessageBox::Save | QMessageBox::Close);
  if (box.exec() != QMessageBox::Save)
  {
    return;
  }
  const QString file = QFileDialog::getSaveFileName(this, tr("Save the report"),
                                                    "trainer-report.json", tr("Reports (*.json)"));
  if (file.isEmpty())
  {
    return;
  }
  std::string error;
  if (!writeReport(file.toStdString(), error))
  {
    QMessageBox::warning(this, windowTitle(), QString::fromStdString(error));
  }
}

void TrainerWindow::openExercise()
{
  const QString file =
    QFileDialog::getOpenFileName(this, tr("Open an exercise"), QString(), tr("Exercises (*.json)"));
  if (!file.isEmpty())
  {
    emit exerciseRequested(file);
  }
}

} // namespace proxima::trainer
