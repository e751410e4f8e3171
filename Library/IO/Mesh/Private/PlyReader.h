// PLY files (ASCII and binary, either byte order) through our own parser. vtkPLYReader was the
// first choice, but it trusts the file: an element without properties, vertex data cut short or
// a face index out of range makes it free wild pointers or read outside its arrays (seen on VTK
// 9.1: "free(): invalid pointer", and a crash in vtkCell::Initialize), where we must refuse the
// file with a message. The format is small enough to read strictly here.
#pragma once

#include "IO/Mesh/Private/PolygonSoup.h"

#include <cstdint>
#include <string>

namespace proxima::detail
{

/// Points (x, y, z; normals from nx, ny, nz; texture coordinates from u, v or s, t or
/// texture_u, texture_v) and the polygons of the "face" element's vertex_indices list (faces of
/// one or two vertices are counted as vertex and line cells); other elements and properties are skipped.
/// Throws InputError for a malformed header, data cut short or unparsable, and face indices out
/// of range.
PolygonSoup readPly(const std::string& path, std::uintmax_t fileSize);

} // namespace proxima::detail
