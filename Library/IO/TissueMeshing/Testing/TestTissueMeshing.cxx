// The tissue's solids against measures that do not come from the mesher: the enclosed volume of
// the surface it filled (the divergence theorem over the input's own faces, and 4/3 pi r^3 for the
// sphere), every tetrahedron inside the wrap by the generalized winding number, the wrap closed
// and manifold by its edge counts, the smallest dihedral angle by another construction, and the
// .vtu file read back equal to what was written. On the bundled sphere and on the
// shipped kidney, a soup of 14 parts with holes and self-intersections.
#include "IO/TissueMeshing/TetMeshFile.h"
#include "IO/TissueMeshing/TissueMeshing.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/TriangleMesh.h"
#include "Geometry/WindingNumber.h"
#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/MeshReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

namespace proxima
{
namespace
{

const std::string kSphere = PROXIMA_SOURCE_DIR "/Data/Meshes/icosphere-4.obj";
const std::string kKidney = PROXIMA_SOURCE_DIR "/Data/Meshes/VH_M_Kidney_L.glb";

// The smallest dihedral angle of the mesh by another construction than TetMesh's (which takes it
// from the faces' normals): at each edge, the other two corners projected onto the plane across
// the edge, and the angle between them there. (VTK 9.1's Verdict "min angle" of a tetrahedron is
// no oracle for this: on one of these tetrahedra it gave 79.8 degrees where the six dihedral
// angles are 39.2, 45.0, 79.8, 81.1, 83.3 and 86.4.)
double projectedMinDihedralAngle(const TetMesh& mesh)
{
  double smallest = 180.0;
  for (const auto& tet : mesh.tets)
  {
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        int others[2];
        int n = 0;
        for (int k = 0; k < 4; ++k)
        {
          if (k != i && k != j)
          {
            others[n++] = k;
          }
        }
        const Vec3& p = mesh.points[tet[i]];
        const Vec3 edge = normalizedOrZero(mesh.points[tet[j]] - p);
        Vec3 u = mesh.points[tet[others[0]]] - p;
        Vec3 v = mesh.points[tet[others[1]]] - p;
        u = u - edge * dot(u, edge);
        v = v - edge * dot(v, edge);
        const double cosine = dot(u, v) / (norm(u) * norm(v));
        smallest =
          std::min(smallest, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi);
      }
    }
  }
  return smallest;
}

// Every edge of a closed, manifold, consistently oriented surface is used once in each
// direction: the count of directed edges with no reverse, or used twice, is its defects.
std::size_t orientedManifoldDefects(const TriangleSoup& surface)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : surface.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{t[k], t[(k + 1) % 3]}];
    }
  }
  std::size_t defects = 0;
  for (const auto& [edge, count] : directed)
  {
    const auto reverse = directed.find({edge.second, edge.first});
    defects += (count != 1 || reverse == directed.end() || reverse->second != 1) ? 1 : 0;
  }
  return defects;
}

TriangleMesh meshOf(const TriangleSoup& soup)
{
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(soup, error)) << "the wrap is not a mesh the kernel takes";
  return mesh;
}

// How far outside the wrap the farthest tetrahedron's centroid is (0 when every one is inside by
// the winding number): Mesh_3 approximates a curved boundary by flat facets, within its facet
// distance, so a tetrahedron at a concave place may stick out of the wrap by that much.
double farthestCentroidOutside(const TetMesh& tets, const TriangleSoup& wrap)
{
  const TriangleMesh surface = meshOf(wrap);
  double farthest = 0.0;
  for (const auto& tet : tets.tets)
  {
    const Vec3 centroid =
      (tets.points[tet[0]] + tets.points[tet[1]] + tets.points[tet[2]] + tets.points[tet[3]]) / 4.0;
    if (windingNumber(surface, centroid) > 0.5)
    {
      continue;
    }
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& t : wrap.triangles)
    {
      const ClosestPointResult closest =
        closestPointOnTriangle(centroid, wrap.points[t[0]], wrap.points[t[1]], wrap.points[t[2]]);
      nearest = std::min(nearest, std::sqrt(closest.squaredDistance));
    }
    farthest = std::max(farthest, nearest);
  }
  return farthest;
}

void expectSoundSolid(const TissueMeshingResult& result, double tetSize)
{
  const TetMesh& tets = result.tets;
  ASSERT_GT(tets.tets.size(), 100u);
  EXPECT_EQ(countInvertedTets(tets), 0u);
  EXPECT_EQ(orientedManifoldDefects(result.wrapped), 0u) << "the wrap is not closed and manifold";
  const double volume = totalVolume(tets);
  // Mesh_3 approximates the wrap's boundary by its facets: the volumes agree closely.
  EXPECT_NEAR(volume / result.wrappedVolume, 1.0, 0.03);
  EXPECT_LE(farthestCentroidOutside(tets, result.wrapped), 0.1 * tetSize);
  const double smallest = minDihedralAngle(tets);
  EXPECT_NEAR(smallest, projectedMinDihedralAngle(tets), 1e-9);
  // Exudation leaves no sliver flatter than this on these surfaces (Mesh_3 reaches about 5-12
  // degrees; an elastic step needs no element near 0).
  EXPECT_GT(smallest, 2.0);
  std::cout << "[ measured ] " << tets.tets.size() << " tetrahedra, " << tets.points.size()
            << " points, min dihedral " << smallest << " deg, volume " << volume << " m^3 (wrap "
            << result.wrappedVolume << "), wrap " << result.wrapSeconds << " s, fill "
            << result.fillSeconds << " s\n";
}

TEST(TissueMeshing, TheSphereIsFilledToItsVolume)
{
  const TriangleSoup sphere = readMeshFile(kSphere);
  TissueMeshingOptions options;
  options.tetSize = 0.01; // a fifth of the 5 cm radius
  const TissueMeshingResult result = meshTissue(sphere, options, kSphere);
  const double radius = 0.05;
  const double ball = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  // The icosphere's own volume is a little under the ball's (its faces are chords).
  const double inputVolume = enclosedVolume(sphere);
  EXPECT_NEAR(inputVolume / ball, 1.0, 0.01);
  EXPECT_GT(result.wrappedVolume, inputVolume) << "the wrap must contain the surface it wraps";
  EXPECT_NEAR(totalVolume(result.tets) / inputVolume, 1.0, 0.03);
  expectSoundSolid(result, options.tetSize);
}

TEST(TissueMeshing, TheKidneySoupIsWrappedAndFilled)
{
  // 14 parts, holes and self-intersecting pairs: no volume of its own to compare with, so the
  // checks are that the wrap holds every point of it, and the tetrahedra the wrap's volume.
  const TriangleSoup kidney = readMeshFile(kKidney);
  TissueMeshingOptions options;
  options.tetSize = 0.005;
  const TissueMeshingResult result = meshTissue(kidney, options, kKidney);
  expectSoundSolid(result, options.tetSize);
  // Every input point lies inside or on the wrap (it contains the soup, by an offset).
  const TriangleMesh wrap = meshOf(result.wrapped);
  std::size_t outside = 0;
  for (std::size_t i = 0; i < kidney.points.size(); i += 97)
  {
    outside += windingNumber(wrap, kidney.points[i]) > 0.5 ? 0 : 1;
  }
  EXPECT_EQ(outside, 0u);
}

TEST(TissueMeshing, TheFileIsReadBackAsWritten)
{
  const TriangleSoup sphere = readMeshFile(kSphere);
  TissueMeshingOptions options;
  options.tetSize = 0.02;
  const TetMesh written = meshTissue(sphere, options, kSphere).tets;
  const std::string path =
    (std::filesystem::temp_directory_path() / "proxima-tissue-roundtrip.vtu").string();
  writeTetMeshFile(path, written);
  const TetMesh read = readTetMeshFile(path);
  std::filesystem::remove(path);
  ASSERT_EQ(read.points.size(), written.points.size());
  ASSERT_EQ(read.tets.size(), written.tets.size());
  for (std::size_t i = 0; i < read.points.size(); ++i)
  {
    EXPECT_EQ(read.points[i], written.points[i]) << "point " << i;
  }
  EXPECT_EQ(read.tets, written.tets);
}

TEST(TissueMeshing, BadInputIsRefusedNamingTheFileOrOption)
{
  const TriangleSoup sphere = readMeshFile(kSphere);
  TissueMeshingOptions options;
  const auto refusal = [&](const TriangleSoup& surface, double tetSize) {
    TissueMeshingOptions changed = options;
    changed.tetSize = tetSize;
    try
    {
      meshTissue(surface, changed, "organ.obj");
    }
    catch (const InputError& error)
    {
      return std::string(error.what());
    }
    return std::string("no refusal");
  };
  EXPECT_EQ(refusal(TriangleSoup{}, 0.01), "organ.obj: the surface has no triangles to fill");
  TriangleSoup broken = sphere;
  broken.points[7].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refusal(broken, 0.01), "organ.obj: a point of the surface is not finite");
  EXPECT_EQ(refusal(sphere, 0.0), "--tet-size: must be a finite length above 0, not 0");
  EXPECT_EQ(refusal(sphere, std::numeric_limits<double>::quiet_NaN()),
            "--tet-size: must be a finite length above 0, not nan");
  EXPECT_EQ(refusal(sphere, 0.2), "--tet-size: 0.2 m is larger than organ.obj (its bounding box's "
                                  "smallest side is 0.1 m)");
}

TEST(TissueMeshing, ABadTetFileIsRefusedNamingIt)
{
  const auto refusal = [](const std::string& path) {
    try
    {
      readTetMeshFile(path);
    }
    catch (const InputError& error)
    {
      return std::string(error.what());
    }
    return std::string("no refusal");
  };
  EXPECT_EQ(refusal("/no/such/file.vtu"),
            "/no/such/file.vtu: cannot open the file (no such regular file)");
  const std::string text =
    (std::filesystem::temp_directory_path() / "proxima-tissue-not-vtu.vtu").string();
  std::ofstream(text) << "not xml at all\n";
  EXPECT_EQ(refusal(text), text + ": not a VTK XML unstructured grid (.vtu) file");
  std::filesystem::remove(text);
}

} // namespace
} // namespace proxima
