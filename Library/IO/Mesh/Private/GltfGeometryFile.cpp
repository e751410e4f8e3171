#include "IO/Mesh/Private/GltfGeometryFile.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace proxima::detail
{
namespace
{
using Json = nlohmann::json;
namespace fs = std::filesystem;

/// The parts of a glTF document that the geometry of its default scene is made of.
constexpr const char* kGeometryKeys[] = {"asset", "scene",     "scenes",      "nodes",  "meshes",
                                         "skins", "accessors", "bufferViews", "buffers"};

/// Calls `edit` on every object of the array `key` of `holder`, if it has one.
template <class Edit>
void forEachIn(Json& holder, const char* key, Edit edit)
{
  const auto list = holder.find(key);
  if (list == holder.end() || !list->is_array())
  {
    return;
  }
  for (Json& entry : *list)
  {
    if (entry.is_object())
    {
      edit(entry);
    }
  }
}

Json geometryOnly(const Json& document, const fs::path& sourceFolder)
{
  Json copy = Json::object();
  for (const char* key : kGeometryKeys)
  {
    const auto it = document.find(key);
    if (it != document.end())
    {
      copy[key] = *it;
    }
  }
  // References into what was left out: cameras, materials, extensions.
  forEachIn(copy, "nodes", [](Json& node) {
    node.erase("camera");
    node.erase("extensions");
  });
  forEachIn(copy, "meshes", [](Json& mesh) {
    forEachIn(mesh, "primitives", [](Json& primitive) {
      primitive.erase("material");
      primitive.erase("extensions");
    });
  });
  // The copy lives elsewhere: a buffer file is named by where it is, not relative to the copy.
  forEachIn(copy, "buffers", [&](Json& buffer) {
    const auto uri = buffer.find("uri");
    if (uri != buffer.end() && uri->is_string() &&
        uri->get_ref<const std::string&>().rfind("data:", 0) != 0)
    {
      *uri = fs::absolute(sourceFolder / uri->get<std::string>()).lexically_normal().string();
    }
  });
  return copy;
}

void writeWord(std::ofstream& out, std::uint32_t value)
{
  const char bytes[4] = {static_cast<char>(value & 0xff), static_cast<char>((value >> 8) & 0xff),
                         static_cast<char>((value >> 16) & 0xff), static_cast<char>(value >> 24)};
  out.write(bytes, 4);
}

/// A name no other copy has, of the same length in every process (reproducible fuzzing: a
/// longer name would change the loop counts of the code that rewrites VTK's messages).
std::string temporaryPath(bool binary)
{
  static std::atomic<unsigned> counter{0};
  char name[64];
  std::snprintf(name, sizeof(name), "proxima-vtk-%010d-%010u%s", static_cast<int>(::getpid()),
                counter++, binary ? ".glb" : ".gltf");
  return (fs::temp_directory_path() / name).string();
}
} // namespace

GltfGeometryFile::GltfGeometryFile(const std::string& sourcePath, const Json& document,
                                   std::optional<std::uint64_t> glbChunksOffset)
  : m_path(temporaryPath(glbChunksOffset.has_value()))
{
  const fs::path source(sourcePath);
  std::string json = geometryOnly(document, source.parent_path()).dump();
  std::ofstream out(m_path, std::ios::binary | std::ios::trunc);
  if (glbChunksOffset)
  {
    std::ifstream in(sourcePath, std::ios::binary);
    in.seekg(0, std::ios::end);
    const std::uint64_t sourceSize = static_cast<std::uint64_t>(in.tellg());
    const std::uint64_t chunksSize = sourceSize - *glbChunksOffset;
    json.resize((json.size() + 3) / 4 * 4, ' '); // GLB chunks are 4-byte aligned
    if (12 + 8 + json.size() + chunksSize > 0xffffffffu)
    {
      throw std::runtime_error(sourcePath +
                               ": the GLB copy for VTK's glTF loader would exceed 4 GiB");
    }
    out.write("glTF", 4);
    writeWord(out, 2);
    writeWord(out, static_cast<std::uint32_t>(12 + 8 + json.size() + chunksSize));
    writeWord(out, static_cast<std::uint32_t>(json.size()));
    out.write("JSON", 4);
    out << json;
    in.seekg(static_cast<std::streamoff>(*glbChunksOffset));
    if (chunksSize > 0)
    {
      out << in.rdbuf();
    }
  }
  else
  {
    out << json;
  }
  out.close();
  if (!out)
  {
    std::error_code ignored;
    fs::remove(m_path, ignored);
    throw std::runtime_error(m_path + ": cannot write the copy of " + sourcePath +
                             " that VTK's glTF loader reads");
  }
}

GltfGeometryFile::~GltfGeometryFile()
{
  std::error_code ignored;
  fs::remove(m_path, ignored);
}

} // namespace proxima::detail
