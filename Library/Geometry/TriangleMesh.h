// The kernel's immutable triangle mesh: validated indices, finite coordinates, and per-triangle
// corner positions stored contiguously so an exact test touches one cache line pair.
#pragma once

#include "Core/Aabb.h"
#include "Core/RigidTransform.h"
#include "Core/Vec3.h"
#include "Geometry/TriangleSoup.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace proxima
{

/// The three corners of one triangle, in the order of its index triple.
struct TriangleCorners
{
  Vec3 a;
  Vec3 b;
  Vec3 c;
};

/// What went wrong when a soup was refused; `message` names the defect and where it is.
struct MeshError
{
  enum class Kind
  {
    None,
    NoTriangles,
    NonFiniteCoordinate,
    IndexOutOfRange,
    AttributeSizeMismatch,
    NonFiniteAttribute
  };
  Kind kind = Kind::None;
  std::string message;
  explicit operator bool() const { return kind != Kind::None; }
};

class TriangleMesh
{
public:
  TriangleMesh() = default;

  /// Validates `soup` and builds the mesh. On failure returns false, fills `error` and leaves
  /// this mesh unchanged. Degenerate (zero-area) triangles are kept: their edges still collide.
  bool build(TriangleSoup soup, MeshError& error);

  std::uint32_t numTriangles() const { return static_cast<std::uint32_t>(m_corners.size()); }
  std::uint32_t numPoints() const { return static_cast<std::uint32_t>(m_soup.points.size()); }
  /// Triangles whose area is zero to double precision (collinear or coincident corners).
  std::uint32_t numDegenerateTriangles() const { return m_numDegenerate; }

  const TriangleCorners& corners(std::uint32_t triangle) const { return m_corners[triangle]; }
  const std::array<std::uint32_t, 3>& indices(std::uint32_t triangle) const
  {
    return m_soup.triangles[triangle];
  }
  const std::vector<Vec3>& points() const { return m_soup.points; }
  bool hasPointNormals() const { return !m_soup.pointNormals.empty(); }
  bool hasTexCoords() const { return !m_soup.texCoords.empty(); }
  const std::vector<Vec3>& pointNormals() const { return m_soup.pointNormals; }
  const std::vector<TexCoord>& texCoords() const { return m_soup.texCoords; }

  const Aabb& bounds() const { return m_bounds; }
  /// Length of the bounding box diagonal: the scene's length scale for tolerances.
  double diagonal() const { return m_bounds.diagonal(); }
  /// Largest absolute coordinate: sets the rounding scale of every position computed near it.
  double maxAbsCoordinate() const { return m_maxAbsCoordinate; }

  /// Makes this mesh `placed` moved by `pose` (points, point normals, corners, bounds; texture
  /// coordinates stay): a moving body's object where it is now. When this mesh is already a copy
  /// of `placed` it allocates nothing, so the haptic thread may call it each tick a body moves;
  /// O(points + triangles).
  void placeAs(const TriangleMesh& placed, const RigidTransform& pose);

  /// Bytes held by the mesh (soup and the per-triangle corner copies).
  std::size_t memoryBytes() const;

private:
  TriangleSoup m_soup;
  std::vector<TriangleCorners> m_corners;
  Aabb m_bounds;
  double m_maxAbsCoordinate = 0.0;
  std::uint32_t m_numDegenerate = 0;
};

} // namespace proxima
