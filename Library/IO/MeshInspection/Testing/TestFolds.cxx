// Folds: neighbouring triangles (sharing a vertex or an edge) that meet beyond what they share.
// Hand-made pairs where the answer is plain, and real meshes dented until their triangles cross,
// against CGAL's Polygon Mesh Processing on a surface mesh: its self-intersecting pairs, found by
// its own code, are what the inspection calls self-intersections and folds together.
#include "IO/MeshInspection/MeshInspection.h"

#include "IO/Mesh/MeshReader.h"

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <cctype>
#include <filesystem>
#include <iterator>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace proxima
{
namespace
{
MeshInspection inspect(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> faces)
{
  TriangleSoup soup;
  soup.points = std::move(points);
  soup.triangles = std::move(faces);
  return inspectMesh(soup);
}

TEST(Folds, NeighboursAcrossAnEdgeFoldWhenTheyOverlapInOnePlane)
{
  // Triangle 0 and, across its edge 1-2: folded back onto it (3), flat beside it (4), bent (5).
  const std::vector<Vec3> points{{0, 0, 0},     {1, 0, 0}, {0, 1, 0},
                                 {0.2, 0.2, 0}, {1, 1, 0}, {1, 1, 1}};
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {1, 2, 3}}).folds.count, 1u);
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {1, 4, 2}}).folds.count, 0u);
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {1, 5, 2}}).folds.count, 0u);
  // Neighbours are never counted as self-intersections, whatever they do.
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {1, 2, 3}}).selfIntersections.count, 0u);
}

TEST(Folds, NeighboursAtAVertexFoldWhenTheyMeetAnywhereElse)
{
  const std::vector<Vec3> points{{0, 0, 0},      {1, 0, 0},   {0, 1, 0},    {0.2, 0.2, 1},
                                 {0.2, 0.2, -1}, {-1, 0, 1},  {-1, 0, -1},  {1, 1, 0},
                                 {-1, 1, 0},     {-1, -1, 0}, {-1, -0.5, 0}};
  // Through the first triangle: its edge opposite the shared vertex crosses it.
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {0, 3, 4}}).folds.count, 1u);
  // Standing in the plane y = 0 on the other side: only the vertex is shared.
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {0, 5, 6}}).folds.count, 0u);
  // In the same plane, overlapping around the direction of the first one's edge 0-2.
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {0, 7, 8}}).folds.count, 1u);
  // In the same plane, in the opposite quadrant: only the vertex.
  EXPECT_EQ(inspect(points, {{0, 1, 2}, {0, 9, 10}}).folds.count, 0u);
}

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

// CGAL's count of self-intersecting face pairs of the soup, made a surface mesh.
std::size_t pairsByCgal(const TriangleSoup& soup)
{
  std::vector<Kernel::Point_3> points;
  for (const Vec3& p : soup.points)
  {
    points.emplace_back(p.x, p.y, p.z);
  }
  std::vector<std::vector<std::size_t>> faces;
  for (const auto& t : soup.triangles)
  {
    faces.push_back({t[0], t[1], t[2]});
  }
  // Corners repeated in the file (STL, OBJ's texture seams) made one by CGAL's own repair.
  CGAL::Polygon_mesh_processing::merge_duplicate_points_in_polygon_soup(points, faces);
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces));
  SurfaceMesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
  return pairs.size();
}

// A mesh, and whether its dents fold some neighbours (so that the comparison covers folds).
struct DentCase
{
  const char* file;
  bool folds;
};

std::ostream& operator<<(std::ostream& out, const DentCase& c)
{
  return out << c.file << (c.folds ? ", folds" : ", no folds");
}

class DentedMesh : public testing::TestWithParam<DentCase>
{};

TEST_P(DentedMesh, SelfIntersectionsAndFoldsTogetherAreCgalsSelfIntersections)
{
  const auto [name, folds] = GetParam();
  const std::string path = std::string(PROXIMA_SHARED_MESHES) + "/" + name;
  if (!std::filesystem::exists(path))
  {
    GTEST_SKIP() << path << " is absent (the shared meshes, ../shared/data/meshes)";
  }
  TriangleSoup soup = readMeshFile(path);
  const MeshInspection before = inspectMesh(soup);
  EXPECT_EQ(before.selfIntersections.count + before.folds.count, pairsByCgal(soup));
  // Three vertices pushed through the part, past its centre: their fans cross it and fold.
  Vec3 low = soup.points[0];
  Vec3 high = soup.points[0];
  for (const Vec3& p : soup.points)
  {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  const Vec3 centre = (low + high) * 0.5;
  for (const std::uint32_t vertex : {0u, 7u, 100u})
  {
    // Every corner on that position moves (an STL file repeats it per triangle).
    const Vec3 from = soup.points[vertex];
    const Vec3 to = from + (centre - from) * 1.1;
    for (Vec3& p : soup.points)
    {
      p = p == from ? to : p;
    }
  }
  const MeshInspection dented = inspectMesh(soup);
  EXPECT_GT(dented.selfIntersections.count, 0u);
  EXPECT_EQ(dented.folds.count > 0, folds);
  EXPECT_EQ(dented.selfIntersections.count + dented.folds.count, pairsByCgal(soup));
  std::printf("%s dented: %zu self-intersecting pairs, %zu folds\n", name,
              dented.selfIntersections.count, dented.folds.count);
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, DentedMesh,
                         testing::Values(DentCase{"spot_triangulated.obj", false},
                                         DentCase{"fandisk.off", true},
                                         DentCase{"M3x10_screw.stl", true}),
                         [](const testing::TestParamInfo<DentCase>& info) {
                           std::string name = info.param.file;
                           for (char& c : name)
                           {
                             c = std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
                           }
                           return name;
                         });

} // namespace
} // namespace proxima
