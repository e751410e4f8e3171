// The applications' Qt main window (the surgical trainer's and the CAD inspector's): VTK's Qt widget showing a scene through the vtkHaptic* classes with the threaded runtime
// behind it, and around it what every haptic application needs:
//   - a Device menu: the mouse (the default: the cursor aims the finger, the wheel or a held
//     space bar presses, Backspace lifts), a SpaceMouse, a Falcon, or a recorded session replayed;
//     a device that cannot be opened is named in a message and the previous one stays;
//   - a Session menu: record the device's samples from now, and save them to a file that
//     `Device > Replay a recording` (or `proxima run --device replay:FILE`) plays back;
//   - a View menu: follow the proxy (on for a real device, off for the mouse, whose cursor must
//     stay over the spot it aims at), come closer or go farther, frame the whole scene;
//   - the HUD (force, contacts, touched object, servo rate and misses), a live force plot, and
//     screenshots (File > Save a screenshot, or the i key).
// Applications derive from it: ticksArrived() receives every servo tick's state (the runtime's
// state stream), hudLines() adds their own lines, and renderer() takes their actors.
#pragma once

#include "DeformingSurfaceActor.h"
#include "ForcePlot.h"
#include "Proxy/CollisionScene.h"
#include "Runtime/FingerPath.h"
#include "Runtime/HapticState.h"
#include "Tissue/TissueDynamics.h"

#include <QMainWindow>
#include <QTimer>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QAction;
class QActionGroup;
class QLabel;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkHapticMouseFinger;
class vtkHapticRenderer;
class vtkHapticStateRepresentation;
class vtkRenderer;
class vtkTextActor;

namespace proxima
{
class HapticDevice;
class RecordingDevice;
} // namespace proxima

namespace proxima::shell
{

struct HapticWindowSettings
{
  std::string title = "Proxima";
  std::shared_ptr<const CollisionScene> scene;
  /// The scene's tissues (Tissue/TissueDynamics.h), or null: the loops step them, and each frame
  /// draws their newest surfaces.
  std::shared_ptr<TissueDynamics> tissue;
  double radius = 0.002;
  double stiffness = 500.0;
  double maxForce = 10.0;
  double servoRate = 1000.0;
  /// The first device: mouse, spacemouse, falcon or replay:FILE (DeviceRegistry.h).
  std::string device = "mouse";
  std::string falconFirmware;
  /// Where a device's workspace centre goes and where the proxy starts; when not given, between
  /// the framed scene and the camera (ProxyCamera.h: startFacingCamera).
  Vec3 start;
  bool startGiven = false;
  int width = 1024;
  int height = 720;
};

class HapticWindow : public QMainWindow
{
  Q_OBJECT

public:
  /// Shows the scene framed, with the haptic loops running on the settings' device (the mouse
  /// when that cannot be opened: the message says why).
  explicit HapticWindow(const HapticWindowSettings& settings, QWidget* parent = nullptr);
  ~HapticWindow() override;

  /// Switches to the device `spec` names (the loops restart with the proxy where it was);
  /// false with `error` when it cannot be opened, and the current device stays.
  bool useDevice(const std::string& spec, std::string& error);
  /// The device in use, as useDevice names it.
  const std::string& deviceSpec() const { return m_deviceSpec; }

  /// Records the device's samples from now (the loops restart, so the recording starts at t = 0
  /// as a replay will).
  void startRecording();
  bool isRecording() const;
  /// Writes what was recorded to `path` (the Replay format) and goes on without recording; false
  /// with `error` if the file could not be written (the recording is kept to try again).
  bool saveRecording(const std::string& path, std::string& error);

  /// Gives the proxy a new radius (a probe's, a tool's): the loops restart with the proxy back at
  /// the start, between the camera and the scene, where a larger sphere has room. False with
  /// `error` if the loops did not start again.
  bool setProxyRadius(double radius, std::string& error);
  double proxyRadius() const { return m_settings.radius; }

  /// The window's picture, as PNG bytes written atomically to `path`; false with `error`.
  bool saveScreenshot(const std::string& path, std::string& error);
  /// The window's picture as PNG bytes (for a file written with others); throws OutputError
  /// naming `path` when there is none.
  std::string screenshotPng(const std::string& path);

  /// The newest state the loops published, the HUD's text and the mouse finger (tests drive it).
  HapticState latestState() const;
  std::string hudText() const;
  vtkHapticMouseFinger* mouseFinger();
  QVTKOpenGLNativeWidget* view() { return m_view; }
  /// Ticks streamed and dropped since the loops last started (a slow frame drops none within
  /// the stream's two seconds).
  std::uint64_t ticksSeen() const { return m_ticksSeen; }
  std::uint64_t ticksDropped() const;

  /// One frame now: drain the ticks, move the representation, the camera and the HUD, render.
  /// The window's timer calls it at about 60 Hz.
  void refresh();

protected:
  /// Every servo tick's state since the last frame, oldest first.
  virtual void ticksArrived(const std::vector<HapticState>& ticks);
  /// Lines the application adds under the HUD's own.
  virtual std::string hudLines(const HapticState& state) const;
  /// The loops restarted (a device change, a recording): the runtime's clock is at 0 again.
  virtual void sessionRestarted() {}
  vtkRenderer* renderer();
  const HapticWindowSettings& settings() const { return m_settings; }
  QMenu* sessionMenu() { return m_sessionMenu; }

private:
  void buildMenus();
  void chooseDevice(QAction* action);
  void chooseReplay();
  void toggleRecording();
  void saveScreenshotAs();
  void frameScene();
  void moveCloser(double factor);
  /// Stops the loops, puts `device` (the current one when null; under a recorder when `record`)
  /// behind them and restarts with the proxy at `proxyStart`, or where it last was.
  bool restartWith(std::unique_ptr<HapticDevice> device, bool record, std::string& error,
                   const std::optional<Vec3>& proxyStart = std::nullopt);
  void showProblem(const std::string& what);

  HapticWindowSettings m_settings;
  QVTKOpenGLNativeWidget* m_view = nullptr;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> m_window;
  vtkSmartPointer<vtkRenderer> m_renderer;
  vtkSmartPointer<vtkHapticRenderer> m_haptics;
  vtkSmartPointer<vtkHapticStateRepresentation> m_representation;
  vtkSmartPointer<vtkTextActor> m_hud;
  vtkSmartPointer<vtkHapticMouseFinger> m_mouse;
  ForcePlot m_forcePlot;
  std::unique_ptr<HapticDevice> m_device;
  std::unique_ptr<RecordingDevice> m_recorder;
  std::string m_deviceSpec;
  /// The tissues' surfaces, each frame brought to the newest step's.
  std::vector<DeformingSurfaceActor> m_tissueActors;
  QTimer m_timer;
  QLabel* m_status = nullptr;
  QMenu* m_sessionMenu = nullptr;
  QActionGroup* m_deviceGroup = nullptr;
  QAction* m_recordAction = nullptr;
  QAction* m_followAction = nullptr;
  std::vector<HapticState> m_ticks;
  std::uint64_t m_ticksSeen = 0;
  std::string m_hudText;
  std::chrono::steady_clock::time_point m_lastFrame;
};

} // namespace proxima::shell
