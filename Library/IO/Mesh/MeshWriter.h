// Writing a triangle soup to a mesh file, for meshes the project generates itself (Data/).
#pragma once

#include "Geometry/TriangleSoup.h"
#include "IO/InputChecks/InputError.h"

#include <string>

namespace proxima
{

/// Writes `soup` through VTK's writers, the format chosen by extension (case-insensitive):
/// .obj (with point normals and texture coordinates when the soup has them, 17 significant
/// digits), .stl (binary, single precision), .ply (binary), .vtp (VTK XML, double precision).
/// The file appears complete or not at all (AtomicOutputFile). Throws InputError when the
/// extension is not one of these, OutputError (an InputError) when the file cannot be written in
/// full, and std::invalid_argument when the soup's attributes do not match its points.
void writeMeshFile(const std::string& path, const TriangleSoup& soup);

/// True when writeMeshFile writes `path`'s format (by its extension), so that a command can
/// refuse another before it makes what it would write.
bool isWritableMeshFormat(const std::string& path);

/// The words writeMeshFile refuses another format with.
inline constexpr const char* kWritableMeshFormatsMessage =
  "cannot write this format (write .obj, .stl, .ply or .vtp)";

} // namespace proxima
