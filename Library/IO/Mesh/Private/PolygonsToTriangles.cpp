#include "IO/Mesh/Private/PolygonsToTriangles.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Mesh/Private/VtkOnUse.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace proxima::detail
{
namespace
{
// The helpers and the messages are polyDataToSoup's (PolyDataToSoup.cpp), word for word: a file
// must be refused the same way whichever of the two converts it.

std::string formatTuple(const double* values, int count)
{
  std::ostringstream out;
  out << "(";
  for (int i = 0; i < count; ++i)
  {
    out << (i ? ", " : "") << values[i];
  }
  out << ")";
  return out.str();
}

void checkFinitePoints(const PolygonSoup& polygons, const std::string& path)
{
  for (std::int64_t i = 0; i < polygons.numPoints(); ++i)
  {
    const double* p = &polygons.points[static_cast<std::size_t>(3 * i)];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      throw InputError(path, "point " + std::to_string(i) + " has a non-finite coordinate " +
                               formatTuple(p, 3));
    }
  }
}

void checkPointIds(const PolygonSoup& polygons, const std::string& path)
{
  const std::int64_t numPoints = polygons.numPoints();
  for (std::int64_t face = 0; face < polygons.numFaces(); ++face)
  {
    const auto f = static_cast<std::size_t>(face);
    for (std::size_t k = polygons.faceStarts[f]; k < polygons.faceStarts[f + 1]; ++k)
    {
      const std::int64_t id = polygons.corners[k];
      if (id < 0 || id >= numPoints)
      {
        throw InputError(path, "polygon " + std::to_string(face) + " refers to point " +
                                 std::to_string(id) + ", out of range (the file has " +
                                 std::to_string(numPoints) + " points)");
      }
    }
  }
}

bool allTriangles(const PolygonSoup& polygons)
{
  for (std::size_t f = 0; f + 1 < polygons.faceStarts.size(); ++f)
  {
    if (polygons.faceStarts[f + 1] - polygons.faceStarts[f] != 3)
    {
      return false;
    }
  }
  return true;
}
} // namespace

TriangleSoup polygonsToTriangles(const PolygonSoup& polygons, const std::string& path, double scale)
{
  const std::int64_t numPoints = polygons.numPoints();
  const std::int64_t numFaces = polygons.numFaces();
  if (numFaces == 0)
  {
    const std::int64_t numLines = polygons.numLines;
    const std::int64_t numVerts = polygons.numVertexCells;
    if (numLines > 0 || numVerts > 0)
    {
      throw InputError(path, "no triangles (only " + std::to_string(numLines) +
                               (numLines == 1 ? " line" : " lines") + " and " +
                               std::to_string(numVerts) +
                               (numVerts == 1 ? " vertex cell)" : " vertex cells)"));
    }
    throw InputError(path, "no triangles");
  }
  checkFinitePoints(polygons, path);
  checkPointIds(polygons, path);

  // Lines and vertex cells beside triangles are simply dropped, as vtkTriangleFilter with
  // PassLinesOff and PassVertsOff does, keeping the triangles and the points as they are.
  if (!allTriangles(polygons))
  {
    return triangulateWithVtk(polygons, path, scale);
  }
  if (numPoints > std::numeric_limits<std::uint32_t>::max() ||
      numFaces > std::numeric_limits<std::uint32_t>::max())
  {
    throw InputError(path, "too large: more than 2^32 points or triangles");
  }

  TriangleSoup soup;
  soup.points.resize(static_cast<std::size_t>(numPoints));
  for (std::int64_t i = 0; i < numPoints; ++i)
  {
    const double* p = &polygons.points[static_cast<std::size_t>(3 * i)];
    Vec3& q = soup.points[static_cast<std::size_t>(i)];
    q = Vec3{p[0] * scale, p[1] * scale, p[2] * scale};
    if (!isFinite(q))
    {
      std::ostringstream out;
      out << "point " << i << " " << formatTuple(p, 3) << " leaves the range of double when "
          << "scaled by " << scale;
      throw InputError(path, out.str());
    }
  }

  soup.triangles.reserve(static_cast<std::size_t>(numFaces));
  for (std::size_t k = 0; k < polygons.corners.size(); k += 3)
  {
    soup.triangles.push_back({static_cast<std::uint32_t>(polygons.corners[k]),
                              static_cast<std::uint32_t>(polygons.corners[k + 1]),
                              static_cast<std::uint32_t>(polygons.corners[k + 2])});
  }

  if (polygons.normals.size() == polygons.points.size() && !polygons.normals.empty())
  {
    soup.pointNormals.resize(static_cast<std::size_t>(numPoints));
    for (std::int64_t i = 0; i < numPoints; ++i)
    {
      const double* n = &polygons.normals[static_cast<std::size_t>(3 * i)];
      if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2]))
      {
        throw InputError(path, "point normal " + std::to_string(i) + " is not finite " +
                                 formatTuple(n, 3));
      }
      // A uniform positive scale leaves directions alone.
      soup.pointNormals[static_cast<std::size_t>(i)] = Vec3{n[0], n[1], n[2]};
    }
  }
  if (polygons.texCoords.size() == 2 * static_cast<std::size_t>(numPoints) &&
      !polygons.texCoords.empty())
  {
    soup.texCoords.resize(static_cast<std::size_t>(numPoints));
    for (std::int64_t i = 0; i < numPoints; ++i)
    {
      const double* t = &polygons.texCoords[static_cast<std::size_t>(2 * i)];
      if (!std::isfinite(t[0]) || !std::isfinite(t[1]))
      {
        throw InputError(path, "texture coordinate " + std::to_string(i) + " is not finite " +
                                 formatTuple(t, 2));
      }
      soup.texCoords[static_cast<std::size_t>(i)] = TexCoord{t[0], t[1]};
    }
  }
  return soup;
}

} // namespace proxima::detail
