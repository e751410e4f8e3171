#include "IO/MeshPreparation/PointNormals.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace proxima
{
namespace
{
using AdjacencyMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// The corners of a point whose normals agree to this, component by component, share one point.
constexpr double kSameNormal = 1e-12;
// A weighted sum of unit normals shorter than this fraction of its weights has lost its direction.
constexpr double kCancelledSum = 1e-12;

double angleBetween(const Vec3& a, const Vec3& b)
{
  // atan2 rather than acos: accurate for the nearly parallel normals of a smooth region.
  return std::atan2(norm(cross(a, b)), dot(a, b));
}

void validate(const TriangleSoup& soup, double featureAngleDegrees)
{
  if (!std::isfinite(featureAngleDegrees) || featureAngleDegrees < 0.0 ||
      featureAngleDegrees > 180.0)
  {
    throw std::invalid_argument("withFeatureAngleNormals: the feature angle must be a finite "
                                "number of degrees in [0, 180], not " +
                                std::to_string(featureAngleDegrees));
  }
  if (soup.points.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max()))
  {
    throw std::invalid_argument("withFeatureAngleNormals: " + std::to_string(soup.points.size()) +
                                " points is more than OpenMesh's int handles can index");
  }
  for (std::size_t i = 0; i < soup.points.size(); ++i)
  {
    if (!isFinite(soup.points[i]))
    {
      throw std::invalid_argument("withFeatureAngleNormals: point " + std::to_string(i) +
                                  " has a non-finite coordinate");
    }
  }
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    for (std::uint32_t index : soup.triangles[t])
    {
      if (index >= soup.points.size())
      {
        throw std::invalid_argument("withFeatureAngleNormals: triangle " + std::to_string(t) +
                                    " refers to point " + std::to_string(index) +
                                    ", out of range (" + std::to_string(soup.points.size()) +
                                    " points)");
      }
    }
  }
  if (!soup.texCoords.empty() && soup.texCoords.size() != soup.points.size())
  {
    throw std::invalid_argument(
      "withFeatureAngleNormals: " + std::to_string(soup.texCoords.size()) +
      " texture coordinates for " + std::to_string(soup.points.size()) + " points");
  }
}

/// For each point, the non-zero-area triangles that use it, in increasing order (compressed rows).
struct PointTriangles
{
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> triangles;

  std::size_t begin(std::uint32_t point) const { return offsets[point]; }
  std::size_t end(std::uint32_t point) const { return offsets[point + 1]; }
};

/// OpenMesh reports each face it cannot link (a non-manifold edge or vertex, a flipped
/// neighbour) on omerr; here that is expected and handled, so the messages would only be noise.
/// omerr is process-wide: the mutex keeps two calls of ours from re-enabling it under each other.
class QuietOpenMeshErrors
{
public:
  QuietOpenMeshErrors()
    : m_lock(mutex())
    , m_wasEnabled(::omerr().is_enabled())
  {
    ::omerr().disable();
  }
  ~QuietOpenMeshErrors()
  {
    if (m_wasEnabled)
    {
      ::omerr().enable();
    }
  }
  QuietOpenMeshErrors(const QuietOpenMeshErrors&) = delete;
  QuietOpenMeshErrors& operator=(const QuietOpenMeshErrors&) = delete;

private:
  static std::mutex& mutex()
  {
    static std::mutex instance;
    return instance;
  }

  std::lock_guard<std::mutex> m_lock;
  bool m_wasEnabled;
};

/// The vertex-face adjacency through OpenMesh's halfedge structure. A soup is not always a
/// manifold OpenMesh can link (non-manifold edges, inconsistently oriented neighbours,
/// duplicates): a face it refuses is added on its own copies of its three points, the way
/// OpenMesh's own importers do, and the copies are mapped back, so every triangle is still
/// found around each of its points.
PointTriangles buildPointTriangles(const TriangleSoup& soup, const std::vector<bool>& hasArea)
{
  const auto numPoints = static_cast<std::uint32_t>(soup.points.size());
  PointTriangles adjacency;
  adjacency.offsets.assign(numPoints + 1, 0);
  std::size_t numFaces = 0;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    if (hasArea[t])
    {
      ++numFaces;
      for (std::uint32_t index : soup.triangles[t])
      {
        ++adjacency.offsets[index + 1];
      }
    }
  }
  for (std::uint32_t i = 0; i < numPoints; ++i)
  {
    adjacency.offsets[i + 1] += adjacency.offsets[i];
  }
  adjacency.triangles.resize(adjacency.offsets[numPoints]);

  AdjacencyMesh mesh;
  std::vector<std::uint32_t> vertexToPoint;
  std::vector<std::uint32_t> faceToTriangle;
  vertexToPoint.reserve(numPoints);
  faceToTriangle.reserve(numFaces);
  mesh.reserve(numPoints, 3 * numFaces, numFaces);
  for (std::uint32_t i = 0; i < numPoints; ++i)
  {
    mesh.add_vertex(AdjacencyMesh::Point(0.0f, 0.0f, 0.0f));
    vertexToPoint.push_back(i);
  }
  {
    const QuietOpenMeshErrors quiet;
    for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    {
      if (!hasArea[t])
      {
        continue;
      }
      const auto& corners = soup.triangles[t];
      OpenMesh::FaceHandle face =
        mesh.add_face(OpenMesh::VertexHandle(static_cast<int>(corners[0])),
                      OpenMesh::VertexHandle(static_cast<int>(corners[1])),
                      OpenMesh::VertexHandle(static_cast<int>(corners[2])));
      if (!face.is_valid())
      {
        OpenMesh::VertexHandle copies[3];
        for (int k = 0; k < 3; ++k)
        {
          copies[k] = mesh.add_vertex(AdjacencyMesh::Point(0.0f, 0.0f, 0.0f));
          vertexToPoint.push_back(corners[static_cast<std::size_t>(k)]);
        }
        face = mesh.add_face(copies[0], copies[1], copies[2]);
      }
      if (!face.is_valid() || static_cast<std::size_t>(face.idx()) != faceToTriangle.size())
      {
        throw std::logic_error("withFeatureAngleNormals: OpenMesh did not add triangle " +
                               std::to_string(t) + " as the next face");
      }
      faceToTriangle.push_back(static_cast<std::uint32_t>(t));
    }
  }

  std::vector<std::uint32_t> filled(adjacency.offsets.begin(), adjacency.offsets.end() - 1);
  for (const auto vertex : mesh.vertices())
  {
    const std::uint32_t point = vertexToPoint[static_cast<std::size_t>(vertex.idx())];
    for (const auto face : vertex.faces())
    {
      if (filled[point] == adjacency.offsets[point + 1])
      {
        throw std::logic_error("withFeatureAngleNormals: OpenMesh lists more faces around point " +
                               std::to_string(point) + " than use it");
      }
      adjacency.triangles[filled[point]++] = faceToTriangle[static_cast<std::size_t>(face.idx())];
    }
  }
  for (std::uint32_t i = 0; i < numPoints; ++i)
  {
    // A circulator that missed a face (a vertex with several fans) must not go unnoticed.
    if (filled[i] != adjacency.offsets[i + 1])
    {
      throw std::logic_error("withFeatureAngleNormals: OpenMesh lists fewer faces around point " +
                             std::to_string(i) + " than use it");
    }
    // Triangle order makes the sums below independent of how OpenMesh circulates.
    std::sort(adjacency.triangles.begin() + adjacency.offsets[i],
              adjacency.triangles.begin() + adjacency.offsets[i + 1]);
  }
  return adjacency;
}

int cornerOf(const std::array<std::uint32_t, 3>& triangle, std::uint32_t point)
{
  return triangle[0] == point ? 0 : (triangle[1] == point ? 1 : 2);
}

bool sameNormal(const Vec3& a, const Vec3& b)
{
  return std::abs(a.x - b.x) <= kSameNormal && std::abs(a.y - b.y) <= kSameNormal &&
         std::abs(a.z - b.z) <= kSameNormal;
}
} // namespace

TriangleSoup withFeatureAngleNormals(const TriangleSoup& soup, double featureAngleDegrees)
{
  validate(soup, featureAngleDegrees);
  const std::size_t numTriangles = soup.triangles.size();
  const auto numPoints = static_cast<std::uint32_t>(soup.points.size());
  // At 180 every pair of normals is within the angle; comparing against a rounded pi could leave
  // out exactly opposite ones.
  const bool everyFace = featureAngleDegrees >= 180.0;
  const double featureAngle = featureAngleDegrees * (std::numbers::pi / 180.0);

  std::vector<Vec3> faceNormals(numTriangles);
  std::vector<bool> hasArea(numTriangles, false);
  std::vector<double> cornerAngles(3 * numTriangles, 0.0);
  for (std::size_t t = 0; t < numTriangles; ++t)
  {
    const auto& triangle = soup.triangles[t];
    const Vec3 p[3] = {soup.points[triangle[0]], soup.points[triangle[1]],
                       soup.points[triangle[2]]};
    const Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
    if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0)
    {
      continue;
    }
    hasArea[t] = true;
    faceNormals[t] = n / norm(n);
    for (int k = 0; k < 3; ++k)
    {
      cornerAngles[3 * t + k] = angleBetween(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
    }
  }

  const PointTriangles adjacency = buildPointTriangles(soup, hasArea);

  std::vector<Vec3> cornerNormals(3 * numTriangles);
  for (std::size_t t = 0; t < numTriangles; ++t)
  {
    if (!hasArea[t])
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t point = soup.triangles[t][static_cast<std::size_t>(k)];
      Vec3 sum;
      double weights = 0.0;
      for (std::size_t i = adjacency.begin(point); i < adjacency.end(point); ++i)
      {
        const std::uint32_t f = adjacency.triangles[i];
        if (everyFace || angleBetween(faceNormals[f], faceNormals[t]) <= featureAngle)
        {
          const double weight = cornerAngles[3 * f + cornerOf(soup.triangles[f], point)];
          sum += faceNormals[f] * weight;
          weights += weight;
        }
      }
      const double length = norm(sum);
      cornerNormals[3 * t + k] = length > kCancelledSum * weights ? sum / length : faceNormals[t];
    }
  }

  // Zero-area triangles borrow, after every real corner is known, so no order dependence.
  for (std::size_t t = 0; t < numTriangles; ++t)
  {
    if (hasArea[t])
    {
      continue;
    }
    const auto& triangle = soup.triangles[t];
    const Vec3 centroid =
      (soup.points[triangle[0]] + soup.points[triangle[1]] + soup.points[triangle[2]]) / 3.0;
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t point = triangle[static_cast<std::size_t>(k)];
      Vec3 normal{0.0, 0.0, 1.0};
      double nearest = std::numeric_limits<double>::infinity();
      // Increasing triangle order and a strict comparison: the lower index wins a tie.
      for (std::size_t i = adjacency.begin(point); i < adjacency.end(point); ++i)
      {
        const std::uint32_t f = adjacency.triangles[i];
        const auto& other = soup.triangles[f];
        const Vec3 otherCentroid =
          (soup.points[other[0]] + soup.points[other[1]] + soup.points[other[2]]) / 3.0;
        const double d = squaredDistance(centroid, otherCentroid);
        if (d < nearest)
        {
          nearest = d;
          normal = cornerNormals[3 * f + cornerOf(other, point)];
        }
      }
      cornerNormals[3 * t + k] = normal;
    }
  }

  // The corners of each point in triangle order (compressed rows again, zero-area ones included).
  std::vector<std::uint32_t> cornerOffsets(numPoints + 1, 0);
  for (const auto& triangle : soup.triangles)
  {
    for (std::uint32_t index : triangle)
    {
      ++cornerOffsets[index + 1];
    }
  }
  for (std::uint32_t i = 0; i < numPoints; ++i)
  {
    cornerOffsets[i + 1] += cornerOffsets[i];
  }
  std::vector<std::uint32_t> pointCorners(3 * numTriangles);
  {
    std::vector<std::uint32_t> filled(cornerOffsets.begin(), cornerOffsets.end() - 1);
    for (std::size_t c = 0; c < 3 * numTriangles; ++c)
    {
      const std::uint32_t point = soup.triangles[c / 3][c % 3];
      pointCorners[filled[point]++] = static_cast<std::uint32_t>(c);
    }
  }

  TriangleSoup result;
  result.triangles.resize(numTriangles);
  const bool hasTexCoords = !soup.texCoords.empty();
  std::vector<std::uint32_t> newPointsOfThisPoint;
  for (std::uint32_t point = 0; point < numPoints; ++point)
  {
    newPointsOfThisPoint.clear();
    for (std::size_t i = cornerOffsets[point]; i < cornerOffsets[point + 1]; ++i)
    {
      const std::uint32_t c = pointCorners[i];
      const Vec3& normal = cornerNormals[c];
      std::uint32_t newIndex = std::numeric_limits<std::uint32_t>::max();
      for (std::uint32_t candidate : newPointsOfThisPoint)
      {
        if (sameNormal(result.pointNormals[candidate], normal))
        {
          newIndex = candidate;
          break;
        }
      }
      if (newIndex == std::numeric_limits<std::uint32_t>::max())
      {
        if (result.points.size() >= std::numeric_limits<std::uint32_t>::max())
        {
          throw std::invalid_argument("withFeatureAngleNormals: splitting the points would make "
                                      "more than 2^32 - 1 of them");
        }
        newIndex = static_cast<std::uint32_t>(result.points.size());
        result.points.push_back(soup.points[point]);
        result.pointNormals.push_back(normal);
        if (hasTexCoords)
        {
          result.texCoords.push_back(soup.texCoords[point]);
        }
        newPointsOfThisPoint.push_back(newIndex);
      }
      result.triangles[c / 3][c % 3] = newIndex;
    }
  }
  return result;
}

} // namespace proxima
