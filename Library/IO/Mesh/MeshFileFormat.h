// The mesh file formats the IO layer reads and writes, chosen by the file name's extension.
#pragma once

#include <optional>
#include <string>

namespace proxima
{

/// A mesh file format Proxima reads.
enum class MeshFileFormat
{
  Stl,  ///< .stl, binary or ASCII
  Obj,  ///< .obj (Wavefront)
  Ply,  ///< .ply, binary or ASCII
  Vtp,  ///< .vtp (VTK's XML polygonal data)
  Gltf, ///< .gltf (JSON with external or embedded buffers) and .glb (binary)
  Off   ///< .off (Object File Format)
};

/// The format named by the extension of `path`, compared case-insensitively (CAD tools write
/// "part.STL"), or nothing when the extension is not one we read.
std::optional<MeshFileFormat> meshFileFormatFromPath(const std::string& path);

/// The extensions we read, for messages: ".stl, .obj, .ply, .vtp, .gltf, .glb, .off".
std::string readableMeshExtensions();

/// Lower-case name of a format ("stl", "obj", ...), for messages and reports.
const char* meshFileFormatName(MeshFileFormat format);

} // namespace proxima
