// vtkHapticRenderer with the real threads: the scene goes live, an edit of the poly data while
// the loops run is published and goes live as a new version without a stop, and the state the
// render thread reads shows the contact. Waits are bounded generously (these check what happens,
// not how fast; the latency is measured by SceneSwapLatency).
#include "VtkTestSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "VTK/vtkHapticRenderer.h"
#include "VTK/vtkHapticScene.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <sstream>
#include <thread>

namespace
{
using namespace proxima;
using proxima::vtk::testing::waitFor;

TEST(HapticRenderer, AnEditWhileRunningGoesLiveAsANewVersion)
{
  auto sphere = proxima::vtk::testing::polyDataOf(makeIcosphere(3, 0.01));
  vtkNew<vtkHapticScene> scene;
  scene->AddObjectData(sphere);
  scene->GenerateSurfaceOff();
  vtkNew<vtkHapticRenderer> renderer;
  renderer->SetScene(scene);
  renderer->SetServoRate(1000.0);
  // From above the sphere, press 3 mm into it and stay there.
  renderer->SetFingerPath(
    proxima::vtk::testing::linearPath({{0, 0, 0.02}, {0, 0, 0.007}, {0, 0, 0.007}}, 0.1));
  ASSERT_TRUE(renderer->Start()) << renderer->GetStartMessage();
  ASSERT_TRUE(waitFor([&] { return renderer->GetLiveSceneVersion() == 1; }));
  ASSERT_TRUE(waitFor([&] { return renderer->GetState().time > 0.25; }));
  HapticState state = renderer->GetState();
  EXPECT_EQ(state.numContacts, 1);
  EXPECT_NEAR(norm(state.proxy), 0.01 + 0.001, 1e-4);
  EXPECT_EQ(state.sceneVersion, 1u);

  // Shrink the sphere to 8 mm while the loops run: the proxy follows the new surface down.
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sphere->GetPoint(i, p);
    sphere->GetPoints()->SetPoint(i, 0.8 * p[0], 0.8 * p[1], 0.8 * p[2]);
  }
  sphere->GetPoints()->Modified();
  EXPECT_EQ(renderer->UpdateScene(), 2u);
  EXPECT_TRUE(renderer->IsRunning());
  ASSERT_TRUE(waitFor([&] { return renderer->GetLiveSceneVersion() == 2; }));
  ASSERT_TRUE(waitFor([&] {
    const HapticState s = renderer->GetState();
    return s.sceneVersion == 2 && norm(s.proxy) < 0.0095;
  }));
  state = renderer->GetState();
  EXPECT_NEAR(norm(state.proxy), 0.008 + 0.001, 1e-4);
  EXPECT_GT(renderer->GetServoStatistics().ticks, 0u);
  renderer->Stop();
  EXPECT_FALSE(renderer->IsRunning());
}

TEST(HapticRenderer, RefusesToStartWithoutADeviceOrAScene)
{
  vtkNew<vtkHapticRenderer> renderer;
  EXPECT_FALSE(renderer->Start());
  EXPECT_NE(renderer->GetStartMessage().find("no device"), std::string::npos);
  renderer->SetFingerPath(proxima::vtk::testing::linearPath({{0, 0, 0.02}}, 0.1));
  EXPECT_FALSE(renderer->Start());
  EXPECT_NE(renderer->GetStartMessage().find("no scene"), std::string::npos);
}

} // namespace

namespace
{
TEST(HapticRenderer, AServoRateOutsideTheRuleIsRefusedNotClamped)
{
  // Runtime/ServoRate.h: 1 to 10 kHz. A refused rate leaves the one before it, so the loops and
  // the proxy's time step never disagree.
  vtkNew<vtkHapticRenderer> renderer;
  renderer->GlobalWarningDisplayOff();
  for (const double rate : {500.0, 1.0, 0.0, 20000.0, std::nan("")})
  {
    EXPECT_FALSE(renderer->SetServoRate(rate)) << rate;
    EXPECT_EQ(renderer->GetServoRate(), 4000.0) << rate;
  }
  renderer->GlobalWarningDisplayOn();
  EXPECT_TRUE(renderer->SetServoRate(1000.0));
  EXPECT_EQ(renderer->GetServoRate(), 1000.0);
  EXPECT_TRUE(renderer->SetServoRate(10000.0));
  EXPECT_EQ(renderer->GetServoRate(), 10000.0);
}

TEST(HapticRenderer, PrintSelfStatesTheDocumentedDefaults)
{
  vtkNew<vtkHapticRenderer> renderer;
  std::ostringstream out;
  renderer->Print(out);
  for (const char* line :
       {"ServoRate: 4000", "ProxyRate: 0", "ProxyRadius: 0.001", "Stiffness: 1000", "MaxForce: 10",
        "MaxIterations: 256", "RealtimeScheduling: Off", "Skin: 0"})
  {
    EXPECT_NE(out.str().find(line), std::string::npos) << line << " in\n" << out.str();
  }
}
} // namespace

namespace
{
TEST(HapticRenderer, ARunThatFinishedStartsAgainOnTheSameScene)
{
  auto sphere = proxima::vtk::testing::polyDataOf(makeIcosphere(2, 0.01));
  vtkNew<vtkHapticScene> scene;
  scene->AddObjectData(sphere);
  vtkNew<vtkHapticRenderer> renderer;
  renderer->SetScene(scene);
  renderer->SetServoRate(1000.0);
  renderer->SetDuration(0.05);
  renderer->SetFingerPath(proxima::vtk::testing::linearPath({{0, 0, 0.02}, {0, 0, 0.007}}, 0.05));
  ASSERT_TRUE(renderer->Start()) << renderer->GetStartMessage();
  ASSERT_TRUE(waitFor([&] { return renderer->IsFinished(); }));
  renderer->Stop();
  ASSERT_TRUE(renderer->Start()) << renderer->GetStartMessage();
  ASSERT_TRUE(waitFor([&] { return renderer->GetLiveSceneVersion() == 1; }));
  ASSERT_TRUE(waitFor([&] { return renderer->IsFinished(); }));
  renderer->Stop();
}
} // namespace

namespace
{
TEST(HapticRenderer, FingerSamplesAndThePlainGettersAreThePathAndTheState)
{
  // The way in from VTK's Python: a finger sample at a time, and the state as plain numbers.
  auto sphere = proxima::vtk::testing::polyDataOf(makeIcosphere(3, 0.01));
  vtkNew<vtkHapticScene> scene;
  scene->AddObject(sphere.Get()); // the vtkPolyData overload
  vtkNew<vtkHapticRenderer> renderer;
  renderer->SetScene(scene);
  renderer->SetServoRate(1000.0);
  renderer->SetDuration(0.1);
  renderer->AddFingerSample(0.0, 0.0, 0.0, 0.02);
  renderer->AddFingerSample(0.05, 0.0, 0.0, 0.008);
  // A sample going back in time is refused (an error event), and the path stays as it was.
  int errors = 0;
  vtkNew<vtkCallbackCommand> countErrors;
  countErrors->SetClientData(&errors);
  countErrors->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  renderer->AddObserver(vtkCommand::ErrorEvent, countErrors);
  renderer->AddFingerSample(0.01, 0.0, 0.0, 0.0);
  renderer->RemoveObserver(countErrors);
  EXPECT_EQ(errors, 1);
  renderer->AddFingerSample(1.0, 0.0, 0.0, 0.008);
  ASSERT_TRUE(renderer->Start()) << renderer->GetStartMessage();
  ASSERT_TRUE(waitFor([&] { return renderer->IsFinished(); }));
  renderer->Stop();
  const HapticState state = renderer->GetState();
  double proxy[3];
  double finger[3];
  double force[3];
  renderer->GetProxyPosition(proxy);
  renderer->GetFingerPosition(finger);
  renderer->GetForce(force);
  EXPECT_EQ(proxy[2], state.proxy.z);
  EXPECT_EQ(finger[2], state.finger.z);
  EXPECT_EQ(force[2], state.force.z);
  EXPECT_EQ(renderer->GetNumberOfContacts(), state.numContacts);
  EXPECT_EQ(renderer->GetStateTick(), state.tick);
  // Held 2 mm inside the sphere's top (the refused sample never reached the path): in contact,
  // pushed back up.
  EXPECT_EQ(finger[2], 0.008);
  EXPECT_GE(state.numContacts, 1);
  EXPECT_GT(force[2], 0.0);
}
} // namespace
