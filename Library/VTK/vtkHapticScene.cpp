#include "VTK/vtkHapticScene.h"

#include "VTK/PolyDataCollisionObject.h"
#include "VTK/ScenePolyData.h"

#include <vtkAlgorithmOutput.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkLinearTransform.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTrivialProducer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <string>
#include <system_error>
#include <utility>

vtkStandardNewMacro(vtkHapticScene);

using Clock = std::chrono::steady_clock;

// One execution's work for the tree builder: the changed objects (mesh and material made on the
// render thread, tree still empty) and the whole snapshot they belong to. The worker writes only
// the staged objects' trees, then `failed` or the published scene; the render thread reads the
// rest of it after joining.
struct vtkHapticScene::Build
{
  struct Staged
  {
    int index = 0;
    vtkDataObject* input = nullptr;
    vtkMTimeType inputTime = 0;
    vtkMTimeType poseTime = 0;
    std::uint64_t settingsVersion = 0;
    std::shared_ptr<proxima::CollisionObject> object;
  };
  std::vector<Staged> staged;
  /// Every object of the new snapshot, staged or shared with the last one.
  std::vector<std::shared_ptr<const proxima::CollisionObject>> objects;
  proxima::SphereTreeOptions treeOptions;
  double leafSizeFactor = 0.0;
  int maxLeafSpheres = 0;
  Clock::time_point start;
  std::atomic<bool> done{false};
  bool failed = false;
  int failedObject = -1;
};

vtkHapticScene::vtkHapticScene()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkHapticScene::~vtkHapticScene()
{
  // A build in flight finishes first: it writes into this object.
  if (m_worker.joinable())
  {
    m_worker.join();
  }
}

int vtkHapticScene::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkHapticScene::AddObject(vtkAlgorithmOutput* polyData)
{
  this->AddInputConnection(0, polyData);
  const int index = this->GetNumberOfInputConnections(0) - 1;
  if (m_objects.size() <= static_cast<std::size_t>(index))
  {
    m_objects.resize(static_cast<std::size_t>(index) + 1);
  }
  return index;
}

int vtkHapticScene::AddObjectData(vtkPolyData* polyData)
{
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(polyData);
  return this->AddObject(producer->GetOutputPort());
}

int vtkHapticScene::AddObject(vtkPolyData* polyData)
{
  return this->AddObjectData(polyData);
}

int vtkHapticScene::GetNumberOfObjects()
{
  return this->GetNumberOfInputConnections(0);
}

vtkHapticScene::ObjectEntry* vtkHapticScene::Entry(int object, const char* setter)
{
  const int numObjects = this->GetNumberOfInputConnections(0);
  if (object < 0 || object >= numObjects)
  {
    vtkErrorMacro(<< setter << "(" << object << ", ...): there is no object " << object
                  << " (the scene has " << numObjects << "); nothing changed");
    return nullptr;
  }
  if (m_objects.size() < static_cast<std::size_t>(numObjects))
  {
    m_objects.resize(static_cast<std::size_t>(numObjects));
  }
  return &m_objects[static_cast<std::size_t>(object)];
}

const vtkHapticScene::ObjectEntry* vtkHapticScene::FindEntry(int object) const
{
  return object >= 0 && static_cast<std::size_t>(object) < m_objects.size()
           ? &m_objects[static_cast<std::size_t>(object)]
           : nullptr;
}

void vtkHapticScene::SetObjectScale(int object, double scale)
{
  if (!(scale > 0.0) || !std::isfinite(scale))
  {
    vtkErrorMacro("Object " << object << ": the scale must be a finite number above 0, not "
                            << scale);
    return;
  }
  ObjectEntry* entry = this->Entry(object, "SetObjectScale");
  if (entry && entry->scale != scale)
  {
    entry->scale = scale;
    ++entry->settingsVersion;
    this->Modified();
  }
}

double vtkHapticScene::GetObjectScale(int object) const
{
  const ObjectEntry* entry = this->FindEntry(object);
  return entry ? entry->scale : 1.0;
}

void vtkHapticScene::SetObjectPose(int object, vtkLinearTransform* pose)
{
  ObjectEntry* entry = this->Entry(object, "SetObjectPose");
  if (entry && entry->pose != pose)
  {
    entry->pose = pose;
    ++entry->settingsVersion;
    this->Modified();
  }
}

vtkLinearTransform* vtkHapticScene::GetObjectPose(int object) const
{
  const ObjectEntry* entry = this->FindEntry(object);
  return entry ? entry->pose.Get() : nullptr;
}

void vtkHapticScene::SetObjectFriction(int object, double staticFriction, double dynamicFriction,
                                       double viscosity)
{
  if (!(staticFriction >= 0.0) || !(dynamicFriction >= 0.0) || !(viscosity >= 0.0) ||
      !std::isfinite(staticFriction + dynamicFriction + viscosity))
  {
    vtkErrorMacro("Object " << object << ": friction coefficients and viscosity must be finite "
                            << "and 0 or more");
    return;
  }
  ObjectEntry* entry = this->Entry(object, "SetObjectFriction");
  if (!entry)
  {
    return;
  }
  entry->staticFriction = staticFriction;
  entry->dynamicFriction = dynamicFriction;
  entry->viscosity = viscosity;
  ++entry->settingsVersion;
  this->Modified();
}

void vtkHapticScene::SetObjectShading(int object, bool shading)
{
  ObjectEntry* entry = this->Entry(object, "SetObjectShading");
  if (entry && entry->shading != shading)
  {
    entry->shading = shading;
    ++entry->settingsVersion;
    this->Modified();
  }
}

vtkMTimeType vtkHapticScene::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  for (const ObjectEntry& entry : m_objects)
  {
    if (entry.pose)
    {
      time = std::max(time, entry.pose->GetMTime());
    }
  }
  return time;
}

std::shared_ptr<const proxima::CollisionScene> vtkHapticScene::GetCollisionScene() const
{
  const std::lock_guard<std::mutex> lock(m_sceneMutex);
  return m_scene;
}

vtkTypeUInt64 vtkHapticScene::GetSceneVersion() const
{
  const std::lock_guard<std::mutex> lock(m_sceneMutex);
  return m_sceneVersion;
}

double vtkHapticScene::GetLastBuildMilliseconds() const
{
  const std::lock_guard<std::mutex> lock(m_sceneMutex);
  return m_lastBuildMilliseconds;
}

bool vtkHapticScene::IsBuilding() const
{
  return m_build && !m_build->done.load(std::memory_order_acquire);
}

bool vtkHapticScene::WaitForBuild()
{
  const bool built = this->FinishBuild();
  if (!built)
  {
    // The failed objects are still stale: the next Update must execute to build them again.
    this->Modified();
  }
  return built;
}

void vtkHapticScene::RunBuild(Build& build)
{
  try
  {
    for (Build::Staged& staged : build.staged)
    {
      build.failedObject = staged.index;
      staged.object->buildQueries(build.treeOptions);
    }
    build.failedObject = -1;
    // The new snapshot is a vector of pointers: unchanged objects are shared, not copied.
    auto scene = std::make_shared<proxima::CollisionScene>();
    scene->objects.reserve(build.objects.size());
    for (const auto& object : build.objects)
    {
      scene->addObject(object);
    }
    std::shared_ptr<const proxima::CollisionScene> replaced;
    {
      const std::lock_guard<std::mutex> lock(m_sceneMutex);
      replaced = std::exchange(m_scene, std::move(scene));
      ++m_sceneVersion;
      m_lastBuildMilliseconds =
        std::chrono::duration<double, std::milli>(Clock::now() - build.start).count();
    }
    // If that was the last hold on the old scene, its objects are freed here, outside the lock
    // the render thread reads the scene through.
  }
  catch (...)
  {
    // Out of memory: no new snapshot; the render thread reports it (VTK's error output is
    // not for this thread).
    build.failed = true;
  }
  build.done.store(true, std::memory_order_release);
}

bool vtkHapticScene::FinishBuild()
{
  if (m_worker.joinable())
  {
    m_worker.join();
  }
  if (!m_build)
  {
    return true;
  }
  const std::unique_ptr<Build> build = std::move(m_build);
  if (build->failed)
  {
    vtkErrorMacro("Cannot build the sphere tree of object "
                  << build->failedObject << " (out of memory?); the previous scene stays in use");
    return false;
  }
  for (const Build::Staged& staged : build->staged)
  {
    ObjectEntry& entry = m_objects[static_cast<std::size_t>(staged.index)];
    entry.built = staged.object;
    entry.builtFrom = staged.input;
    entry.builtFromTime = staged.inputTime;
    entry.builtPoseTime = staged.poseTime;
    entry.builtSettingsVersion = staged.settingsVersion;
    entry.builtLeafSizeFactor = build->leafSizeFactor;
    entry.builtMaxLeafSpheres = build->maxLeafSpheres;
  }
  return true;
}

int vtkHapticScene::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                vtkInformationVector* outputVector)
{
  const auto start = Clock::now();
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const int numObjects = inputVector[0]->GetNumberOfInformationObjects();
  m_numRebuilt = 0;
  // One build at a time. If the last one failed, its objects are still stale and are staged
  // again below.
  this->FinishBuild();
  if (numObjects == 0)
  {
    vtkErrorMacro("A haptic scene needs at least one object (AddObject).");
    return 0;
  }
  if (m_objects.size() < static_cast<std::size_t>(numObjects))
  {
    m_objects.resize(static_cast<std::size_t>(numObjects));
  }

  // Stage every changed object: the checks and conversion touch VTK and run here, one object at
  // a time; the trees, plain kernel code and most of the work, are built by RunBuild, here or on
  // the worker. Only when every tree is complete does a new snapshot replace the old one, so a
  // failure leaves the last good scene in place.
  auto build = std::make_unique<Build>();
  build->start = start;
  build->leafSizeFactor = this->LeafSizeFactor;
  build->maxLeafSpheres = this->MaxLeafSpheresPerNode;
  build->treeOptions.leafSizeFactor = this->LeafSizeFactor;
  build->treeOptions.maxLeafSpheresPerNode =
    static_cast<std::uint32_t>(this->MaxLeafSpheresPerNode);
  build->treeOptions.numBuildThreads = this->ParallelTreeBuild ? 0u : 1u;
  for (int i = 0; i < numObjects; ++i)
  {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], i);
    const ObjectEntry& entry = m_objects[static_cast<std::size_t>(i)];
    const vtkMTimeType poseTime = entry.pose ? entry.pose->GetMTime() : 0;
    const bool stale =
      !entry.built || entry.builtFrom != input || entry.builtFromTime != input->GetMTime() ||
      entry.builtPoseTime != poseTime || entry.builtSettingsVersion != entry.settingsVersion ||
      entry.builtLeafSizeFactor != this->LeafSizeFactor ||
      entry.builtMaxLeafSpheres != this->MaxLeafSpheresPerNode;
    if (!stale)
    {
      build->objects.push_back(entry.built);
      continue;
    }
    proxima::vtk::PolyDataObjectSettings settings;
    settings.scale = entry.scale;
    settings.pose = entry.pose;
    settings.shading = entry.shading;
    settings.material.staticFriction = entry.staticFriction;
    settings.material.dynamicFriction = entry.dynamicFriction;
    settings.material.viscosity = entry.viscosity;
    Build::Staged staged;
    staged.index = i;
    staged.input = input;
    staged.inputTime = input->GetMTime();
    staged.poseTime = poseTime;
    staged.settingsVersion = entry.settingsVersion;
    try
    {
      staged.object =
        std::make_shared<proxima::CollisionObject>(proxima::vtk::prepareCollisionObject(
          input, "vtkHapticScene object " + std::to_string(i), settings));
    }
    catch (const std::exception& error)
    {
      vtkErrorMacro("Cannot build object " << i << ": " << error.what()
                                           << " (the previous scene stays in use)");
      return 0;
    }
    build->objects.push_back(staged.object);
    build->staged.push_back(std::move(staged));
    this->UpdateProgress(0.2 * (i + 1) / numObjects);
    if (this->GetAbortExecute())
    {
      return 1;
    }
  }
  m_numRebuilt = static_cast<int>(build->staged.size());

  const std::shared_ptr<const proxima::CollisionScene> last = this->GetCollisionScene();
  const bool sameObjects = last && last->objects.size() == build->objects.size();
  if (build->staged.empty() && sameObjects)
  {
    if (this->GenerateSurface)
    {
      proxima::vtk::scenePolyData(*last, output);
    }
    this->UpdateProgress(1.0);
    return 1;
  }

  if (this->BackgroundBuild && !build->staged.empty())
  {
    if (this->GenerateSurface)
    {
      // From the new meshes, before the worker starts (it writes only the trees).
      proxima::CollisionScene upcoming;
      for (const auto& object : build->objects)
      {
        upcoming.addObject(object);
      }
      proxima::vtk::scenePolyData(upcoming, output);
    }
    m_build = std::move(build);
    try
    {
      m_worker = std::thread([this, job = m_build.get()] { this->RunBuild(*job); });
    }
    catch (const std::system_error&)
    {
      // No thread to be had: build here instead.
      this->RunBuild(*m_build);
    }
    this->UpdateProgress(1.0);
    return 1;
  }

  m_build = std::move(build);
  this->RunBuild(*m_build);
  if (!this->FinishBuild())
  {
    return 0;
  }
  this->UpdateProgress(0.8);
  if (this->GenerateSurface)
  {
    proxima::vtk::scenePolyData(*this->GetCollisionScene(), output);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkHapticScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LeafSizeFactor: " << this->LeafSizeFactor << "\n";
  os << indent << "MaxLeafSpheresPerNode: " << this->MaxLeafSpheresPerNode << "\n";
  os << indent << "GenerateSurface: " << (this->GenerateSurface ? "On" : "Off") << "\n";
  os << indent << "ParallelTreeBuild: " << (this->ParallelTreeBuild ? "On" : "Off") << "\n";
  os << indent << "BackgroundBuild: " << (this->BackgroundBuild ? "On" : "Off")
     << (this->IsBuilding() ? " (building)" : "") << "\n";
  os << indent << "SceneVersion: " << this->GetSceneVersion() << "\n";
  for (std::size_t i = 0; i < m_objects.size(); ++i)
  {
    const ObjectEntry& entry = m_objects[i];
    os << indent << "Object " << i << ": scale " << entry.scale << ", pose "
       << (entry.pose ? "set" : "none") << ", shading " << (entry.shading ? "on" : "off")
       << ", friction " << entry.staticFriction << "/" << entry.dynamicFriction << ", viscosity "
       << entry.viscosity;
    if (entry.built)
    {
      os << ", " << entry.built->mesh.numTriangles() << " triangles";
    }
    os << "\n";
  }
}
