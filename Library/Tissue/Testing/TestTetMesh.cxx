// The tetrahedral mesh's measures against closed forms: the regular tetrahedron's dihedral angle
// arccos(1/3) and volume a^3 / (6 sqrt 2), the corner tetrahedron's 90 and arccos(1/sqrt 3)
// degrees, the unit cube cut into Kuhn's six tetrahedra, and flat and inverted elements.
#include "Tissue/TetMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace proxima
{
namespace
{

constexpr double kDegrees = 180.0 / std::numbers::pi;

TEST(TetMesh, RegularTetrahedronHasTheClosedFormAngleAndVolume)
{
  const double a = 0.01; // a 1 cm edge
  const Vec3 p0{0, 0, 0};
  const Vec3 p1{a, 0, 0};
  const Vec3 p2{a / 2, a * std::sqrt(3.0) / 2, 0};
  const Vec3 p3{a / 2, a * std::sqrt(3.0) / 6, a * std::sqrt(2.0 / 3.0)};
  EXPECT_NEAR(signedTetVolume(p0, p1, p2, p3), a * a * a / (6.0 * std::sqrt(2.0)), 1e-20);
  EXPECT_NEAR(minDihedralAngle(p0, p1, p2, p3), std::acos(1.0 / 3.0) * kDegrees, 1e-9);
  // The other orientation: the same angles, the volume negated.
  EXPECT_NEAR(signedTetVolume(p0, p2, p1, p3), -a * a * a / (6.0 * std::sqrt(2.0)), 1e-20);
  EXPECT_NEAR(minDihedralAngle(p0, p2, p1, p3), std::acos(1.0 / 3.0) * kDegrees, 1e-9);
}

TEST(TetMesh, CornerTetrahedronHasRightAndSlantedAngles)
{
  // Edges along the axes meet faces at 90 degrees; the slanted face x + y + z = 1 meets each
  // axis plane at arccos(1 / sqrt 3).
  const double smallest = minDihedralAngle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_NEAR(smallest, std::acos(1.0 / std::sqrt(3.0)) * kDegrees, 1e-9);
  EXPECT_NEAR(signedTetVolume({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), 1.0 / 6.0, 1e-15);
}

TEST(TetMesh, KuhnsSixTetrahedraFillTheUnitCube)
{
  TetMesh cube;
  for (int i = 0; i < 8; ++i)
  {
    cube.points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  }
  // Each tetrahedron is a path from corner 0 to corner 7 along the three axes in one order.
  const int axes[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
  for (const auto& order : axes)
  {
    const std::uint32_t b = order[0];
    const std::uint32_t c = b + order[1];
    std::array<std::uint32_t, 4> tet{0, b, c, 7};
    if (signedTetVolume(cube.points[0], cube.points[b], cube.points[c], cube.points[7]) < 0.0)
    {
      std::swap(tet[1], tet[2]);
    }
    cube.tets.push_back(tet);
  }
  EXPECT_NEAR(totalVolume(cube), 1.0, 1e-15);
  EXPECT_EQ(countInvertedTets(cube), 0u);
  // Kuhn's tetrahedra have dihedral angles of 45, 60 and 90 degrees.
  EXPECT_NEAR(minDihedralAngle(cube), 45.0, 1e-9);
}

TEST(TetMesh, FlatAndInvertedTetrahedraAreFound)
{
  TetMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  mesh.tets = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 1, 4, 2}};
  EXPECT_EQ(countInvertedTets(mesh), 2u); // one inverted, one flat (all four in z = 0)
  EXPECT_EQ(minDihedralAngle(mesh.points[0], mesh.points[1], mesh.points[4], mesh.points[2]), 0.0);
  EXPECT_EQ(minDihedralAngle(TetMesh{}), 180.0);
}

} // namespace
} // namespace proxima
