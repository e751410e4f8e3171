#include "VTK/PolyDataCollisionObject.h"

#include "IO/Mesh/MeshReader.h"
#include "IO/Mesh/PolyDataToSoup.h"
#include "IO/MeshPreparation/PointNormals.h"
#include "IO/Scene/ScenePose.h"

#include <vtkLinearTransform.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace proxima::vtk
{
namespace
{
double millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

// The kernel has no per-object transforms (trees are built in world coordinates), so a pose is
// baked into the points with the IO layer's ScenePose; only a rigid one keeps the mesh's shape
// and its normals meaningful.
ScenePose rigidPose(vtkLinearTransform* transform)
{
  vtkMatrix4x4* matrix = transform->GetMatrix();
  double rotation[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      rotation[i][j] = matrix->GetElement(i, j);
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double product = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        product += rotation[k][i] * rotation[k][j];
      }
      if (!(std::abs(product - (i == j ? 1.0 : 0.0)) <= 1e-9))
      {
        throw std::invalid_argument("the pose is not a rigid transform (rotation and "
                                    "translation only); put scaling in the object's scale");
      }
    }
  }
  if (!(vtkMath::Determinant3x3(rotation) > 0.0) || matrix->GetElement(3, 0) != 0.0 ||
      matrix->GetElement(3, 1) != 0.0 || matrix->GetElement(3, 2) != 0.0 ||
      matrix->GetElement(3, 3) != 1.0)
  {
    throw std::invalid_argument("the pose is not a rigid transform (it mirrors or projects)");
  }
  double quaternion[4];
  vtkMath::Matrix3x3ToQuaternion(rotation, quaternion);
  ScenePose pose;
  pose.rotation =
    UnitQuaternion::normalized(quaternion[0], quaternion[1], quaternion[2], quaternion[3]);
  pose.translation = {matrix->GetElement(0, 3), matrix->GetElement(1, 3), matrix->GetElement(2, 3)};
  return pose;
}
} // namespace

CollisionObject prepareCollisionObject(vtkPolyData* data, const std::string& name,
                                       const PolyDataObjectSettings& settings,
                                       PolyDataObjectReport* report)
{
  const auto conversionStart = std::chrono::steady_clock::now();
  TriangleSoup soup = polyDataToSoup(data, name, settings.scale);
  bool computedNormals = false;
  if (settings.shading && soup.pointNormals.empty())
  {
    // In the data's own frame, before the pose: the normals belong to the shape.
    soup = withFeatureAngleNormals(soup, settings.featureAngleDegrees);
    computedNormals = true;
  }
  if (settings.pose)
  {
    soup = posed(std::move(soup), rigidPose(settings.pose));
  }
  CollisionObject object;
  object.mesh = buildTriangleMesh(std::move(soup), name);
  object.material = settings.material;
  object.material.shading = settings.shading;
  if (report)
  {
    report->numTriangles = object.mesh.numTriangles();
    report->numDegenerateTriangles = object.mesh.numDegenerateTriangles();
    report->computedNormals = computedNormals;
    report->conversionMilliseconds = millisecondsSince(conversionStart);
  }
  return object;
}

CollisionObject buildCollisionObject(vtkPolyData* data, const std::string& name,
                                     const PolyDataObjectSettings& settings,
                                     PolyDataObjectReport* report)
{
  CollisionObject object = prepareCollisionObject(data, name, settings, report);
  const auto buildStart = std::chrono::steady_clock::now();
  object.buildQueries(settings.tree);
  if (report)
  {
    report->treeBuildMilliseconds = millisecondsSince(buildStart);
  }
  return object;
}

} // namespace proxima::vtk
