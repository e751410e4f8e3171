// The surface of a tetrahedral solid: the faces that belong to one tetrahedron only, faced out.
// It is what the proxy touches: a triangle mesh over the solid's own points, so that the points
// a simulation step leaves are the surface's points as they are (ProxySolver::setObjectPoints).
#pragma once

#include "Geometry/TriangleSoup.h"
#include "Tissue/TetMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace proxima
{
/// The faces of `mesh` that no second tetrahedron shares, each as three indices into
/// mesh.points, ordered so that (b - a) x (c - a) points out of its tetrahedron. A closed,
/// conforming solid gives a closed surface; faces are listed in the order of their tetrahedra.
std::vector<std::array<std::uint32_t, 3>> boundaryTriangles(const TetMesh& mesh);

/// The surface as a triangle soup over all of `mesh`'s points (those inside the solid unused), so
/// that point i of the soup is point i of the solid: what a scene object of the tissue is built
/// from, and what ProxySolver::setObjectPoints is given the solid's positions for.
TriangleSoup boundarySoup(const TetMesh& mesh);
} // namespace proxima
