// Reading meshes from files into the kernel's types. This is where file data becomes kernel
// data: every defect (missing or garbled file, non-finite coordinates, indices out of range, no
// triangles) is refused here with an InputError naming the file and the defect, so nothing bad
// reaches the haptic loop. No VTK or OpenMesh type appears in this header.
#pragma once

#include "Geometry/TriangleMesh.h"
#include "Geometry/TriangleSoup.h"
#include "IO/InputChecks/InputError.h"

#include <string>

namespace proxima
{

/// Reads the triangles of a mesh file, chosen by extension (case-insensitive): STL, VTP (VTK XML
/// poly data) and glTF/GLB (all meshes of the default scene, node transforms applied, merged into
/// one soup) through VTK's readers, OFF through OpenMesh's parser, and OBJ and PLY through strict
/// parsers of our own (VTK's readers of these two accept NaN, out-of-range indices and truncated
/// data, silently or by crashing; see IO/Mesh/Private/ObjReader.h and PlyReader.h). Precision: OBJ,
/// PLY, VTP and ASCII OFF as written (OFF in double despite OpenMesh's float parse, see
/// IO/Mesh/Private/OffReader.h); STL, glTF and binary OFF in single precision. Polygons and triangle
/// strips are triangulated (OBJ, PLY and OFF without VTK when their faces are all triangles;
/// polygons of more than three corners, and STL, VTP and glTF, through VTK in a module loaded on
/// first use); lines and vertices are ignored. Point normals and texture
/// coordinates are carried over when the file has them (one per point). Every coordinate is
/// multiplied by `scale` (file units to metres).
///
/// Throws InputError for a missing, unreadable, empty or garbled file, an unsupported extension,
/// a non-finite coordinate, normal or texture coordinate, an index out of range, or a file with
/// no triangles. Throws std::invalid_argument when `scale` is not a positive finite number.
TriangleSoup readMeshFile(const std::string& path, double scale = 1.0);

/// readMeshFile followed by TriangleMesh::build: the mesh the kernel works on. A MeshError
/// becomes an InputError naming the file. Degenerate triangles are kept (and counted by
/// TriangleMesh::numDegenerateTriangles).
TriangleMesh loadTriangleMesh(const std::string& path, double scale = 1.0);

/// TriangleMesh::build of a soup read from `path` (changed since, say by
/// withFeatureAngleNormals): a MeshError becomes an InputError naming the file.
TriangleMesh buildTriangleMesh(TriangleSoup soup, const std::string& path);

} // namespace proxima
