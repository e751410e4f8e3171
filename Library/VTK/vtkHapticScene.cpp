#include "VTK/vtkHapticScene.h"

#include "VTK/PolyDataCollisionObject.h"
#include "VTK/Private/ParallelFor.h"
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
#include <exception>
#include <string>

vtkStandardNewMacro(vtkHapticScene);

vtkHapticScene::vtkHapticScene()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkHapticScene::~vtkHapticScene() = default;

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
  this->Entry(index);
  return index;
}

int vtkHapticScene::AddObjectData(vtkPolyData* polyData)
{
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(polyData);
  return this->AddObject(producer->GetOutputPort());
}

int vtkHapticScene::GetNumberOfObjects()
{
  return this->GetNumberOfInputConnections(0);
}

vtkHapticScene::ObjectEntry& vtkHapticScene::Entry(int object)
{
  const auto index = static_cast<std::size_t>(std::max(object, 0));
  if (index >= m_objects.size())
  {
    m_objects.resize(index + 1);
  }
  return m_objects[index];
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
  ObjectEntry& entry = this->Entry(object);
  if (entry.scale != scale)
  {
    entry.scale = scale;
    ++entry.settingsVersion;
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
  ObjectEntry& entry = this->Entry(object);
  if (entry.pose != pose)
  {
    entry.pose = pose;
    ++entry.settingsVersion;
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
  ObjectEntry& entry = this->Entry(object);
  entry.staticFriction = staticFriction;
  entry.dynamicFriction = dynamicFriction;
  entry.viscosity = viscosity;
  ++entry.settingsVersion;
  this->Modified();
}

void vtkHapticScene::SetObjectShading(int object, bool shading)
{
  ObjectEntry& entry = this->Entry(object);
  if (entry.shading != shading)
  {
    entry.shading = shading;
    ++entry.settingsVersion;
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

int vtkHapticScene::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                vtkInformationVector* outputVector)
{
  const auto start = std::chrono::steady_clock::now();
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const int numObjects = inputVector[0]->GetNumberOfInformationObjects();
  m_numRebuilt = 0;
  if (numObjects == 0)
  {
    vtkErrorMacro("A haptic scene needs at least one object (AddObject).");
    return 0;
  }

  // Build every changed object first; only when all are complete does a new snapshot replace
  // the old one, so a failure leaves the last good scene in place. The checks and conversion
  // touch VTK and run one object at a time; the trees, plain kernel code and most of the work,
  // are built in parallel (vtkSMPTools), one object per task.
  struct Staged
  {
    int index;
    vtkDataObject* input;
    vtkMTimeType poseTime;
    proxima::CollisionObject object;
  };
  std::vector<Staged> staged;
  for (int i = 0; i < numObjects; ++i)
  {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], i);
    ObjectEntry& entry = this->Entry(i);
    const vtkMTimeType poseTime = entry.pose ? entry.pose->GetMTime() : 0;
    const bool stale = !entry.built || entry.builtFrom != input ||
                       entry.builtFromTime != input->GetMTime() ||
                       entry.builtPoseTime != poseTime ||
                       entry.builtSettingsVersion != entry.settingsVersion ||
                       entry.builtLeafSizeFactor != this->LeafSizeFactor ||
                       entry.builtMaxLeafSpheres != this->MaxLeafSpheresPerNode;
    if (!stale)
    {
      continue;
    }
    proxima::vtk::PolyDataObjectSettings settings;
    settings.scale = entry.scale;
    settings.pose = entry.pose;
    settings.shading = entry.shading;
    settings.material.staticFriction = entry.staticFriction;
    settings.material.dynamicFriction = entry.dynamicFriction;
    settings.material.viscosity = entry.viscosity;
    try
    {
      staged.push_back(Staged{i, input, poseTime,
                              proxima::vtk::prepareCollisionObject(
                                input, "vtkHapticScene object " + std::to_string(i), settings)});
    }
    catch (const std::exception& error)
    {
      vtkErrorMacro("Cannot build object " << i << ": " << error.what()
                                           << " (the previous scene stays in use)");
      return 0;
    }
    this->UpdateProgress(0.2 * (i + 1) / numObjects);
    if (this->GetAbortExecute())
    {
      return 1;
    }
  }

  proxima::SphereTreeOptions treeOptions;
  treeOptions.leafSizeFactor = this->LeafSizeFactor;
  treeOptions.maxLeafSpheresPerNode = static_cast<std::uint32_t>(this->MaxLeafSpheresPerNode);
  std::vector<char> failed(staged.size(), 0);
  auto buildTree = [&](long k) {
    try
    {
      auto& object = staged[static_cast<std::size_t>(k)].object;
      object.tree.build(object.mesh, treeOptions);
    }
    catch (...)
    {
      failed[static_cast<std::size_t>(k)] = 1;
    }
  };
  if (this->ParallelTreeBuild && staged.size() > 1)
  {
    proxima::vtk::detail::parallelForEach(static_cast<long>(staged.size()), buildTree);
  }
  else
  {
    for (std::size_t k = 0; k < staged.size(); ++k)
    {
      buildTree(static_cast<long>(k));
    }
  }
  for (std::size_t k = 0; k < staged.size(); ++k)
  {
    if (failed[k])
    {
      vtkErrorMacro("Cannot build the sphere tree of object "
                    << staged[k].index << " (out of memory?); the previous scene stays in use");
      return 0;
    }
  }
  this->UpdateProgress(0.8);

  for (Staged& built : staged)
  {
    ObjectEntry& entry = this->Entry(built.index);
    entry.built = std::make_shared<const proxima::CollisionObject>(std::move(built.object));
    entry.builtFrom = built.input;
    entry.builtFromTime = built.input->GetMTime();
    entry.builtPoseTime = built.poseTime;
    entry.builtSettingsVersion = entry.settingsVersion;
    entry.builtLeafSizeFactor = this->LeafSizeFactor;
    entry.builtMaxLeafSpheres = this->MaxLeafSpheresPerNode;
    ++m_numRebuilt;
  }
  std::vector<std::shared_ptr<const proxima::CollisionObject>> objects;
  for (int i = 0; i < numObjects; ++i)
  {
    objects.push_back(this->Entry(i).built);
  }

  const bool sameObjects = m_scene && m_scene->objects.size() == objects.size();
  if (m_numRebuilt > 0 || !sameObjects)
  {
    // The new scene shares every unchanged object with the old one: a pointer each.
    auto scene = std::make_shared<proxima::CollisionScene>();
    scene->objects.reserve(objects.size());
    for (const auto& object : objects)
    {
      scene->addObject(object);
    }
    m_scene = std::move(scene);
    ++m_sceneVersion;
  }

  if (this->GenerateSurface)
  {
    proxima::vtk::scenePolyData(*m_scene, output);
  }
  m_lastBuildMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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
  os << indent << "SceneVersion: " << m_sceneVersion << "\n";
  for (std::size_t i = 0; i < m_objects.size(); ++i)
  {
    const ObjectEntry& entry = m_objects[i];
    os << indent << "Object " << i << ": scale " << entry.scale << ", pose "
       << (entry.pose ? "set" : "none") << ", shading " << (entry.shading ? "on" : "off")
       << ", friction " << entry.staticFriction << "/" << entry.dynamicFriction
       << ", viscosity " << entry.viscosity;
    if (entry.built)
    {
      os << ", " << entry.built->mesh.numTriangles() << " triangles";
    }
    os << "\n";
  }
}
