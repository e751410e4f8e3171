#include "Tissue/TetMesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace proxima
{

double signedTetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return dot(cross(b - a, c - a), d - a) / 6.0;
}

double totalVolume(const TetMesh& mesh)
{
  double volume = 0.0;
  for (const auto& tet : mesh.tets)
  {
    volume += signedTetVolume(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                              mesh.points[tet[3]]);
  }
  return volume;
}

double minDihedralAngle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  // The dihedral angle at the edge that faces i and j share is pi minus the angle between their
  // outward normals. Face i is the one opposite corner i, its corners in the order that makes
  // its normal point away from corner i when (a, b, c, d) is positively oriented (each order is
  // an odd permutation of a, b, c, d); the volume's sign turns them for the other orientation.
  // Taken from the orientation rather than from a side test, so that a flat tetrahedron gets two
  // opposite normals and an angle of 0.
  const Vec3 faces[4][3] = {{b, c, d}, {a, d, c}, {a, b, d}, {a, c, b}};
  const double sign = signedTetVolume(a, b, c, d) < 0.0 ? -1.0 : 1.0;
  Vec3 outward[4];
  for (int i = 0; i < 4; ++i)
  {
    const Vec3 normal = cross(faces[i][1] - faces[i][0], faces[i][2] - faces[i][0]);
    const double length = norm(normal);
    if (!(length > 0.0))
    {
      return 0.0; // a face with no area: the tetrahedron is flat
    }
    outward[i] = normal * (sign / length);
  }
  double smallest = 180.0;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      const double cosine = std::clamp(dot(outward[i], outward[j]), -1.0, 1.0);
      smallest = std::min(smallest, 180.0 - std::acos(cosine) * 180.0 / std::numbers::pi);
    }
  }
  return smallest;
}

double minDihedralAngle(const TetMesh& mesh)
{
  double smallest = 180.0;
  for (const auto& tet : mesh.tets)
  {
    smallest = std::min(smallest, minDihedralAngle(mesh.points[tet[0]], mesh.points[tet[1]],
                                                   mesh.points[tet[2]], mesh.points[tet[3]]));
  }
  return smallest;
}

std::size_t countInvertedTets(const TetMesh& mesh)
{
  return static_cast<std::size_t>(
    std::count_if(mesh.tets.begin(), mesh.tets.end(), [&](const auto& tet) {
      return !(signedTetVolume(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                               mesh.points[tet[3]]) > 0.0);
    }));
}

} // namespace proxima
