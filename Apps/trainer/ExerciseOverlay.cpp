#include "ExerciseOverlay.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTubeFilter.h>

#include <algorithm>
#include <cstdio>

namespace proxima::trainer
{
namespace
{
vtkSmartPointer<vtkActor> makeSphere(const Vec3& center, double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(center.x, center.y, center.z);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkActor> makeLine(const std::vector<Vec3>& line, double radius)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(static_cast<int>(line.size()));
  for (const Vec3& p : line)
  {
    cells->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
  }
  vtkNew<vtkPolyData> polyline;
  polyline->SetPoints(points);
  polyline->SetLines(cells);
  vtkNew<vtkTubeFilter> tube;
  tube->SetInputData(polyline);
  tube->SetRadius(radius);
  tube->SetNumberOfSides(12);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(tube->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.15, 0.45, 0.95);
  return actor;
}

std::string taskLine(const ExerciseTask& task, const TaskScore& score)
{
  char line[160];
  switch (task.kind)
  {
    case TaskKind::Palpation:
      std::snprintf(line, sizeof line, "palpation: %d mark%s", score.palpation.marks,
                    score.palpation.marks == 1 ? "" : "s");
      break;
    case TaskKind::Targets:
    {
      const auto touched = static_cast<std::size_t>(score.targets.touched);
      const std::size_t count = task.targets.targets.size();
      std::snprintf(line, sizeof line, "targets: %zu of %zu touched%s%s", touched, count,
                    touched < count ? ", next " : "",
                    touched < count ? task.targets.targets[touched].name.c_str() : "");
      break;
    }
    case TaskKind::Trace:
      std::snprintf(line, sizeof line, "trace: %.0f%% of the line covered, %.0f%% off it",
                    100.0 * score.trace.coverage, 100.0 * score.trace.offLine);
      break;
  }
  return line;
}
} // namespace

ExerciseOverlay::ExerciseOverlay(const Exercise& exercise, vtkRenderer* renderer)
  : m_exercise(exercise)
  , m_renderer(renderer)
  , m_targets(exercise.tasks.size())
  , m_marks(exercise.tasks.size())
{
  for (std::size_t t = 0; t < exercise.tasks.size(); ++t)
  {
    const ExerciseTask& task = exercise.tasks[t];
    if (task.kind == TaskKind::Targets)
    {
      for (const ExerciseTarget& target : task.targets.targets)
      {
        m_targets[t].push_back(makeSphere(target.center, target.radius));
        renderer->AddActor(m_targets[t].back());
        expandBox(m_box, target.center, target.radius + 0.01);
        m_framed = true;
      }
    }
    if (task.kind == TaskKind::Trace)
    {
      // Half the tolerance thick: it stands out of a bumpy bone surface it lies on.
      renderer->AddActor(makeLine(task.trace.line, task.trace.tolerance / 2.0));
      for (const Vec3& p : task.trace.line)
      {
        expandBox(m_box, p, 0.01);
      }
      m_framed = true;
    }
  }
}

void ExerciseOverlay::update(const ExerciseScore& score)
{
  for (std::size_t t = 0; t < m_exercise.tasks.size(); ++t)
  {
    const TaskScore& progress = score.tasks[t];
    const auto touched = static_cast<std::size_t>(progress.targets.touched);
    for (std::size_t i = 0; i < m_targets[t].size(); ++i)
    {
      vtkProperty* look = m_targets[t][i]->GetProperty();
      if (i < touched)
      {
        look->SetColor(0.6, 0.6, 0.6);
        look->SetOpacity(0.5);
      }
      else if (i == touched)
      {
        look->SetColor(1.0, 0.85, 0.1);
        look->SetOpacity(0.6);
      }
      else
      {
        look->SetColor(0.2, 0.8, 0.3);
        look->SetOpacity(0.5);
      }
    }
    if (m_exercise.tasks[t].kind == TaskKind::Palpation && progress.palpation.mark)
    {
      if (m_marks[t])
      {
        m_renderer->RemoveActor(m_marks[t]);
      }
      m_marks[t] = makeSphere(*progress.palpation.mark, m_exercise.radius);
      m_marks[t]->GetProperty()->SetColor(0.9, 0.1, 0.1);
      m_renderer->AddActor(m_marks[t]);
    }
    else if (m_marks[t] && !progress.palpation.mark)
    {
      m_renderer->RemoveActor(m_marks[t]);
      m_marks[t] = nullptr;
    }
  }
}

bool ExerciseOverlay::bounds(double box[6]) const
{
  std::copy(m_box, m_box + 6, box);
  return m_framed;
}

void expandBox(double box[6], const Vec3& p, double margin)
{
  box[0] = std::min(box[0], p.x - margin);
  box[1] = std::max(box[1], p.x + margin);
  box[2] = std::min(box[2], p.y - margin);
  box[3] = std::max(box[3], p.y + margin);
  box[4] = std::min(box[4], p.z - margin);
  box[5] = std::max(box[5], p.z + margin);
}

std::string touchedText(const Exercise& exercise, const HapticState& state)
{
  for (const ExerciseTissue& tissue : exercise.tissues)
  {
    if (static_cast<int>(tissue.object) == state.contactObject)
    {
      return "touching " + tissue.name;
    }
  }
  return state.contactObject >= 0 ? "touching object " + std::to_string(state.contactObject)
                                  : "free";
}

std::string taskLines(const Exercise& exercise, const ExerciseScore& score)
{
  std::string text;
  for (std::size_t t = 0; t < exercise.tasks.size(); ++t)
  {
    text += (t > 0 ? "\n" : "") + taskLine(exercise.tasks[t], score.tasks[t]);
  }
  return text;
}

} // namespace proxima::trainer
