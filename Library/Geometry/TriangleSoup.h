// A triangle soup as it comes from a file or a generator: points, index triples and optional
// per-point attributes. No checks yet: TriangleMesh::build validates it for the kernel.
#pragma once

#include "Core/Vec3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace proxima
{

/// A point's texture coordinate: where on a texture image (TextureImage) the point lies; the
/// image spans [0, 1) on each axis and repeats outside.
struct TexCoord
{
  double u = 0.0; ///< Across the image: 0 at its first column's edge.
  double v = 0.0; ///< Up the image: 0 at its bottom row's edge.
};

/// Unchecked mesh data: points, triangles as index triples into them, and optional per-point
/// attributes. TriangleMesh::build() validates it.
struct TriangleSoup
{
  /// The points (m).
  std::vector<Vec3> points;
  /// One index triple per triangle, each index into `points`.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Empty, or one normal per point (shading interpolates these with the contact weights).
  std::vector<Vec3> pointNormals;
  /// Empty, or one texture coordinate per point.
  std::vector<TexCoord> texCoords;
};

} // namespace proxima
