// The VTK pipeline in a few lines: a sphere from vtkSphereSource as a haptic scene object, and a
// vtkHapticRenderer that runs the proxy and servo loops on their own threads while a scripted
// finger presses into the sphere; the main thread reads the published state, as a render loop
// would each frame, and prints the proxy and the force.
#include "Runtime/FingerPath.h"
#include "VTK/vtkHapticRenderer.h"
#include "VTK/vtkHapticScene.h"

#include <vtkNew.h>
#include <vtkSphereSource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.05); // metres
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  vtkNew<vtkHapticScene> scene;
  scene->AddObject(sphere->GetOutputPort());
  scene->Update();

  // Down onto the top of the sphere, 3 mm into it, in 0.2 s, then held.
  proxima::FingerPath finger;
  finger.append(0.0, {0.0, 0.0, 0.06});
  finger.append(0.2, {0.0, 0.0, 0.047});
  finger.append(10.0, {0.0, 0.0, 0.047});

  vtkNew<vtkHapticRenderer> haptics;
  haptics->SetScene(scene);
  haptics->SetFingerPath(finger);
  haptics->SetProxyRadius(0.001);
  haptics->SetStiffness(1000.0);
  if (!haptics->Start())
  {
    std::fprintf(stderr, "the haptic loops did not start\n");
    return 1;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  const proxima::HapticState state = haptics->GetState();
  haptics->Stop();
  std::printf("proxy %.4f %.4f %.4f m, force %.3f %.3f %.3f N, %d contact(s)\n", state.proxy.x,
              state.proxy.y, state.proxy.z, state.force.x, state.force.y, state.force.z,
              state.numContacts);
  // On the sphere (a 64 x 64 facet approximation of it) and pushed back up by about 4 N.
  const bool onSurface = std::fabs(state.proxy.z - 0.051) < 0.001;
  const bool pushedUp = state.force.z > 3.0 && state.force.z < 5.0;
  return onSurface && pushedUp && state.numContacts > 0 ? 0 : 1;
}
