// `proxima view`: replays a finger path through a mesh or a scene in the threaded runtime and
// draws it in a VTK window: the surface, the proxy, the finger's ghost, the spring, the contact
// planes, the friction cones and the force, with the loops' statistics. `--screenshot PNG`
// renders offscreen at a chosen moment of the path and exits instead: for a scripted finger
// (--device sim) from the lockstep run up to that moment, without waiting for it. With
// `--device mouse` the cursor aims the finger (vtkHapticMouseFinger) and no path is needed.
//
// The camera first frames the whole scene; then, but for the mouse (whose cursor must stay over
// the spot it aims at), it follows the proxy, keeping the direction and distance the user gives it
// with the mouse ('c' switches following on and off).
#include "Command.h"
#include "DeformingSurfaceActor.h"
#include "DisplayCheck.h"
#include "ForcePlot.h"
#include "HudText.h"
#include "ProxyCamera.h"
#include "SceneSurfaceActor.h"
#include "WindowPng.h"
#include "DeviceChoice.h"
#include "OutputChecks.h"
#include "SceneOptions.h"
#include "Validators.h"

#include "Dynamics/BodyCoupling.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputError.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/Scene/SceneBuilder.h"
#include "IO/Scene/SceneTissue.h"
#include "IO/ScriptedRun/ScriptedRun.h"
#include "Runtime/LockstepRuntime.h"
#include "Runtime/LoopStatistics.h"
#include "Runtime/PointerDevice.h"
#include "Runtime/ServoRate.h"
#include "VTK/LockstepStates.h"
#include "VTK/vtkHapticMouseFinger.h"
#include "VTK/vtkHapticRenderer.h"
#include "VTK/vtkHapticStateRepresentation.h"

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLineSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkInteractionStyle);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace proxima::cli
{
namespace
{
bool isPngExtension(const std::string& extension)
{
  return extension.size() == 4 && std::tolower(static_cast<unsigned char>(extension[1])) == 'p' &&
         std::tolower(static_cast<unsigned char>(extension[2])) == 'n' &&
         std::tolower(static_cast<unsigned char>(extension[3])) == 'g';
}

/// Whether `path` promises a format other than PNG, the only one the screenshot is written in:
/// an extension other than .png (any case), as x.jpg, is refused rather than given PNG bytes. A
/// name without one (/dev/stdout, a pipe) promises nothing and gets PNG.
bool namesAnotherFormat(const std::string& path)
{
  const std::string extension = std::filesystem::path(path).extension().string();
  return !extension.empty() && !isPngExtension(extension);
}

struct ViewOptions
{
  SceneOptions scene;
  DeviceChoiceOptions device;
  std::string screenshot;
  double at = -1.0;
  int width = 800;
  int height = 600;
  double viewDistance = 0.0;
  double forceScale = 0.0;
};

// The HUD's lines: the shell's status, and for the mouse how deep the finger is pressed and how
// to press it.
std::string statusText(const HapticState& state, const LoopStatistics& servo,
                       const vtkHapticMouseFinger* mouse)
{
  std::string text = shell::hapticStatusText(state, servo);
  if (mouse != nullptr)
  {
    char line[200];
    std::snprintf(line, sizeof line,
                  "\nmouse: pressed %.2f mm   wheel or held space presses, Backspace lifts, "
                  "a drag turns the camera",
                  mouse->GetDepth() * 1000.0);
    text += line;
  }
  return text;
}

// The window's picture as proxima-view-N.png in the current folder, N the first number not
// taken; one line says where it went, or why it did not (the session goes on either way).
void saveWindowPicture(vtkRenderWindow* window)
{
  std::string name;
  for (int n = 1; n < 100000; ++n)
  {
    name = "proxima-view-" + std::to_string(n) + ".png";
    if (!std::filesystem::exists(name))
    {
      break;
    }
  }
  try
  {
    AtomicOutputFile file(name);
    file.write(shell::windowPng(window, name));
    file.commit();
    std::cout << "proxima view: saved the window's picture to " << name << std::endl;
  }
  catch (const InputError& error)
  {
    std::cerr << "proxima: " << error.what() << std::endl;
  }
}

// Where a mouse's finger starts without a path: above the scene (shell::startAboveScene).
FingerPath mouseStartPath(const CollisionScene& scene, double radius)
{
  FingerPath path;
  path.append(0.0, shell::startAboveScene(scene, radius));
  return path;
}

// The mean of the contact normals: the side of free space the proxy is on.
Vec3 freeSide(const HapticState& state)
{
  Vec3 sum;
  for (int i = 0; i < state.numContacts; ++i)
  {
    sum += state.contacts[i].normal;
  }
  const double length = norm(sum);
  return length > 0.0 ? sum / length : state.contacts[0].normal;
}

// The state at `at` seconds into `path` (which starts at 0), from a lockstep run of its ticks
// with the finger read from `device`; every tick's force goes to `plot`.
HapticState lockstepStateAt(const SceneOptions& shared, const CollisionScene& scene,
                            const FingerPath& path, double at, HapticDevice& device,
                            shell::ForcePlot& plot, TickDynamics* bodies)
{
  ProxyParameters parameters = proxyParameters(shared);
  // The real-time default, deterministic: the picture shows the tick the window would show.
  tickBudget(shared, TickWorkBudget::realtimeDefault()).applyTo(parameters);
  const std::uint64_t ticks = ticksCovering(0.0, at, shared.rate);
  HapticState last;
  vtk::playLockstepStates(
    scene, parameters, servoParameters(shared), path, shared.rate, device,
    [&last, &plot, ticks](const HapticState& state) {
      last = state;
      plot.add(state.time, norm(state.force));
      return state.tick + 1 < ticks;
    },
    bodies);
  return last;
}

// The scene's surface: one actor for the objects that stay put, one per body, which its pose
// moves (placeBodyActors), and one per tissue, which draws its solid's newest step
// (updateTissueActors).
struct SceneActors
{
  vtkSmartPointer<vtkActor> still;
  std::vector<std::uint32_t> bodyObjects;
  std::vector<vtkSmartPointer<vtkActor>> bodies;
  std::vector<shell::DeformingSurfaceActor> tissues;
};

SceneActors makeSceneActors(const std::shared_ptr<const CollisionScene>& scene,
                            const TickDynamics* bodies,
                            const std::shared_ptr<TissueDynamics>& tissue)
{
  SceneActors actors;
  std::vector<std::uint32_t> notStill;
  if (bodies != nullptr)
  {
    actors.bodyObjects = bodies->movingObjects();
    notStill = actors.bodyObjects;
  }
  if (tissue != nullptr)
  {
    const std::vector<std::uint32_t> deforming = tissue->deformingObjects();
    notStill.insert(notStill.end(), deforming.begin(), deforming.end());
  }
  actors.still = shell::makeSceneSurfaceActor(*scene, shell::stillObjects(*scene, notStill));
  for (const std::uint32_t object : actors.bodyObjects)
  {
    actors.bodies.push_back(shell::makeSceneSurfaceActor(*scene, {object}));
  }
  actors.tissues = shell::makeTissueActors(tissue, scene);
  return actors;
}

void placeBodyActors(const SceneActors& actors, const BodyPoses& poses)
{
  for (int i = 0; i < poses.count; ++i)
  {
    const auto at =
      std::find(actors.bodyObjects.begin(), actors.bodyObjects.end(), poses.objects[i]);
    if (at == actors.bodyObjects.end())
    {
      continue;
    }
    const RigidTransform& pose = poses.poses[i];
    vtkNew<vtkMatrix4x4> matrix;
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        matrix->SetElement(r, c, pose.row[r][c]);
      }
      matrix->SetElement(r, 3, pose.translation[r]);
    }
    actors.bodies[static_cast<std::size_t>(at - actors.bodyObjects.begin())]->SetUserMatrix(matrix);
  }
}

// The tissues' actors brought to the newest step the loops (or a lockstep run) handed over.
void updateTissueActors(SceneActors& actors)
{
  for (shell::DeformingSurfaceActor& tissue : actors.tissues)
  {
    tissue.update();
  }
}

// A hinge's axis, drawn through its anchor so that the picture shows what the body turns about.
struct HingeAxis
{
  std::uint32_t object = 0;
  Vec3 anchor;
  Vec3 direction;
};

// The hinges of the scene file's own bodies (an MJCF mechanism's joints are its file's).
std::vector<HingeAxis> sceneHinges(const SceneDescription& description)
{
  std::vector<HingeAxis> hinges;
  for (std::uint32_t object = 0; object < description.objects.size(); ++object)
  {
    const SceneObject& item = description.objects[object];
    const double length = norm(item.body.axis);
    if (item.hasBody && item.body.mjcfBody.empty() && item.body.joint == SceneJoint::Hinge &&
        length > 0.0 && std::isfinite(length))
    {
      hinges.push_back({object, item.body.anchor, item.body.axis / length});
    }
  }
  return hinges;
}

// The gap between two boxes (0 when they overlap).
double gapBetween(const Aabb& a, const Aabb& b)
{
  const Vec3 below = componentMax(a.lower - b.upper, Vec3{0.0, 0.0, 0.0});
  const Vec3 above = componentMax(b.lower - a.upper, Vec3{0.0, 0.0, 0.0});
  return norm(componentMax(below, above));
}

// Where `object` is now: its box as placed, moved by its body's pose when it has one.
Aabb objectBounds(const CollisionScene& scene, std::size_t object, const BodyPoses& poses)
{
  const Aabb& placed = scene.objects[object].mesh.bounds();
  for (int i = 0; i < poses.count; ++i)
  {
    if (poses.objects[i] == object)
    {
      Aabb moved;
      for (int corner = 0; corner < 8; ++corner)
      {
        moved.expand(poses.poses[i].apply({corner & 1 ? placed.upper.x : placed.lower.x,
                                           corner & 2 ? placed.upper.y : placed.lower.y,
                                           corner & 4 ? placed.upper.z : placed.lower.z}));
      }
      return moved;
    }
  }
  return placed;
}

// What a picture frames: the object the proxy touches (touching none, the one nearest it), its
// neighbours (the objects within the touched one's own size of it), each where its body's pose
// has moved it, the proxy, the finger and the anchors of the framed objects' hinges. The whole
// scene shrank the proxy to a dot on a large table, and the proxy alone lost the objects it was
// among.
Aabb framedBounds(const CollisionScene& scene, const HapticState& state,
                  const std::vector<HingeAxis>& hinges, const BodyPoses& poses)
{
  Aabb proxyBox;
  proxyBox.expand(state.proxy, state.proxyRadius);
  std::size_t touched = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t object = 0; object < scene.objects.size(); ++object)
  {
    const double gap = gapBetween(objectBounds(scene, object, poses), proxyBox);
    if (gap < nearest)
    {
      nearest = gap;
      touched = object;
    }
  }
  if (state.numContacts > 0 && state.contactObject >= 0 &&
      static_cast<std::size_t>(state.contactObject) < scene.objects.size())
  {
    touched = static_cast<std::size_t>(state.contactObject);
  }
  Aabb framed = proxyBox;
  framed.expand(state.finger);
  if (scene.objects.size() == 0)
  {
    return framed;
  }
  const Aabb touchedBox = objectBounds(scene, touched, poses);
  for (std::size_t object = 0; object < scene.objects.size(); ++object)
  {
    const Aabb box = objectBounds(scene, object, poses);
    if (object != touched && gapBetween(box, touchedBox) > touchedBox.diagonal())
    {
      continue;
    }
    framed.expand(box.lower);
    framed.expand(box.upper);
    for (const HingeAxis& hinge : hinges)
    {
      if (hinge.object == object)
      {
        framed.expand(hinge.anchor);
      }
    }
  }
  return framed;
}

// Sizes the force arrow for a picture framing `framed`, and widens `framed` to hold the arrow
// at the clamp in the force's direction (from a proxy at the edge of the framed objects it would
// leave the picture). The shaft at the clamp is two fifths of the framed radius; the head, a
// thirteenth of it, keeps its size, so that a force of a few hundredths of the clamp still shows.
void frameForceArrow(vtkHapticStateRepresentation* representation, Aabb& framed,
                     const HapticState& state, double maxForce, double forceScaleOption)
{
  const double radius = 0.5 * framed.diagonal();
  const double scale = forceScaleOption > 0.0 ? forceScaleOption : 0.4 * radius / maxForce;
  const double head = 0.08 * radius;
  representation->SetForceScale(scale);
  representation->SetForceArrowHeadLength(head);
  const double magnitude = norm(state.force);
  if (magnitude > 0.0 && std::isfinite(magnitude))
  {
    framed.expand(state.proxy + state.force * ((maxForce * scale + head) / magnitude));
  }
}

// Thin lines along the hinges' axes, through their anchors, as long as the framed diagonal.
std::vector<vtkSmartPointer<vtkActor>> makeHingeActors(const std::vector<HingeAxis>& hinges,
                                                       double length)
{
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const HingeAxis& hinge : hinges)
  {
    const Vec3 from = hinge.anchor - hinge.direction * (0.5 * length);
    const Vec3 to = hinge.anchor + hinge.direction * (0.5 * length);
    vtkNew<vtkLineSource> line;
    line->SetPoint1(from.x, from.y, from.z);
    line->SetPoint2(to.x, to.y, to.z);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(line->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    // Magenta: no other part of the picture (surfaces, proxy, spring, force, plot) has it.
    actor->GetProperty()->SetColor(0.95, 0.25, 0.95);
    actor->GetProperty()->SetLineWidth(3.0);
    actor->GetProperty()->LightingOff();
    actors.push_back(actor);
  }
  return actors;
}

// Looks at the proxy from `distance`, from the free side of its contacts (tilted, so that the
// planes and the cones show in depth), or along the camera's current direction.
void aimAtProxy(vtkCamera* camera, const HapticState& state, double distance)
{
  Vec3 direction;
  if (state.numContacts > 0)
  {
    const Vec3 n = freeSide(state);
    // Any vector not along n, to tilt the view by about 50 degrees off the normal.
    const Vec3 other = std::abs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    Vec3 side = cross(n, other);
    side = side / norm(side);
    direction = n + side * 1.2;
  }
  else
  {
    double position[3];
    double focus[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focus);
    direction = {position[0] - focus[0], position[1] - focus[1], position[2] - focus[2]};
  }
  direction = direction / norm(direction);
  const Vec3 eye = state.proxy + direction * distance;
  camera->SetFocalPoint(state.proxy.x, state.proxy.y, state.proxy.z);
  camera->SetPosition(eye.x, eye.y, eye.z);
  if (state.numContacts > 0)
  {
    const Vec3 n = freeSide(state);
    camera->SetViewUp(n.x, n.y, n.z);
  }
  camera->OrthogonalizeViewUp();
}

// What a view plays, loaded and checked before any window object exists: every refusal of the
// input comes first, and alike with or without a display.
struct ViewInputs
{
  LoadedScene loaded;
  std::vector<HingeAxis> hinges;
  std::shared_ptr<BodyCoupling> bodies;
  /// The scene's tissues: deformed by the window's loops, or by a lockstep screenshot's run.
  std::shared_ptr<TissueDynamics> tissue;
  FingerPath fingerPath;
  std::shared_ptr<const CollisionScene> scene;
  double pathSeconds = 0.0;
  /// --at, or the path's end.
  double at = 0.0;
  /// --screenshot's temporary, made now so that an unwritable one fails before the run.
  std::optional<AtomicOutputFile> screenshotFile;
};

// Fills `inputs` (not returned: the screenshot's temporary file is not movable).
void loadViewInputs(const ViewOptions& options, ViewInputs& inputs)
{
  const SceneOptions& shared = options.scene;
  // The viewer runs the real-time loops: their rate rule, refused before anything is loaded.
  if (!isServoRate(shared.rate))
  {
    throw InputError("--rate", "must be " + servoRateRange() + " (the servo loop's range)");
  }
  const bool mouse = options.device.device == "mouse";
  if (shared.path.empty() && !mouse)
  {
    throw InputError("--path", "is required (but with --device mouse, where the cursor aims)");
  }
  if (mouse && !options.screenshot.empty())
  {
    throw InputError("--screenshot", "the mouse moves the finger only in a window: give "
                                     "--screenshot a --path, or take the window's picture");
  }
  inputs.loaded = loadScene(shared);
  inputs.hinges = sceneHinges(inputs.loaded.description);
  // A scene's bodies move in the window and in a screenshot (Documentation/Dynamics.md).
  inputs.bodies = sceneBodies(shared, inputs.loaded);
  // Tissue deforms in the window, its solid stepped on a thread of its own beside the loops, and
  // in a screenshot, the same steps as `proxima run` (Documentation/Tissue.md).
  inputs.tissue = buildSceneTissue(inputs.loaded, shared.stiffness, shared.rate);
  inputs.fingerPath = shared.path.empty() ? mouseStartPath(*inputs.loaded.scene, shared.radius)
                                          : readFingerPathFile(shared.path);
  checkRadiusAgainstScene(shared, inputs.loaded);
  checkPathStart(shared, inputs.loaded, inputs.fingerPath);
  inputs.scene = std::move(inputs.loaded.scene);
  inputs.pathSeconds = inputs.fingerPath.endTime() - inputs.fingerPath.startTime();
  inputs.at = options.at >= 0.0 ? options.at : inputs.pathSeconds;
  if (inputs.at > inputs.pathSeconds)
  {
    throw InputError("--at", shortNumber(inputs.at) + " s is after the end of the path (" +
                               shortNumber(inputs.pathSeconds) + " s)");
  }
  refuseOverlappingFiles(
    {{options.screenshot, "--screenshot"}, {options.device.recordDevice, "--record-device"}},
    runInputs(shared, inputs.loaded, options.device));
  if (!options.screenshot.empty())
  {
    if (namesAnotherFormat(options.screenshot))
    {
      throw InputError(options.screenshot, "a screenshot is a PNG file: name it .png");
    }
    inputs.screenshotFile.emplace(options.screenshot);
  }
}

// The scene's bodies or its tissues (a scene has one kind or none): what the loops step after
// each proxy update.
std::shared_ptr<TickDynamics> dynamicsOfInputs(const ViewInputs& inputs)
{
  if (inputs.tissue != nullptr)
  {
    return inputs.tissue;
  }
  return inputs.bodies;
}

// The haptic loops' settings: the scene, the device, the proxy's start and the knobs.
void configureHaptics(vtkHapticRenderer* haptics, const SceneOptions& shared,
                      const ViewInputs& inputs, HapticDevice& device)
{
  haptics->SetCollisionScene(inputs.scene, dynamicsOfInputs(inputs));
  haptics->SetDevice(&device);
  const Vec3& start = inputs.fingerPath.positions.front();
  haptics->SetProxyStart(start.x, start.y, start.z);
  haptics->SetProxyRadius(shared.radius);
  haptics->SetStiffness(shared.stiffness);
  haptics->SetMaxForce(shared.maxForce);
  haptics->SetMaxIterations(shared.maxIterations);
  haptics->SetSkin(shared.skin);
  haptics->SetServoRate(shared.rate);
  const TickWorkBudget budget = tickBudget(shared, TickWorkBudget::realtimeDefault());
  haptics->SetTickBudgetSeconds(budget.seconds);
  haptics->SetTickBudgetIterations(budget.iterations);
  haptics->SetTickSafetyCapSeconds(budget.safetyCapSeconds);
}

// What is drawn: the scene's surface, the proxy's representation, the HUD and the force plot, in
// one renderer and window.
struct ViewStage
{
  ViewStage(const ViewOptions& options, const ViewInputs& inputs)
    : surface(makeSceneActors(inputs.scene, inputs.bodies.get(), inputs.tissue))
    // The last 5 s of force, 0 to the clamp.
    , forcePlot(5.0, options.scene.maxForce)
  {
    shell::styleHud(status);
    if (surface.still != nullptr)
    {
      renderer->AddActor(surface.still);
    }
    for (const vtkSmartPointer<vtkActor>& body : surface.bodies)
    {
      renderer->AddActor(body);
    }
    for (const shell::DeformingSurfaceActor& tissue : surface.tissues)
    {
      renderer->AddActor(tissue.actor());
    }
    representation->AddToRenderer(renderer);
    renderer->AddViewProp(status);
    forcePlot.addToRenderer(renderer);
    renderer->SetBackground(0.1, 0.12, 0.16);
    renderer->SetBackground2(0.25, 0.28, 0.34);
    renderer->GradientBackgroundOn();
    renderer->SetUseDepthPeeling(1);
    window->SetSize(options.width, options.height);
    window->SetAlphaBitPlanes(1);
    window->SetMultiSamples(0);
    window->AddRenderer(renderer);
    window->SetWindowName("proxima view");
    renderer->ResetCamera();
  }

  /// The force arrow and the hinges' axes sized for the objects framed around `state`.
  Aabb frame(const ViewOptions& options, const ViewInputs& inputs, const HapticState& state,
             const BodyPoses& poses)
  {
    Aabb framed = framedBounds(*inputs.scene, state, inputs.hinges, poses);
    frameForceArrow(representation, framed, state, options.scene.maxForce, options.forceScale);
    for (const vtkSmartPointer<vtkActor>& axis : makeHingeActors(inputs.hinges, framed.diagonal()))
    {
      renderer->AddActor(axis);
    }
    return framed;
  }

  SceneActors surface;
  vtkNew<vtkHapticStateRepresentation> representation;
  vtkNew<vtkTextActor> status;
  shell::ForcePlot forcePlot;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
};

// --screenshot: the state at --at, drawn offscreen into the PNG; for a scripted finger from the
// lockstep run, for a real device by living through it.
int takeScreenshot(const ViewOptions& options, ViewInputs& inputs, ViewStage& stage,
                   vtkHapticRenderer* haptics, RunDevice& device, const FingerPath& shifted)
{
  const SceneOptions& shared = options.scene;
  LoopStatistics servo;
  HapticState state;
  BodyPoses poses;
  const bool lockstep = options.device.device == "sim";
  if (lockstep)
  {
    // A scripted finger needs no real clock: the state at --at comes from the lockstep run (the
    // same steps as the threads, on a virtual clock) in a fraction of --at, and is the same
    // picture every time. It takes the real-time default budget (lockstepStateAt), so that it
    // shows the tick the window would show.
    state = lockstepStateAt(shared, *inputs.scene, shifted, inputs.at, device.device(),
                            stage.forcePlot, dynamicsOfInputs(inputs).get());
    servo.rate = shared.rate;
    if (inputs.bodies != nullptr)
    {
      inputs.bodies->poses(poses);
    }
    // The organ as the press has deformed it at --at, not as the scene file gives it.
    updateTissueActors(stage.surface);
  }
  else
  {
    // A real device moves in real time: its state at --at is reached by living through it.
    haptics->SetDuration(inputs.at + 0.5);
    if (!haptics->Start())
    {
      throw std::runtime_error("the haptic threads did not start: " + haptics->GetStartMessage());
    }
    while (haptics->GetState().time < inputs.at && !haptics->IsFinished())
    {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    state = haptics->GetState();
    servo = haptics->GetServoStatistics();
    poses = haptics->GetBodyPoses();
    haptics->Stop();
    // The surfaces of the last step the loops took.
    updateTissueActors(stage.surface);
  }
  placeBodyActors(stage.surface, poses);
  const Aabb framed = stage.frame(options, inputs, state, poses);
  stage.representation->SetState(state);
  stage.status->SetInput(statusText(state, servo, nullptr).c_str());
  if (!lockstep)
  {
    stage.forcePlot.add(state.time, norm(state.force));
  }
  stage.forcePlot.update();
  vtkRenderer* renderer = stage.renderer;
  const double distance = options.viewDistance > 0.0 ? options.viewDistance : 40.0 * shared.radius;
  aimAtProxy(renderer->GetActiveCamera(), state, distance);
  if (options.viewDistance <= 0.0)
  {
    // From the same side, far enough back for the framed objects to fit.
    double bounds[6] = {framed.lower.x, framed.upper.x, framed.lower.y,
                        framed.upper.y, framed.lower.z, framed.upper.z};
    renderer->ResetCamera(bounds);
  }
  renderer->ResetCameraClippingRange();
  stage.window->SetOffScreenRendering(1);
  inputs.screenshotFile->write(shell::windowPng(stage.window, options.screenshot));
  inputs.screenshotFile->commit();
  device.finish();
  char line[512];
  std::snprintf(line, sizeof line, "%dx%d at t = %.4f s (%s), %d contacts%s, force %.4f N\n",
                options.width, options.height, state.time, lockstep ? "lockstep" : "real time",
                state.numContacts, state.conditions.has(TickCondition::stuck) ? " (sticking)" : "",
                norm(state.force));
  writeStandardOutput(options.screenshot + ": " + line);
  return kExitOk;
}

// What the window's timer and keys act on.
struct WindowFrame
{
  vtkHapticRenderer* haptics;
  ViewStage* stage;
  vtkHapticMouseFinger* mouse;
  bool follow;
  std::chrono::steady_clock::time_point last;
};

// About 60 times a second: the path restarted when it ends (the mouse's run has no end), the
// mouse finger moved, and the drawing brought to the latest state.
void onWindowTimer(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* f = static_cast<WindowFrame*>(clientData);
  if (f->haptics->IsFinished())
  {
    f->haptics->Stop();
    f->haptics->Start();
  }
  const auto now = std::chrono::steady_clock::now();
  if (f->mouse != nullptr)
  {
    f->mouse->Update(std::chrono::duration<double>(now - f->last).count());
  }
  f->last = now;
  ViewStage& stage = *f->stage;
  const HapticState state = f->haptics->GetState();
  stage.representation->SetState(state);
  placeBodyActors(stage.surface, f->haptics->GetBodyPoses());
  updateTissueActors(stage.surface);
  stage.forcePlot.add(state.time, norm(state.force));
  stage.forcePlot.update();
  stage.status->SetInput(statusText(state, f->haptics->GetServoStatistics(), f->mouse).c_str());
  if (f->follow && state.tick > 0)
  {
    shell::followProxy(stage.renderer->GetActiveCamera(), state.proxy);
  }
  stage.renderer->ResetCameraClippingRange();
  static_cast<vtkRenderWindowInteractor*>(caller)->Render();
}

// 'c' switches following the proxy; 'i' or Print saves the window's picture.
void onWindowKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* keys = static_cast<vtkRenderWindowInteractor*>(caller);
  const char* key = keys->GetKeySym();
  auto* f = static_cast<WindowFrame*>(clientData);
  if (key != nullptr && std::string(key) == "c")
  {
    f->follow = !f->follow;
  }
  if (key != nullptr && (std::string(key) == "i" || std::string(key) == "Print"))
  {
    saveWindowPicture(keys->GetRenderWindow());
  }
}

// The window: the path played in real time and looped, or the mouse aiming the finger, until the
// window is closed.
int runWindow(const ViewOptions& options, const ViewInputs& inputs, ViewStage& stage,
              vtkHapticRenderer* haptics, RunDevice& device)
{
  const SceneOptions& shared = options.scene;
  const bool mouse = options.device.device == "mouse";
  // The arrow and the hinges sized for the objects around the finger's start.
  HapticState start;
  start.proxy = inputs.fingerPath.positions.front();
  start.finger = start.proxy;
  start.proxyRadius = shared.radius;
  stage.frame(options, inputs, start, BodyPoses{});

  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(stage.window);
  interactor->Initialize();
  vtkNew<vtkHapticMouseFinger> mouseFinger;
  if (mouse)
  {
    // A wheel notch presses half a radius; a held space bar five radii a second.
    mouseFinger->SetDevice(static_cast<PointerDevice*>(&device.openedDevice()));
    mouseFinger->SetHapticRenderer(haptics);
    mouseFinger->SetRenderer(stage.renderer);
    mouseFinger->SetInteractor(interactor);
    mouseFinger->SetDepthStep(0.5 * shared.radius);
    mouseFinger->SetPressSpeed(5.0 * shared.radius);
  }
  haptics->SetDuration(mouse ? 0.0 : inputs.pathSeconds + 0.5);
  if (!haptics->Start())
  {
    throw std::runtime_error("the haptic threads did not start: " + haptics->GetStartMessage());
  }
  if (options.viewDistance > 0.0)
  {
    // The scene framed, then brought to the distance asked for.
    stage.renderer->GetActiveCamera()->SetDistance(options.viewDistance);
  }
  WindowFrame frame{haptics, &stage, mouse ? mouseFinger.Get() : nullptr, !mouse,
                    std::chrono::steady_clock::now()};
  vtkNew<vtkCallbackCommand> onTimer;
  onTimer->SetClientData(&frame);
  onTimer->SetCallback(onWindowTimer);
  interactor->AddObserver(vtkCommand::TimerEvent, onTimer);
  vtkNew<vtkCallbackCommand> onKey;
  onKey->SetClientData(&frame);
  onKey->SetCallback(onWindowKey);
  interactor->AddObserver(vtkCommand::KeyPressEvent, onKey);
  interactor->CreateRepeatingTimer(16);
  stage.window->Render();
  interactor->Start();
  // Closed (q, e or the window's close): the last state in one line, as a screenshot prints its.
  const HapticState last = haptics->GetState();
  haptics->Stop();
  device.finish();
  char line[256];
  std::snprintf(line, sizeof line,
                "proxima view: closed at t = %.4f s, %d contacts, force %.4f N\n", last.time,
                last.numContacts, norm(last.force));
  writeStandardOutput(line);
  return kExitOk;
}

int view(const ViewOptions& options)
{
  ViewInputs inputs;
  loadViewInputs(options, inputs);
  const bool mouse = options.device.device == "mouse";
  // The runtime's clock starts at 0; a path that starts later is shifted to start with it.
  FingerPath shifted = inputs.fingerPath;
  for (double& time : shifted.times)
  {
    time -= inputs.fingerPath.startTime();
  }
  // The finger's device, as for `proxima run --device` (sim plays the path); made before the
  // renderer, so that it outlives the haptic threads. A mouse session has no end:
  // --record-device keeps its first ten minutes.
  constexpr double kMouseRecordingSeconds = 600.0;
  RunDevice device(options.device, shifted,
                   ticksCovering(0.0, mouse ? kMouseRecordingSeconds : inputs.pathSeconds + 0.5,
                                 options.scene.rate));
  // Last of the checks, so that every refusal of the input above comes first and alike with or
  // without a display; before the first VTK window object.
  const std::string noDisplay = shell::displayProblem("proxima view");
  if (!noDisplay.empty())
  {
    throw InputError("proxima view", noDisplay);
  }
  vtkNew<vtkHapticRenderer> haptics;
  configureHaptics(haptics, options.scene, inputs, device.device());
  ViewStage stage(options, inputs);
  if (!options.screenshot.empty())
  {
    return takeScreenshot(options, inputs, stage, haptics, device, shifted);
  }
  return runWindow(options, inputs, stage, haptics, device);
}
} // namespace

Command addViewCommand(CLI::App& parent)
{
  auto options = std::make_shared<ViewOptions>();
  CLI::App* app = parent.add_subcommand(kViewSummary.name, kViewSummary.description);
  // Not required here: --device mouse aims the finger without one (checked in view()).
  addSceneOptionsThroughPath(*app, options->scene, false);
  app->add_option("--screenshot", options->screenshot,
                  "Render offscreen to this PNG at --at and exit, instead of opening a window");
  app
    ->add_option("--at", options->at,
                 "With --screenshot: seconds into the path to capture (default: its end)")
    ->check(finiteNumber(false));
  app->add_option("--width", options->width, "Window width in pixels (default 800)")
    ->check(wholeNumberIn(kWindowSizeRange));
  app->add_option("--height", options->height, "Window height in pixels (default 600)")
    ->check(wholeNumberIn(kWindowSizeRange));
  app
    ->add_option("--view-distance", options->viewDistance,
                 "Camera distance from the proxy in metres (default: a --screenshot frames "
                 "the touched object and its neighbours; the window the whole scene)")
    ->check(numberIn(ParameterRange{0.0, true, 1e6, " m"}));
  app
    ->add_option("--force-scale", options->forceScale,
                 "Force arrow's shaft length in metres per newton (default: at --max-force, "
                 "two fifths of the radius of what the picture frames)")
    ->check(numberIn(ParameterRange{0.0, true, 1e6, " m/N"}));
  addDeviceOptions(*app, options->device);
  addSceneOptionsAfterPath(*app, options->scene, kRealtimeRateRange);
  addTickBudgetOption(
    *app, options->scene,
    "Default: default, the real-time default budget, also for a --screenshot of the scripted "
    "path, which runs in lockstep");
  app->callback([options, app] { checkSceneOptions(options->scene, *app); });
  return Command{app, [options] { return view(*options); }};
}

} // namespace proxima::cli
