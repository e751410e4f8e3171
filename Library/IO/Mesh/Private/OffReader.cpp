#include "IO/Mesh/Private/OffReader.h"

#include "IO/InputChecks/InputError.h"

#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/IO/reader/OFFReader.hh>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace proxima::detail
{
namespace
{
using OpenMesh::EdgeHandle;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

/// Thrown from inside OpenMesh's parser to stop it at the first defect: the parser itself never
/// checks its stream, and would go on reading zeros (or stale values) to the end.
struct StopParsing
{
  std::string defect;
};

/// A vertex's three coordinates as the file writes them, parsed in double.
using Position = std::array<double, 3>;

/// Whether `fromText` (a coordinate parsed in double) is the number OpenMesh parsed as
/// `fromOpenMesh` (in float) from the same text. Rounding the text to double and then to float can
/// land one float step away from rounding it to float at once, so either neighbour counts too.
bool isSameCoordinate(double fromText, float fromOpenMesh)
{
  return static_cast<double>(std::nextafter(fromOpenMesh, -HUGE_VALF)) <= fromText &&
         fromText <= static_cast<double>(std::nextafter(fromOpenMesh, HUGE_VALF));
}

/// Receives what OpenMesh's OFF parser reads. Only vertices, faces, vertex normals and texture
/// coordinates matter; every other callback of the interface is accepted and ignored.
class SoupImporter : public OpenMesh::IO::BaseImporter
{
public:
  /// `positionsInDouble`: the ASCII file's coordinates parsed in double, one per vertex in file
  /// order, which replace OpenMesh's float ones; null for a binary file, whose float32
  /// coordinates OpenMesh already reads exactly.
  SoupImporter(const std::istream& stream, std::uint64_t expectedVertices,
               std::uint64_t expectedFaces, const std::vector<Position>* positionsInDouble)
    : m_stream(stream)
    , m_expectedVertices(expectedVertices)
    , m_expectedFaces(expectedFaces)
    , m_positionsInDouble(positionsInDouble)
  {}

  /// What was read, with normals and texture coordinates when the file had them (OpenMesh reads
  /// them in float; zero for a vertex without).
  PolygonSoup takePolygons()
  {
    if (m_hasNormals)
    {
      m_polygons.normals.reserve(3 * m_normalValues.size());
      for (const auto& n : m_normalValues)
      {
        m_polygons.normals.insert(m_polygons.normals.end(), n.begin(), n.end());
      }
    }
    if (m_hasTexCoords)
    {
      m_polygons.texCoords.reserve(2 * m_texCoordValues.size());
      for (const auto& t : m_texCoordValues)
      {
        m_polygons.texCoords.insert(m_polygons.texCoords.end(), t.begin(), t.end());
      }
    }
    return std::move(m_polygons);
  }

  std::uint64_t numVertices() const { return m_numVertices; }
  std::uint64_t numFaces() const { return m_numFaces; }

  VertexHandle add_vertex(const OpenMesh::Vec3f& p) override
  {
    if (m_positionsInDouble && !m_stream.fail())
    {
      return addVertex(positionInDouble(p));
    }
    return addVertex(p[0], p[1], p[2]);
  }
  VertexHandle add_vertex(const OpenMesh::Vec3d& p) override { return addVertex(p[0], p[1], p[2]); }
  VertexHandle add_vertex() override { return addVertex(0.0, 0.0, 0.0); }

  FaceHandle add_face(const VHandles& indices) override
  {
    if (m_stream.fail())
    {
      throw StopParsing{"cannot read face " + std::to_string(m_numFaces) + " (of " +
                        std::to_string(m_expectedFaces) + "): malformed or truncated data"};
    }
    m_ids.clear();
    for (const VertexHandle& handle : indices)
    {
      // OpenMesh keeps the parsed unsigned index in an int: a huge one comes back negative.
      const auto index = static_cast<std::uint32_t>(handle.idx());
      if (index >= m_numVertices)
      {
        throw StopParsing{"face " + std::to_string(m_numFaces) + " refers to vertex " +
                          std::to_string(index) + ", out of range (the file has " +
                          std::to_string(m_numVertices) + " vertices)"};
      }
      m_ids.push_back(static_cast<std::int64_t>(index));
    }
    // Faces of one or two vertices are vertex cells and lines, counted only.
    m_polygons.addCell(m_ids.data(), m_ids.size());
    return FaceHandle(static_cast<int>(m_numFaces++));
  }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }

  void set_normal(VertexHandle vh, const OpenMesh::Vec3f& n) override
  {
    setNormal(vh, n[0], n[1], n[2]);
  }
  void set_normal(VertexHandle vh, const OpenMesh::Vec3d& n) override
  {
    setNormal(vh, n[0], n[1], n[2]);
  }
  void set_texcoord(VertexHandle vh, const OpenMesh::Vec2f& t) override
  {
    if (vh.idx() >= 0 && static_cast<std::size_t>(vh.idx()) < m_texCoordValues.size())
    {
      m_hasTexCoords = true;
      m_texCoordValues[static_cast<std::size_t>(vh.idx())] = {t[0], t[1]};
    }
  }

  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_point(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_status(VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
  // The header's counts are not trusted with memory: a garbled header could ask for billions.
  void reserve(unsigned int, unsigned int, unsigned int) override {}

  size_t n_vertices() const override { return static_cast<size_t>(m_numVertices); }
  size_t n_faces() const override { return static_cast<size_t>(m_numFaces); }
  size_t n_edges() const override { return 0; }

private:
  /// The double coordinates of the vertex OpenMesh has just read as `single`. The walk that
  /// parsed them follows OpenMesh's reading number by number, so they are the same numbers; a
  /// mismatch would be a bug of that walk, not of the file, and must not pass unseen.
  Position positionInDouble(const OpenMesh::Vec3f& single) const
  {
    const auto index = static_cast<std::size_t>(m_numVertices);
    if (index >= m_positionsInDouble->size())
    {
      throw std::logic_error("OFF reader: OpenMesh read more vertices than the check walk found");
    }
    const Position& position = (*m_positionsInDouble)[index];
    for (int i = 0; i < 3; ++i)
    {
      if (!isSameCoordinate(position[static_cast<std::size_t>(i)], single[i]))
      {
        std::ostringstream out;
        out.precision(17);
        out << "OFF reader: vertex " << index << " coordinate " << i << " parsed as "
            << position[static_cast<std::size_t>(i)] << " in double but " << single[i]
            << " by OpenMesh";
        throw std::logic_error(out.str());
      }
    }
    return position;
  }

  VertexHandle addVertex(const Position& p) { return addVertex(p[0], p[1], p[2]); }

  VertexHandle addVertex(double x, double y, double z)
  {
    if (m_stream.fail())
    {
      throw StopParsing{"cannot read the coordinates of vertex " + std::to_string(m_numVertices) +
                        " (of " + std::to_string(m_expectedVertices) +
                        "): malformed or truncated data"};
    }
    m_polygons.addPoint(x, y, z);
    m_normalValues.push_back({0.0f, 0.0f, 0.0f});
    m_texCoordValues.push_back({0.0f, 0.0f});
    return VertexHandle(static_cast<int>(m_numVertices++));
  }

  void setNormal(VertexHandle vh, double x, double y, double z)
  {
    if (vh.idx() >= 0 && static_cast<std::size_t>(vh.idx()) < m_normalValues.size())
    {
      m_hasNormals = true;
      m_normalValues[static_cast<std::size_t>(vh.idx())] = {
        static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
    }
  }

  const std::istream& m_stream;
  std::uint64_t m_expectedVertices = 0;
  std::uint64_t m_expectedFaces = 0;
  std::uint64_t m_numVertices = 0;
  std::uint64_t m_numFaces = 0;
  const std::vector<Position>* m_positionsInDouble = nullptr;
  PolygonSoup m_polygons;
  std::vector<std::array<float, 3>> m_normalValues;
  std::vector<std::array<float, 2>> m_texCoordValues;
  std::vector<std::int64_t> m_ids;
  bool m_hasNormals = false;
  bool m_hasTexCoords = false;
};

struct OffHeader
{
  bool binary = false;
  std::uint64_t numVertices = 0;
  std::uint64_t numFaces = 0;
};

/// Reads the header the way OpenMesh will (first line, then three counts), to refuse a garbled
/// one before OpenMesh loops over counts it never checked.
OffHeader readHeader(const std::string& path)
{
  std::ifstream stream(path, std::ios::binary);
  std::string first;
  std::getline(stream, first);
  OffHeader header;
  const std::size_t off = first.find("OFF");
  if (off == std::string::npos || off > 4)
  {
    throw InputError(path, "not an OFF file (the first line is not an OFF header)");
  }
  const std::size_t rest = first.find_first_not_of(" \t\r", off + 3);
  // BINARY must be the header line's only word after OFF: OpenMesh's reader reads a line such as
  // "OFF\x9f40-  BINARY" as ASCII, with counts this check would then have skipped (found by
  // fuzzing: OpenMesh allocated without bound).
  const std::size_t end = first.find_last_not_of(" \t\r");
  header.binary = rest != std::string::npos && first.compare(rest, end + 1 - rest, "BINARY") == 0;
  if (!header.binary && first.find("BINARY") != std::string::npos)
  {
    throw InputError(path, "garbled OFF header (BINARY must follow OFF alone on the first line)");
  }
  if (!header.binary && rest != std::string::npos &&
      std::isdigit(static_cast<unsigned char>(first[rest])))
  {
    // OpenMesh takes the whole first line as the header and would read the first vertex as the
    // counts.
    throw InputError(path, "the vertex, face and edge counts must be on the line after 'OFF' "
                           "(OpenMesh's reader does not accept them on the header line)");
  }
  if (header.binary)
  {
    // Three 32-bit counts (vertices, faces, edges) follow the header line; every vertex takes at
    // least 12 bytes and every face 16, so counts the rest of the file cannot hold are garbage
    // that OpenMesh would allocate for (found by fuzzing).
    std::uint32_t counts[3] = {0, 0, 0};
    stream.read(reinterpret_cast<char*>(counts), sizeof counts);
    const std::streamoff at = stream.tellg();
    stream.seekg(0, std::ios::end);
    const std::streamoff size = stream.tellg();
    if (!stream || at < 0 || size < at)
    {
      throw InputError(path, "cannot read the vertex, face and edge counts of the binary OFF file");
    }
    const auto left = static_cast<std::uint64_t>(size - at);
    if (12ull * counts[0] + 16ull * counts[1] > left)
    {
      throw InputError(path, "the binary OFF header counts " + std::to_string(counts[0]) +
                               " vertices and " + std::to_string(counts[1]) +
                               " faces, more than the file's " + std::to_string(left) +
                               " bytes can hold");
    }
    header.numVertices = counts[0];
    header.numFaces = counts[1];
  }
  else
  {
    long long vertices = -1;
    long long faces = -1;
    long long edges = -1;
    stream >> vertices >> faces >> edges;
    if (!stream || vertices < 0 || faces < 0)
    {
      throw InputError(path, "cannot read the vertex, face and edge counts after the OFF header "
                             "(comment lines are not supported there)");
    }
    header.numVertices = static_cast<std::uint64_t>(vertices);
    header.numFaces = static_cast<std::uint64_t>(faces);
  }
  return header;
}

/// The longest valence accepted on an ASCII face line (no real polygon comes near it).
constexpr long long kMaxFaceValence = 1 << 16;

/// Checks the ASCII faces before OpenMesh reads them: OpenMesh reads a face's vertex count into
/// an unsigned int and loops over it, so "-3 0 1 2", a huge count or one too long for the type
/// made it allocate without bound (found by fuzzing). The walk follows OpenMesh's reading: the
/// counts as numbers, each vertex as three numbers (six with N) and then the rest of its line
/// (colours, texture coordinates), each face as a count and that many indices, number by number
/// across lines, and then, when the header says C (COFF), the rest of its line (the face's
/// colour). Where the numbers run out, the file is refused here too.
///
/// Returns each vertex's first three numbers parsed in double: OpenMesh parses them in float
/// (about 7 digits), which moves the surface by up to half a float step (1.5e-8 file units on
/// fandisk.off, whose four-digit coordinates are nearly all beyond float), and this walk reads
/// the same numbers anyway. The vector grows with the numbers actually read, never with the
/// header's count.
std::vector<Position> checkAsciiAndReadPositions(const std::string& path, const OffHeader& header)
{
  std::ifstream stream(path, std::ios::binary);
  std::string line;
  std::getline(stream, line); // the OFF header
  const std::string prefix = line.substr(0, line.find("OFF"));
  long long counts[3] = {0, 0, 0};
  stream >> counts[0] >> counts[1] >> counts[2];
  const int numbersPerVertex = prefix.find('N') != std::string::npos ? 6 : 3;
  // OpenMesh reads a colour after a face's indices only in a C file; in a plain OFF file it reads
  // the colour's first number as the next face's vertex count, so that is where a file with face
  // colours and no C fails, and the message says why.
  const bool faceColours = prefix.find('C') != std::string::npos;
  const std::string colourHint =
    faceColours ? "" : "; if the faces carry colours, the header must be COFF";
  std::vector<Position> positions;
  for (std::uint64_t v = 0; v < header.numVertices; ++v)
  {
    Position position = {0.0, 0.0, 0.0};
    double normalComponent = 0.0;
    for (int i = 0; i < numbersPerVertex; ++i)
    {
      double& target = i < 3 ? position[static_cast<std::size_t>(i)] : normalComponent;
      if (!(stream >> target))
      {
        // Not left to OpenMesh: past the end of its stream it goes on to the faces with a vertex
        // count it never read (found by fuzzing: "OFF\n446104461 4 7" and nothing more).
        throw InputError(path, "cannot read the coordinates of vertex " + std::to_string(v) +
                                 " (of " + std::to_string(header.numVertices) +
                                 "): malformed or truncated data");
      }
    }
    positions.push_back(position);
    std::getline(stream, line);
  }
  for (std::uint64_t f = 0; f < header.numFaces; ++f)
  {
    const std::string where =
      "cannot read face " + std::to_string(f) + " (of " + std::to_string(header.numFaces) + "): ";
    long long valence = 0;
    if (!(stream >> valence))
    {
      if (stream.eof())
      {
        throw InputError(path, where + "malformed or truncated data");
      }
      throw InputError(path, where + "it does not start with a vertex count of at most " +
                               std::to_string(kMaxFaceValence) + colourHint);
    }
    if (valence <= 0 || valence > kMaxFaceValence ||
        static_cast<std::uint64_t>(valence) > header.numVertices)
    {
      throw InputError(path, where + "a vertex count of " + std::to_string(valence) +
                               " (it must be from 1 to the file's " +
                               std::to_string(header.numVertices) + " vertices, at most " +
                               std::to_string(kMaxFaceValence) + ")" + colourHint);
    }
    long long read = 0;
    long long index = 0;
    while (read < valence && stream >> index)
    {
      ++read;
    }
    if (read < valence)
    {
      throw InputError(path, where + "it announces " + std::to_string(valence) + " vertices but " +
                               std::to_string(read) + " indices follow" + colourHint);
    }
    if (faceColours)
    {
      std::getline(stream, line);
    }
  }
  return positions;
}

} // namespace

PolygonSoup readOffWithOpenMesh(const std::string& path)
{
  const OffHeader header = readHeader(path);
  std::vector<Position> positionsInDouble;
  if (!header.binary)
  {
    positionsInDouble = checkAsciiAndReadPositions(path, header);
  }
  // OpenMesh's reader is a process-wide singleton whose format options are set by can_u_read and
  // used by read: two threads must not interleave them.
  static std::mutex readerMutex;
  std::lock_guard<std::mutex> lock(readerMutex);
  OpenMesh::IO::_OFFReader_& reader = OpenMesh::IO::OFFReader();
  if (!reader.can_u_read(path))
  {
    throw InputError(path, "not an OFF file OpenMesh can read (unsupported header: 4D or "
                           "n-dimensional vertices?)");
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
  {
    throw InputError(path, "cannot open the file");
  }
  SoupImporter importer(stream, header.numVertices, header.numFaces,
                        header.binary ? nullptr : &positionsInDouble);
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexNormal;
  options += OpenMesh::IO::Options::VertexTexCoord;
  if (header.binary)
  {
    options += OpenMesh::IO::Options::Binary;
  }
  try
  {
    if (!reader.read(stream, importer, options))
    {
      throw InputError(path, "OpenMesh could not parse the file");
    }
  }
  catch (const StopParsing& stop)
  {
    throw InputError(path, stop.defect);
  }
  if (!header.binary && importer.numVertices() < header.numVertices)
  {
    throw InputError(path, "truncated: the header announces " + std::to_string(header.numVertices) +
                             " vertices, the file holds " + std::to_string(importer.numVertices()));
  }
  return importer.takePolygons();
}

} // namespace proxima::detail
