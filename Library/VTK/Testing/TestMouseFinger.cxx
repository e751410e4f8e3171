// vtkHapticMouseFinger with a real window (under the image tests' Xvfb), the real threads and a
// floor: mouse events sent through the interactor as a window would send them, checked against
// the geometry of a flat floor at z = 0 seen from straight above. The cursor at the window's
// centre hovers the proxy's sphere on the floor (z = r); wheel notches press the finger in by
// DepthStep each, and the force is then kp times the press (the proxy stays on the floor). A
// drag turns the camera without moving the finger, and the wheel does not zoom. Waits are bounded
// generously: these check what happens, not how fast.
#include "VtkTestSupport.h"

#include "Runtime/PointerDevice.h"
#include "Tissue/Testing/SoftBlock.h"
#include "Tissue/TissueDynamics.h"
#include "VTK/vtkHapticMouseFinger.h"
#include "VTK/vtkHapticRenderer.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>

namespace
{
using namespace proxima;
using proxima::vtk::testing::waitFor;

// A 10 cm square floor at z = 0, centred on the origin.
std::shared_ptr<const CollisionScene> floorScene()
{
  TriangleSoup soup;
  soup.points = {{-0.05, -0.05, 0.0}, {0.05, -0.05, 0.0}, {0.05, 0.05, 0.0}, {-0.05, 0.05, 0.0}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(soup, error));
  auto scene = std::make_shared<CollisionScene>();
  scene->addObject(std::move(mesh));
  return scene;
}

struct MouseRig
{
  static constexpr double kRadius = 0.002;
  static constexpr double kStiffness = 500.0;

  PointerDevice device{PointerDeviceSettings{{0.01, 0.01, 0.05}, 0.5}};
  vtkNew<vtkHapticRenderer> haptics;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  vtkNew<vtkHapticMouseFinger> mouse;

  explicit MouseRig(std::shared_ptr<const CollisionScene> scene = floorScene(),
                    std::shared_ptr<TickDynamics> dynamics = nullptr)
  {
    haptics->SetCollisionScene(std::move(scene), std::move(dynamics));
    haptics->SetDevice(&device);
    haptics->SetProxyStart(0.01, 0.01, 0.05);
    haptics->SetProxyRadius(kRadius);
    haptics->SetStiffness(kStiffness);
    haptics->SetServoRate(1000.0);
    window->SetSize(400, 400);
    window->SetOffScreenRendering(1);
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 0.3);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer->ResetCameraClippingRange(-0.05, 0.05, -0.05, 0.05, -0.01, 0.06);
    interactor->SetRenderWindow(window);
    interactor->SetInteractorStyle(style);
    window->Render();
    mouse->SetDevice(&device);
    mouse->SetHapticRenderer(haptics);
    mouse->SetRenderer(renderer);
    mouse->SetInteractor(interactor);
    mouse->SetDepthStep(0.5 * kRadius);
  }

  void send(unsigned long event, int x, int y)
  {
    interactor->SetEventInformation(x, y);
    interactor->InvokeEvent(event, nullptr);
  }
};

// The soft block (5 kPa, 4 x 4 x 2 cm of 5 mm cells, fixed along its base) with its top at z = 0,
// where the floor is, and its surface.
std::shared_ptr<TissueDynamics> softBlock(std::shared_ptr<const CollisionScene>& scene)
{
  constexpr int kCellsAcross = 8;
  scene = testing_support::softBlockScene(kCellsAcross);
  return testing_support::softBlockDynamics(kCellsAcross, MouseRig::kStiffness, 1000.0);
}

TEST(MouseFinger, TheCursorHoversTheFingerOverTheSurfaceUnderIt)
{
  MouseRig rig;
  ASSERT_TRUE(rig.haptics->Start()) << rig.haptics->GetStartMessage();
  rig.send(vtkCommand::MouseMoveEvent, 200, 200);
  EXPECT_TRUE(rig.mouse->IsHovering());
  // The window's centre looks straight down the z axis: the sphere first touches at z = r.
  const Vec3 aim = rig.device.aim();
  EXPECT_NEAR(aim.x, 0.0, 1e-9);
  EXPECT_NEAR(aim.y, 0.0, 1e-9);
  EXPECT_NEAR(aim.z, MouseRig::kRadius, 1e-9);
  // The finger gets there (at most 0.5 m/s) and the proxy with it, touching without pressing:
  // no force once both are there. (On a loaded machine the proxy loop lags the servo during the
  // descent, and just after the start the servo limits the force's rate of change
  // (ServoParameters::sceneChangeWindow), so that transient takes a few ticks to return to 0: the
  // wait covers them.)
  ASSERT_TRUE(waitFor([&] {
    const HapticState state = rig.haptics->GetState();
    return norm(state.finger - aim) < 1e-12 && norm(state.proxy - aim) < 1e-9 &&
           norm(state.force) < 1e-6;
  }))
    << "force " << norm(rig.haptics->GetState().force);
  const HapticState rest = rig.haptics->GetState();
  EXPECT_LT(norm(rest.force), 1e-6);
  EXPECT_NEAR(rest.proxy.z, MouseRig::kRadius, 1e-9);
  rig.haptics->Stop();
}

TEST(MouseFinger, WheelNotchesPressTheFingerInAndTheForceIsKpTimesThePress)
{
  MouseRig rig;
  ASSERT_TRUE(rig.haptics->Start()) << rig.haptics->GetStartMessage();
  rig.send(vtkCommand::MouseMoveEvent, 200, 200);
  ASSERT_TRUE(waitFor([&] { return rig.haptics->GetState().numContacts > 0; }));
  vtkCamera* camera = rig.renderer->GetActiveCamera();
  const double distanceBefore = camera->GetDistance();
  for (int notch = 0; notch < 4; ++notch)
  {
    rig.send(vtkCommand::MouseWheelForwardEvent, 200, 200);
  }
  // The style did not zoom on them: the mouse finger took them.
  EXPECT_EQ(camera->GetDistance(), distanceBefore);
  EXPECT_DOUBLE_EQ(rig.mouse->GetDepth(), 2.0 * MouseRig::kRadius);
  // Pressed 2r below the proxy on the floor: finger at z = -r, force kp * 2r straight up. The
  // state's force comes from the servo, which can publish a tick or more after the finger got
  // there on a loaded machine, so the wait is for both (a force that never arrives still fails).
  const double pressedForce = MouseRig::kStiffness * 2.0 * MouseRig::kRadius;
  ASSERT_TRUE(waitFor([&] {
    rig.mouse->Update(0.0);
    const HapticState state = rig.haptics->GetState();
    return std::abs(state.finger.z + MouseRig::kRadius) < 1e-9 &&
           std::abs(state.force.z - pressedForce) < 1e-6;
  }))
    << "finger z " << rig.haptics->GetState().finger.z << ", force z "
    << rig.haptics->GetState().force.z;
  const HapticState state = rig.haptics->GetState();
  EXPECT_NEAR(state.proxy.z, MouseRig::kRadius, 1e-9);
  EXPECT_NEAR(state.force.z, pressedForce, 1e-6);
  EXPECT_NEAR(state.force.x, 0.0, 1e-6);
  EXPECT_NEAR(state.force.y, 0.0, 1e-6);
  // A notch back and Backspace lift it.
  rig.send(vtkCommand::MouseWheelBackwardEvent, 200, 200);
  EXPECT_DOUBLE_EQ(rig.mouse->GetDepth(), 1.5 * MouseRig::kRadius);
  rig.interactor->SetKeySym("BackSpace");
  rig.interactor->InvokeEvent(vtkCommand::KeyPressEvent, nullptr);
  EXPECT_EQ(rig.mouse->GetDepth(), 0.0);
  rig.haptics->Stop();
}

TEST(MouseFinger, ADragTurnsTheCameraAndLeavesTheFinger)
{
  MouseRig rig;
  ASSERT_TRUE(rig.haptics->Start()) << rig.haptics->GetStartMessage();
  rig.send(vtkCommand::MouseMoveEvent, 200, 200);
  const Vec3 aim = rig.device.aim();
  double before[3];
  rig.renderer->GetActiveCamera()->GetPosition(before);
  rig.send(vtkCommand::LeftButtonPressEvent, 200, 200);
  rig.send(vtkCommand::MouseMoveEvent, 260, 230);
  rig.mouse->Update(0.1);
  EXPECT_EQ(rig.device.aim(), aim);
  rig.send(vtkCommand::LeftButtonReleaseEvent, 260, 230);
  double after[3];
  rig.renderer->GetActiveCamera()->GetPosition(after);
  EXPECT_GT(std::abs(after[0] - before[0]) + std::abs(after[1] - before[1]), 1e-3);
  // Free again, the next move aims: off the centre now, still on the floor's hover height.
  rig.send(vtkCommand::MouseMoveEvent, 250, 220);
  EXPECT_NE(rig.device.aim(), aim);
  rig.haptics->Stop();
}

// On tissue the wheel sets how deep the finger goes, as on a rigid surface: pressed 4 notches
// (4 mm) into the soft block, the finger stays 4 mm below the block's top as the scene gave it
// while the block gives way under it, the proxy sinking into the dent and the force staying below
// kp times the press. Measured from the sinking proxy, the press ran the finger deeper at every
// frame, a constant force of kp times 4 mm pushing the block centimetres down.
TEST(MouseFinger, OnTissueTheWheelSetsHowDeepTheFingerGoesNotTheForce)
{
  std::shared_ptr<const CollisionScene> scene;
  std::shared_ptr<TissueDynamics> tissue = softBlock(scene);
  MouseRig rig(scene, tissue);
  ASSERT_TRUE(rig.haptics->Start()) << rig.haptics->GetStartMessage();
  rig.send(vtkCommand::MouseMoveEvent, 200, 200);
  ASSERT_TRUE(waitFor([&] {
    rig.mouse->Update(0.0);
    return rig.haptics->GetState().numContacts > 0;
  }));
  for (int notch = 0; notch < 4; ++notch)
  {
    rig.send(vtkCommand::MouseWheelForwardEvent, 200, 200);
  }
  const double press = 2.0 * MouseRig::kRadius;
  ASSERT_DOUBLE_EQ(rig.mouse->GetDepth(), press);
  // A second of the block under the press (200 steps of its solid), aimed again at every poll as
  // the window's frames aim.
  const double pressedAt = rig.haptics->GetState().time;
  ASSERT_TRUE(waitFor([&] {
    rig.mouse->Update(0.0);
    return rig.haptics->GetState().time > pressedAt + 1.0;
  }));
  rig.mouse->Update(0.0);
  const HapticState state = rig.haptics->GetState();
  rig.haptics->Stop();
  // The finger where the press puts it below the top at rest (the cursor's hover point, z = r).
  EXPECT_NEAR(state.finger.z, MouseRig::kRadius - press, 1e-9);
  // The block gave way: the proxy sank below where it touched the top at rest, and the force is
  // below kp times the press, yet the block pushes back. (Unless the servo faded a stale proxy's
  // force on a starved machine. A sanitizer build steps the block in 7-19 ms, on the solid's own
  // thread: each step comes several ticks late, and the block still settles under the press.)
  EXPECT_LT(state.proxy.z, MouseRig::kRadius - 0.0005);
  EXPECT_LT(state.force.z, MouseRig::kStiffness * press);
  if (!state.conditions.has(TickCondition::forceFading))
  {
    EXPECT_GT(state.force.z, 0.0);
  }
}

} // namespace
