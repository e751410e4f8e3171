#include "ExerciseScreenshot.h"

#include "ExerciseOverlay.h"
#include "HudText.h"
#include "SceneSurfaceActor.h"
#include "VTK/vtkHapticStateRepresentation.h"
#include "WindowPng.h"

#include <vtkAutoInit.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <cstdio>

VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace proxima::trainer
{
namespace
{
std::string hudText(const Exercise& exercise, const HapticState& state, const ExerciseScore& score)
{
  char head[256];
  std::snprintf(head, sizeof head, "%s\nt %.2f s   force %.2f N   %s   damage events %zu",
                exercise.name.c_str(), state.time, norm(state.force),
                touchedText(exercise, state).c_str(), score.damage.size());
  return std::string(head) + "\n" + taskLines(exercise, score);
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

  ExerciseOverlay overlay(exercise, renderer);
  overlay.update(score);
  double bounds[6];
  const bool framed = overlay.bounds(bounds);
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
    // The proxy in the picture too, with a centimetre around it.
    expandBox(bounds, state.proxy, 0.01);
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
