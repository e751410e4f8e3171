// The kernel alone (find_package(Proxima COMPONENTS Kernel), or pkg-config proxima-kernel): no
// VTK, no file formats, no third-party package. A procedural floor, a finger pressed 2 mm into it
// tick by tick, and the force it feels: kp (proxy - finger) = 1000 N/m x 3 mm up.
#include "Geometry/ProceduralMeshes.h"
#include "Runtime/HapticSession.h"

#include <cmath>
#include <cstdio>
#include <memory>

int main()
{
  proxima::TriangleMesh floor;
  proxima::MeshError error;
  if (!floor.build(proxima::makeGrid(0.1, 10), error))
  {
    std::fprintf(stderr, "%s\n", error.message.c_str());
    return 1;
  }
  auto scene = std::make_shared<proxima::CollisionScene>();
  scene->addObject(std::move(floor));
  proxima::HapticSessionSettings settings;
  settings.proxy.radius = 0.001;
  proxima::HapticSession session(scene, settings);
  proxima::HapticState state;
  for (int tick = 0; tick <= 100; ++tick)
  {
    state = session.step({0.0, 0.0, 0.003 - 0.005 * tick / 100.0}); // 3 mm above to 2 mm below
  }
  std::printf("proxy z %.6f m, force %.4f N\n", state.proxy.z, state.force.z);
  return std::fabs(state.force.z - 3.0) < 1e-6 ? 0 : 1;
}
