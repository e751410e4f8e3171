// The copy of a checked glTF file that VTK's loader reads instead of the user's file. Two reasons:
// VTK parses the file's JSON with another parser than our checks (jsoncpp accepts comments and
// trailing bytes that nlohmann-json refuses), so it must read exactly the document that was
// checked, re-serialised; and the copy keeps only what a haptic scene is made of (scenes, nodes,
// meshes, skins, accessors, buffer views, buffers), so images, materials, animations, cameras and
// extensions, which VTK decodes and trusts without bounds checks (fuzzing: a SEGV on a texture
// naming an image VTK had dropped), never reach it. A GLB's chunks after its JSON are copied byte
// for byte; a .gltf's buffer files are named by absolute paths. The copy is removed with this.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace proxima::detail
{

class GltfGeometryFile
{
public:
  /// Writes the copy of `sourcePath`, whose parsed JSON is `document`. For a GLB,
  /// `glbChunksOffset` is where the chunks after its JSON chunk begin in `sourcePath`. Throws
  /// std::runtime_error naming the temporary file when it cannot be written.
  GltfGeometryFile(const std::string& sourcePath, const nlohmann::json& document,
                   std::optional<std::uint64_t> glbChunksOffset);
  ~GltfGeometryFile();
  GltfGeometryFile(const GltfGeometryFile&) = delete;
  GltfGeometryFile& operator=(const GltfGeometryFile&) = delete;

  /// The copy, with the source's extension (VTK's loader dispatches on it).
  const std::string& path() const { return m_path; }

private:
  std::string m_path;
};

} // namespace proxima::detail
