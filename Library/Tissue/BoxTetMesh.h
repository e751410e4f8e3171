// A box filled with tetrahedra: the solid of the elastic model's checks against closed forms (a
// cantilever beam, a block pressed by a sphere), where the exact answer is known for a box.
#pragma once

#include "Core/Vec3.h"
#include "Tissue/TetMesh.h"

namespace proxima
{

/// The box from `lower` to `upper` cut into nx x ny x nz cells, each cut into Kuhn's six
/// tetrahedra along its diagonal from the lower corner to the upper one. Every cell is cut the
/// same way, so neighbouring cells share whole faces (the mesh is conforming). Points are
/// numbered x fastest, then y, then z: (i, j, k) is i + (nx + 1) (j + (ny + 1) k).
TetMesh makeBoxTetMesh(const Vec3& lower, const Vec3& upper, int nx, int ny, int nz);

} // namespace proxima
