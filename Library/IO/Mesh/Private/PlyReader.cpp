#include "IO/Mesh/Private/PlyReader.h"

#include "IO/InputChecks/InputError.h"

#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace proxima::detail
{
namespace
{
enum class Encoding
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

enum class ScalarType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64,
  Unknown
};

ScalarType scalarType(const std::string& name)
{
  static const std::map<std::string, ScalarType> types = {
    {"char", ScalarType::Int8},      {"int8", ScalarType::Int8},
    {"uchar", ScalarType::UInt8},    {"uint8", ScalarType::UInt8},
    {"short", ScalarType::Int16},    {"int16", ScalarType::Int16},
    {"ushort", ScalarType::UInt16},  {"uint16", ScalarType::UInt16},
    {"int", ScalarType::Int32},      {"int32", ScalarType::Int32},
    {"uint", ScalarType::UInt32},    {"uint32", ScalarType::UInt32},
    {"float", ScalarType::Float32},  {"float32", ScalarType::Float32},
    {"double", ScalarType::Float64}, {"float64", ScalarType::Float64}};
  const auto found = types.find(name);
  return found == types.end() ? ScalarType::Unknown : found->second;
}

std::size_t scalarSize(ScalarType type)
{
  switch (type)
  {
    case ScalarType::Int8:
    case ScalarType::UInt8: return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16: return 2;
    case ScalarType::Int32:
    case ScalarType::UInt32:
    case ScalarType::Float32: return 4;
    case ScalarType::Float64: return 8;
    case ScalarType::Unknown: break;
  }
  return 0;
}

struct Property
{
  std::string name;
  bool isList = false;
  ScalarType countType = ScalarType::Unknown;
  ScalarType type = ScalarType::Unknown; ///< the items' type for a list
};

struct Element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;

  int find(const std::string& propertyName) const
  {
    for (std::size_t i = 0; i < properties.size(); ++i)
    {
      if (properties[i].name == propertyName)
      {
        return static_cast<int>(i);
      }
    }
    return -1;
  }
};

struct Header
{
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  std::size_t dataOffset = 0;
};

Header parseHeader(const std::string& path, const std::string& bytes)
{
  Header header;
  std::size_t position = 0;
  int lineNumber = 0;
  bool sawFormat = false;
  auto fail = [&](const std::string& defect) {
    throw InputError(path, "PLY header line " + std::to_string(lineNumber) + ": " + defect);
  };
  while (true)
  {
    const std::size_t end = bytes.find('\n', position);
    if (end == std::string::npos)
    {
      throw InputError(path, lineNumber == 0 ? "not a PLY file (it does not start with 'ply')"
                                             : "not a PLY file (the header has no end_header)");
    }
    std::string line = bytes.substr(position, end - position);
    position = end + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (lineNumber == 1)
    {
      if (line != "ply")
      {
        throw InputError(path, "not a PLY file (it does not start with 'ply')");
      }
      continue;
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info")
    {
      continue;
    }
    if (keyword == "format")
    {
      std::string format;
      words >> format;
      sawFormat = true;
      if (format == "ascii")
      {
        header.encoding = Encoding::Ascii;
      }
      else if (format == "binary_little_endian")
      {
        header.encoding = Encoding::BinaryLittleEndian;
      }
      else if (format == "binary_big_endian")
      {
        header.encoding = Encoding::BinaryBigEndian;
      }
      else
      {
        fail("unknown format '" + format + "'");
      }
    }
    else if (keyword == "element")
    {
      Element element;
      std::string count;
      words >> element.name >> count;
      const auto result = std::from_chars(count.data(), count.data() + count.size(), element.count);
      if (element.name.empty() || result.ec != std::errc() ||
          result.ptr != count.data() + count.size())
      {
        fail("malformed element line '" + line + "'");
      }
      header.elements.push_back(element);
    }
    else if (keyword == "property")
    {
      if (header.elements.empty())
      {
        fail("property before any element");
      }
      Property property;
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType;
        std::string itemType;
        words >> countType >> itemType >> property.name;
        property.isList = true;
        property.countType = scalarType(countType);
        property.type = scalarType(itemType);
        if (property.countType == ScalarType::Unknown || property.type == ScalarType::Unknown ||
            property.countType == ScalarType::Float32 ||
            property.countType == ScalarType::Float64 || property.name.empty())
        {
          fail("malformed list property '" + line + "'");
        }
      }
      else
      {
        words >> property.name;
        property.type = scalarType(type);
        if (property.type == ScalarType::Unknown || property.name.empty())
        {
          fail("malformed property '" + line + "'");
        }
      }
      header.elements.back().properties.push_back(property);
    }
    else if (keyword == "end_header")
    {
      break;
    }
    else
    {
      fail("unknown keyword '" + keyword + "'");
    }
  }
  if (!sawFormat)
  {
    throw InputError(path, "PLY header has no format line");
  }
  for (const Element& element : header.elements)
  {
    if (element.properties.empty())
    {
      throw InputError(path, "PLY element '" + element.name + "' has no properties");
    }
  }
  header.dataOffset = position;
  return header;
}

/// Reads the data section value by value, in either encoding, refusing anything cut short.
class DataCursor
{
public:
  DataCursor(const std::string& path, const std::string& bytes, const Header& header)
    : m_path(path)
    , m_bytes(bytes)
    , m_position(header.dataOffset)
    , m_encoding(header.encoding)
  {}

  /// Bytes not read yet: every value still to come takes at least one.
  std::size_t remaining() const { return m_bytes.size() - m_position; }
  void setContext(const Element& element, std::uint64_t item)
  {
    m_element = &element;
    m_item = item;
  }

  double read(ScalarType type)
  {
    if (m_encoding == Encoding::Ascii)
    {
      return readAscii(type);
    }
    const std::size_t size = scalarSize(type);
    if (m_bytes.size() - m_position < size)
    {
      failHere("the data ends early (truncated file)");
    }
    unsigned char raw[8];
    std::memcpy(raw, m_bytes.data() + m_position, size);
    m_position += size;
    const bool swap =
      (m_encoding == Encoding::BinaryBigEndian) != (std::endian::native == std::endian::big);
    if (swap)
    {
      for (std::size_t i = 0; i < size / 2; ++i)
      {
        std::swap(raw[i], raw[size - 1 - i]);
      }
    }
    switch (type)
    {
      case ScalarType::Int8: return static_cast<double>(static_cast<std::int8_t>(raw[0]));
      case ScalarType::UInt8: return static_cast<double>(raw[0]);
      case ScalarType::Int16: return static_cast<double>(load<std::int16_t>(raw));
      case ScalarType::UInt16: return static_cast<double>(load<std::uint16_t>(raw));
      case ScalarType::Int32: return static_cast<double>(load<std::int32_t>(raw));
      case ScalarType::UInt32: return static_cast<double>(load<std::uint32_t>(raw));
      case ScalarType::Float32: return static_cast<double>(load<float>(raw));
      case ScalarType::Float64: return load<double>(raw);
      case ScalarType::Unknown: break;
    }
    return 0.0;
  }

  [[noreturn]] void failHere(const std::string& defect) const
  {
    throw InputError(m_path, "PLY element '" + m_element->name + "' item " +
                               std::to_string(m_item) + ": " + defect);
  }

private:
  template <class T>
  static T load(const unsigned char* raw)
  {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  double readAscii(ScalarType type)
  {
    while (m_position < m_bytes.size() &&
           std::isspace(static_cast<unsigned char>(m_bytes[m_position])))
    {
      ++m_position;
    }
    std::size_t end = m_position;
    while (end < m_bytes.size() && !std::isspace(static_cast<unsigned char>(m_bytes[end])))
    {
      ++end;
    }
    if (end == m_position)
    {
      failHere("the data ends early (truncated file)");
    }
    const char* first = m_bytes.data() + m_position;
    const char* last = m_bytes.data() + end;
    m_position = end;
    double value = 0.0;
    if (type == ScalarType::Float32 || type == ScalarType::Float64)
    {
      const auto result = std::from_chars(first, last, value);
      if (result.ptr != last ||
          (result.ec != std::errc() && result.ec != std::errc::result_out_of_range))
      {
        failHere("cannot read '" + std::string(first, last) + "' as a number");
      }
      if (result.ec == std::errc::result_out_of_range)
      {
        value = std::strtod(std::string(first, last).c_str(), nullptr);
      }
      return value;
    }
    long long integer = 0;
    const auto result = std::from_chars(first, last, integer);
    if (result.ptr != last || result.ec != std::errc())
    {
      failHere("cannot read '" + std::string(first, last) + "' as an integer");
    }
    return static_cast<double>(integer);
  }

  const std::string& m_path;
  const std::string& m_bytes;
  std::size_t m_position = 0;
  Encoding m_encoding;
  const Element* m_element = nullptr;
  std::uint64_t m_item = 0;
};

int findFirst(const Element& element, std::initializer_list<const char*> names)
{
  for (const char* name : names)
  {
    if (const int index = element.find(name); index >= 0)
    {
      return index;
    }
  }
  return -1;
}
} // namespace

PolygonSoup readPly(const std::string& path, std::uintmax_t fileSize)
{
  std::string bytes(static_cast<std::size_t>(fileSize), '\0');
  {
    std::ifstream stream(path, std::ios::binary);
    stream.read(bytes.data(), static_cast<std::streamsize>(fileSize));
    if (static_cast<std::uintmax_t>(stream.gcount()) != fileSize)
    {
      throw InputError(path, "cannot read the whole file");
    }
  }
  const Header header = parseHeader(path, bytes);

  const Element* vertexElement = nullptr;
  const Element* faceElement = nullptr;
  for (const Element& element : header.elements)
  {
    vertexElement = element.name == "vertex" && !vertexElement ? &element : vertexElement;
    faceElement = element.name == "face" && !faceElement ? &element : faceElement;
  }
  if (!vertexElement || vertexElement->find("x") < 0 || vertexElement->find("y") < 0 ||
      vertexElement->find("z") < 0)
  {
    throw InputError(path, "PLY header has no vertex element with x, y and z");
  }
  const int indicesProperty =
    faceElement ? findFirst(*faceElement, {"vertex_indices", "vertex_index"}) : -1;
  if (indicesProperty < 0 ||
      !faceElement->properties[static_cast<std::size_t>(indicesProperty)].isList)
  {
    throw InputError(
      path, "no triangles (the PLY header has no face element with a vertex_indices list)");
  }
  // Reject counts the file cannot hold before reserving memory for them (a garbled header).
  const std::uint64_t dataBytes = bytes.size() - header.dataOffset;
  if (vertexElement->count > dataBytes || faceElement->count > dataBytes)
  {
    throw InputError(path, "truncated: the PLY header announces " +
                             std::to_string(vertexElement->count) + " vertices and " +
                             std::to_string(faceElement->count) + " faces, more than the file's " +
                             std::to_string(dataBytes) + " bytes of data can hold");
  }

  const int x = vertexElement->find("x");
  const int y = vertexElement->find("y");
  const int z = vertexElement->find("z");
  const int nx = vertexElement->find("nx");
  const int ny = vertexElement->find("ny");
  const int nz = vertexElement->find("nz");
  const bool hasNormals = nx >= 0 && ny >= 0 && nz >= 0;
  const int u = findFirst(*vertexElement, {"u", "s", "texture_u", "texture_s"});
  const int v = findFirst(*vertexElement, {"v", "t", "texture_v", "texture_t"});
  const bool hasTexCoords = u >= 0 && v >= 0;

  const auto numVertices = static_cast<std::int64_t>(vertexElement->count);
  PolygonSoup polygons;
  polygons.points.resize(static_cast<std::size_t>(3 * numVertices));
  if (hasNormals)
  {
    polygons.normals.resize(static_cast<std::size_t>(3 * numVertices));
  }
  if (hasTexCoords)
  {
    polygons.texCoords.resize(static_cast<std::size_t>(2 * numVertices));
  }

  DataCursor cursor(path, bytes, header);
  std::vector<double> values;
  std::vector<std::int64_t> ids;
  for (const Element& element : header.elements)
  {
    const bool isVertex = &element == vertexElement;
    const bool isFace = &element == faceElement;
    values.resize(element.properties.size());
    for (std::uint64_t item = 0; item < element.count; ++item)
    {
      cursor.setContext(element, item);
      for (std::size_t p = 0; p < element.properties.size(); ++p)
      {
        const Property& property = element.properties[p];
        if (!property.isList)
        {
          values[p] = cursor.read(property.type);
          continue;
        }
        const double count = cursor.read(property.countType);
        if (count < 0)
        {
          cursor.failHere("negative list length");
        }
        // An ASCII count is read as a number whatever its declared type: a garbled one
        // (333333333 for a uchar) must not size the index buffer (found by fuzzing:
        // Testing/Fuzz/Findings/FuzzMeshReader-ply).
        if (count > static_cast<double>(cursor.remaining()))
        {
          cursor.failHere("list length " + std::to_string(static_cast<long long>(count)) +
                          " is more than the file has bytes left");
        }
        const bool keep = isFace && static_cast<int>(p) == indicesProperty;
        if (keep)
        {
          ids.resize(static_cast<std::size_t>(count));
        }
        for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k)
        {
          const double value = cursor.read(property.type);
          if (keep)
          {
            if (value < 0 || value >= static_cast<double>(numVertices))
            {
              throw InputError(path, "face " + std::to_string(item) + " refers to vertex " +
                                       std::to_string(static_cast<long long>(value)) +
                                       ", out of range (the file has " +
                                       std::to_string(numVertices) + " vertices)");
            }
            ids[k] = static_cast<std::int64_t>(value);
          }
        }
        if (keep)
        {
          // Faces of one or two vertices are vertex cells and lines, counted only.
          polygons.addCell(ids.data(), ids.size());
        }
      }
      if (isVertex)
      {
        const auto id = static_cast<std::size_t>(item);
        double* point = &polygons.points[3 * id];
        point[0] = values[static_cast<std::size_t>(x)];
        point[1] = values[static_cast<std::size_t>(y)];
        point[2] = values[static_cast<std::size_t>(z)];
        if (hasNormals)
        {
          double* normal = &polygons.normals[3 * id];
          normal[0] = values[static_cast<std::size_t>(nx)];
          normal[1] = values[static_cast<std::size_t>(ny)];
          normal[2] = values[static_cast<std::size_t>(nz)];
        }
        if (hasTexCoords)
        {
          double* texCoord = &polygons.texCoords[2 * id];
          texCoord[0] = values[static_cast<std::size_t>(u)];
          texCoord[1] = values[static_cast<std::size_t>(v)];
        }
      }
    }
  }
  return polygons;
}

} // namespace proxima::detail
