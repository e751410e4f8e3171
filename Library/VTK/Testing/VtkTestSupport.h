// Helpers of the VTK layer's tests: kernel soups as vtkPolyData (the input a user's pipeline
// would give), the straight-line finger paths the image tests press with, and a bounded wait for
// what the haptic threads do.
#pragma once

#include "Geometry/TriangleSoup.h"
#include "Runtime/FingerPath.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <chrono>
#include <functional>
#include <initializer_list>
#include <thread>

namespace proxima::vtk::testing
{

/// Polls `condition` every millisecond until it holds (true) or a generous minute has passed
/// (false): the threaded tests check what happens, not how fast.
inline bool waitFor(const std::function<bool()>& condition)
{
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!condition())
  {
    if (std::chrono::steady_clock::now() > deadline)
    {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

inline vtkSmartPointer<vtkPolyData> polyDataOf(const TriangleSoup& soup)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Vec3& p : soup.points)
  {
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& triangle : soup.triangles)
  {
    const vtkIdType ids[3] = {triangle[0], triangle[1], triangle[2]};
    polys->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polys);
  if (!soup.pointNormals.empty())
  {
    vtkNew<vtkDoubleArray> normals;
    normals->SetNumberOfComponents(3);
    normals->SetName("Normals");
    for (const Vec3& n : soup.pointNormals)
    {
      normals->InsertNextTuple3(n.x, n.y, n.z);
    }
    data->GetPointData()->SetNormals(normals);
  }
  return data;
}

/// A path through `waypoints`, `seconds` apart (interpolated linearly at any rate).
inline FingerPath linearPath(std::initializer_list<Vec3> waypoints, double seconds)
{
  FingerPath path;
  double time = 0.0;
  for (const Vec3& point : waypoints)
  {
    path.append(time, point);
    time += seconds;
  }
  return path;
}

} // namespace proxima::vtk::testing
