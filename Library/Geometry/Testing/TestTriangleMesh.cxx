// TriangleMesh::build: every defect of DESIGN.md section 6 is refused with a message that names
// where it is, a refused build leaves the mesh as it was, and degenerate triangles are counted
// (against CGAL's exact collinearity test) but kept.
#include "Geometry/TriangleMesh.h"

#include "ExactOracle.h"
#include "GeometryTestSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace proxima::test
{
namespace
{

/// A valid random soup of `numTriangles` triangles over `numPoints` points.
TriangleSoup makeSoup(Random& random, std::uint32_t numPoints, std::uint32_t numTriangles,
                      bool withAttributes)
{
  TriangleSoup soup;
  for (std::uint32_t i = 0; i < numPoints; ++i)
  {
    soup.points.push_back(random.inCube(1.0));
    if (withAttributes)
    {
      soup.pointNormals.push_back(random.direction());
      soup.texCoords.push_back({random.uniform(0, 1), random.uniform(0, 1)});
    }
  }
  for (std::uint32_t t = 0; t < numTriangles; ++t)
  {
    soup.triangles.push_back({static_cast<std::uint32_t>(random.integer(0, int(numPoints) - 1)),
                              static_cast<std::uint32_t>(random.integer(0, int(numPoints) - 1)),
                              static_cast<std::uint32_t>(random.integer(0, int(numPoints) - 1))});
  }
  return soup;
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

TEST(TriangleMesh, RefusesEachDefectNamingWhereItIs)
{
  constexpr std::uint64_t kSeed = 0x3e5a0001;
  Random random(kSeed);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 2000; ++trial)
  {
    const auto numPoints = static_cast<std::uint32_t>(random.integer(3, 200));
    const auto numTriangles = static_cast<std::uint32_t>(random.integer(1, 300));
    TriangleSoup soup = makeSoup(random, numPoints, numTriangles, random.chance(0.5));
    const bool withAttributes = !soup.pointNormals.empty();
    const int defect = random.integer(0, withAttributes ? 6 : 3);
    const auto where = static_cast<std::uint32_t>(random.integer(0, int(numPoints) - 1));
    const auto whichTriangle = static_cast<std::uint32_t>(random.integer(0, int(numTriangles) - 1));
    MeshError::Kind expectedKind = MeshError::Kind::None;
    std::string expectedText;
    switch (defect)
    {
      case 0:
        soup.points[where][random.integer(0, 2)] = random.chance(0.5) ? nan : -inf;
        expectedKind = MeshError::Kind::NonFiniteCoordinate;
        expectedText = "point " + std::to_string(where);
        break;
      case 1:
      {
        const auto bad = numPoints + static_cast<std::uint32_t>(random.integer(0, 5));
        soup.triangles[whichTriangle][random.integer(0, 2)] =
          random.chance(0.2) ? std::numeric_limits<std::uint32_t>::max() : bad;
        expectedKind = MeshError::Kind::IndexOutOfRange;
        expectedText = "triangle " + std::to_string(whichTriangle);
        break;
      }
      case 2:
        soup.triangles.clear();
        expectedKind = MeshError::Kind::NoTriangles;
        expectedText = "no triangles";
        break;
      case 3:
        soup.points[where].x = inf;
        expectedKind = MeshError::Kind::NonFiniteCoordinate;
        expectedText = "point " + std::to_string(where);
        break;
      case 4:
        soup.pointNormals.pop_back();
        expectedKind = MeshError::Kind::AttributeSizeMismatch;
        expectedText = std::to_string(numPoints - 1);
        break;
      case 5:
        soup.texCoords.push_back({0, 0});
        expectedKind = MeshError::Kind::AttributeSizeMismatch;
        expectedText = std::to_string(numPoints + 1);
        break;
      default:
        if (random.chance(0.5))
        {
          soup.pointNormals[where].z = nan;
          expectedText = "normal " + std::to_string(where);
        }
        else
        {
          soup.texCoords[where].v = inf;
          expectedText = "coordinate " + std::to_string(where);
        }
        expectedKind = MeshError::Kind::NonFiniteAttribute;
        break;
    }
    TriangleMesh mesh;
    MeshError error;
    EXPECT_FALSE(mesh.build(soup, error)) << "seed 0x3e5a0001 trial " << trial;
    EXPECT_EQ(error.kind, expectedKind) << "trial " << trial << ": " << error.message;
    EXPECT_TRUE(contains(error.message, expectedText))
      << "trial " << trial << ": \"" << error.message << "\" should name \"" << expectedText
      << "\"";
    EXPECT_TRUE(static_cast<bool>(error));
    EXPECT_EQ(mesh.numTriangles(), 0u) << "a refused build must leave the mesh unchanged";
  }
}

TEST(TriangleMesh, ARefusedBuildLeavesTheOldMesh)
{
  Random random(0x3e5a0002);
  TriangleMesh mesh;
  MeshError error;
  ASSERT_TRUE(mesh.build(makeSoup(random, 10, 12, true), error)) << error.message;
  EXPECT_FALSE(error);
  const TriangleCorners before = mesh.corners(5);
  TriangleSoup bad = makeSoup(random, 10, 3, false);
  bad.points[2].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(mesh.build(bad, error));
  EXPECT_EQ(mesh.numTriangles(), 12u);
  EXPECT_EQ(mesh.corners(5).a, before.a);
  EXPECT_TRUE(mesh.hasPointNormals());
}

// movePoints: the corners and bounds follow the moved points (checked against the triangles'
// indices, independently of how the mesh stores them), a collapsed triangle counts as degenerate,
// and a wrong count or a NaN point changes nothing.
TEST(TriangleMesh, MovePointsMovesCornersAndBoundsOrNothing)
{
  Random random(0x3e5a0005);
  TriangleMesh mesh;
  MeshError error;
  ASSERT_TRUE(mesh.build(makeSoup(random, 10, 12, true), error)) << error.message;
  std::vector<Vec3> moved = mesh.points();
  for (Vec3& p : moved)
  {
    p = p * 2.0 + Vec3{5.0, -1.0, 0.5};
  }
  const std::array<std::uint32_t, 3> first = mesh.indices(0);
  moved[first[1]] = moved[first[0]]; // triangle 0 collapses onto an edge
  ASSERT_TRUE(mesh.movePoints(moved.data(), moved.size()));
  Aabb expected;
  for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
  {
    const std::array<std::uint32_t, 3>& tri = mesh.indices(t);
    EXPECT_EQ(mesh.corners(t).a, moved[tri[0]]) << t;
    EXPECT_EQ(mesh.corners(t).b, moved[tri[1]]) << t;
    EXPECT_EQ(mesh.corners(t).c, moved[tri[2]]) << t;
    for (std::uint32_t k : tri)
    {
      expected.expand(moved[k]);
    }
  }
  EXPECT_EQ(mesh.bounds().lower, expected.lower);
  EXPECT_EQ(mesh.bounds().upper, expected.upper);
  EXPECT_GE(mesh.numDegenerateTriangles(), 1u);

  const TriangleCorners before = mesh.corners(5);
  std::vector<Vec3> bad = moved;
  bad[3].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(mesh.movePoints(bad.data(), bad.size()));
  EXPECT_FALSE(mesh.movePoints(moved.data(), moved.size() - 1));
  EXPECT_EQ(mesh.corners(5).a, before.a);
  EXPECT_EQ(mesh.points()[3], moved[3]);
}

TEST(TriangleMesh, CountsDegenerateTrianglesAndKeepsThem)
{
  // Against CGAL's exact collinearity test, on soups mixing fat triangles, slivers to aspect
  // 1e12 (not degenerate), and exactly collinear or coincident corners (degenerate).
  constexpr std::uint64_t kSeed = 0x3e5a0003;
  Random random(kSeed);
  const TriangleShape shapes[] = {TriangleShape::Fat,        TriangleShape::Needle,
                                  TriangleShape::Cap,        TriangleShape::Collinear,
                                  TriangleShape::Coincident, TriangleShape::SinglePoint};
  long numChecked = 0;
  for (int soupIndex = 0; soupIndex < 100; ++soupIndex)
  {
    TriangleSoup soup;
    std::uint32_t expectedDegenerate = 0;
    Aabb expectedBounds;
    for (int t = 0; t < 100; ++t)
    {
      const TriangleShape shape = shapes[random.integer(0, 5)];
      const double size = random.chance(0.5) ? 1.0 : 1e-3;
      const TriangleCorners c =
        makeTriangle(random, shape, size, random.chance(0.3) ? Vec3{1e4, 0, 0} : Vec3{},
                     random.logUniform(0.0, 12.0));
      const auto first = static_cast<std::uint32_t>(soup.points.size());
      for (const Vec3& p : {c.a, c.b, c.c})
      {
        soup.points.push_back(p);
        expectedBounds.expand(p);
      }
      soup.triangles.push_back({first, first + 1, first + 2});
      expectedDegenerate += CGAL::collinear(toExact(c.a), toExact(c.b), toExact(c.c)) ? 1u : 0u;
    }
    TriangleMesh mesh;
    MeshError error;
    ASSERT_TRUE(mesh.build(soup, error)) << error.message;
    EXPECT_EQ(mesh.numTriangles(), 100u);
    EXPECT_EQ(mesh.numDegenerateTriangles(), expectedDegenerate)
      << "seed 0x3e5a0003 soup " << soupIndex;
    EXPECT_EQ(mesh.bounds().lower, expectedBounds.lower);
    EXPECT_EQ(mesh.bounds().upper, expectedBounds.upper);
    EXPECT_EQ(mesh.maxAbsCoordinate(), std::fmax(maxAbsComponent(expectedBounds.lower),
                                                 maxAbsComponent(expectedBounds.upper)));
    for (std::uint32_t t = 0; t < mesh.numTriangles(); ++t)
    {
      const auto& index = mesh.indices(t);
      EXPECT_EQ(mesh.corners(t).a, soup.points[index[0]]);
      EXPECT_EQ(mesh.corners(t).b, soup.points[index[1]]);
      EXPECT_EQ(mesh.corners(t).c, soup.points[index[2]]);
      ++numChecked;
    }
  }
  EXPECT_EQ(numChecked, 10000);
}

TEST(TriangleMesh, UnusedPointsStillCountAndAttributesArePassedThrough)
{
  Random random(0x3e5a0004);
  TriangleSoup soup = makeSoup(random, 50, 5, true);
  TriangleMesh mesh;
  MeshError error;
  ASSERT_TRUE(mesh.build(soup, error));
  EXPECT_EQ(mesh.numPoints(), 50u);
  EXPECT_EQ(mesh.pointNormals().size(), 50u);
  EXPECT_EQ(mesh.texCoords()[7].u, soup.texCoords[7].u);
  EXPECT_GE(mesh.memoryBytes(), 50 * sizeof(Vec3) + 5 * sizeof(TriangleCorners));
}

} // namespace
} // namespace proxima::test
