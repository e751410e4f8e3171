#include "VTK/ScenePolyData.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace proxima::vtk
{

void scenePolyData(const CollisionScene& scene, vtkPolyData* output)
{
  vtkIdType numPoints = 0;
  vtkIdType numTriangles = 0;
  for (const proxima::CollisionObject& object : scene.objects)
  {
    numPoints += object.mesh.numPoints();
    numTriangles += object.mesh.numTriangles();
  }
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(numPoints);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * numTriangles);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numTriangles + 1);
  vtkNew<vtkIntArray> objectIds;
  objectIds->SetName("ObjectId");
  objectIds->SetNumberOfValues(numTriangles);
  vtkIdType point = 0;
  vtkIdType triangle = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
  {
    const proxima::TriangleMesh& mesh = scene.objects[i].mesh;
    const vtkIdType firstPoint = point;
    for (const proxima::Vec3& p : mesh.points())
    {
      coordinates->SetTuple3(point++, p.x, p.y, p.z);
    }
    for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
    {
      const auto& corners = mesh.indices(t);
      for (int k = 0; k < 3; ++k)
      {
        connectivity->SetValue(3 * triangle + k, firstPoint + corners[k]);
      }
      offsets->SetValue(triangle, 3 * triangle);
      objectIds->SetValue(triangle, static_cast<int>(i));
      ++triangle;
    }
  }
  offsets->SetValue(numTriangles, 3 * numTriangles);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(objectIds);
}

vtkSmartPointer<vtkPolyData> scenePolyData(const CollisionScene& scene)
{
  auto output = vtkSmartPointer<vtkPolyData>::New();
  scenePolyData(scene, output);
  return output;
}

} // namespace proxima::vtk
