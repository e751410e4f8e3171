// Load a mesh, play a finger path over it in lockstep and print, per tick, the proxy and the force
// a device would render: the kernel (HapticSession) and the IO layer's readers, nothing else.
//   probe_mesh MESH SCALE RADIUS PATH.csv
// MESH in any format `proxima run` reads, SCALE its units in metres, RADIUS the proxy's in metres,
// PATH a finger path (t,x,y,z). Writes CSV to standard output (tick,t,proxy xyz,force xyz, with
// every digit) and the largest force to standard error. The same numbers as `proxima run`'s trace.
#include "IO/Mesh/MeshReader.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "Runtime/HapticSession.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>

int main(int argc, char** argv)
{
  if (argc != 5)
  {
    std::fprintf(stderr, "usage: %s MESH SCALE RADIUS PATH.csv\n", argv[0]);
    return 2;
  }
  try
  {
    auto scene = std::make_shared<proxima::CollisionScene>();
    scene->addObject(proxima::loadTriangleMesh(argv[1], std::strtod(argv[2], nullptr)));
    proxima::HapticSessionSettings settings;
    settings.proxy.radius = std::strtod(argv[3], nullptr);
    proxima::HapticSession session(scene, settings);
    const proxima::FingerPath path = proxima::readFingerPathFile(argv[4]);

    double largest = 0.0;
    std::printf("tick,t,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z\n");
    for (const proxima::HapticState& state : session.run(path))
    {
      std::printf("%llu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  static_cast<unsigned long long>(state.tick), state.time, state.proxy.x,
                  state.proxy.y, state.proxy.z, state.force.x, state.force.y, state.force.z);
      largest = std::fmax(largest, std::sqrt(dot(state.force, state.force)));
    }
    std::fprintf(stderr, "%zu ticks, largest force %.3f N\n", path.size(), largest);
    return 0;
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "%s\n", error.what());
    return 2;
  }
}
