// Cheap checks of a file's first bytes (and, for binary STL, its size) against its extension,
// so that a garbled or misnamed file gets a clear message instead of whatever a reader makes of
// it: VTK's STL reader, for one, reads random bytes as triangles of random floats.
#pragma once

#include "IO/Mesh/MeshFileFormat.h"

#include <cstdint>
#include <string>

namespace proxima::detail
{

/// Throws InputError when the start of the file cannot be `format`. For STL, a file that does
/// not look like ASCII ("solid" followed by text) is binary, and its size must hold the triangle
/// count in its header: 84 + 50 n bytes. OBJ, PLY and OFF are checked in depth by their own readers.
void checkSignature(const std::string& path, MeshFileFormat format, std::uintmax_t fileSize);

} // namespace proxima::detail
