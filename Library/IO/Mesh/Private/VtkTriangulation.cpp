#include "IO/Mesh/Private/VtkTriangulation.h"

#include "IO/Mesh/PolyDataToSoup.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace proxima::detail
{

TriangleSoup triangulatePolygonsWithVtk(const PolygonSoup& polygons, const std::string& path,
                                        double scale)
{
  const auto numPoints = static_cast<vtkIdType>(polygons.numPoints());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    points->SetPoint(i, &polygons.points[static_cast<std::size_t>(3 * i)]);
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (std::size_t f = 0; f + 1 < polygons.faceStarts.size(); ++f)
  {
    ids.assign(polygons.corners.begin() + static_cast<std::ptrdiff_t>(polygons.faceStarts[f]),
               polygons.corners.begin() + static_cast<std::ptrdiff_t>(polygons.faceStarts[f + 1]));
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetPolys(polys);
  if (!polygons.normals.empty())
  {
    vtkNew<vtkDoubleArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      normals->SetTuple(i, &polygons.normals[static_cast<std::size_t>(3 * i)]);
    }
    data->GetPointData()->SetNormals(normals);
  }
  if (!polygons.texCoords.empty())
  {
    vtkNew<vtkDoubleArray> texCoords;
    texCoords->SetName("TCoords");
    texCoords->SetNumberOfComponents(2);
    texCoords->SetNumberOfTuples(numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      texCoords->SetTuple(i, &polygons.texCoords[static_cast<std::size_t>(2 * i)]);
    }
    data->GetPointData()->SetTCoords(texCoords);
  }
  return polyDataToSoup(data, path, scale);
}

} // namespace proxima::detail
