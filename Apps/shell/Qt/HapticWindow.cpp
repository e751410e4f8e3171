#include "HapticWindow.h"

#include "HudText.h"
#include "ProxyCamera.h"
#include "SceneSurfaceActor.h"
#include "WindowPng.h"

#include "Devices/DeviceRecording.h"
#include "Devices/DeviceRegistry.h"
#include "Devices/ReplayDevice.h"
#include "IO/Output/AtomicOutputFile.h"
#include "Runtime/PointerDevice.h"
#include "VTK/vtkHapticMouseFinger.h"
#include "VTK/vtkHapticRenderer.h"
#include "VTK/vtkHapticStateRepresentation.h"

#include <QAction>
#include <QActionGroup>
#include <QFileDialog>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <cstdio>
#include <exception>
#include <optional>

namespace proxima::shell
{
namespace
{
// Two seconds of ticks at the fastest servo rate: a frame that stalls that long still drops none.
constexpr std::size_t kStreamCapacity = 20000;
// A recording keeps its first ten minutes (the recorder reserves them up front).
constexpr double kRecordingSeconds = 600.0;

} // namespace

HapticWindow::HapticWindow(const HapticWindowSettings& settings, QWidget* parent)
  : QMainWindow(parent)
  , m_settings(settings)
  , m_forcePlot(5.0, settings.maxForce)
{
  setWindowTitle(QString::fromStdString(m_settings.title));
  resize(m_settings.width, m_settings.height);

  m_view = new QVTKOpenGLNativeWidget(this);
  m_window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  m_window->SetMultiSamples(0);
  m_window->SetAlphaBitPlanes(1);
  m_view->setRenderWindow(m_window);
  setCentralWidget(m_view);

  m_renderer = vtkSmartPointer<vtkRenderer>::New();
  // The objects that stay put in one actor; each tissue in its own, whose points its steps move.
  const std::vector<std::uint32_t> still = stillObjects(
    *m_settings.scene, m_settings.tissue != nullptr ? m_settings.tissue->deformingObjects()
                                                    : std::vector<std::uint32_t>{});
  if (vtkSmartPointer<vtkActor> surface = makeSceneSurfaceActor(*m_settings.scene, still))
  {
    m_renderer->AddActor(surface);
  }
  m_tissueActors = makeTissueActors(m_settings.tissue, m_settings.scene);
  for (const DeformingSurfaceActor& tissue : m_tissueActors)
  {
    m_renderer->AddActor(tissue.actor());
  }
  m_representation = vtkSmartPointer<vtkHapticStateRepresentation>::New();
  m_representation->SetForceScale(30.0 * m_settings.radius / m_settings.maxForce);
  m_representation->AddToRenderer(m_renderer);
  m_hud = vtkSmartPointer<vtkTextActor>::New();
  styleHud(m_hud);
  m_renderer->AddViewProp(m_hud);
  m_forcePlot.addToRenderer(m_renderer);
  m_renderer->SetBackground(0.1, 0.12, 0.16);
  m_renderer->SetBackground2(0.25, 0.28, 0.34);
  m_renderer->GradientBackgroundOn();
  m_window->AddRenderer(m_renderer);

  vtkRenderWindowInteractor* interactor = m_window->GetInteractor();
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);

  m_haptics = vtkSmartPointer<vtkHapticRenderer>::New();
  m_haptics->SetCollisionScene(m_settings.scene, m_settings.tissue);
  m_haptics->SetProxyRadius(m_settings.radius);
  m_haptics->SetStiffness(m_settings.stiffness);
  m_haptics->SetMaxForce(m_settings.maxForce);
  m_haptics->SetServoRate(m_settings.servoRate);
  m_haptics->SetStateStreamCapacity(static_cast<vtkIdType>(kStreamCapacity));

  // A wheel notch presses half a radius; a held space bar five radii a second (as proxima view).
  m_mouse = vtkSmartPointer<vtkHapticMouseFinger>::New();
  m_mouse->SetHapticRenderer(m_haptics);
  m_mouse->SetRenderer(m_renderer);
  m_mouse->SetInteractor(interactor);
  m_mouse->SetDepthStep(0.5 * m_settings.radius);
  m_mouse->SetPressSpeed(5.0 * m_settings.radius);

  m_status = new QLabel(this);
  statusBar()->addPermanentWidget(m_status, 1);
  buildMenus();
  frameScene();
  if (!m_settings.startGiven)
  {
    // Between the camera and the scene, just outside the sphere around it: the mouse's first
    // move then goes to the surface it points at through free space.
    m_settings.start =
      startFacingCamera(*m_settings.scene, m_renderer->GetActiveCamera(), m_settings.radius);
    m_settings.startGiven = true;
  }
  m_haptics->SetProxyStart(m_settings.start.x, m_settings.start.y, m_settings.start.z);

  std::string error;
  if (!useDevice(m_settings.device, error))
  {
    std::string fallback;
    useDevice("mouse", fallback);
    showProblem(error + "; the mouse moves the finger instead");
  }
  m_lastFrame = std::chrono::steady_clock::now();
  connect(&m_timer, &QTimer::timeout, this, &HapticWindow::refresh);
  m_timer.start(16);
}

HapticWindow::~HapticWindow()
{
  m_timer.stop();
  m_haptics->Stop();
  m_mouse->SetDevice(nullptr);
}

void HapticWindow::buildMenus()
{
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* screenshot = file->addAction(tr("Save a &screenshot..."));
  screenshot->setShortcuts({QKeySequence("Ctrl+S"), QKeySequence(Qt::Key_I)});
  connect(screenshot, &QAction::triggered, this, &HapticWindow::saveScreenshotAs);
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"));
  quit->setShortcut(QKeySequence("Ctrl+Q"));
  connect(quit, &QAction::triggered, this, &QWidget::close);

  QMenu* device = menuBar()->addMenu(tr("&Device"));
  m_deviceGroup = new QActionGroup(this);
  const std::pair<const char*, const char*> devices[] = {{"mouse", "&Mouse (no device needed)"},
                                                         {"spacemouse", "&SpaceMouse"},
                                                         {"falcon", "Novint &Falcon"}};
  for (const auto& [spec, label] : devices)
  {
    QAction* action = device->addAction(tr(label));
    action->setCheckable(true);
    action->setData(QString(spec));
    m_deviceGroup->addAction(action);
  }
  connect(m_deviceGroup, &QActionGroup::triggered, this, &HapticWindow::chooseDevice);
  device->addSeparator();
  QAction* replay = device->addAction(tr("&Replay a recording..."));
  connect(replay, &QAction::triggered, this, &HapticWindow::chooseReplay);

  m_sessionMenu = menuBar()->addMenu(tr("&Session"));
  m_recordAction = m_sessionMenu->addAction(tr("&Record the device"));
  m_recordAction->setCheckable(true);
  m_recordAction->setShortcut(QKeySequence("Ctrl+R"));
  connect(m_recordAction, &QAction::triggered, this, &HapticWindow::toggleRecording);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  m_followAction = view->addAction(tr("&Follow the proxy"));
  m_followAction->setCheckable(true);
  m_followAction->setShortcut(QKeySequence(Qt::Key_C));
  QAction* closer = view->addAction(tr("Come &closer"));
  closer->setShortcut(QKeySequence("Ctrl++"));
  connect(closer, &QAction::triggered, this, [this] { moveCloser(1.0 / 1.25); });
  QAction* farther = view->addAction(tr("Go &farther"));
  farther->setShortcut(QKeySequence("Ctrl+-"));
  connect(farther, &QAction::triggered, this, [this] { moveCloser(1.25); });
  QAction* overlays = view->addAction(tr("Show the &HUD and the force plot"));
  overlays->setObjectName("showOverlays");
  overlays->setCheckable(true);
  overlays->setChecked(true);
  overlays->setShortcut(QKeySequence(Qt::Key_H));
  connect(overlays, &QAction::toggled, this, [this](bool visible) {
    // A clean picture of the scene alone, for a screenshot.
    m_hud->SetVisibility(visible);
    m_forcePlot.setVisible(visible);
  });
  QAction* frame = view->addAction(tr("Frame the &whole scene"));
  frame->setShortcut(QKeySequence(Qt::Key_Home));
  connect(frame, &QAction::triggered, this, &HapticWindow::frameScene);
}

bool HapticWindow::useDevice(const std::string& spec, std::string& error)
{
  DeviceOptions options;
  options.path.append(0.0, m_settings.start);
  options.falconFirmware = m_settings.falconFirmware;
  std::unique_ptr<HapticDevice> device = openDevice(spec, options, error);
  if (!device)
  {
    return false;
  }
  // A replay starts where its recording does, as the recorded session did; a live device takes
  // over the proxy where the last one left it.
  std::optional<Vec3> proxyStart;
  if (spec.rfind("replay:", 0) == 0)
  {
    proxyStart = device->read(0.0).position;
  }
  if (!restartWith(std::move(device), false, error, proxyStart))
  {
    return false;
  }
  m_deviceSpec = spec;
  const bool mouse = spec == "mouse";
  // The mouse's cursor must stay over the spot it aims at: the camera stays put for it.
  m_followAction->setChecked(!mouse);
  for (QAction* action : m_deviceGroup->actions())
  {
    action->setChecked(action->data().toString().toStdString() == spec);
  }
  m_recordAction->setChecked(false);
  return true;
}

bool HapticWindow::setProxyRadius(double radius, std::string& error)
{
  m_settings.radius = radius;
  m_haptics->SetProxyRadius(radius);
  m_representation->SetForceScale(30.0 * radius / m_settings.maxForce);
  m_mouse->SetDepthStep(0.5 * radius);
  m_mouse->SetPressSpeed(5.0 * radius);
  // The proxy where it was could hold a larger sphere inside the surface it touched.
  return restartWith(nullptr, false, error, m_settings.start);
}

bool HapticWindow::restartWith(std::unique_ptr<HapticDevice> device, bool record,
                               std::string& error, const std::optional<Vec3>& proxyStart)
{
  const HapticState last = m_haptics->GetState();
  const bool wasRunning = m_haptics->IsRunning();
  m_haptics->Stop();
  m_mouse->SetDevice(nullptr);
  m_recorder.reset();
  if (device)
  {
    m_device = std::move(device);
  }
  if (record)
  {
    m_recorder = std::make_unique<RecordingDevice>(
      *m_device, static_cast<std::size_t>(kRecordingSeconds * m_settings.servoRate));
  }
  auto* pointer = dynamic_cast<PointerDevice*>(m_device.get());
  m_mouse->SetDevice(pointer);
  m_haptics->SetDevice(m_recorder ? static_cast<HapticDevice*>(m_recorder.get()) : m_device.get());
  if (proxyStart)
  {
    m_haptics->SetProxyStart(proxyStart->x, proxyStart->y, proxyStart->z);
  }
  else if (wasRunning)
  {
    // The proxy goes on from where it was, not from the first start.
    m_haptics->SetProxyStart(last.proxy.x, last.proxy.y, last.proxy.z);
  }
  if (!m_haptics->Start())
  {
    error = "the haptic loops did not start: " + m_haptics->GetStartMessage();
    return false;
  }
  m_ticks.clear();
  m_ticksSeen = 0;
  m_forcePlot.add(0.0, 0.0);
  sessionRestarted();
  return true;
}

void HapticWindow::chooseDevice(QAction* action)
{
  const std::string spec = action->data().toString().toStdString();
  if (spec == m_deviceSpec)
  {
    return;
  }
  std::string error;
  if (!useDevice(spec, error))
  {
    showProblem(error);
    for (QAction* other : m_deviceGroup->actions())
    {
      other->setChecked(other->data().toString().toStdString() == m_deviceSpec);
    }
  }
}

void HapticWindow::chooseReplay()
{
  const QString file = QFileDialog::getOpenFileName(this, tr("Replay a recording"), QString(),
                                                    tr("Device recordings (*.csv);;All files (*)"));
  if (file.isEmpty())
  {
    return;
  }
  std::string error;
  if (!useDevice("replay:" + file.toStdString(), error))
  {
    showProblem(error);
  }
}

void HapticWindow::startRecording()
{
  std::string error;
  if (!restartWith(nullptr, true, error))
  {
    showProblem(error);
  }
  m_recordAction->setChecked(isRecording());
}

bool HapticWindow::isRecording() const
{
  return m_recorder != nullptr;
}

bool HapticWindow::saveRecording(const std::string& path, std::string& error)
{
  if (!m_recorder)
  {
    error = path + ": nothing is being recorded";
    return false;
  }
  // The servo thread appends to the samples: stopped while they are written, then restarted.
  m_haptics->Stop();
  if (!writeDeviceRecording(path, m_recorder->samples(), error))
  {
    m_haptics->Start();
    return false;
  }
  m_recordAction->setChecked(false);
  return restartWith(nullptr, false, error);
}

void HapticWindow::toggleRecording()
{
  if (!isRecording())
  {
    startRecording();
    return;
  }
  const QString file = QFileDialog::getSaveFileName(
    this, tr("Save the recording"), "proxima-session.csv", tr("Device recordings (*.csv)"));
  if (file.isEmpty())
  {
    m_recordAction->setChecked(true);
    return;
  }
  std::string error;
  if (!saveRecording(file.toStdString(), error))
  {
    m_recordAction->setChecked(true);
    showProblem(error);
  }
}

std::string HapticWindow::screenshotPng(const std::string& path)
{
  return windowPng(m_window, path);
}

bool HapticWindow::saveScreenshot(const std::string& path, std::string& error)
{
  try
  {
    writeFileAtomically(path, windowPng(m_window, path));
    return true;
  }
  catch (const std::exception& failure)
  {
    error = failure.what();
    return false;
  }
}

void HapticWindow::saveScreenshotAs()
{
  const QString file = QFileDialog::getSaveFileName(this, tr("Save a screenshot"),
                                                    "proxima-window.png", tr("PNG images (*.png)"));
  if (file.isEmpty())
  {
    return;
  }
  std::string error;
  if (!saveScreenshot(file.toStdString(), error))
  {
    showProblem(error);
  }
  else
  {
    statusBar()->showMessage(tr("Saved ") + file, 5000);
  }
}

void HapticWindow::frameScene()
{
  vtkCamera* camera = m_renderer->GetActiveCamera();
  // Looking down the scene's z, as proxima view does: the start is above the scene's top.
  camera->SetPosition(0.0, -1.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  m_renderer->ResetCamera();
  m_renderer->ResetCameraClippingRange();
}

void HapticWindow::moveCloser(double factor)
{
  m_renderer->GetActiveCamera()->Dolly(1.0 / factor);
  m_renderer->ResetCameraClippingRange();
}

void HapticWindow::showProblem(const std::string& what)
{
  statusBar()->showMessage(QString::fromStdString(what), 10000);
  // Tests run without anybody to close a dialog: they read the status bar.
  if (qEnvironmentVariableIsEmpty("PROXIMA_NO_DIALOGS"))
  {
    QMessageBox::warning(this, windowTitle(), QString::fromStdString(what));
  }
}

HapticState HapticWindow::latestState() const
{
  return m_haptics->GetState();
}

std::string HapticWindow::hudText() const
{
  return m_hudText;
}

vtkHapticMouseFinger* HapticWindow::mouseFinger()
{
  return m_mouse;
}

std::uint64_t HapticWindow::ticksDropped() const
{
  return m_haptics->GetDroppedStates();
}

vtkRenderer* HapticWindow::renderer()
{
  return m_renderer;
}

void HapticWindow::ticksArrived(const std::vector<HapticState>& /*ticks*/) {}

std::string HapticWindow::hudLines(const HapticState& /*state*/) const
{
  return {};
}

void HapticWindow::refresh()
{
  const auto now = std::chrono::steady_clock::now();
  if (m_deviceSpec == "mouse")
  {
    m_mouse->Update(std::chrono::duration<double>(now - m_lastFrame).count());
  }
  m_lastFrame = now;
  m_ticks.clear();
  m_haptics->DrainStates(m_ticks);
  m_ticksSeen += m_ticks.size();
  for (const HapticState& tick : m_ticks)
  {
    m_forcePlot.add(tick.time, norm(tick.force));
  }
  ticksArrived(m_ticks);
  for (DeformingSurfaceActor& tissue : m_tissueActors)
  {
    tissue.update();
  }
  const HapticState state = m_haptics->GetState();
  m_representation->SetState(state);
  m_forcePlot.update();
  std::string text = hapticStatusText(state, m_haptics->GetServoStatistics());
  if (m_deviceSpec == "mouse")
  {
    char line[200];
    std::snprintf(line, sizeof line,
                  "\nmouse: pressed %.2f mm   wheel or held space presses, Backspace lifts",
                  m_mouse->GetDepth() * 1000.0);
    text += line;
  }
  if (isRecording())
  {
    // The recorder keeps the ten minutes it reserved room for (the servo thread never allocates).
    text += m_recorder->samplesLeftOut() > 0 ? "\nRECORDING FULL: the first ten minutes are kept"
                                             : "\nRECORDING";
  }
  const std::string extra = hudLines(state);
  if (!extra.empty())
  {
    text += "\n" + extra;
  }
  m_hudText = text;
  m_hud->SetInput(m_hudText.c_str());
  if (m_followAction->isChecked() && state.tick > 0)
  {
    followProxy(m_renderer->GetActiveCamera(), state.proxy);
  }
  m_renderer->ResetCameraClippingRange();
  m_status->setText(QString::fromStdString(m_deviceSpec) +
                    (isRecording() ? tr("   recording") : QString()));
  m_window->Render();
}

} // namespace proxima::shell
