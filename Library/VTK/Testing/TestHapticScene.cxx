// vtkHapticScene: objects placed by their poses as an independent vtkTransform places their
// points, materials carried to the kernel, a new snapshot (and version) for each edit with only
// the edited object rebuilt, and a bad edit refused with the last good scene kept.
#include "VtkTestSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "VTK/vtkHapticScene.h"

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

namespace
{
using namespace proxima;
using proxima::vtk::testing::polyDataOf;

struct TwoObjects : ::testing::Test
{
  void SetUp() override
  {
    box = polyDataOf(makeBox({0.01, 0.02, 0.03}));
    sphere = polyDataOf(makeIcosphere(2, 0.01));
    scene->AddObjectData(box);
    scene->AddObjectData(sphere);
    pose->Translate(0.1, 0.0, 0.0);
    pose->RotateZ(90.0);
    scene->SetObjectPose(1, pose);
    scene->SetObjectFriction(0, 0.5, 0.3, 2.0);
    scene->SetObjectScale(1, 2.0);
  }

  vtkSmartPointer<vtkPolyData> box;
  vtkSmartPointer<vtkPolyData> sphere;
  vtkNew<vtkTransform> pose;
  vtkNew<vtkHapticScene> scene;
};

TEST_F(TwoObjects, PlacesObjectsByScaleThenPose)
{
  scene->Update();
  const auto snapshot = scene->GetCollisionScene();
  ASSERT_TRUE(snapshot);
  ASSERT_EQ(snapshot->objects.size(), 2u);
  EXPECT_EQ(scene->GetSceneVersion(), 1u);
  const TriangleMesh& placed = snapshot->objects[1].mesh;
  ASSERT_EQ(placed.numPoints(), static_cast<std::uint32_t>(sphere->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sphere->GetPoint(i, p);
    const double scaled[3] = {2.0 * p[0], 2.0 * p[1], 2.0 * p[2]};
    double expected[3];
    pose->TransformPoint(scaled, expected);
    EXPECT_NEAR(placed.points()[i].x, expected[0], 1e-15);
    EXPECT_NEAR(placed.points()[i].y, expected[1], 1e-15);
    EXPECT_NEAR(placed.points()[i].z, expected[2], 1e-15);
  }
  const SurfaceMaterial& material = snapshot->objects[0].material;
  EXPECT_EQ(material.staticFriction, 0.5);
  EXPECT_EQ(material.dynamicFriction, 0.3);
  EXPECT_EQ(material.viscosity, 2.0);
  EXPECT_FALSE(snapshot->objects[1].material.hasFriction());
  // The output is the placed surface, every triangle tagged with its object.
  vtkPolyData* output = scene->GetOutput();
  EXPECT_EQ(
    output->GetNumberOfCells(),
    static_cast<vtkIdType>(snapshot->objects[0].mesh.numTriangles() + placed.numTriangles()));
  EXPECT_EQ(output->GetCellData()->GetArray("ObjectId")->GetTuple1(output->GetNumberOfCells() - 1),
            1.0);
}

TEST_F(TwoObjects, AnEditRebuildsOnlyItsObjectIntoANewSnapshot)
{
  scene->Update();
  const auto first = scene->GetCollisionScene();
  EXPECT_EQ(scene->GetNumberOfObjectsRebuilt(), 2);

  // Nothing changed: no new snapshot.
  scene->Update();
  EXPECT_EQ(scene->GetCollisionScene(), first);
  EXPECT_EQ(scene->GetSceneVersion(), 1u);

  // Edit the box's points.
  double p[3];
  box->GetPoint(0, p);
  box->GetPoints()->SetPoint(0, p[0] - 0.01, p[1], p[2]);
  box->GetPoints()->Modified();
  scene->Update();
  EXPECT_EQ(scene->GetNumberOfObjectsRebuilt(), 1);
  EXPECT_EQ(scene->GetSceneVersion(), 2u);
  const auto second = scene->GetCollisionScene();
  ASSERT_NE(second, first);
  EXPECT_DOUBLE_EQ(second->objects[0].mesh.points()[0].x, p[0] - 0.01);
  // The old snapshot is untouched: a haptic thread holding it sees the old model whole.
  EXPECT_DOUBLE_EQ(first->objects[0].mesh.points()[0].x, p[0]);

  // Move the sphere's pose: 5 cm along its own y, which the 90 degree turn about z points
  // along world -x.
  pose->Translate(0.0, 0.05, 0.0);
  scene->Update();
  EXPECT_EQ(scene->GetNumberOfObjectsRebuilt(), 1);
  EXPECT_EQ(scene->GetSceneVersion(), 3u);
  EXPECT_NEAR(scene->GetCollisionScene()->objects[1].mesh.bounds().lower.x,
              second->objects[1].mesh.bounds().lower.x - 0.05, 1e-12);

  // A material edit.
  scene->SetObjectFriction(1, 0.2, 0.1, 0.0);
  scene->Update();
  EXPECT_EQ(scene->GetSceneVersion(), 4u);
  EXPECT_EQ(scene->GetCollisionScene()->objects[1].material.staticFriction, 0.2);
}

TEST_F(TwoObjects, ParallelTreeBuildsEqualSerialOnes)
{
  scene->Update();
  const auto parallel = scene->GetCollisionScene();
  vtkNew<vtkHapticScene> serial;
  serial->AddObjectData(box);
  serial->AddObjectData(sphere);
  serial->SetObjectPose(1, pose);
  serial->SetObjectScale(1, 2.0);
  serial->ParallelTreeBuildOff();
  serial->Update();
  const auto oracle = serial->GetCollisionScene();
  ASSERT_EQ(parallel->objects.size(), oracle->objects.size());
  for (std::size_t i = 0; i < oracle->objects.size(); ++i)
  {
    const auto& a = parallel->objects[i].tree.nodes();
    const auto& b = oracle->objects[i].tree.nodes();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t n = 0; n < a.size(); ++n)
    {
      EXPECT_EQ(a[n].radius, b[n].radius);
      EXPECT_EQ(a[n].rightOrFirst, b[n].rightOrFirst);
    }
  }
}

TEST_F(TwoObjects, ANewSnapshotSharesTheObjectsAnEditDidNotTouch)
{
  scene->Update();
  const auto first = scene->GetCollisionScene();
  scene->SetObjectFriction(1, 0.2, 0.1, 0.0);
  scene->Update();
  const auto second = scene->GetCollisionScene();
  ASSERT_NE(second, first);
  // The box is the same object in both, not a copy; the sphere is a new one.
  EXPECT_EQ(second->objects.shared(0), first->objects.shared(0));
  EXPECT_NE(second->objects.shared(1), first->objects.shared(1));
}

TEST_F(TwoObjects, ABackgroundBuildKeepsTheOldSceneUntilTheNewOneIsComplete)
{
  scene->BackgroundBuildOn();
  scene->Update();
  ASSERT_TRUE(scene->WaitForBuild());
  const auto first = scene->GetCollisionScene();
  ASSERT_TRUE(first);
  EXPECT_EQ(scene->GetSceneVersion(), 1u);

  double p[3];
  box->GetPoint(0, p);
  box->GetPoints()->SetPoint(0, p[0] - 0.01, p[1], p[2]);
  box->GetPoints()->Modified();
  scene->Update();
  EXPECT_EQ(scene->GetNumberOfObjectsRebuilt(), 1);
  // Until the worker is done, the last snapshot is the one in use.
  if (scene->IsBuilding())
  {
    EXPECT_EQ(scene->GetCollisionScene(), first);
  }
  ASSERT_TRUE(scene->WaitForBuild());
  EXPECT_FALSE(scene->IsBuilding());
  EXPECT_EQ(scene->GetSceneVersion(), 2u);
  const auto second = scene->GetCollisionScene();
  EXPECT_DOUBLE_EQ(second->objects[0].mesh.points()[0].x, p[0] - 0.01);
  EXPECT_EQ(second->objects.shared(1), first->objects.shared(1));
  // The tree was built (the same as a build on the calling thread).
  vtkNew<vtkHapticScene> inline_;
  inline_->AddObjectData(box);
  inline_->Update();
  const auto& built = second->objects[0].tree.nodes();
  const auto& oracle = inline_->GetCollisionScene()->objects[0].tree.nodes();
  ASSERT_EQ(built.size(), oracle.size());
  EXPECT_EQ(std::memcmp(built.data(), oracle.data(), built.size() * sizeof(built[0])), 0);

  // Nothing changed: no build, no new version.
  scene->Update();
  EXPECT_FALSE(scene->IsBuilding());
  EXPECT_EQ(scene->GetSceneVersion(), 2u);
}

TEST_F(TwoObjects, SettersRefuseAnIndexThatIsNoObject)
{
  scene->Update();
  const auto before = scene->GetCollisionScene();
  // Each refusal is an error event (an observer takes it instead of the output window).
  int errors = 0;
  vtkNew<vtkCallbackCommand> countErrors;
  countErrors->SetClientData(&errors);
  countErrors->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  scene->AddObserver(vtkCommand::ErrorEvent, countErrors);
  for (const int bad : {-1, 2, 1000})
  {
    scene->SetObjectScale(bad, 3.0);
    scene->SetObjectFriction(bad, 0.9, 0.9, 1.0);
    scene->SetObjectShading(bad, true);
    scene->SetObjectPose(bad, pose);
  }
  scene->RemoveObserver(countErrors);
  EXPECT_EQ(errors, 12);
  // Object 0 (which std::max(object, 0) once edited for -1) and object 1 are as they were.
  EXPECT_EQ(scene->GetObjectScale(0), 1.0);
  EXPECT_EQ(scene->GetObjectScale(1), 2.0);
  EXPECT_EQ(scene->GetObjectPose(0), nullptr);
  EXPECT_EQ(scene->GetObjectScale(-1), 1.0);
  scene->Update();
  EXPECT_EQ(scene->GetCollisionScene(), before);
  EXPECT_EQ(scene->GetSceneVersion(), 1u);
  EXPECT_EQ(before->objects[0].material.staticFriction, 0.5);
}

TEST_F(TwoObjects, ABadEditKeepsTheLastGoodScene)
{
  scene->Update();
  const auto good = scene->GetCollisionScene();
  sphere->GetPoints()->SetPoint(1, 0.0, std::numeric_limits<double>::infinity(), 0.0);
  sphere->GetPoints()->Modified();
  scene->GlobalWarningDisplayOff();
  scene->Update();
  EXPECT_EQ(scene->GetCollisionScene(), good);
  EXPECT_EQ(scene->GetSceneVersion(), 1u);

  // A pose that scales is refused too.
  sphere->GetPoints()->SetPoint(1, 0.0, 0.0, 0.01);
  sphere->GetPoints()->Modified();
  pose->Scale(2.0, 1.0, 1.0);
  scene->Update();
  scene->GlobalWarningDisplayOn();
  EXPECT_EQ(scene->GetCollisionScene(), good);
}

} // namespace
