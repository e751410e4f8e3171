#include "Geometry/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace proxima
{
namespace
{
MeshError makeError(MeshError::Kind kind, const std::string& message)
{
  MeshError error;
  error.kind = kind;
  error.message = message;
  return error;
}

bool isDegenerate(const TriangleCorners& t)
{
  // Exactly zero cross product: the corners are collinear or coincide in double precision.
  const Vec3 n = cross(t.b - t.a, t.c - t.a);
  return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}
} // namespace

bool TriangleMesh::build(TriangleSoup soup, MeshError& error)
{
  error = MeshError{};
  if (soup.triangles.empty())
  {
    error = makeError(MeshError::Kind::NoTriangles, "no triangles");
    return false;
  }
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    if (!isFinite(soup.points[i]))
    {
      std::ostringstream out;
      out << "point " << i << " has a non-finite coordinate (" << soup.points[i].x << ", "
          << soup.points[i].y << ", " << soup.points[i].z << ")";
      error = makeError(MeshError::Kind::NonFiniteCoordinate, out.str());
      return false;
    }
  }
  const std::size_t numPointsInSoup = soup.points.size();
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    for (std::uint32_t index : soup.triangles[t])
    {
      if (index >= numPointsInSoup)
      {
        std::ostringstream out;
        out << "triangle " << t << " refers to point " << index << " but there are only "
            << numPointsInSoup << " points";
        error = makeError(MeshError::Kind::IndexOutOfRange, out.str());
        return false;
      }
    }
  }
  if (!soup.pointNormals.empty() && soup.pointNormals.size() != numPointsInSoup)
  {
    error = makeError(MeshError::Kind::AttributeSizeMismatch,
                      "point normals count " + std::to_string(soup.pointNormals.size()) +
                        " differs from points count " + std::to_string(numPointsInSoup));
    return false;
  }
  if (!soup.texCoords.empty() && soup.texCoords.size() != numPointsInSoup)
  {
    error = makeError(MeshError::Kind::AttributeSizeMismatch,
                      "texture coordinates count " + std::to_string(soup.texCoords.size()) +
                        " differs from points count " + std::to_string(numPointsInSoup));
    return false;
  }
  for (std::size_t i = 0; i < soup.pointNormals.size(); ++i)
  {
    if (!isFinite(soup.pointNormals[i]))
    {
      error = makeError(MeshError::Kind::NonFiniteAttribute,
                        "point normal " + std::to_string(i) + " is not finite");
      return false;
    }
  }
  for (std::size_t i = 0; i < soup.texCoords.size(); ++i)
  {
    if (!std::isfinite(soup.texCoords[i].u) || !std::isfinite(soup.texCoords[i].v))
    {
      error = makeError(MeshError::Kind::NonFiniteAttribute,
                        "texture coordinate " + std::to_string(i) + " is not finite");
      return false;
    }
  }

  std::vector<TriangleCorners> corners(soup.triangles.size());
  Aabb bounds;
  std::uint32_t numDegenerate = 0;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const auto& tri = soup.triangles[t];
    corners[t] = TriangleCorners{soup.points[tri[0]], soup.points[tri[1]], soup.points[tri[2]]};
    bounds.expand(corners[t].a);
    bounds.expand(corners[t].b);
    bounds.expand(corners[t].c);
    numDegenerate += isDegenerate(corners[t]) ? 1u : 0u;
  }

  m_soup = std::move(soup);
  m_corners = std::move(corners);
  m_bounds = bounds;
  m_maxAbsCoordinate = std::max(maxAbsComponent(bounds.lower), maxAbsComponent(bounds.upper));
  m_numDegenerate = numDegenerate;
  return true;
}

void TriangleMesh::placeAs(const TriangleMesh& placed, const RigidTransform& pose)
{
  if (m_soup.points.size() != placed.m_soup.points.size() ||
      m_soup.triangles.size() != placed.m_soup.triangles.size() ||
      m_soup.pointNormals.size() != placed.m_soup.pointNormals.size())
  {
    *this = placed; // not a copy yet: the one allocation, off the haptic thread's steady state
  }
  for (std::size_t i = 0; i < placed.m_soup.points.size(); ++i)
  {
    m_soup.points[i] = pose.apply(placed.m_soup.points[i]);
  }
  for (std::size_t i = 0; i < placed.m_soup.pointNormals.size(); ++i)
  {
    m_soup.pointNormals[i] = pose.rotate(placed.m_soup.pointNormals[i]);
  }
  copyCornersFromPoints();
}

void TriangleMesh::copyCornersFromPoints()
{
  Aabb bounds;
  for (std::size_t t = 0; t < m_corners.size(); ++t)
  {
    const auto& tri = m_soup.triangles[t];
    m_corners[t] =
      TriangleCorners{m_soup.points[tri[0]], m_soup.points[tri[1]], m_soup.points[tri[2]]};
    bounds.expand(m_corners[t].a);
    bounds.expand(m_corners[t].b);
    bounds.expand(m_corners[t].c);
  }
  m_bounds = bounds;
  m_maxAbsCoordinate = std::max(maxAbsComponent(bounds.lower), maxAbsComponent(bounds.upper));
}

bool TriangleMesh::movePoints(const Vec3* points, std::size_t count)
{
  if (count != m_soup.points.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (!isFinite(points[i]))
    {
      return false;
    }
  }
  std::copy(points, points + count, m_soup.points.begin());
  copyCornersFromPoints();
  // A deformation, unlike a rigid placement, can collapse a triangle or open a collapsed one.
  std::uint32_t numDegenerate = 0;
  for (const TriangleCorners& corners : m_corners)
  {
    numDegenerate += isDegenerate(corners) ? 1u : 0u;
  }
  m_numDegenerate = numDegenerate;
  return true;
}

std::size_t TriangleMesh::memoryBytes() const
{
  return m_soup.points.capacity() * sizeof(Vec3) +
         m_soup.triangles.capacity() * sizeof(m_soup.triangles[0]) +
         m_soup.pointNormals.capacity() * sizeof(Vec3) +
         m_soup.texCoords.capacity() * sizeof(TexCoord) +
         m_corners.capacity() * sizeof(TriangleCorners);
}

} // namespace proxima
