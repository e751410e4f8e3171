// A triangle soup as it comes from a file or a generator: points, index triples and optional
// per-point attributes. No checks yet: TriangleMesh::build validates it for the kernel.
#pragma once

#include "Core/Vec3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace proxima
{

struct TexCoord
{
  double u = 0.0;
  double v = 0.0;
};

struct TriangleSoup
{
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Empty, or one normal per point (shading interpolates these with the contact weights).
  std::vector<Vec3> pointNormals;
  /// Empty, or one texture coordinate per point.
  std::vector<TexCoord> texCoords;
};

} // namespace proxima
