// Where a ball tool cannot reach (ToolReach.h): on two blocks with a slot between them, where the
// answer is known in closed form, and on the shared meshes sample by sample against an
// independent distance: VTK's static cell locator, the closest point of the whole surface to each
// tangent ball's centre, compared with the tool's radius.
#include "IO/MeshInspection/MeshInspection.h"
#include "IO/MeshInspection/ToolReach.h"

#include "Geometry/ProceduralMeshes.h"
#include "IO/Mesh/MeshReader.h"
#include "VtkTestSupport.h"

#include <gtest/gtest.h>

#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangle.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>

namespace proxima
{
namespace
{
// Two 10 mm cubes with a slot of `gap` between their facing faces (x = -gap/2 and x = gap/2).
TriangleSoup blocksWithASlot(double gap)
{
  const double half = 0.005;
  TriangleSoup soup = makeBox({half, half, half}, {-gap / 2 - half, 0.0, 0.0});
  const TriangleSoup other = makeBox({half, half, half}, {gap / 2 + half, 0.0, 0.0});
  const auto base = static_cast<std::uint32_t>(soup.points.size());
  soup.points.insert(soup.points.end(), other.points.begin(), other.points.end());
  for (const auto& t : other.triangles)
  {
    soup.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  soup.pointNormals.clear();
  return soup;
}

// A file's name as a test's: letters and digits, the rest underscores.
std::string fileTestName(std::string name)
{
  for (char& c : name)
  {
    c = std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
  }
  return name;
}

ToolReach reachOf(const TriangleSoup& soup, double radius, bool keepSamples = false)
{
  const MeshInspection inspection = inspectMesh(soup);
  ToolReachOptions options;
  options.toolRadius = radius;
  options.keepSamples = keepSamples;
  return findToolReach(soup, inspection.closed && inspection.misorientedEdges.count == 0, options);
}

TEST(ToolReach, AToolWiderThanTheSlotCannotTouchItsFacingWallsAndANarrowerOneCan)
{
  const double gap = 0.002;
  const TriangleSoup soup = blocksWithASlot(gap);
  const double faceArea = 0.01 * 0.01;

  const ToolReach narrow = reachOf(soup, 0.4 * gap);
  EXPECT_TRUE(narrow.outsideOnly);
  EXPECT_EQ(narrow.unreachableSamples, 0u);
  EXPECT_EQ(narrow.regionCount, 0u);
  EXPECT_NEAR(narrow.area, 12.0 * faceArea, 1e-15);

  // A ball tangent to one facing wall reaches 2R across: over the gap, into the other block.
  const ToolReach wide = reachOf(soup, 0.6 * gap);
  EXPECT_NEAR(wide.unreachableArea, 2.0 * faceArea, 1e-15);
  EXPECT_EQ(wide.unreachableTriangles.size(), 4u);
  ASSERT_EQ(wide.regionCount, 2u);
  for (const UnreachableRegion& region : wide.regions)
  {
    EXPECT_NEAR(std::abs(region.point.x), gap / 2, 1e-15);
    EXPECT_NEAR(region.area, faceArea, 1e-15);
    // The largest ball that touches a facing wall spans the slot: radius gap / 2.
    EXPECT_NEAR(region.largestReachingRadius, gap / 2, 1e-6 * gap);
  }
}

TEST(ToolReach, TheSamplesCoverEveryTriangleOnce)
{
  // Triangles far longer than the tool are split (at most maxSplit per edge), and the samples'
  // areas add up to each triangle's own, computed by VTK.
  const TriangleSoup soup = blocksWithASlot(0.002);
  const ToolReach reach = reachOf(soup, 0.0015, true);
  std::map<std::uint32_t, double> areaOf;
  std::map<std::uint32_t, int> samplesOf;
  for (const ReachSample& sample : reach.sampleList)
  {
    areaOf[sample.triangle] += sample.area;
    ++samplesOf[sample.triangle];
  }
  ASSERT_EQ(areaOf.size(), soup.triangles.size());
  for (std::uint32_t t = 0; t < soup.triangles.size(); ++t)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& q = soup.points[soup.triangles[t][k]];
      p[k][0] = q.x;
      p[k][1] = q.y;
      p[k][2] = q.z;
    }
    EXPECT_NEAR(areaOf[t], vtkTriangle::TriangleArea(p[0], p[1], p[2]), 1e-15);
    // Edges of 10 mm and 14 mm over a 1.5 mm tool: 10 splits, capped at 8 per edge.
    EXPECT_EQ(samplesOf[t], 64);
  }
}

// A shared mesh, the scale that makes it a hand-held part, and a tool's radius.
struct ReachCase
{
  const char* file;
  double scale;
  double radius;
};

std::ostream& operator<<(std::ostream& out, const ReachCase& c)
{
  return out << c.file << " at scale " << c.scale << ", tool " << c.radius << " m";
}

class SharedMeshReach : public testing::TestWithParam<ReachCase>
{};

TEST_P(SharedMeshReach, EverySampleAgreesWithVtksDistanceToTheSurface)
{
  const auto [name, scale, radius] = GetParam();
  const std::string path = std::string(PROXIMA_SHARED_MESHES) + "/" + name;
  if (!std::filesystem::exists(path))
  {
    GTEST_SKIP() << path << " is absent (the shared meshes, ../shared/data/meshes)";
  }
  const TriangleSoup soup = readMeshFile(path, scale);
  const ToolReach reach = reachOf(soup, radius, true);
  ASSERT_EQ(reach.sampleList.size(), reach.samples);

  const vtkSmartPointer<vtkPolyData> surface = vtk::testing::polyDataOf(soup);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  // The distance from the centre of the ball tangent at the sample on `side` to the surface.
  const auto clearance = [&](const ReachSample& sample, const Vec3& side) {
    const Vec3 centre = sample.point + side * radius;
    double x[3] = {centre.x, centre.y, centre.z};
    double closest[3];
    vtkIdType cellId = 0;
    int subId = 0;
    double squared = 0.0;
    locator->FindClosestPoint(x, closest, cell, cellId, subId, squared);
    return std::sqrt(squared);
  };
  // Decided by the ball less the documented slack (1e-6 of R); samples within 1e-9 R of that
  // boundary are left out, where rounding may decide either way.
  const double limit = radius * (1.0 - 1e-6);
  std::size_t checked = 0;
  std::size_t unreachable = 0;
  for (const ReachSample& sample : reach.sampleList)
  {
    const double distance = clearance(sample, sample.side);
    if (std::abs(distance - limit) < 1e-9 * radius)
    {
      continue;
    }
    ++checked;
    EXPECT_EQ(sample.reachable, distance > limit)
      << "triangle " << sample.triangle << ": the ball's centre is " << distance
      << " from the surface, the tool " << radius;
    if (!sample.reachable)
    {
      ++unreachable;
      if (!reach.outsideOnly)
      {
        // Both sides were tried: the other one is blocked too.
        EXPECT_LE(clearance(sample, -sample.side), limit + 1e-9 * radius);
      }
    }
  }
  EXPECT_GT(checked, reach.samples * 99 / 100);
  EXPECT_LE(unreachable, reach.unreachableSamples);
  std::printf("%s at %g m: %zu samples, %zu unreachable (%.2f%% of the area) in %zu regions, %s\n",
              name, radius, reach.samples, reach.unreachableSamples,
              100.0 * reach.unreachableArea / reach.area, reach.regionCount,
              reach.outsideOnly ? "outside only" : "both sides");
}

// Scales and radii as the inspector's documentation probes them (Documentation/CadInspector.md).
INSTANTIATE_TEST_SUITE_P(SharedMeshes, SharedMeshReach,
                         testing::Values(ReachCase{"M3x10_screw.stl", 0.001, 0.0002},
                                         ReachCase{"fandisk.off", 0.1, 0.002},
                                         ReachCase{"featuretype.STL", 0.01, 0.001},
                                         ReachCase{"abc_00000050_trimesh_000.stl", 1.0, 0.002}),
                         [](const testing::TestParamInfo<ReachCase>& info) {
                           return fileTestName(info.param.file);
                         });

} // namespace
} // namespace proxima
