// vtkHapticSphereTreeFilter: the tree it keeps is the kernel's tree of the same mesh, the spheres
// it draws cover the surface, a new Level redraws without a rebuild, an edit upstream rebuilds,
// and bad data is refused with the old tree kept.
#include "VtkTestSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "VTK/vtkHapticSphereTreeFilter.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using namespace proxima;
using proxima::vtk::testing::polyDataOf;

TEST(SphereTreeFilter, KeepsTheKernelsTreeOfTheScaledMesh)
{
  const TriangleSoup soup = makeIcosphere(3, 10.0);
  vtkNew<vtkHapticSphereTreeFilter> filter;
  filter->SetInputData(polyDataOf(soup));
  filter->SetScale(0.001);
  filter->Update();
  const auto object = filter->GetCollisionObject();
  ASSERT_TRUE(object);

  // Oracle: the kernel's own build on the same soup scaled by hand.
  TriangleSoup scaled = soup;
  for (Vec3& p : scaled.points)
  {
    p = p * 0.001;
  }
  TriangleMesh mesh;
  MeshError error;
  ASSERT_TRUE(mesh.build(scaled, error));
  SphereTree tree;
  tree.build(mesh);
  ASSERT_EQ(object->mesh.numTriangles(), mesh.numTriangles());
  for (std::uint32_t i = 0; i < mesh.numPoints(); ++i)
  {
    EXPECT_EQ(object->mesh.points()[i], mesh.points()[i]);
  }
  EXPECT_EQ(object->tree.numNodes(), tree.numNodes());
  EXPECT_EQ(object->tree.depth(), tree.depth());
  EXPECT_EQ(object->tree.numLeafSpheres(), tree.numLeafSpheres());
}

TEST(SphereTreeFilter, DrawnSpheresAtALevelCoverEveryVertex)
{
  const TriangleSoup soup = makeIcosphere(3, 0.01);
  vtkNew<vtkHapticSphereTreeFilter> filter;
  filter->SetInputData(polyDataOf(soup));
  filter->SetLevel(3);
  filter->SetSphereResolution(8);
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  const auto spheres = filter->GetCollisionObject()->tree.spheresAtLevel(3);
  ASSERT_FALSE(spheres.empty());
  // 8 around, 4 rings: 2 + 3 * 8 points and 2 * 3 * 8 triangles per sphere.
  ASSERT_EQ(output->GetNumberOfPoints(), static_cast<vtkIdType>(spheres.size() * 26));
  ASSERT_EQ(output->GetNumberOfCells(), static_cast<vtkIdType>(spheres.size() * 48));
  // Every drawn point lies on its sphere.
  for (std::size_t s = 0; s < spheres.size(); ++s)
  {
    for (vtkIdType k = 0; k < 26; ++k)
    {
      double p[3];
      output->GetPoint(static_cast<vtkIdType>(s) * 26 + k, p);
      const double distance = norm(Vec3{p[0], p[1], p[2]} - spheres[s].center);
      EXPECT_NEAR(distance, spheres[s].radius, 1e-12 + 1e-9 * spheres[s].radius);
    }
  }
  // The level's spheres cover the surface: every mesh vertex is inside one (independent of how
  // the tree was built: it is what a bounding hierarchy promises).
  for (const Vec3& vertex : soup.points)
  {
    bool covered = false;
    for (const Sphere& sphere : spheres)
    {
      covered = covered || norm(vertex - sphere.center) <= sphere.radius * (1.0 + 1e-6);
    }
    EXPECT_TRUE(covered) << "vertex (" << vertex.x << ", " << vertex.y << ", " << vertex.z << ")";
  }
  EXPECT_STREQ(output->GetCellData()->GetScalars()->GetName(), "Radius");
}

TEST(SphereTreeFilter, ALevelChangeRedrawsWithoutRebuildingAndAnEditRebuilds)
{
  auto data = polyDataOf(makeIcosphere(2, 0.01));
  vtkNew<vtkHapticSphereTreeFilter> filter;
  filter->SetInputData(data);
  filter->Update();
  const auto first = filter->GetCollisionObject();
  const vtkIdType cellsAtLevel4 = filter->GetOutput()->GetNumberOfCells();

  filter->SetLevel(1);
  filter->Update();
  EXPECT_EQ(filter->GetCollisionObject(), first);
  EXPECT_LT(filter->GetOutput()->GetNumberOfCells(), cellsAtLevel4);

  // Move one point and say so: the tree is rebuilt from the new geometry.
  double p[3];
  data->GetPoints()->GetPoint(0, p);
  data->GetPoints()->SetPoint(0, p[0] * 2.0, p[1] * 2.0, p[2] * 2.0);
  data->GetPoints()->Modified();
  filter->Update();
  const auto second = filter->GetCollisionObject();
  ASSERT_NE(second, first);
  EXPECT_DOUBLE_EQ(second->mesh.points()[0].x, p[0] * 2.0);
}

TEST(SphereTreeFilter, RefusesNonFinitePointsAndKeepsTheOldTree)
{
  auto data = polyDataOf(makeIcosphere(1, 0.01));
  vtkNew<vtkHapticSphereTreeFilter> filter;
  filter->SetInputData(data);
  filter->Update();
  const auto good = filter->GetCollisionObject();
  ASSERT_TRUE(good);
  data->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  data->GetPoints()->Modified();
  filter->GlobalWarningDisplayOff();
  filter->Update();
  filter->GlobalWarningDisplayOn();
  EXPECT_EQ(filter->GetCollisionObject(), good);
}

} // namespace
