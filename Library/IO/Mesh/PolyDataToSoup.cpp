#include "IO/Mesh/PolyDataToSoup.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/Private/VtkMessageCapture.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace proxima
{
namespace
{
using detail::VtkMessageCapture;

std::string formatTuple(const double* values, int count)
{
  std::ostringstream out;
  out << "(";
  for (int i = 0; i < count; ++i)
  {
    out << (i ? ", " : "") << values[i];
  }
  out << ")";
  return out.str();
}

void checkFinitePoints(vtkPoints* points, const std::string& path)
{
  if (!points)
  {
    return;
  }
  double p[3];
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      throw InputError(path, "point " + std::to_string(i) + " has a non-finite coordinate " +
                               formatTuple(p, 3));
    }
  }
}

/// Readers copy indices from the file into cells unchecked; a bad one would send the
/// triangulation (and later the kernel) reading outside the points.
void checkPointIds(vtkCellArray* cells, vtkIdType numPoints, const char* cellName,
                   const std::string& path)
{
  if (!cells)
  {
    return;
  }
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType cellIndex = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellIndex)
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      if (ids[k] < 0 || ids[k] >= numPoints)
      {
        throw InputError(path, std::string(cellName) + " " + std::to_string(cellIndex) +
                                 " refers to point " + std::to_string(ids[k]) +
                                 ", out of range (the file has " + std::to_string(numPoints) +
                                 " points)");
      }
    }
  }
}

vtkIdType numCells(vtkCellArray* cells)
{
  return cells ? cells->GetNumberOfCells() : 0;
}

/// Normals or texture coordinates for every point, or null when the file has none (or has
/// them for some other count, which cannot be per point).
vtkDataArray* perPointArray(vtkDataArray* array, vtkIdType numPoints, int minComponents)
{
  if (array && array->GetNumberOfTuples() == numPoints &&
      array->GetNumberOfComponents() >= minComponents)
  {
    return array;
  }
  return nullptr;
}
} // namespace

TriangleSoup polyDataToSoup(vtkPolyData* data, const std::string& path, double scale)
{
  const vtkIdType numPoints = data ? data->GetNumberOfPoints() : 0;
  const vtkIdType numPolys = data ? numCells(data->GetPolys()) : 0;
  const vtkIdType numStrips = data ? numCells(data->GetStrips()) : 0;
  if (numPolys == 0 && numStrips == 0)
  {
    const vtkIdType numLines = data ? numCells(data->GetLines()) : 0;
    const vtkIdType numVerts = data ? numCells(data->GetVerts()) : 0;
    if (numLines > 0 || numVerts > 0)
    {
      throw InputError(path, "no triangles (only " + std::to_string(numLines) +
                               (numLines == 1 ? " line" : " lines") + " and " +
                               std::to_string(numVerts) +
                               (numVerts == 1 ? " vertex cell)" : " vertex cells)"));
    }
    throw InputError(path, "no triangles");
  }
  checkFinitePoints(data->GetPoints(), path);
  checkPointIds(data->GetPolys(), numPoints, "polygon", path);
  checkPointIds(data->GetStrips(), numPoints, "triangle strip", path);

  // Most files hold triangles only: then the cells are used as they are, which for the 1.5M
  // triangles of a CT iso-surface saves a full copy.
  vtkSmartPointer<vtkPolyData> triangles = data;
  if (numStrips > 0 || data->GetPolys()->IsHomogeneous() != 3 || numCells(data->GetLines()) > 0 ||
      numCells(data->GetVerts()) > 0)
  {
    VtkMessageCapture capture;
    vtkNew<vtkTriangleFilter> filter;
    filter->SetInputData(data);
    filter->PassLinesOff();
    filter->PassVertsOff();
    filter->Update();
    if (capture.hasErrors())
    {
      throw InputError(path, "cannot triangulate the polygons (" + capture.bestMessage() + ")");
    }
    triangles = filter->GetOutput();
  }
  vtkCellArray* cells = triangles->GetPolys();
  if (numCells(cells) == 0)
  {
    throw InputError(path, "no triangles (its " + std::to_string(numPolys + numStrips) +
                             " polygons and strips triangulate to nothing)");
  }
  if (triangles->GetNumberOfPoints() > std::numeric_limits<std::uint32_t>::max() ||
      cells->GetNumberOfCells() > std::numeric_limits<std::uint32_t>::max())
  {
    throw InputError(path, "too large: more than 2^32 points or triangles");
  }

  TriangleSoup soup;
  const vtkIdType outPoints = triangles->GetNumberOfPoints();
  soup.points.resize(static_cast<std::size_t>(outPoints));
  for (vtkIdType i = 0; i < outPoints; ++i)
  {
    double p[3];
    triangles->GetPoint(i, p);
    Vec3& q = soup.points[static_cast<std::size_t>(i)];
    q = Vec3{p[0] * scale, p[1] * scale, p[2] * scale};
    if (!isFinite(q))
    {
      std::ostringstream out;
      out << "point " << i << " " << formatTuple(p, 3) << " leaves the range of double when "
          << "scaled by " << scale;
      throw InputError(path, out.str());
    }
  }

  soup.triangles.reserve(static_cast<std::size_t>(cells->GetNumberOfCells()));
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(size, ids);
    if (size == 3)
    {
      soup.triangles.push_back({static_cast<std::uint32_t>(ids[0]),
                                static_cast<std::uint32_t>(ids[1]),
                                static_cast<std::uint32_t>(ids[2])});
    }
  }

  vtkPointData* pointData = triangles->GetPointData();
  if (vtkDataArray* normals = perPointArray(pointData->GetNormals(), outPoints, 3))
  {
    soup.pointNormals.resize(static_cast<std::size_t>(outPoints));
    for (vtkIdType i = 0; i < outPoints; ++i)
    {
      double n[3];
      normals->GetTuple(i, n);
      if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2]))
      {
        throw InputError(path, "point normal " + std::to_string(i) + " is not finite " +
                                 formatTuple(n, 3));
      }
      // A uniform positive scale leaves directions alone.
      soup.pointNormals[static_cast<std::size_t>(i)] = Vec3{n[0], n[1], n[2]};
    }
  }
  vtkDataArray* texCoords = perPointArray(pointData->GetTCoords(), outPoints, 2);
  if (!texCoords)
  {
    // glTF names its first set this way without always marking it as the texture coordinates.
    texCoords = perPointArray(pointData->GetArray("TEXCOORD_0"), outPoints, 2);
  }
  if (texCoords)
  {
    soup.texCoords.resize(static_cast<std::size_t>(outPoints));
    std::vector<double> tuple(static_cast<std::size_t>(texCoords->GetNumberOfComponents()));
    for (vtkIdType i = 0; i < outPoints; ++i)
    {
      texCoords->GetTuple(i, tuple.data());
      if (!std::isfinite(tuple[0]) || !std::isfinite(tuple[1]))
      {
        throw InputError(path, "texture coordinate " + std::to_string(i) + " is not finite " +
                                 formatTuple(tuple.data(), 2));
      }
      soup.texCoords[static_cast<std::size_t>(i)] = TexCoord{tuple[0], tuple[1]};
    }
  }
  return soup;
}

} // namespace proxima
