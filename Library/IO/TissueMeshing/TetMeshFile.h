// Tetrahedral meshes as files: VTK's XML unstructured grid (.vtu), which ParaView and VTK's
// readers open, with each tetrahedron as a VTK_TETRA cell. VTK stays in the .cpp file.
#pragma once

#include "Tissue/TetMesh.h"

#include <string>

namespace proxima
{

/// Writes `mesh` to `path` as a .vtu file, atomically (AtomicOutputFile: all or nothing). Throws
/// OutputError naming the file when it cannot be written.
void writeTetMeshFile(const std::string& path, const TetMesh& mesh);

/// Reads the tetrahedra of the .vtu file at `path` (cells of other types are refused). Throws
/// InputError naming the file for one that cannot be read, has no tetrahedron, has a cell that
/// is not a tetrahedron, or a point that is not finite.
TetMesh readTetMeshFile(const std::string& path);

} // namespace proxima
