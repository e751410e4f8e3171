#include "DeformingSurfaceActor.h"

#include "SceneSurfaceActor.h"
#include "VTK/ScenePolyData.h"

#include <vtkDataArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace proxima::shell
{

DeformingSurfaceActor::DeformingSurfaceActor(const CollisionScene& scene, std::uint32_t object)
  : m_object(object)
{
  CollisionScene one; // shares the object's mesh, copies nothing
  one.addObject(scene.objects.shared(object));
  m_surface = proxima::vtk::scenePolyData(one);
  m_actor = makeSurfaceActor(m_surface);
}

bool DeformingSurfaceActor::movePoints(const std::vector<Vec3>& points)
{
  vtkPoints* drawn = m_surface->GetPoints();
  if (drawn == nullptr || static_cast<std::size_t>(drawn->GetNumberOfPoints()) != points.size())
  {
    return false;
  }
  vtkDataArray* coordinates = drawn->GetData();
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    coordinates->SetTuple3(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
  }
  drawn->Modified();
  m_surface->Modified();
  return true;
}

} // namespace proxima::shell
