// OFF files through OpenMesh's parser (VTK has no OFF reader), collected as raw polygons rather
// than into an OpenMesh halfedge mesh: a halfedge mesh drops non-manifold faces, and a polygon
// soup must arrive whole.
#pragma once

#include "IO/Mesh/Private/PolygonSoup.h"

#include <string>

namespace proxima::detail
{

/// Points (with normals and texture coordinates when the file has them) and polygons, as read;
/// faces of one or two vertices are counted as vertex and line cells. Throws InputError for a bad header,
/// unparsable or truncated data (reported with the vertex or face where parsing stopped) and
/// indices out of range. Coordinates are stored in double: an ASCII file's as the text writes them
/// (OpenMesh parses them in float, so the reader's own pre-check walk parses them again in double
/// and those replace OpenMesh's), a binary file's as its float32 values, exactly.
PolygonSoup readOffWithOpenMesh(const std::string& path);

} // namespace proxima::detail
