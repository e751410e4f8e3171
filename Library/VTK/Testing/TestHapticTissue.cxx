// vtkHapticTissue, the pipeline's source of a tissue's surface as it deforms: at rest before any
// step, then, after a press played in lockstep (which hands its steps over as the threaded loops
// do), the object's triangles over exactly the solid's points; nothing new without a new step;
// a tissue that is not there is refused and draws nothing.
#include "VTK/vtkHapticTissue.h"

#include "Runtime/LockstepRuntime.h"
#include "Runtime/SimulatedDevice.h"
#include "Tissue/Testing/SoftBlock.h"

#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

namespace proxima
{
namespace
{
constexpr double kRate = 1000.0;

// The soft block of 6 x 6 x 3 cells, kp = 1000 N/m at 1 kHz.
constexpr int kCellsAcross = 6;

TEST(HapticTissue, DrawsTheObjectOverTheNewestStepsPoints)
{
  const auto scene = testing_support::softBlockScene(kCellsAcross);
  auto tissue = testing_support::softBlockDynamics(kCellsAcross, 1000.0, kRate);

  vtkNew<vtkHapticTissue> source;
  source->SetTissue(tissue, scene, 0);
  EXPECT_FALSE(source->TakeNewestStep()); // no step yet
  source->Update();
  vtkPolyData* drawn = source->GetOutput();
  const TriangleMesh& mesh = scene->objects[0].mesh;
  ASSERT_EQ(drawn->GetNumberOfPoints(), static_cast<vtkIdType>(mesh.numPoints()));
  ASSERT_EQ(drawn->GetNumberOfPolys(), static_cast<vtkIdType>(mesh.numTriangles()));
  ASSERT_NE(drawn->GetCellData()->GetArray("ObjectId"), nullptr);
  for (std::uint32_t i = 0; i < mesh.numPoints(); ++i)
  {
    double p[3];
    drawn->GetPoint(i, p);
    EXPECT_EQ(p[2], mesh.points()[i].z) << "at rest, point " << i;
  }

  // A press 3 mm into the block's top, held, in lockstep.
  FingerPath path;
  for (int k = 0; k <= 400; ++k)
  {
    const double t = k / kRate;
    path.times.push_back(t);
    path.positions.push_back(Vec3{0.0, 0.0, t < 0.2 ? 0.01 - 0.065 * t : -0.003});
  }
  ProxyParameters proxy;
  proxy.radius = 0.005;
  proxy.timeStep = 1.0 / kRate;
  auto solver = std::make_unique<ProxySolver>();
  solver->setScene(scene.get(), proxy);
  solver->resetProxy(path.positions.front() + Vec3{0.0, 0.0, proxy.radius});
  tissue->attach(*solver);
  SimulatedDevice device(path);
  LockstepSettings settings;
  settings.rate = kRate;
  settings.numTicks = ticksCovering(path.startTime(), path.endTime(), kRate);
  runLockstep(
    settings, *solver, device, ServoParameters{}, [](const HapticState&) {}, tissue.get());
  ASSERT_GT(tissue->reading(0).maxDisplacement, 0.0005);

  ASSERT_TRUE(source->TakeNewestStep());
  source->Update();
  drawn = source->GetOutput();
  EXPECT_EQ(source->GetStepDrawn(), tissue->steps());
  const std::vector<Vec3>& solid = tissue->solid(0).positions();
  ASSERT_EQ(drawn->GetNumberOfPoints(), static_cast<vtkIdType>(solid.size()));
  double deepest = 0.0;
  for (std::size_t i = 0; i < solid.size(); ++i)
  {
    double p[3];
    drawn->GetPoint(static_cast<vtkIdType>(i), p);
    ASSERT_EQ(std::memcmp(p, &solid[i], sizeof p), 0) << "point " << i;
    deepest = std::min(deepest, p[2]);
  }
  EXPECT_LT(deepest, -0.0005); // the dent is drawn
  EXPECT_EQ(drawn->GetNumberOfPolys(), static_cast<vtkIdType>(mesh.numTriangles()));
  EXPECT_FALSE(source->TakeNewestStep()); // nothing newer

  // A tissue that is not there draws nothing.
  vtkNew<vtkHapticTissue> missing;
  missing->GlobalWarningDisplayOff();
  missing->SetTissue(tissue, scene, 1);
  missing->Update();
  EXPECT_EQ(missing->GetOutput()->GetNumberOfPoints(), 0);
}

} // namespace
} // namespace proxima
