// A box filled with tetrahedra: the solid of the elastic model's checks against closed forms (a
// cantilever beam, a block pressed by a sphere), where the exact answer is known for a box.
#pragma once

#include "Core/Vec3.h"
#include "Tissue/TetMesh.h"

#include <vector>

namespace proxima
{

/// The box from `lower` to `upper` cut into nx x ny x nz cells, each cut into Kuhn's six
/// tetrahedra along its diagonal from the lower corner to the upper one. Every cell is cut the
/// same way, so neighbouring cells share whole faces (the mesh is conforming). Points are
/// numbered x fastest, then y, then z: (i, j, k) is i + (nx + 1) (j + (ny + 1) k).
TetMesh makeBoxTetMesh(const Vec3& lower, const Vec3& upper, int nx, int ny, int nz);

/// The same for a grid whose planes are at the given coordinates along each axis (each list
/// increasing, at least two), so that cells may be finer in one place than another: a block
/// pressed by a sphere needs cells much smaller than the contact under it and few far from it.
TetMesh makeGridTetMesh(const std::vector<double>& xs, const std::vector<double>& ys,
                        const std::vector<double>& zs);

/// Coordinates from `from` to `to` whose spacing is `finest` at `from` and grows by `growth`
/// (at least 1) from one cell to the next; the last cell ends at `to`, at least as long as the
/// one before it and under twice `growth` times it.
std::vector<double> gradedCoordinates(double from, double to, double finest, double growth);

} // namespace proxima
