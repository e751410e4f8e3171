// Measures the time from a vtkPolyData modification to the new sphere tree being live in the
// haptic thread, through vtkHapticScene and vtkHapticRenderer with the loops running at 4 kHz:
//   scene-swap-latency MESH [SCALE] [REPEATS] [COPIES] [serial|parallel|background] [EDITED]
// COPIES (default 1) objects of the mesh stand side by side. Each repeat moves every point of
// the first EDITED copies (default all) by 0.1 mm, calls Modified(), then UpdateScene (the
// render thread's part of the rebuild) and waits for the proxy loop to report the new version
// live. serial builds each tree on one thread, parallel (the default) on every core, both on
// this thread; background builds on every core on the scene's worker thread, and this thread
// calls UpdateScene every 0.1 ms, as a render loop would each frame, until the new scene is
// published. Prints one JSON object with each repeat's times in milliseconds and the process's
// resident memory after it (and its peak). A measurement program, not a test: run it by hand
// (Documentation/VtkPipeline.md has the numbers).
#include "VtkTestSupport.h"

#include "IO/Mesh/MeshReader.h"
#include "VTK/vtkHapticRenderer.h"
#include "VTK/vtkHapticScene.h"
#include "VTK/vtkHapticSphereTreeFilter.h"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>

#include <algorithm>
#include <vector>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

namespace
{
// A field of /proc/self/status (VmRSS, VmHWM) in MiB, or -1 where there is none.
double statusMiB(const std::string& field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind(field + ":", 0) == 0)
    {
      return std::atof(line.c_str() + field.size() + 1) / 1024.0;
    }
  }
  return -1.0;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: scene-swap-latency MESH [SCALE] [REPEATS] [COPIES]\n";
    return 2;
  }
  using Clock = std::chrono::steady_clock;
  const double scale = argc > 2 ? std::atof(argv[2]) : 1.0;
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 3;
  const int copies = argc > 4 ? std::max(1, std::atoi(argv[4])) : 1;
  const int edited = argc > 6 ? std::clamp(std::atoi(argv[6]), 1, copies) : copies;
  const proxima::TriangleSoup soup = proxima::readMeshFile(argv[1], scale);
  auto data = proxima::vtk::testing::polyDataOf(soup);

  // The share of the sphere tree in a rebuild, measured once through the filter.
  vtkNew<vtkHapticSphereTreeFilter> filter;
  filter->SetInputData(data);
  filter->SetLevel(0);
  filter->SetParallelTreeBuild(argc <= 5 || std::string(argv[5]) != "serial");
  const auto filterStart = Clock::now();
  filter->Update();
  const double filterMs =
    std::chrono::duration<double, std::milli>(Clock::now() - filterStart).count();
  const double treeMs = filter->GetTreeBuildMilliseconds();

  vtkNew<vtkHapticScene> scene;
  std::vector<vtkSmartPointer<vtkPolyData>> objects{data};
  scene->AddObjectData(data);
  double size[6];
  data->GetBounds(size);
  for (int c = 1; c < copies; ++c)
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->DeepCopy(data);
    vtkNew<vtkTransform> beside;
    beside->Translate(1.5 * c * (size[1] - size[0]), 0.0, 0.0);
    scene->SetObjectPose(scene->AddObjectData(copy), beside);
    objects.push_back(copy);
  }
  scene->GenerateSurfaceOff();
  const std::string mode = argc > 5 ? argv[5] : "parallel";
  scene->SetParallelTreeBuild(mode != "serial");
  scene->SetBackgroundBuild(mode == "background");
  vtkNew<vtkHapticRenderer> renderer;
  renderer->SetScene(scene);
  renderer->SetServoRate(4000.0);
  double bounds[6];
  data->GetBounds(bounds);
  // The finger rests above the mesh, in free space.
  proxima::FingerPath path;
  path.append(0.0,
              {0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), bounds[5] + 0.01});
  renderer->SetFingerPath(path);
  const auto firstStart = Clock::now();
  if (mode == "background")
  {
    // Start needs a scene: the first one is built before the loops start.
    scene->Update();
    scene->WaitForBuild();
  }
  if (!renderer->Start())
  {
    std::cerr << "cannot start: " << renderer->GetStartMessage() << "\n";
    return 1;
  }
  while (renderer->GetLiveSceneVersion() < 1)
  {
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  const double firstMs =
    std::chrono::duration<double, std::milli>(Clock::now() - firstStart).count();

  // What one object of the scene holds (mesh and tree): what a copy of it would cost.
  const proxima::CollisionObject& firstObject = scene->GetCollisionScene()->objects[0];
  const double objectMiB =
    static_cast<double>(firstObject.mesh.memoryBytes() + firstObject.tree.memoryBytes()) /
    (1024.0 * 1024.0);

  std::cout << "{\n  \"mesh\": \"" << argv[1] << "\",\n  \"triangles\": " << soup.triangles.size()
            << ",\n  \"mode\": \"" << mode << "\",\n  \"copies\": " << copies
            << ",\n  \"edited\": " << edited << ",\n  \"filter_total_ms\": " << filterMs
            << ",\n  \"filter_tree_build_ms\": " << treeMs
            << ",\n  \"start_to_first_live_ms\": " << firstMs
            << ",\n  \"object_mib\": " << objectMiB << ",\n  \"repeats\": [\n";
  for (int r = 0; r < repeats; ++r)
  {
    const auto start = Clock::now();
    for (int e = 0; e < edited; ++e)
    {
      vtkPolyData* object = objects[static_cast<std::size_t>(e)];
      vtkPoints* points = object->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3];
        points->GetPoint(i, p);
        points->SetPoint(i, p[0], p[1], p[2] + 0.0001);
      }
      points->Modified();
    }
    const auto modified = Clock::now();
    const std::uint64_t lastPublished = renderer->GetLiveSceneVersion();
    std::uint64_t version = renderer->UpdateScene();
    const auto renderThreadFree = Clock::now();
    while (version <= lastPublished)
    {
      std::this_thread::sleep_for(std::chrono::microseconds(100));
      version = renderer->UpdateScene();
    }
    const auto published = Clock::now();
    while (renderer->GetLiveSceneVersion() < version)
    {
      std::this_thread::sleep_for(std::chrono::microseconds(20));
    }
    const auto live = Clock::now();
    auto ms = [](Clock::time_point a, Clock::time_point b) {
      return std::chrono::duration<double, std::milli>(b - a).count();
    };
    std::cout << "    {\"edit_ms\": " << ms(start, modified)
              << ", \"render_thread_busy_ms\": " << ms(modified, renderThreadFree)
              << ", \"modified_to_published_ms\": " << ms(modified, published)
              << ", \"scene_build_ms\": " << scene->GetLastBuildMilliseconds()
              << ", \"published_to_live_ms\": " << ms(published, live)
              << ", \"modified_to_live_ms\": " << ms(modified, live)
              << ", \"rss_mib\": " << statusMiB("VmRSS")
              << ", \"peak_rss_mib\": " << statusMiB("VmHWM") << "}" << (r + 1 < repeats ? "," : "")
              << "\n";
  }
  const proxima::LoopStatistics servo = renderer->GetServoStatistics();
  std::cout << "  ],\n  \"servo_ticks\": " << servo.ticks
            << ",\n  \"servo_missed_deadlines\": " << servo.missedDeadlines
            << ",\n  \"servo_p99_jitter_us\": " << servo.jitterQuantileNanoseconds(0.99) / 1000.0
            << "\n}\n";
  renderer->Stop();
  return 0;
}
