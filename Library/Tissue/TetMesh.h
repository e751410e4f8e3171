// A tetrahedral mesh of a solid: the elements the tissue's elastic model is made of, filled into
// an organ's closed surface by IO/TissueMeshing. Plain C++ like the kernel, so that the solver can
// step it without any meshing library.
#pragma once

#include "Core/Vec3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace proxima
{

/// Points and tetrahedra, each tetrahedron four indices into the points, positively oriented:
/// (b - a) x (c - a) . (d - a) > 0, so that every signed volume is the element's volume.
struct TetMesh
{
  /// The points (m).
  std::vector<Vec3> points;
  /// One index quadruple per tetrahedron, each index into `points`.
  std::vector<std::array<std::uint32_t, 4>> tets;
};

/// The signed volume of tetrahedron (a, b, c, d), positive for the orientation TetMesh keeps.
double signedTetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The sum of the tetrahedra's signed volumes (m^3).
double totalVolume(const TetMesh& mesh);

/// The smallest of a tetrahedron's six dihedral angles (degrees): 70.53 for a regular one, 0 for
/// a flat one (a sliver), which an elastic model cannot step stably.
double minDihedralAngle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The smallest dihedral angle of all the mesh's tetrahedra (degrees); 180 for an empty mesh.
double minDihedralAngle(const TetMesh& mesh);

/// The number of tetrahedra whose signed volume is not above 0 (inverted or flat).
std::size_t countInvertedTets(const TetMesh& mesh);

} // namespace proxima
