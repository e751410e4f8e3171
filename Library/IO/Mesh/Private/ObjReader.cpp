#include "IO/Mesh/Private/ObjReader.h"

#include "IO/InputChecks/InputError.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace proxima::detail
{
namespace
{
std::string at(std::uint64_t line)
{
  return "line " + std::to_string(line) + ": ";
}

/// Splits on blanks; views into `text`.
void splitWords(std::string_view text, std::vector<std::string_view>& words)
{
  words.clear();
  std::size_t i = 0;
  while (i < text.size())
  {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r'))
    {
      ++i;
    }
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r')
    {
      ++i;
    }
    if (i > start)
    {
      words.push_back(text.substr(start, i - start));
    }
  }
}

/// A number as written; one too large for a double ("1e999") is read as infinite, as strtod
/// would, so that it is reported as the non-finite coordinate it becomes.
bool parseDouble(std::string_view word, double& value)
{
  if (!word.empty() && word.front() == '+')
  {
    word.remove_prefix(1);
  }
  const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
  if (word.empty() || result.ptr != word.data() + word.size())
  {
    return false;
  }
  if (result.ec == std::errc::result_out_of_range)
  {
    // from_chars leaves the value alone; tell overflow from underflow by the exponent's sign.
    const bool underflow =
      word.find("e-") != std::string_view::npos || word.find("E-") != std::string_view::npos;
    const double magnitude = underflow ? 0.0 : HUGE_VAL;
    value = word.front() == '-' ? -magnitude : magnitude;
    return true;
  }
  return result.ec == std::errc();
}

bool parseIndex(std::string_view word, long long& value)
{
  if (!word.empty() && word.front() == '+')
  {
    word.remove_prefix(1);
  }
  const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
  return !word.empty() && result.ec == std::errc() && result.ptr == word.data() + word.size();
}

std::string formatNumbers(const double* values, std::size_t count)
{
  std::ostringstream out;
  out << "(";
  for (std::size_t i = 0; i < count; ++i)
  {
    out << (i ? ", " : "") << values[i];
  }
  out << ")";
  return out.str();
}

enum Kind
{
  kVertex = 0,
  kTexCoord = 1,
  kNormal = 2
};
const char* const kKindNames[3] = {"vertex", "texture coordinate", "normal"};
const char* const kKindPlurals[3] = {"vertices", "texture coordinates", "normals"};

/// One face corner: 1-based indices into v, vt and vn after resolving relative ones; 0 = none.
using Corner = std::array<std::uint32_t, 3>;

struct CornerHash
{
  std::size_t operator()(const Corner& c) const
  {
    std::uint64_t h = c[0];
    h = h * 0x9E3779B97F4A7C15ull ^ c[1];
    h = h * 0x9E3779B97F4A7C15ull ^ c[2];
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

/// The largest absolute reference seen for one kind of index, checked once the file's counts are
/// known: OBJ lets a face name a vertex defined further down.
struct LargestReference
{
  long long index = 0;
  std::uint64_t line = 0;
};

enum class CellKind : std::uint8_t
{
  Face,
  Line,
  Point
};

struct ParsedObj
{
  std::vector<double> vertices;  // xyz
  std::vector<double> texCoords; // uv
  std::vector<double> normals;   // xyz
  std::vector<Corner> corners;
  std::vector<std::uint32_t> cellSizes;
  std::vector<CellKind> cellKinds;
  bool usesTexCoords = false;
  bool usesNormals = false;
};

ParsedObj parse(const std::string& path)
{
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
  {
    throw InputError(path, "cannot open the file");
  }
  ParsedObj obj;
  LargestReference largest[3];
  std::string line;
  std::vector<std::string_view> words;
  std::uint64_t lineNumber = 0;
  while (std::getline(stream, line))
  {
    ++lineNumber;
    for (char c : line)
    {
      const auto byte = static_cast<unsigned char>(c);
      if (byte < 0x20 && c != '\t' && c != '\r' && c != '\f' && c != '\v')
      {
        std::ostringstream out;
        out << at(lineNumber) << "not an OBJ text file (control byte 0x" << std::hex
            << static_cast<int>(byte) << ")";
        throw InputError(path, out.str());
      }
    }
    std::string_view text(line);
    if (const auto hash = text.find('#'); hash != std::string_view::npos)
    {
      text = text.substr(0, hash);
    }
    splitWords(text, words);
    if (words.empty())
    {
      continue;
    }
    const std::string_view keyword = words[0];
    if (keyword == "v" || keyword == "vt" || keyword == "vn")
    {
      const Kind kind = keyword == "v" ? kVertex : (keyword == "vt" ? kTexCoord : kNormal);
      std::vector<double>& store =
        kind == kVertex ? obj.vertices : (kind == kTexCoord ? obj.texCoords : obj.normals);
      const std::size_t width = kind == kTexCoord ? 2 : 3;
      const std::uint64_t number = store.size() / width + 1;
      // "vt u" alone is allowed (v = 0); v may carry w or colours after x y z, ignored.
      const std::size_t needed = kind == kTexCoord ? 1 : 3;
      const std::size_t available = std::min(words.size() - 1, width);
      if (available < needed)
      {
        throw InputError(path, at(lineNumber) + kKindNames[kind] + " " + std::to_string(number) +
                                 " has " + std::to_string(available) + " numbers, needs " +
                                 std::to_string(needed));
      }
      double values[3] = {0.0, 0.0, 0.0};
      for (std::size_t i = 0; i < available; ++i)
      {
        if (!parseDouble(words[1 + i], values[i]))
        {
          throw InputError(path, at(lineNumber) + "cannot read '" + std::string(words[1 + i]) +
                                   "' as a number in " + kKindNames[kind] + " " +
                                   std::to_string(number));
        }
      }
      for (std::size_t i = 0; i < available; ++i)
      {
        if (!std::isfinite(values[i]))
        {
          throw InputError(path, at(lineNumber) + kKindNames[kind] + " " + std::to_string(number) +
                                   " has a non-finite coordinate " +
                                   formatNumbers(values, available));
        }
      }
      store.insert(store.end(), values, values + width);
    }
    else if (keyword == "f" || keyword == "l" || keyword == "p")
    {
      const std::uint64_t current[3] = {obj.vertices.size() / 3, obj.texCoords.size() / 2,
                                        obj.normals.size() / 3};
      std::uint32_t size = 0;
      for (std::size_t w = 1; w < words.size(); ++w)
      {
        // "v", "v/vt", "v//vn" or "v/vt/vn".
        std::string_view reference = words[w];
        Corner corner{0, 0, 0};
        for (int kind = 0; kind < 3 && !reference.empty(); ++kind)
        {
          const std::size_t slash = reference.find('/');
          const std::string_view part = reference.substr(0, slash);
          reference =
            slash == std::string_view::npos ? std::string_view() : reference.substr(slash + 1);
          if (part.empty() && kind > 0)
          {
            continue;
          }
          long long index = 0;
          if (!parseIndex(part, index))
          {
            throw InputError(path, at(lineNumber) + "cannot read '" + std::string(words[w]) +
                                     "' as a " + std::string(keyword) + " reference");
          }
          if (index == 0)
          {
            throw InputError(path, at(lineNumber) + kKindNames[kind] +
                                     " index 0 is out of range (OBJ indices start at 1)");
          }
          if (index < 0)
          {
            // Relative to the elements defined so far: -1 is the latest.
            if (static_cast<unsigned long long>(-index) > current[kind])
            {
              throw InputError(path, at(lineNumber) + kKindNames[kind] + " index " +
                                       std::to_string(index) + " is out of range (only " +
                                       std::to_string(current[kind]) + " defined so far)");
            }
            index = static_cast<long long>(current[kind]) + 1 + index;
          }
          if (index > 0xFFFFFFFFll)
          {
            throw InputError(path, at(lineNumber) + kKindNames[kind] + " index " +
                                     std::to_string(index) + " is out of range");
          }
          if (index > largest[kind].index)
          {
            largest[kind] = LargestReference{index, lineNumber};
          }
          corner[static_cast<std::size_t>(kind)] = static_cast<std::uint32_t>(index);
        }
        if (corner[0] == 0)
        {
          throw InputError(path,
                           at(lineNumber) + "'" + std::string(words[w]) + "' names no vertex");
        }
        obj.usesTexCoords = obj.usesTexCoords || corner[1] != 0;
        obj.usesNormals = obj.usesNormals || corner[2] != 0;
        obj.corners.push_back(corner);
        ++size;
      }
      // A face of two corners, or none, is not a polygon: most likely a file cut off mid-face
      // or a damaged line, and dropping it in silence would leave a hole.
      const std::uint32_t fewest = keyword == "f" ? 3 : (keyword == "l" ? 2 : 1);
      if (size < fewest)
      {
        throw InputError(path, at(lineNumber) + "'" + std::string(keyword) + "' with " +
                                 std::to_string(size) + (size == 1 ? " corner" : " corners") +
                                 ": it needs at least " + std::to_string(fewest) +
                                 " (is the file cut off or the line damaged?)");
      }
      obj.cellSizes.push_back(size);
      obj.cellKinds.push_back(keyword == "f" ? CellKind::Face
                                             : (keyword == "l" ? CellKind::Line : CellKind::Point));
    }
    // Every other statement (o, g, s, usemtl, mtllib, curves...) carries no triangle geometry.
  }
  if (stream.bad())
  {
    throw InputError(path, "read error after line " + std::to_string(lineNumber));
  }
  const std::uint64_t totals[3] = {obj.vertices.size() / 3, obj.texCoords.size() / 2,
                                   obj.normals.size() / 3};
  for (int kind = 0; kind < 3; ++kind)
  {
    if (static_cast<std::uint64_t>(largest[kind].index) > totals[kind])
    {
      throw InputError(path, at(largest[kind].line) + kKindNames[kind] + " index " +
                               std::to_string(largest[kind].index) +
                               " is out of range (the file has " + std::to_string(totals[kind]) +
                               " " + kKindPlurals[kind] + ")");
    }
  }
  return obj;
}
} // namespace

PolygonSoup readObj(const std::string& path)
{
  const ParsedObj obj = parse(path);
  PolygonSoup polygons;

  // Point i is the file's vertex i (unused ones included), with the vt and vn of the first corner
  // that names it; a corner naming the same vertex with another vt or vn (a UV seam, a crease)
  // gets a point of its own, appended. Files written with one vt and vn per vertex thus keep
  // their numbering exactly.
  const auto numVertices = static_cast<std::int64_t>(obj.vertices.size() / 3);
  const bool withAttributes = obj.usesTexCoords || obj.usesNormals;
  std::vector<std::array<std::uint32_t, 2>> attributesOf(
    withAttributes ? static_cast<std::size_t>(numVertices) : 0, {0u, 0u});
  std::vector<bool> named(withAttributes ? static_cast<std::size_t>(numVertices) : 0, false);
  auto appendPoint = [&](std::uint32_t vertex, std::uint32_t texCoord, std::uint32_t normal) {
    const double* v = &obj.vertices[3 * (vertex - 1)];
    polygons.addPoint(v[0], v[1], v[2]);
    if (obj.usesNormals)
    {
      const double zero[3] = {0.0, 0.0, 0.0};
      const double* n = normal ? &obj.normals[3 * (normal - 1)] : zero;
      polygons.normals.insert(polygons.normals.end(), n, n + 3);
    }
    if (obj.usesTexCoords)
    {
      const double zero[2] = {0.0, 0.0};
      const double* t = texCoord ? &obj.texCoords[2 * (texCoord - 1)] : zero;
      polygons.texCoords.insert(polygons.texCoords.end(), t, t + 2);
    }
  };
  if (withAttributes)
  {
    for (const Corner& corner : obj.corners)
    {
      if (!named[corner[0] - 1])
      {
        named[corner[0] - 1] = true;
        attributesOf[corner[0] - 1] = {corner[1], corner[2]};
      }
    }
  }
  polygons.points.reserve(obj.vertices.size());
  for (std::int64_t i = 0; i < numVertices; ++i)
  {
    const auto vertex = static_cast<std::uint32_t>(i + 1);
    const std::array<std::uint32_t, 2> attributes = withAttributes
                                                      ? attributesOf[static_cast<std::size_t>(i)]
                                                      : std::array<std::uint32_t, 2>{0u, 0u};
    appendPoint(vertex, attributes[0], attributes[1]);
  }
  std::vector<std::int64_t> pointOfCorner(obj.corners.size());
  std::unordered_map<Corner, std::int64_t, CornerHash> extraPoints;
  for (std::size_t c = 0; c < obj.corners.size(); ++c)
  {
    const Corner& corner = obj.corners[c];
    const std::size_t vertex = corner[0] - 1;
    if (!withAttributes ||
        (attributesOf[vertex][0] == corner[1] && attributesOf[vertex][1] == corner[2]))
    {
      pointOfCorner[c] = static_cast<std::int64_t>(vertex);
      continue;
    }
    const auto [found, inserted] = extraPoints.emplace(corner, polygons.numPoints());
    if (inserted)
    {
      appendPoint(corner[0], corner[1], corner[2]);
    }
    pointOfCorner[c] = found->second;
  }

  std::size_t first = 0;
  for (std::size_t cell = 0; cell < obj.cellSizes.size(); ++cell)
  {
    const std::uint32_t size = obj.cellSizes[cell];
    const std::int64_t* ids = &pointOfCorner[first];
    first += size;
    switch (obj.cellKinds[cell])
    {
      // A face of one or two corners is a vertex cell or a line.
      case CellKind::Face: polygons.addCell(ids, size); break;
      // A polyline of any length is one line cell; a single point, a vertex cell.
      case CellKind::Line: ++(size >= 2 ? polygons.numLines : polygons.numVertexCells); break;
      // p with any number of points is one (poly-)vertex cell.
      case CellKind::Point: ++polygons.numVertexCells; break;
    }
  }
  return polygons;
}

} // namespace proxima::detail
