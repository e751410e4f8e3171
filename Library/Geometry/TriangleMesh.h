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
  Vec3 a; ///< The corner of the triple's first index.
  Vec3 b; ///< The corner of the triple's second index.
  Vec3 c; ///< The corner of the triple's third index.
};

/// What went wrong when a soup was refused; `message` names the defect and where it is.
struct MeshError
{
  /// The defect that made TriangleMesh::build() refuse the soup.
  enum class Kind
  {
    None,                  ///< No error: the soup was accepted.
    NoTriangles,           ///< The soup has no triangle.
    NonFiniteCoordinate,   ///< A point has an infinite or NaN coordinate.
    IndexOutOfRange,       ///< A triangle refers to a point past the end of the points.
    AttributeSizeMismatch, ///< Normals or texture coordinates are neither none nor one per point.
    NonFiniteAttribute     ///< A point normal or texture coordinate is infinite or NaN.
  };
  /// The defect; None when there is none.
  Kind kind = Kind::None;
  /// A sentence for people naming the defect and where it is (the point or triangle index).
  std::string message;
  /// True when there is an error.
  explicit operator bool() const { return kind != Kind::None; }
};

/// The kernel's triangle mesh: a TriangleSoup that build() validated, with each triangle's corners
/// copied out for the exact tests. It does not change after build() except through placeAs() and
/// movePoints().
class TriangleMesh
{
public:
  TriangleMesh() = default;

  /// Validates `soup` and builds the mesh. On failure returns false, fills `error` and leaves
  /// this mesh unchanged. Degenerate (zero-area) triangles are kept: their edges still collide.
  bool build(TriangleSoup soup, MeshError& error);

  /// Number of triangles; 0 before a successful build().
  std::uint32_t numTriangles() const { return static_cast<std::uint32_t>(m_corners.size()); }
  /// Number of points, used by a triangle or not.
  std::uint32_t numPoints() const { return static_cast<std::uint32_t>(m_soup.points.size()); }
  /// Triangles whose area is zero to double precision (collinear or coincident corners).
  std::uint32_t numDegenerateTriangles() const { return m_numDegenerate; }

  /// The corners of triangle `triangle` (unchecked: it must be below numTriangles()).
  const TriangleCorners& corners(std::uint32_t triangle) const { return m_corners[triangle]; }
  /// The point indices of triangle `triangle` (unchecked: it must be below numTriangles()).
  const std::array<std::uint32_t, 3>& indices(std::uint32_t triangle) const
  {
    return m_soup.triangles[triangle];
  }
  /// The points, indexed by the triangles' index triples.
  const std::vector<Vec3>& points() const { return m_soup.points; }
  /// True when the mesh has one normal per point.
  bool hasPointNormals() const { return !m_soup.pointNormals.empty(); }
  /// True when the mesh has one texture coordinate per point.
  bool hasTexCoords() const { return !m_soup.texCoords.empty(); }
  /// The point normals as given (finite, not normalised here); empty when there are none.
  const std::vector<Vec3>& pointNormals() const { return m_soup.pointNormals; }
  /// The texture coordinates; empty when there are none.
  const std::vector<TexCoord>& texCoords() const { return m_soup.texCoords; }

  /// The box around every triangle's corners (points no triangle uses are left out).
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

  /// Moves the points to `points` (`count` of them, as many as numPoints(), all finite), keeping
  /// the triangles: a deforming surface where it is now (corners, bounds and the degenerate count
  /// follow; point normals and texture coordinates stay as they were). Returns false and changes
  /// nothing for another count or a non-finite point. Allocates nothing; O(points + triangles).
  bool movePoints(const Vec3* points, std::size_t count);

  /// Bytes held by the mesh (soup and the per-triangle corner copies).
  std::size_t memoryBytes() const;

private:
  /// Remakes every triangle's corner copy, the bounds and the largest coordinate from the points
  /// as they now are (placeAs and movePoints). Allocates nothing.
  void copyCornersFromPoints();

  TriangleSoup m_soup;
  std::vector<TriangleCorners> m_corners;
  Aabb m_bounds;
  double m_maxAbsCoordinate = 0.0;
  std::uint32_t m_numDegenerate = 0;
};

} // namespace proxima
