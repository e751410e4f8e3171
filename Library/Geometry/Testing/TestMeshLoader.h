// A minimal mesh loader for the geometry tests only: ASCII OBJ ('v' and 'f' lines, polygons fanned
// into triangles), OFF, binary STL, and binary little-endian PLY with float vertices and one face
// list. It keeps the tests independent of the IO layer; real reading, welding and validation live
// in Library/IO. Anything else (VTP, GLB, ASCII STL or PLY) is reported as unsupported.
#pragma once

#include "Geometry/TriangleSoup.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace proxima::test
{

struct LoadedMesh
{
  bool ok = false;
  std::string error;
  TriangleSoup soup;
};

namespace detail
{

inline std::string lowerExtension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

inline void addPolygon(TriangleSoup& soup, const std::vector<std::uint32_t>& polygon)
{
  for (std::size_t i = 2; i < polygon.size(); ++i)
  {
    soup.triangles.push_back({polygon[0], polygon[i - 1], polygon[i]});
  }
}

inline LoadedMesh loadObj(std::istream& in)
{
  LoadedMesh mesh;
  std::string line;
  std::vector<std::uint32_t> polygon;
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string tag;
    fields >> tag;
    if (tag == "v")
    {
      Vec3 p;
      fields >> p.x >> p.y >> p.z;
      mesh.soup.points.push_back(p);
    }
    else if (tag == "f")
    {
      polygon.clear();
      std::string corner;
      while (fields >> corner)
      {
        // "i", "i/t", "i//n" or "i/t/n"; negative indices count back from the last vertex.
        const long index = std::stol(corner.substr(0, corner.find('/')));
        const long resolved =
          index < 0 ? static_cast<long>(mesh.soup.points.size()) + index : index - 1;
        polygon.push_back(static_cast<std::uint32_t>(resolved));
      }
      addPolygon(mesh.soup, polygon);
    }
  }
  mesh.ok = true;
  return mesh;
}

inline LoadedMesh loadOff(std::istream& in)
{
  LoadedMesh mesh;
  std::string header;
  in >> header;
  if (header != "OFF")
  {
    mesh.error = "not an OFF file";
    return mesh;
  }
  std::size_t numPoints = 0;
  std::size_t numFaces = 0;
  std::size_t numEdges = 0;
  in >> numPoints >> numFaces >> numEdges;
  mesh.soup.points.resize(numPoints);
  for (Vec3& p : mesh.soup.points)
  {
    in >> p.x >> p.y >> p.z;
  }
  std::vector<std::uint32_t> polygon;
  for (std::size_t f = 0; f < numFaces && in; ++f)
  {
    std::size_t count = 0;
    in >> count;
    polygon.resize(count);
    for (std::uint32_t& index : polygon)
    {
      in >> index;
    }
    addPolygon(mesh.soup, polygon);
  }
  mesh.ok = static_cast<bool>(in);
  mesh.error = mesh.ok ? "" : "truncated OFF file";
  return mesh;
}

inline LoadedMesh loadBinaryStl(const std::vector<char>& bytes)
{
  LoadedMesh mesh;
  std::uint32_t numTriangles = 0;
  if (bytes.size() < 84)
  {
    mesh.error = "too short for a binary STL";
    return mesh;
  }
  std::memcpy(&numTriangles, bytes.data() + 80, 4);
  if (bytes.size() != 84 + std::size_t{numTriangles} * 50)
  {
    mesh.error = "not a binary STL (size does not match the triangle count)";
    return mesh;
  }
  // Unindexed: every corner is its own point, as the file has it.
  for (std::uint32_t t = 0; t < numTriangles; ++t)
  {
    const char* record = bytes.data() + 84 + std::size_t{t} * 50 + 12; // skip the normal
    const auto first = static_cast<std::uint32_t>(mesh.soup.points.size());
    for (int corner = 0; corner < 3; ++corner)
    {
      float xyz[3];
      std::memcpy(xyz, record + corner * 12, 12);
      mesh.soup.points.push_back({xyz[0], xyz[1], xyz[2]});
    }
    mesh.soup.triangles.push_back({first, first + 1, first + 2});
  }
  mesh.ok = true;
  return mesh;
}

/// Binary little-endian PLY with `element vertex` of float x, y, z (first, other float or uchar
/// properties after them are skipped) and `element face` with one `list uchar int` property.
inline LoadedMesh loadBinaryPly(const std::vector<char>& bytes)
{
  LoadedMesh mesh;
  const std::string text(bytes.data(), std::min<std::size_t>(bytes.size(), 4096));
  const auto headerEnd = text.find("end_header\n");
  if (text.rfind("ply", 0) != 0 || headerEnd == std::string::npos ||
      text.find("format binary_little_endian 1.0") == std::string::npos)
  {
    mesh.error = "only binary little-endian PLY is supported here";
    return mesh;
  }
  std::istringstream header(text.substr(0, headerEnd));
  std::string line;
  std::size_t numVertices = 0;
  std::size_t numFaces = 0;
  std::size_t vertexBytes = 0;
  std::string element;
  while (std::getline(header, line))
  {
    std::istringstream fields(line);
    std::string keyword;
    fields >> keyword;
    if (keyword == "element")
    {
      std::size_t count = 0;
      fields >> element >> count;
      if (element == "vertex")
      {
        numVertices = count;
      }
      else if (element == "face")
      {
        numFaces = count;
      }
      else
      {
        mesh.error = "unsupported PLY element: " + element;
        return mesh;
      }
    }
    else if (keyword == "property" && element == "vertex")
    {
      std::string type;
      fields >> type;
      vertexBytes += (type == "float" || type == "float32" || type == "int") ? 4
                     : (type == "double")                                    ? 8
                                                                             : 1;
    }
    else if (keyword == "property" && element == "face" &&
             line.find("list uchar int") == std::string::npos &&
             line.find("list uint8 int32") == std::string::npos)
    {
      mesh.error = "unsupported face property: " + line;
      return mesh;
    }
  }
  std::size_t offset = headerEnd + std::strlen("end_header\n");
  if (bytes.size() < offset + numVertices * vertexBytes)
  {
    mesh.error = "truncated PLY vertices";
    return mesh;
  }
  mesh.soup.points.resize(numVertices);
  for (std::size_t v = 0; v < numVertices; ++v, offset += vertexBytes)
  {
    float xyz[3];
    std::memcpy(xyz, bytes.data() + offset, 12);
    mesh.soup.points[v] = {xyz[0], xyz[1], xyz[2]};
  }
  std::vector<std::uint32_t> polygon;
  for (std::size_t f = 0; f < numFaces; ++f)
  {
    if (offset + 1 > bytes.size())
    {
      mesh.error = "truncated PLY faces";
      return mesh;
    }
    const auto count = static_cast<unsigned char>(bytes[offset]);
    offset += 1;
    if (offset + std::size_t{count} * 4 > bytes.size())
    {
      mesh.error = "truncated PLY faces";
      return mesh;
    }
    polygon.resize(count);
    std::memcpy(polygon.data(), bytes.data() + offset, std::size_t{count} * 4);
    offset += std::size_t{count} * 4;
    addPolygon(mesh.soup, polygon);
  }
  mesh.ok = true;
  return mesh;
}

} // namespace detail

/// Loads `path` if its format is one of the trivial ones above; `ok` false with `error` otherwise.
inline LoadedMesh loadTestMesh(const std::string& path)
{
  LoadedMesh mesh;
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    mesh.error = "cannot open " + path;
    return mesh;
  }
  const std::string extension = detail::lowerExtension(path);
  if (extension == "obj")
  {
    return detail::loadObj(file);
  }
  if (extension == "off")
  {
    return detail::loadOff(file);
  }
  if (extension == "stl" || extension == "ply")
  {
    const std::vector<char> bytes((std::istreambuf_iterator<char>(file)),
                                  std::istreambuf_iterator<char>());
    return extension == "stl" ? detail::loadBinaryStl(bytes) : detail::loadBinaryPly(bytes);
  }
  mesh.error = "format not supported by the test loader: " + path;
  return mesh;
}

} // namespace proxima::test
