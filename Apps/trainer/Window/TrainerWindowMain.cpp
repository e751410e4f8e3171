#include "TrainerWindowMain.h"

#include "DisplayCheck.h"
#include "Exercises/ExerciseFile.h"
#include "Exercises/ExerciseScene.h"
#include "TrainerWindow.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Scene/SceneTissue.h"
#include "IO/Output/StandardOutput.h"

#include <QApplication>
#include <QFileDialog>
#include <QInputDialog>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

namespace proxima::trainer
{
namespace
{
shell::HapticWindowSettings windowSettings(const Exercise& exercise, LoadedScene& loaded,
                                           const TrainerWindowOptions& options)
{
  shell::HapticWindowSettings settings;
  settings.title = "Proxima trainer: " + exercise.name;
  settings.scene = std::move(loaded.scene);
  settings.radius = exercise.radius;
  settings.stiffness = exercise.stiffness;
  settings.maxForce = exercise.maxForce;
  settings.servoRate = exercise.rate;
  settings.device = options.device;
  settings.falconFirmware = options.falconFirmware;
  settings.width = options.width;
  settings.height = options.height;
  return settings;
}

// A window on the exercise at `path`; throws InputError for a file or scene that cannot be used.
std::unique_ptr<TrainerWindow> openWindow(const std::string& path,
                                          const TrainerWindowOptions& options)
{
  const Exercise exercise = readExerciseFile(path);
  LoadedScene loaded = loadExerciseScene(exerciseRunSettings(exercise, ""));
  // A soft organ deforms in the window: the loops step its solid as the headless session does.
  std::shared_ptr<TissueDynamics> tissue =
    buildSceneTissue(loaded, exercise.stiffness, exercise.rate);
  shell::HapticWindowSettings settings = windowSettings(exercise, loaded, options);
  settings.tissue = std::move(tissue);
  return std::make_unique<TrainerWindow>(exercise, settings);
}

// The exercise to open when none was given: one of the shipped ones, or a file; empty to quit.
std::string pickExercise()
{
  const std::string folder = shippedExerciseFolder();
  std::vector<std::string> files;
  if (!folder.empty())
  {
    for (const auto& entry : std::filesystem::directory_iterator(folder))
    {
      if (entry.path().extension() == ".json")
      {
        files.push_back(entry.path().string());
      }
    }
    std::sort(files.begin(), files.end());
  }
  QStringList items;
  for (const std::string& file : files)
  {
    items << QString::fromStdString(std::filesystem::path(file).stem().string());
  }
  const QString other = QObject::tr("Another exercise file...");
  items << other;
  bool chosen = false;
  const QString item = QInputDialog::getItem(nullptr, QObject::tr("Proxima trainer"),
                                             QObject::tr("Exercise:"), items, 0, false, &chosen);
  if (!chosen)
  {
    return {};
  }
  if (item == other)
  {
    return QFileDialog::getOpenFileName(nullptr, QObject::tr("Open an exercise"), QString(),
                                        QObject::tr("Exercises (*.json)"))
      .toStdString();
  }
  return files[static_cast<std::size_t>(items.indexOf(item))];
}
} // namespace

std::string shippedExerciseFolder()
{
  if (const char* folder = std::getenv("PROXIMA_EXERCISE_DIR"); folder != nullptr && *folder)
  {
    return folder;
  }
#ifdef PROXIMA_SHIPPED_EXERCISES
  if (std::filesystem::is_directory(PROXIMA_SHIPPED_EXERCISES))
  {
    return PROXIMA_SHIPPED_EXERCISES;
  }
#endif
  return {};
}

int runTrainerWindow(const TrainerWindowOptions& options, int argc, char** argv)
{
  const std::string noDisplay = shell::displayProblem("proxima-trainer");
  if (!noDisplay.empty())
  {
    throw InputError("the trainer's window", noDisplay);
  }
  // Before the application: the OpenGL context VTK's widget needs (DEBIAN-NOTES.md).
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  std::unique_ptr<TrainerWindow> window;
  if (!options.exercise.empty())
  {
    // The exercise named on the command line is refused with status 2 like any other input.
    window = openWindow(options.exercise, options);
  }
  // One picked from the list and refused (a soft organ's, which scores headless only) is named
  // in a message and the list comes back, as File > Open does below.
  while (window == nullptr)
  {
    const std::string path = pickExercise();
    if (path.empty())
    {
      return 0;
    }
    try
    {
      window = openWindow(path, options);
    }
    catch (const std::exception& error)
    {
      // On stderr too, as a refusal on the command line is: a terminal keeps what the box said.
      std::fprintf(stderr, "proxima-trainer: %s\n", error.what());
      QMessageBox::warning(nullptr, QObject::tr("Proxima trainer"),
                           QString::fromStdString(error.what()));
    }
  }
  // File > Open an exercise: a window on the new one replaces this one; a bad file is named in a
  // message and the current window stays.
  std::function<void(TrainerWindow&)> connectOpen = [&](TrainerWindow& current) {
    QObject::connect(
      &current, &TrainerWindow::exerciseRequested, &current, [&](const QString& file) {
        try
        {
          std::unique_ptr<TrainerWindow> next = openWindow(file.toStdString(), options);
          connectOpen(*next);
          next->show();
          window->hide();
          window->deleteLater();
          window.release();
          window = std::move(next);
        }
        catch (const std::exception& error)
        {
          QMessageBox::warning(window.get(), QObject::tr("Proxima trainer"),
                               QString::fromStdString(error.what()));
        }
      });
  };
  connectOpen(*window);
  window->show();
  const int status = QApplication::exec();
  // The last attempt in one line, as proxima view prints its last state: scripts read it.
  const ExerciseScore score = window->score();
  int tasksPassed = 0;
  int marks = 0;
  for (const TaskScore& task : score.tasks)
  {
    tasksPassed += task.passed ? 1 : 0;
    marks += task.palpation.marks;
  }
  char line[512];
  std::snprintf(line, sizeof line,
                "proxima-trainer: closed %s: %s (%d of %zu tasks, %d marks, %zu damage events, "
                "peak force %.2f N, %llu ticks scored, %llu dropped)\n",
                window->exercise().name.c_str(), score.passed ? "passed" : "not passed",
                tasksPassed, score.tasks.size(), marks, score.damage.size(), score.peakForce,
                static_cast<unsigned long long>(score.ticks),
                static_cast<unsigned long long>(window->ticksDropped()));
  window.reset();
  writeStandardOutput(line);
  return status == 0 ? 0 : 1;
}

} // namespace proxima::trainer
