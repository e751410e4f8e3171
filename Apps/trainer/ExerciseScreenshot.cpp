#include "ExerciseScreenshot.h"

#include "HudText.h"
#include "SceneSurfaceActor.h"
#include "VTK/vtkHapticStateRepresentation.h"
#include "WindowPng.h"

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTubeFilter.h>

#include <algorithm>
#include <cstdio>

VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace proxima::trainer
{
namespace
{
void addSphere(vtkRenderer* renderer, const Vec3& center, double radius, double r, double g,
               double b, double opacity)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(center.x, center.y, center.z);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetOpacity(opacity);
  renderer->AddActor(actor);
}

void addLine(vtkRenderer* renderer, const std::vector<Vec3>& line, double radius)
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
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.15, 0.45, 0.95);
  renderer->AddActor(actor);
}

void expand(double bounds[6], const Vec3& p, double margin)
{
  bounds[0] = std::min(bounds[0], p.x - margin);
  bounds[1] = std::max(bounds[1], p.x + margin);
  bounds[2] = std::min(bounds[2], p.y - margin);
  bounds[3] = std::max(bounds[3], p.y + margin);
  bounds[4] = std::min(bounds[4], p.z - margin);
  bounds[5] = std::max(bounds[5], p.z + margin);
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

std::string hudText(const Exercise& exercise, const HapticState& state, const ExerciseScore& score)
{
  std::string touched = "free";
  for (const ExerciseTissue& tissue : exercise.tissues)
  {
    if (static_cast<int>(tissue.object) == state.contactObject)
    {
      touched = "touching " + tissue.name;
    }
  }
  if (touched == "free" && state.contactObject >= 0)
  {
    touched = "touching object " + std::to_string(state.contactObject);
  }
  char head[256];
  std::snprintf(head, sizeof head, "%s\nt %.2f s   force %.2f N   %s   damage events %zu",
                exercise.name.c_str(), state.time, norm(state.force), touched.c_str(),
                score.damage.size());
  std::string text = head;
  for (std::size_t t = 0; t < exercise.tasks.size(); ++t)
  {
    text += "\n" + taskLine(exercise.tasks[t], score.tasks[t]);
  }
  return text;
}
} // namespace

std::string exerciseScreenshot(const Exercise& exercise, const CollisionScene& scene,
                               const HapticState& state, const ExerciseScore& score,
                               shell::ForcePlot& forcePlot, const ScreenshotSize& size,
                               const std::string& path)
{
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(shell::makeSceneSurfaceActor(scene));
  vtkNew<vtkHapticStateRepresentation> representation;
  representation->SetForceScale(30.0 * exercise.radius / exercise.maxForce);
  representation->SetState(state);
  representation->AddToRenderer(renderer);

  double bounds[6] = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  bool framed = false;
  for (std::size_t t = 0; t < exercise.tasks.size(); ++t)
  {
    const ExerciseTask& task = exercise.tasks[t];
    const TaskScore& progress = score.tasks[t];
    if (task.kind == TaskKind::Targets)
    {
      for (std::size_t i = 0; i < task.targets.targets.size(); ++i)
      {
        const ExerciseTarget& target = task.targets.targets[i];
        const auto touched = static_cast<std::size_t>(progress.targets.touched);
        const double shade = i < touched ? 0.6 : 0.0;
        if (i < touched)
        {
          addSphere(renderer, target.center, target.radius, shade, shade, shade, 0.5);
        }
        else if (i == touched)
        {
          addSphere(renderer, target.center, target.radius, 1.0, 0.85, 0.1, 0.6);
        }
        else
        {
          addSphere(renderer, target.center, target.radius, 0.2, 0.8, 0.3, 0.5);
        }
        expand(bounds, target.center, target.radius + 0.01);
        framed = true;
      }
    }
    if (task.kind == TaskKind::Trace)
    {
      // Half the tolerance thick: it stands out of a bumpy bone surface it lies on.
      addLine(renderer, task.trace.line, task.trace.tolerance / 2.0);
      for (const Vec3& p : task.trace.line)
      {
        expand(bounds, p, 0.01);
      }
      framed = true;
    }
    if (task.kind == TaskKind::Palpation && progress.palpation.mark)
    {
      addSphere(renderer, *progress.palpation.mark, exercise.radius, 0.9, 0.1, 0.1, 1.0);
    }
  }
  vtkNew<vtkTextActor> hud;
  shell::styleHud(hud);
  hud->SetInput(hudText(exercise, state, score).c_str());
  renderer->AddViewProp(hud);
  forcePlot.update();
  forcePlot.addToRenderer(renderer);
  renderer->SetBackground(0.1, 0.12, 0.16);
  renderer->SetBackground2(0.25, 0.28, 0.34);
  renderer->GradientBackgroundOn();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(size.width, size.height);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  if (framed)
  {
    expand(bounds, state.proxy, 0.01);
    renderer->ResetCamera(bounds);
  }
  else
  {
    renderer->ResetCamera();
  }
  renderer->ResetCameraClippingRange();
  return shell::windowPng(window, path);
}

} // namespace proxima::trainer
