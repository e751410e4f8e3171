#include "IO/Mesh/Private/GltfChecks.h"

#include "IO/InputChecks/InputError.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string_view>
#include <vector>

namespace proxima::detail
{
namespace
{
using Json = nlohmann::json;

constexpr std::uint32_t kChunkJson = 0x4E4F534Au; // "JSON", little-endian
constexpr std::uint32_t kChunkBin = 0x004E4942u;  // "BIN\0"
// VTK's loader reads lengths, counts and offsets as int.
constexpr std::uint64_t kLargestVtkInt = 2147483647u;
constexpr std::uint64_t kArrayBuffer = 34962u;
constexpr std::uint64_t kElementArrayBuffer = 34963u;

/// The checks of one file: its path for the messages and the parsed document.
class GltfChecker
{
public:
  GltfChecker(const std::string& path, const Json& document, std::optional<std::uint64_t> binChunk)
    : m_path(path)
    , m_document(document)
    , m_binChunk(binChunk)
  {}

  void run()
  {
    if (!m_document.is_object())
    {
      fail("the JSON is not an object");
    }
    checkBuffers();
    checkBufferViews();
    checkAccessors();
    checkMeshes();
    checkImagesTexturesMaterials();
    checkSkins();
    checkNodes();
    checkScenes();
  }

private:
  [[noreturn]] void fail(const std::string& defect) const
  {
    throw InputError(m_path, "not a valid glTF file: " + defect);
  }

  /// The array `key` of the document, or an empty one when it is absent.
  const Json& array(const Json& object, const char* key, const std::string& where) const
  {
    static const Json empty = Json::array();
    const auto it = object.find(key);
    if (it == object.end())
    {
      return empty;
    }
    if (!it->is_array())
    {
      fail(where + key + " is not an array");
    }
    return *it;
  }

  const Json& topArray(const char* key) const { return array(m_document, key, ""); }

  const Json& item(const Json& list, std::size_t index, const std::string& name) const
  {
    const Json& entry = list[index];
    if (!entry.is_object())
    {
      fail(name + " " + std::to_string(index) + " is not an object");
    }
    return entry;
  }

  /// A non-negative integer field; `fallback` when absent (an absent required field fails).
  std::uint64_t unsignedField(const Json& object, const char* key, const std::string& where,
                              std::optional<std::uint64_t> fallback = std::nullopt) const
  {
    const auto it = object.find(key);
    if (it == object.end())
    {
      if (!fallback)
      {
        fail(where + " has no " + key);
      }
      return *fallback;
    }
    if (!it->is_number_unsigned())
    {
      fail(where + ": " + key + " is not a non-negative integer");
    }
    return it->get<std::uint64_t>();
  }

  /// An index field that must point into the document's array `target` (when present).
  std::optional<std::uint64_t> indexField(const Json& object, const char* key,
                                          const std::string& where, const char* target,
                                          bool required = false) const
  {
    if (!required && object.find(key) == object.end())
    {
      return std::nullopt;
    }
    const std::uint64_t index = unsignedField(object, key, where);
    requireIndex(index, where + ": " + key, target);
    return index;
  }

  void requireIndex(std::uint64_t index, const std::string& what, const char* target) const
  {
    const std::size_t size = topArray(target).size();
    if (index >= size)
    {
      fail(what + " refers to " + target + "[" + std::to_string(index) + "] but the file has " +
           std::to_string(size));
    }
  }

  void requireIndexArray(const Json& object, const char* key, const std::string& where,
                         const char* target) const
  {
    const Json& list = array(object, key, where + ": ");
    for (std::size_t i = 0; i < list.size(); ++i)
    {
      if (!list[i].is_number_unsigned())
      {
        fail(where + ": " + key + "[" + std::to_string(i) + "] is not a non-negative integer");
      }
      requireIndex(list[i].get<std::uint64_t>(), where + ": " + key + "[" + std::to_string(i) + "]",
                   target);
    }
  }

  static std::string name(const char* kind, std::size_t index)
  {
    return std::string(kind) + " " + std::to_string(index);
  }

  void checkBuffers()
  {
    const Json& buffers = topArray("buffers");
    m_bufferLengths.clear();
    for (std::size_t i = 0; i < buffers.size(); ++i)
    {
      const Json& buffer = item(buffers, i, "buffer");
      const std::string where = name("buffer", i);
      const std::uint64_t length = unsignedField(buffer, "byteLength", where);
      if (length == 0)
      {
        fail(where + " has a byteLength of 0");
      }
      const std::uint64_t available = availableBytes(buffer, i, where);
      if (available < length)
      {
        fail(where + " announces " + std::to_string(length) + " bytes but holds " +
             std::to_string(available));
      }
      if (length > kLargestVtkInt)
      {
        fail(where + " announces " + std::to_string(length) +
             " bytes (VTK's loader reads up to 2^31 - 1)");
      }
      m_bufferLengths.push_back(length);
    }
  }

  /// How many bytes buffer `index` really has.
  std::uint64_t availableBytes(const Json& buffer, std::size_t index,
                               const std::string& where) const
  {
    const auto uri = buffer.find("uri");
    if (uri == buffer.end())
    {
      if (index != 0 || !m_binChunk)
      {
        fail(where + " has no uri (only the first buffer of a .glb file with a BIN chunk may)");
      }
      return *m_binChunk;
    }
    if (!uri->is_string())
    {
      fail(where + ": uri is not a string");
    }
    const std::string& text = uri->get_ref<const std::string&>();
    if (text.rfind("data:", 0) == 0)
    {
      return dataUriBytes(text, where);
    }
    namespace fs = std::filesystem;
    const fs::path file = fs::path(m_path).parent_path() / text;
    std::error_code error;
    if (text.empty() || !fs::is_regular_file(file, error))
    {
      fail(where + ": its file '" + text + "' is missing or not a regular file");
    }
    const std::uintmax_t size = fs::file_size(file, error);
    if (error)
    {
      fail(where + ": cannot read the size of its file '" + text + "'");
    }
    return size;
  }

  /// The decoded length of a base64 data: URI, refusing any other encoding or a bad character.
  std::uint64_t dataUriBytes(const std::string& uri, const std::string& where) const
  {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos)
    {
      fail(where + ": its data: uri has no ','");
    }
    const std::string_view header(uri.data(), comma);
    if (header.size() < 7 || header.substr(header.size() - 7) != ";base64")
    {
      fail(where + ": its data: uri is not base64 (only ';base64,' data is read)");
    }
    std::uint64_t symbols = 0;
    std::uint64_t padding = 0;
    for (std::size_t i = comma + 1; i < uri.size(); ++i)
    {
      const char c = uri[i];
      const bool symbol = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                          (c >= '0' && c <= '9') || c == '+' || c == '/';
      if (symbol && padding == 0)
      {
        ++symbols;
      }
      else if (c == '=' && padding < 2)
      {
        ++padding;
      }
      else
      {
        fail(where + ": its base64 data has a bad character at offset " +
             std::to_string(i - comma - 1));
      }
    }
    if ((symbols + padding) % 4 != 0)
    {
      fail(where + ": its base64 data is not a whole number of 4-character groups");
    }
    return symbols * 3 / 4;
  }

  void checkBufferViews()
  {
    const Json& views = topArray("bufferViews");
    for (std::size_t i = 0; i < views.size(); ++i)
    {
      const Json& view = item(views, i, "bufferView");
      const std::string where = name("bufferView", i);
      const std::uint64_t buffer = *indexField(view, "buffer", where, "buffers", true);
      const std::uint64_t offset = unsignedField(view, "byteOffset", where, 0);
      const std::uint64_t length = unsignedField(view, "byteLength", where);
      const std::uint64_t bufferLength = m_bufferLengths[buffer];
      if (length == 0 || offset > bufferLength || length > bufferLength - offset)
      {
        fail(where + " (byteOffset " + std::to_string(offset) + ", byteLength " +
             std::to_string(length) + ") does not lie within buffer " + std::to_string(buffer) +
             " of " + std::to_string(bufferLength) + " bytes");
      }
      const std::uint64_t stride = unsignedField(view, "byteStride", where, 0);
      if (view.contains("byteStride") && (stride < 4 || stride > 252 || stride % 4 != 0))
      {
        fail(where + ": byteStride " + std::to_string(stride) +
             " is not a multiple of 4 from 4 to 252");
      }
      // VTK's loader drops a view with another target, and every later view's index shifts.
      const std::uint64_t target = unsignedField(view, "target", where, kArrayBuffer);
      if (target != kArrayBuffer && target != kElementArrayBuffer)
      {
        fail(where + ": target " + std::to_string(target) +
             " is neither 34962 (vertices) nor 34963 (indices)");
      }
    }
  }

  static std::uint64_t componentSize(std::uint64_t type)
  {
    switch (type)
    {
      case 5120: // BYTE
      case 5121: // UNSIGNED_BYTE
        return 1;
      case 5122: // SHORT
      case 5123: // UNSIGNED_SHORT
        return 2;
      case 5125: // UNSIGNED_INT
      case 5126: // FLOAT
        return 4;
      default: return 0;
    }
  }

  static std::uint64_t componentCount(const std::string& type)
  {
    static const std::pair<const char*, std::uint64_t> kTypes[] = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}};
    for (const auto& [typeName, count] : kTypes)
    {
      if (type == typeName)
      {
        return count;
      }
    }
    return 0;
  }

  void checkAccessors()
  {
    const Json& accessors = topArray("accessors");
    const Json& views = topArray("bufferViews");
    for (std::size_t i = 0; i < accessors.size(); ++i)
    {
      const Json& accessor = item(accessors, i, "accessor");
      const std::string where = name("accessor", i);
      if (accessor.contains("sparse"))
      {
        fail(where + " is sparse (sparse accessors are not read)");
      }
      const std::uint64_t component = unsignedField(accessor, "componentType", where);
      const std::uint64_t componentBytes = componentSize(component);
      if (componentBytes == 0)
      {
        fail(where + ": unknown componentType " + std::to_string(component));
      }
      const auto type = accessor.find("type");
      const std::uint64_t components =
        type != accessor.end() && type->is_string() ? componentCount(type->get<std::string>()) : 0;
      if (components == 0)
      {
        fail(where + ": type is missing or not one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4");
      }
      const std::uint64_t count = unsignedField(accessor, "count", where);
      if (count == 0)
      {
        fail(where + " has a count of 0");
      }
      // Without a bufferView the values would be zeros; no exporter writes that for a mesh.
      const std::uint64_t view = *indexField(accessor, "bufferView", where, "bufferViews", true);
      const std::uint64_t offset = unsignedField(accessor, "byteOffset", where, 0);
      const std::uint64_t elementBytes = componentBytes * components;
      const Json& viewObject = views[view];
      const std::uint64_t stride = unsignedField(viewObject, "byteStride", "", elementBytes);
      const std::uint64_t viewLength = viewObject["byteLength"].get<std::uint64_t>();
      // count <= viewLength keeps the product below 2^64 (the stride is at most 252).
      const bool fits = offset <= viewLength && count <= viewLength &&
                        offset + stride * (count - 1) + elementBytes <= viewLength;
      if (!fits)
      {
        fail(where + " (byteOffset " + std::to_string(offset) + ", " + std::to_string(count) +
             " elements of " + std::to_string(elementBytes) + " bytes, stride " +
             std::to_string(stride) + ") reaches beyond bufferView " + std::to_string(view) +
             " of " + std::to_string(viewLength) + " bytes");
      }
      // VTK's loader drops an accessor whose bounds do not match its type, and every later
      // accessor's index then names the one after it (fuzzing: a read of an accessor past the end).
      for (const char* bound : {"min", "max"})
      {
        const auto values = accessor.find(bound);
        if (values != accessor.end() && !(values->is_array() && values->size() == components &&
                                          std::all_of(values->begin(), values->end(),
                                                      [](const Json& v) { return v.is_number(); })))
        {
          fail(where + ": " + bound + " is not an array of " + std::to_string(components) +
               " numbers");
        }
      }
      m_accessors.push_back({component, components, count});
    }
  }

  struct AccessorShape
  {
    std::uint64_t componentType = 0;
    std::uint64_t components = 0;
    std::uint64_t count = 0;
  };

  void checkMeshes()
  {
    const Json& meshes = topArray("meshes");
    for (std::size_t m = 0; m < meshes.size(); ++m)
    {
      const Json& mesh = item(meshes, m, "mesh");
      const Json& primitives = array(mesh, "primitives", name("mesh", m) + ": ");
      if (primitives.empty())
      {
        fail(name("mesh", m) + " has no primitives");
      }
      for (std::size_t p = 0; p < primitives.size(); ++p)
      {
        checkPrimitive(item(primitives, p, name("mesh", m) + " primitive"),
                       name("mesh", m) + " primitive " + std::to_string(p));
      }
    }
  }

  void checkPrimitive(const Json& primitive, const std::string& where)
  {
    const std::uint64_t mode = unsignedField(primitive, "mode", where, 4);
    if (mode != 4)
    {
      fail(
        where + " has mode " + std::to_string(mode) +
        " (only triangles, mode 4, are read; 0-3 are points and lines, 5 and 6 strips and fans)");
    }
    const auto attributes = primitive.find("attributes");
    if (attributes == primitive.end() || !attributes->is_object())
    {
      fail(where + " has no attributes object");
    }
    if (!attributes->contains("POSITION"))
    {
      fail(where + " has no POSITION attribute");
    }
    const AccessorShape position =
      m_accessors[*indexField(*attributes, "POSITION", where + " attribute", "accessors", true)];
    if (position.componentType != 5126 || position.components != 3)
    {
      fail(where + ": its POSITION accessor is not of float VEC3");
    }
    checkAttributes(*attributes, position.count, where + " attribute");
    const Json& targets = array(primitive, "targets", where + ": ");
    for (std::size_t t = 0; t < targets.size(); ++t)
    {
      checkAttributes(item(targets, t, where + " morph target"), position.count,
                      where + " morph target " + std::to_string(t) + " attribute");
    }
    std::uint64_t corners = position.count;
    if (const auto indices = indexField(primitive, "indices", where, "accessors"))
    {
      const AccessorShape& shape = m_accessors[*indices];
      if (shape.components != 1 || (shape.componentType != 5121 && shape.componentType != 5123 &&
                                    shape.componentType != 5125))
      {
        fail(where + ": its indices accessor is not of unsigned byte, short or int SCALAR");
      }
      corners = shape.count;
    }
    if (corners % 3 != 0)
    {
      fail(where + " has " + std::to_string(corners) + " triangle corners, not a multiple of 3");
    }
    indexField(primitive, "material", where, "materials");
  }

  /// Every attribute names an accessor with one element per vertex.
  void checkAttributes(const Json& attributes, std::uint64_t vertices,
                       const std::string& where) const
  {
    for (auto it = attributes.begin(); it != attributes.end(); ++it)
    {
      const std::string what = where + " " + it.key();
      if (!it->is_number_unsigned())
      {
        fail(what + " is not an accessor index");
      }
      requireIndex(it->get<std::uint64_t>(), what, "accessors");
      const std::uint64_t count = m_accessors[it->get<std::uint64_t>()].count;
      if (count != vertices)
      {
        fail(what + " has " + std::to_string(count) + " elements for " + std::to_string(vertices) +
             " vertices");
      }
    }
  }

  void checkImagesTexturesMaterials() const
  {
    const Json& images = topArray("images");
    for (std::size_t i = 0; i < images.size(); ++i)
    {
      indexField(item(images, i, "image"), "bufferView", name("image", i), "bufferViews");
    }
    const Json& textures = topArray("textures");
    for (std::size_t i = 0; i < textures.size(); ++i)
    {
      indexField(item(textures, i, "texture"), "source", name("texture", i), "images");
      indexField(textures[i], "sampler", name("texture", i), "samplers");
    }
    const Json& materials = topArray("materials");
    for (std::size_t i = 0; i < materials.size(); ++i)
    {
      checkTextureReferences(item(materials, i, "material"), name("material", i));
    }
  }

  /// The texture references of a material (glTF 2.0 core; extensions are not looked into).
  void checkTextureReferences(const Json& material, const std::string& where) const
  {
    const auto check = [&](const Json& holder, const char* key) {
      const auto it = holder.find(key);
      if (it != holder.end())
      {
        if (!it->is_object())
        {
          fail(where + ": " + key + " is not an object");
        }
        indexField(*it, "index", where + " " + key, "textures", true);
      }
    };
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
    {
      check(material, key);
    }
    const auto pbr = material.find("pbrMetallicRoughness");
    if (pbr != material.end() && pbr->is_object())
    {
      check(*pbr, "baseColorTexture");
      check(*pbr, "metallicRoughnessTexture");
    }
  }

  void checkSkins() const
  {
    const Json& skins = topArray("skins");
    for (std::size_t i = 0; i < skins.size(); ++i)
    {
      const Json& skin = item(skins, i, "skin");
      // Without joints VTK's loader drops the skin, and a node's skin index points past the end.
      const auto joints = skin.find("joints");
      if (joints == skin.end() || !joints->is_array() || joints->empty())
      {
        fail(name("skin", i) + " has no joints");
      }
      requireIndexArray(skin, "joints", name("skin", i), "nodes");
      indexField(skin, "skeleton", name("skin", i), "nodes");
      indexField(skin, "inverseBindMatrices", name("skin", i), "accessors");
    }
    const Json& animations = topArray("animations");
    for (std::size_t a = 0; a < animations.size(); ++a)
    {
      const Json& animation = item(animations, a, "animation");
      const std::string where = name("animation", a);
      const Json& samplers = array(animation, "samplers", where + ": ");
      for (std::size_t s = 0; s < samplers.size(); ++s)
      {
        indexField(item(samplers, s, where + " sampler"), "input", where, "accessors", true);
        indexField(samplers[s], "output", where, "accessors", true);
      }
      const Json& channels = array(animation, "channels", where + ": ");
      for (std::size_t c = 0; c < channels.size(); ++c)
      {
        const Json& channel = item(channels, c, where + " channel");
        if (unsignedField(channel, "sampler", where + " channel " + std::to_string(c)) >=
            samplers.size())
        {
          fail(where + " channel " + std::to_string(c) + " refers to a sampler it does not have");
        }
        const auto target = channel.find("target");
        if (target != channel.end() && target->is_object())
        {
          indexField(*target, "node", where + " channel " + std::to_string(c), "nodes");
        }
      }
    }
  }

  void checkNodes() const
  {
    const Json& nodes = topArray("nodes");
    std::vector<int> parents(nodes.size(), 0);
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      const Json& node = item(nodes, i, "node");
      const std::string where = name("node", i);
      indexField(node, "mesh", where, "meshes");
      indexField(node, "skin", where, "skins");
      // VTK's loader drops such a node (glTF forbids it), and the node indices after it shift.
      if (node.contains("skin") && node.contains("matrix"))
      {
        fail(where + " has both a skin and a matrix (a skinned node is placed by its joints)");
      }
      indexField(node, "camera", where, "cameras");
      requireIndexArray(node, "children", where, "nodes");
      for (const Json& child : array(node, "children", where + ": "))
      {
        if (++parents[child.get<std::size_t>()] > 1)
        {
          fail("node " + std::to_string(child.get<std::size_t>()) + " has more than one parent");
        }
      }
    }
    // With at most one parent each, the nodes form a forest unless some lie on a cycle, which
    // no walk from a parentless node reaches (VTK's loader would recurse along it for ever).
    std::vector<bool> reached(nodes.size(), false);
    std::vector<std::size_t> stack;
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      if (parents[i] == 0)
      {
        stack.push_back(i);
      }
    }
    while (!stack.empty())
    {
      const std::size_t node = stack.back();
      stack.pop_back();
      reached[node] = true;
      for (const Json& child : array(nodes[node], "children", ""))
      {
        stack.push_back(child.get<std::size_t>());
      }
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      if (!reached[i])
      {
        fail("node " + std::to_string(i) + " is its own ancestor (the node hierarchy has a cycle)");
      }
    }
  }

  void checkScenes() const
  {
    const Json& scenes = topArray("scenes");
    for (std::size_t i = 0; i < scenes.size(); ++i)
    {
      const Json& scene = item(scenes, i, "scene");
      // VTK's loader drops an empty scene, and the document's scene index then misses.
      if (scene.empty())
      {
        fail(name("scene", i) + " is an empty object");
      }
      requireIndexArray(scene, "nodes", name("scene", i), "nodes");
    }
    indexField(m_document, "scene", "the document", "scenes");
  }

  const std::string& m_path;
  const Json& m_document;
  std::optional<std::uint64_t> m_binChunk;
  std::vector<std::uint64_t> m_bufferLengths;
  std::vector<AccessorShape> m_accessors;
};

std::uint32_t littleEndian32(const char* bytes)
{
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i)
  {
    value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  }
  return value;
}

std::string readBytes(std::ifstream& stream, std::uint64_t offset, std::uint64_t count)
{
  std::string bytes(static_cast<std::size_t>(count), '\0');
  stream.seekg(static_cast<std::streamoff>(offset));
  stream.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(stream.gcount()));
  return bytes;
}
} // namespace

GltfGeometryFile checkGltfAndCopyGeometry(const std::string& path, std::uintmax_t fileSize)
{
  std::ifstream stream(path, std::ios::binary);
  std::string text;
  std::optional<std::uint64_t> binChunk;
  std::optional<std::uint64_t> chunksAfterJson;
  if (readBytes(stream, 0, 4) == "glTF")
  {
    const std::string header = readBytes(stream, 0, 20);
    if (header.size() < 20)
    {
      throw InputError(
        path, "not a valid GLB file: too short for its 12-byte header and a chunk header (" +
                std::to_string(fileSize) + " bytes)");
    }
    const std::uint32_t version = littleEndian32(header.data() + 4);
    const std::uint32_t length = littleEndian32(header.data() + 8);
    if (version != 2)
    {
      throw InputError(path, "not a valid GLB file: version " + std::to_string(version) +
                               " (only 2 is read)");
    }
    if (length != fileSize)
    {
      throw InputError(path, "not a valid GLB file: its header announces " +
                               std::to_string(length) + " bytes but the file has " +
                               std::to_string(fileSize));
    }
    const std::uint64_t jsonLength = littleEndian32(header.data() + 12);
    if (littleEndian32(header.data() + 16) != kChunkJson)
    {
      throw InputError(path, "not a valid GLB file: its first chunk is not JSON");
    }
    if (jsonLength == 0 || 20 + jsonLength > length)
    {
      throw InputError(path, "not a valid GLB file: its JSON chunk of " +
                               std::to_string(jsonLength) + " bytes does not fit in the file's " +
                               std::to_string(length));
    }
    text = readBytes(stream, 20, jsonLength);
    chunksAfterJson = 20 + jsonLength;
    // The chunks must tile the file exactly: VTK's loader reads chunk headers until the end of
    // the file, and a few bytes too short for a header kept it allocating for ever (fuzzing).
    std::uint64_t offset = 20 + jsonLength;
    while (offset < length)
    {
      if (length - offset < 8)
      {
        throw InputError(path, "not a valid GLB file: " + std::to_string(length - offset) +
                                 " bytes at its end are too short for a chunk header");
      }
      const std::string chunk = readBytes(stream, offset, 8);
      const std::uint64_t chunkLength = littleEndian32(chunk.data());
      if (chunkLength > length - offset - 8)
      {
        throw InputError(path, "not a valid GLB file: its chunk at byte " + std::to_string(offset) +
                                 " of " + std::to_string(chunkLength) +
                                 " bytes does not fit in the file's " + std::to_string(length));
      }
      if (offset == 20 + jsonLength && littleEndian32(chunk.data() + 4) == kChunkBin)
      {
        binChunk = chunkLength;
      }
      offset += 8 + chunkLength;
    }
  }
  else
  {
    text = readBytes(stream, 0, fileSize);
  }
  Json document;
  try
  {
    document = Json::parse(text);
  }
  catch (const Json::parse_error& error)
  {
    throw InputError(path, "not a valid glTF file: the JSON does not parse (at byte " +
                             std::to_string(error.byte) + ")");
  }
  catch (const Json::exception&)
  {
    // A number too large for any type (out_of_range 406) and the like.
    throw InputError(path,
                     "not a valid glTF file: the JSON does not parse (a number out of range)");
  }
  GltfChecker(path, document, binChunk).run();
  return GltfGeometryFile(path, document, chunksAfterJson);
}

} // namespace proxima::detail
