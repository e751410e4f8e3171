#include "SceneSurfaceActor.h"

#include "VTK/ScenePolyData.h"

#include <vtkAlgorithmOutput.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>

#include <algorithm>

namespace proxima::shell
{

namespace
{
// The surface's look: sharp edges kept, smooth bends smooth, one warm tissue colour.
vtkSmartPointer<vtkActor> surfaceActorOf(vtkPolyDataNormals* normals)
{
  normals->SetFeatureAngle(60.0);
  normals->SplittingOn();
  normals->ConsistencyOn();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.8, 0.72);
  actor->GetProperty()->SetSpecular(0.2);
  return actor;
}
} // namespace

vtkSmartPointer<vtkActor> makeSceneSurfaceActor(const CollisionScene& scene)
{
  return makeSurfaceActor(proxima::vtk::scenePolyData(scene));
}

vtkSmartPointer<vtkActor> makeSurfaceActor(vtkPolyData* surface)
{
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(surface);
  return surfaceActorOf(normals);
}

vtkSmartPointer<vtkActor> makeSurfaceActor(vtkAlgorithmOutput* surface)
{
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputConnection(surface);
  return surfaceActorOf(normals);
}

vtkSmartPointer<vtkActor> makeSceneSurfaceActor(const CollisionScene& scene,
                                                const std::vector<std::uint32_t>& objects)
{
  if (objects.empty())
  {
    return nullptr;
  }
  CollisionScene some; // shares the objects' meshes, copies nothing
  for (const std::uint32_t object : objects)
  {
    some.addObject(scene.objects.shared(object));
  }
  return makeSceneSurfaceActor(some);
}

std::vector<std::uint32_t> stillObjects(const CollisionScene& scene,
                                        const std::vector<std::uint32_t>& notStill)
{
  std::vector<std::uint32_t> still;
  for (std::uint32_t object = 0; object < scene.objects.size(); ++object)
  {
    if (std::find(notStill.begin(), notStill.end(), object) == notStill.end())
    {
      still.push_back(object);
    }
  }
  return still;
}

} // namespace proxima::shell
