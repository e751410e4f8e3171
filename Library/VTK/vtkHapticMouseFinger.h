// The mouse as a haptic finger: a person without a device moves the cursor over the scene and
// the finger follows it (PointerDevice, speed-limited), on the plane through the proxy that faces
// the camera (PointerAimPlane). The wheel and the space bar press it in:
//   - the wheel steps the depth behind that plane (forward presses in, back pulls out);
//   - the space bar, held, presses in at PressSpeed; Backspace lifts the finger to depth 0.
// The finger follows the cursor only while no mouse button is held: a drag moves the camera, as
// the interactor style says, and leaves the finger where it was. The wheel is taken from the
// style (it no longer zooms: the right button still does).
//
// Over a surface and not pressed in, the finger hovers where the proxy would first touch the
// surface under the cursor (a sweep of the proxy's sphere along the cursor's ray through the
// scene's sphere trees), so a press goes into what the cursor points at.
//
// Use: SetDevice, SetHapticRenderer, SetRenderer, SetInteractor; then call Update(seconds) at each
// frame (the window's timer), which re-aims for the camera and proxy of the moment.
#pragma once

#include "Runtime/PointerAimPlane.h"
#include "VTK/vtkHapticRenderer.h"

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <memory>

class vtkCallbackCommand;
class vtkInteractorObserver;
class vtkRenderer;
class vtkRenderWindowInteractor;

namespace proxima
{
class PointerDevice;
struct SphereTreeScratch;
}

/// The mouse as a haptic finger, for a person without a device: aims a PointerDevice at the
/// cursor on the plane through the proxy that faces the camera, at a depth behind it that the
/// wheel steps, a held space bar increases and Backspace sets to 0. Use it on the thread that
/// renders.
class vtkHapticMouseFinger : public vtkObject
{
public:
  /// A new mouse finger, with no device, renderers or interactor yet.
  static vtkHapticMouseFinger* New();
  /// Prints the properties and the depth.
  vtkTypeMacro(vtkHapticMouseFinger, vtkObject) void PrintSelf(ostream& os,
                                                               vtkIndent indent) override;

  /// The device to aim (not owned; it must outlive this object's use).
  void SetDevice(proxima::PointerDevice* device) { m_device = device; }
  /// The renderer whose state gives the proxy, and whose scene the hover sweeps.
  void SetHapticRenderer(vtkHapticRenderer* haptics);
  /// The renderer whose camera maps the cursor into the world.
  void SetRenderer(vtkRenderer* renderer);
  /// The interactor whose mouse and keys move the finger (observed until set to another).
  void SetInteractor(vtkRenderWindowInteractor* interactor);

  ///@{
  /// Depth per wheel notch in metres (default 0.5 mm); proxima view sets it to half the proxy
  /// radius.
  vtkSetClampMacro(DepthStep, double, 0.0, VTK_DOUBLE_MAX);
  /// Depth per wheel notch (m).
  vtkGetMacro(DepthStep, double);
  /// Speed at which a held space bar presses the finger in, in m/s (default 5 mm/s); proxima
  /// view sets it to five proxy radii per second.
  vtkSetClampMacro(PressSpeed, double, 0.0, VTK_DOUBLE_MAX);
  /// Speed at which a held space bar presses the finger in (m/s).
  vtkGetMacro(PressSpeed, double);
  ///@}

  /// How far the finger is pressed behind the plane, in metres.
  double GetDepth() const { return m_aimPlane.depth(); }
  /// Sets the depth in metres (negative or not finite is taken as 0); the finger moves at the
  /// next aim.
  void SetDepth(double depth) { m_aimPlane.setDepth(depth); }
  /// Steps the depth by `notches` wheel notches (negative pulls out).
  void StepDepth(int notches);

  /// Aims the finger at the cursor's display position (pixels from the bottom left): what a
  /// mouse move does. Kept as the cursor for the next Update.
  void AimAtDisplayPoint(int x, int y);
  /// Re-aims from the last cursor position for the camera and proxy now, after pressing in for
  /// `seconds` if the space bar is held. Call once a frame.
  void Update(double seconds);

  /// Whether the cursor is over a surface (the last aim found a hover point).
  bool IsHovering() const { return m_hovering; }

protected:
  vtkHapticMouseFinger();
  ~vtkHapticMouseFinger() override;

  double DepthStep = 0.0005; ///< Depth per wheel notch (m): SetDepthStep.
  double PressSpeed = 0.005; ///< Speed of a held space bar's press (m/s): SetPressSpeed.

private:
  vtkHapticMouseFinger(const vtkHapticMouseFinger&) = delete;
  void operator=(const vtkHapticMouseFinger&) = delete;

  static void OnEvent(vtkObject* caller, unsigned long event, void* clientData, void* callData);
  void Aim();

  proxima::PointerDevice* m_device = nullptr;
  vtkSmartPointer<vtkHapticRenderer> m_haptics;
  vtkSmartPointer<vtkRenderer> m_renderer;
  vtkSmartPointer<vtkRenderWindowInteractor> m_interactor;
  vtkSmartPointer<vtkInteractorObserver> m_style;
  vtkSmartPointer<vtkCallbackCommand> m_callback;
  proxima::PointerAimPlane m_aimPlane;
  std::unique_ptr<proxima::SphereTreeScratch> m_scratch;
  int m_cursor[2] = {0, 0};
  bool m_hasCursor = false;
  bool m_buttonHeld = false;
  bool m_pressing = false;
  bool m_hovering = false;
};
