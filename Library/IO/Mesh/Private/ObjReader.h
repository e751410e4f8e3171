// OBJ files through our own parser. vtkOBJReader was the first choice, but on VTK 9.1 it reads
// "nan", "inf" and unparsable numbers as 0 without a word, passes face indices out of range into
// the cells (and reads texture coordinates from beyond its arrays for a bad vt index), stores
// coordinates as float (a file written with 17 digits does not come back), and gives every face
// corner its own point once the file has vt or vn. Reading OBJ strictly is short work.
#pragma once

#include "IO/Mesh/Private/PolygonSoup.h"

#include <string>

namespace proxima::detail
{

/// Points in double precision: the file's vertices in file order, each with the texture
/// coordinate and normal of the first face corner naming it, then one more point for every other
/// (v, vt, vn) combination a corner uses (UV seams, creases); normals and texture coordinates
/// exist when any corner refers to them (zero for corners that do not). f statements become faces
/// (with one or two corners, a vertex cell or a line, only counted), l statements lines and p
/// statements vertex cells (counted). Throws InputError, with the line number, at the first
/// non-text byte, unparsable or non-finite number in a v, vt or vn statement, and index (0, or
/// out of range, relative or absolute) in an f, l or p statement.
PolygonSoup readObj(const std::string& path);

} // namespace proxima::detail
