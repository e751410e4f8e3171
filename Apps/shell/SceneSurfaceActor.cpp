#include "SceneSurfaceActor.h"

#include "VTK/ScenePolyData.h"

#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>

namespace proxima::shell
{

vtkSmartPointer<vtkActor> makeSceneSurfaceActor(const CollisionScene& scene)
{
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(proxima::vtk::scenePolyData(scene));
  normals->SetFeatureAngle(60.0);
  normals->SplittingOn();
  normals->ConsistencyOn();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto surface = vtkSmartPointer<vtkActor>::New();
  surface->SetMapper(mapper);
  surface->GetProperty()->SetColor(0.85, 0.8, 0.72);
  surface->GetProperty()->SetSpecular(0.2);
  return surface;
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

} // namespace proxima::shell
