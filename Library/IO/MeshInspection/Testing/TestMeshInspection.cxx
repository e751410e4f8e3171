// The mesh inspection's counts: on hand-made meshes where every count is known, and on the shared
// real meshes against independent computations: VTK's own topology filters (vtkCleanPolyData
// merging identical points, vtkFeatureEdges for boundary and non-manifold edges, and
// vtkPolyDataConnectivityFilter for pieces and for the loops of the boundary edges), an ordered
// map of corner positions for collapsed and duplicate triangles, and one of directed edges between
// VTK's merged points for misoriented edges.
#include "IO/MeshInspection/MeshInspection.h"

#include "IO/Mesh/MeshReader.h"
#include "VtkTestSupport.h"

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkMeshQuality.h>
#include <vtkFeatureEdges.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <string>

namespace proxima
{
namespace
{
TriangleSoup soupOf(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> triangles)
{
  TriangleSoup soup;
  soup.points = std::move(points);
  soup.triangles = std::move(triangles);
  return soup;
}

// A tetrahedron with outward faces.
const std::vector<Vec3> kTetraPoints{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<std::array<std::uint32_t, 3>> kTetraFaces{
  {0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};

TEST(MeshInspection, AClosedTetrahedronHasNoDefects)
{
  const MeshInspection r = inspectMesh(soupOf(kTetraPoints, kTetraFaces));
  EXPECT_EQ(r.triangles, 4u);
  EXPECT_EQ(r.vertices, 4u);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_EQ(r.boundaryEdges.count, 0u);
  EXPECT_EQ(r.boundaryLoops.count, 0u);
  EXPECT_EQ(r.nonManifoldEdges.count, 0u);
  EXPECT_EQ(r.misorientedEdges.count, 0u);
  EXPECT_EQ(r.collapsedTriangles.count, 0u);
  EXPECT_EQ(r.zeroAreaTriangles.count, 0u);
  EXPECT_EQ(r.duplicateTriangles.count, 0u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_TRUE(r.closed);
}

TEST(MeshInspection, CornersRepeatedAsInAnStlFileAreOneVertexAndMinusZeroIsZero)
{
  TriangleSoup soup;
  for (const auto& face : kTetraFaces)
  {
    const auto base = static_cast<std::uint32_t>(soup.points.size());
    for (const std::uint32_t corner : face)
    {
      Vec3 p = kTetraPoints[corner];
      // Written -0 in some places, as some exporters do.
      p.x = p.x == 0.0 && base % 2 == 1 ? -0.0 : p.x;
      soup.points.push_back(p);
    }
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const MeshInspection r = inspectMesh(soup);
  EXPECT_EQ(r.vertices, 4u);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_TRUE(r.closed);
}

TEST(MeshInspection, AMissingFaceIsOneLoopOfThreeBoundaryEdges)
{
  auto faces = kTetraFaces;
  faces.pop_back();
  const MeshInspection r = inspectMesh(soupOf(kTetraPoints, faces));
  EXPECT_EQ(r.boundaryEdges.count, 3u);
  ASSERT_EQ(r.boundaryLoops.count, 1u);
  EXPECT_EQ(r.boundaryLoopEdges, std::vector<std::size_t>{3});
  EXPECT_FALSE(r.closed);
  // The first boundary edge is met on triangle 0, {0, 2, 1}: its edge from 0 to 2.
  ASSERT_FALSE(r.boundaryEdges.first.empty());
  EXPECT_EQ(r.boundaryEdges.first[0].triangle, 0u);
  EXPECT_EQ(r.boundaryEdges.first[0].point, (Vec3{0.0, 0.5, 0.0}));
}

TEST(MeshInspection, AFlippedFaceMisorientsItsThreeEdges)
{
  auto faces = kTetraFaces;
  std::swap(faces[2][1], faces[2][2]);
  const MeshInspection r = inspectMesh(soupOf(kTetraPoints, faces));
  EXPECT_EQ(r.misorientedEdges.count, 3u);
  EXPECT_TRUE(r.closed);
}

TEST(MeshInspection, ThreeTrianglesOnOneEdgeMakeItNonManifold)
{
  const MeshInspection r = inspectMesh(soupOf(
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));
  EXPECT_EQ(r.nonManifoldEdges.count, 1u);
  EXPECT_EQ(r.edges, 7u);
  EXPECT_EQ(r.boundaryEdges.count, 6u);
  // The six rim edges meet at vertices 0 and 1: one group.
  EXPECT_EQ(r.boundaryLoops.count, 1u);
  EXPECT_FALSE(r.closed);
}

TEST(MeshInspection, CollapsedZeroAreaAndDuplicateTriangles)
{
  auto faces = kTetraFaces;
  faces.push_back({1, 1, 2}); // collapsed
  faces.push_back({2, 0, 1}); // the first face again, rotated
  faces.push_back({1, 0, 2}); // and reversed
  std::vector<Vec3> points = kTetraPoints;
  points.push_back({2, 0, 0}); // 4, on the line through 0 and 1
  faces.push_back({0, 1, 4});  // zero area
  const MeshInspection r = inspectMesh(soupOf(points, faces));
  EXPECT_EQ(r.collapsedTriangles.count, 1u);
  EXPECT_EQ(r.collapsedTriangles.first[0].triangle, 4u);
  EXPECT_EQ(r.duplicateTriangles.count, 2u);
  EXPECT_EQ(r.zeroAreaTriangles.count, 1u);
  EXPECT_EQ(r.zeroAreaTriangles.first[0].triangle, 7u);
}

TEST(MeshInspection, TwoSeparateTetrahedraAreTwoComponents)
{
  std::vector<Vec3> points = kTetraPoints;
  auto faces = kTetraFaces;
  for (const Vec3& p : kTetraPoints)
  {
    points.push_back(p + Vec3{5, 0, 0});
  }
  for (const auto& f : kTetraFaces)
  {
    faces.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
  }
  const MeshInspection r = inspectMesh(soupOf(points, faces));
  EXPECT_EQ(r.components, 2u);
  EXPECT_TRUE(r.closed);
}

// --- The shared meshes against VTK's filters ---------------------------------------------------

struct VtkCounts
{
  std::size_t boundaryEdges = 0;
  std::size_t nonManifoldEdges = 0;
  std::size_t boundaryLoops = 0;
  std::size_t components = 0;
};

vtkSmartPointer<vtkPolyData> cleanedPolyData(const TriangleSoup& soup)
{
  const vtkSmartPointer<vtkPolyData> raw = vtk::testing::polyDataOf(soup);
  // Identical points merged (tolerance 0), and triangles that collapse removed rather than made
  // lines: the inspection's definitions.
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(raw);
  clean->SetTolerance(0.0);
  clean->PointMergingOn();
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  clean->Update();
  return clean->GetOutput();
}

std::size_t regions(vtkPolyData* data)
{
  vtkNew<vtkPolyDataConnectivityFilter> connectivity;
  connectivity->SetInputData(data);
  connectivity->SetExtractionModeToAllRegions();
  connectivity->Update();
  return static_cast<std::size_t>(connectivity->GetNumberOfExtractedRegions());
}

VtkCounts countWithVtk(const TriangleSoup& soup)
{
  const vtkSmartPointer<vtkPolyData> cleaned = cleanedPolyData(soup);
  VtkCounts counts;
  for (const bool boundary : {true, false})
  {
    vtkNew<vtkFeatureEdges> edges;
    edges->SetInputData(cleaned);
    edges->SetBoundaryEdges(boundary);
    edges->SetNonManifoldEdges(!boundary);
    edges->FeatureEdgesOff();
    edges->ManifoldEdgesOff();
    edges->ColoringOff();
    edges->Update();
    const auto lines = static_cast<std::size_t>(edges->GetOutput()->GetNumberOfLines());
    if (boundary)
    {
      counts.boundaryEdges = lines;
      counts.boundaryLoops = lines > 0 ? regions(edges->GetOutput()) : 0;
    }
    else
    {
      counts.nonManifoldEdges = lines;
    }
  }
  counts.components = regions(cleaned);
  return counts;
}

// Collapsed and duplicate triangles by corner positions in an ordered map: another route than
// the inspection's vertex ids and hash sets.
std::pair<std::size_t, std::size_t> collapsedAndDuplicates(const TriangleSoup& soup)
{
  using Corner = std::array<double, 3>;
  std::map<std::array<Corner, 3>, int> seen;
  std::size_t collapsed = 0;
  std::size_t duplicates = 0;
  for (const auto& t : soup.triangles)
  {
    std::array<Corner, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& p = soup.points[t[k]];
      // + 0.0 turns -0 into +0.
      corners[k] = {p.x + 0.0, p.y + 0.0, p.z + 0.0};
    }
    collapsed += corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2];
    std::sort(corners.begin(), corners.end());
    duplicates += seen[corners]++ > 0 ? 1 : 0;
  }
  return {collapsed, duplicates};
}

// Misoriented edges on VTK's merged points: each edge used by exactly two triangles whose
// directed uses run the same way, counted over an ordered map of directed point pairs.
std::size_t misorientedByVtkPoints(vtkPolyData* cleaned)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  std::map<std::pair<vtkIdType, vtkIdType>, int> undirected;
  vtkCellArray* polys = cleaned->GetPolys();
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids) != 0;)
  {
    for (vtkIdType k = 0; k < size; ++k)
    {
      const vtkIdType a = ids[k];
      const vtkIdType b = ids[(k + 1) % size];
      ++directed[{a, b}];
      ++undirected[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::size_t misoriented = 0;
  for (const auto& [edge, uses] : undirected)
  {
    misoriented += uses == 2 && (directed[edge] == 2 || directed[{edge.second, edge.first}] == 2);
  }
  return misoriented;
}

// Self-intersecting pairs by brute force: every pair of triangles whose boxes overlap, tested with
// CGAL's exact predicate, without the box-intersection broad phase the inspection uses.
std::size_t selfIntersectionsByBruteForce(const TriangleSoup& soup)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Triangle_3> triangles;
  std::vector<std::size_t> index;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const auto& c = soup.triangles[t];
    Kernel::Point_3 p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = {soup.points[c[k]].x, soup.points[c[k]].y, soup.points[c[k]].z};
    }
    if (!CGAL::collinear(p[0], p[1], p[2]))
    {
      triangles.emplace_back(p[0], p[1], p[2]);
      index.push_back(t);
    }
  }
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    const CGAL::Bbox_3 box = triangles[i].bbox();
    for (std::size_t j = i + 1; j < triangles.size(); ++j)
    {
      if (!CGAL::do_overlap(box, triangles[j].bbox()))
      {
        continue;
      }
      bool shared = false;
      for (int a = 0; a < 3; ++a)
      {
        for (int b = 0; b < 3; ++b)
        {
          shared = shared || triangles[i].vertex(a) == triangles[j].vertex(b);
        }
      }
      pairs += !shared && CGAL::do_intersect(triangles[i], triangles[j]) ? 1 : 0;
    }
  }
  return pairs;
}

TEST(MeshInspection, TwoCrossingTrianglesIntersectAndNeighboursDoNot)
{
  // Triangle 0 in z = 0; triangle 1 stands through it; triangle 2 shares an edge with 0.
  const MeshInspection r = inspectMesh(soupOf(
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -1}, {0.2, 0.2, 1}, {0.3, 0.1, 1}, {1, 1, 0}},
    {{0, 1, 2}, {3, 4, 5}, {1, 6, 2}}));
  EXPECT_EQ(r.selfIntersections.count, 1u);
  ASSERT_EQ(r.selfIntersections.first.size(), 1u);
  EXPECT_EQ(r.selfIntersections.first[0].triangle, 0u);
  EXPECT_EQ(r.selfIntersections.first[0].other, 1u);
}

// Slivers by VTK's mesh quality filter: the smallest angle of each triangle, in degrees, on the
// raw triangles (collapsed and zero-area ones, which the inspection calls degenerate, left out by
// the caller's counts).
std::size_t sliversByVtk(const TriangleSoup& soup, const MeshInspection& r, double degrees)
{
  const vtkSmartPointer<vtkPolyData> raw = vtk::testing::polyDataOf(soup);
  vtkNew<vtkMeshQuality> quality;
  quality->SetInputData(raw);
  quality->SetTriangleQualityMeasureToMinAngle();
  quality->Update();
  vtkDataArray* angles = quality->GetOutput()->GetCellData()->GetArray("Quality");
  std::size_t below = 0;
  for (vtkIdType i = 0; i < angles->GetNumberOfTuples(); ++i)
  {
    below += angles->GetTuple1(i) < degrees ? 1 : 0;
  }
  // VTK gives a degenerate triangle a smallest angle of 0 (or NaN, which is not below).
  return below - std::min(below, r.collapsedTriangles.count + r.zeroAreaTriangles.count);
}

TEST(MeshInspection, ASliverHasAnAngleBelowTheThreshold)
{
  // Angles of about 0.57 degrees at the far corners; the second triangle's smallest is 45.
  const MeshInspection r =
    inspectMesh(soupOf({{0, 0, 0}, {1, 0, 0}, {0.5, 0.005, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 3}}));
  EXPECT_EQ(r.sliverTriangles.count, 1u);
  MeshInspectionOptions strict;
  strict.sliverAngleDegrees = 0.5;
  EXPECT_EQ(inspectMesh(soupOf({{0, 0, 0}, {1, 0, 0}, {0.5, 0.005, 0}}, {{0, 1, 2}}), strict)
              .sliverTriangles.count,
            0u);
}

TEST(MeshInspection, WeldingJoinsCornersWithinTheToleranceTransitivelyAndKeepsTheFirst)
{
  const TriangleSoup soup =
    soupOf({{0, 0, 0}, {0.4e-6, 0, 0}, {0.8e-6, 0, 0}, {1, 0, 0}}, {{0, 3, 1}, {2, 3, 1}});
  const TriangleSoup welded = weldCorners(soup, 0.5e-6);
  // 0 and 1 are within the tolerance, 1 and 2 too: all three become corner 0's position.
  EXPECT_EQ(welded.points[1], soup.points[0]);
  EXPECT_EQ(welded.points[2], soup.points[0]);
  EXPECT_EQ(welded.points[3], soup.points[3]);
  EXPECT_EQ(weldCorners(soup, 0.3e-6).points[1], soup.points[1]);
}

class SharedMeshInspection : public testing::TestWithParam<const char*>
{};

TEST_P(SharedMeshInspection, CountsAgreeWithVtksTopologyFilters)
{
  const std::string path = std::string(PROXIMA_SHARED_MESHES) + "/" + GetParam();
  if (!std::filesystem::exists(path))
  {
    GTEST_SKIP() << path << " is absent (the shared meshes, ../shared/data/meshes)";
  }
  const TriangleSoup soup = readMeshFile(path);
  const MeshInspection r = inspectMesh(soup);
  const VtkCounts vtk = countWithVtk(soup);
  EXPECT_EQ(r.boundaryEdges.count, vtk.boundaryEdges);
  EXPECT_EQ(r.nonManifoldEdges.count, vtk.nonManifoldEdges);
  EXPECT_EQ(r.boundaryLoops.count, vtk.boundaryLoops);
  EXPECT_EQ(r.components, vtk.components);
  EXPECT_EQ(r.misorientedEdges.count, misorientedByVtkPoints(cleanedPolyData(soup)));
  const auto [collapsed, duplicates] = collapsedAndDuplicates(soup);
  EXPECT_EQ(r.collapsedTriangles.count, collapsed);
  EXPECT_EQ(r.duplicateTriangles.count, duplicates);
  EXPECT_EQ(r.closed, vtk.boundaryEdges == 0 && vtk.nonManifoldEdges == 0);
  EXPECT_EQ(r.sliverTriangles.count, sliversByVtk(soup, r, 1.0));
  // The brute force is quadratic: meshes up to 16,000 triangles.
  if (soup.triangles.size() <= 16000)
  {
    EXPECT_EQ(r.selfIntersections.count, selfIntersectionsByBruteForce(soup));
  }
  std::printf("%s: %zu triangles, %zu vertices, %zu boundary edges in %zu loops, %zu non-manifold, "
              "%zu misoriented, %zu collapsed, %zu zero-area, %zu slivers, %zu duplicate, "
              "%zu self-intersecting pairs, "
              "%zu components, %s\n",
              GetParam(), r.triangles, r.vertices, r.boundaryEdges.count, r.boundaryLoops.count,
              r.nonManifoldEdges.count, r.misorientedEdges.count, r.collapsedTriangles.count,
              r.zeroAreaTriangles.count, r.sliverTriangles.count, r.duplicateTriangles.count,
              r.selfIntersections.count, r.components, r.closed ? "closed" : "open");
}

// The featuretype part is closed only after welding at a millionth of its diagonal (its
// provenance): the welded counts against VTK's merging of points within the same distance.
TEST(MeshInspection, TheCrackedCadPartClosesWhenWeldedAtAMillionthOfItsDiagonal)
{
  const std::string path = std::string(PROXIMA_SHARED_MESHES) + "/featuretype.STL";
  if (!std::filesystem::exists(path))
  {
    GTEST_SKIP() << path << " is absent (the shared meshes, ../shared/data/meshes)";
  }
  const TriangleSoup soup = readMeshFile(path);
  EXPECT_FALSE(inspectMesh(soup).closed);
  const double tolerance = 5.8e-6;
  const MeshInspection welded = inspectMesh(weldCorners(soup, tolerance));
  EXPECT_TRUE(welded.closed);
  EXPECT_EQ(welded.boundaryEdges.count, 0u);
  EXPECT_EQ(welded.components, 1u);

  vtkSmartPointer<vtkPolyData> raw = cleanedPolyData(soup);
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputData(raw);
  merge->ToleranceIsAbsoluteOn();
  merge->SetAbsoluteTolerance(tolerance);
  merge->ConvertPolysToLinesOff();
  merge->Update();
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(merge->GetOutput());
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  EXPECT_EQ(edges->GetOutput()->GetNumberOfLines(), 0);
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, SharedMeshInspection,
                         testing::Values("stanford-bunny.obj", "teapot.obj",
                                         "spot_triangulated.obj", "abc_00000050_trimesh_000.stl",
                                         "fandisk.off", "M3x10_screw.stl", "featuretype.STL",
                                         "VH_M_Liver.glb", "Angel_decimated.vtp"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                           {
                             c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           }
                           return name;
                         });

} // namespace
} // namespace proxima
