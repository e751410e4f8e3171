// Texture on a surface (paper 4.3): texture coordinates interpolated with the contact weights,
// Blinn's bump mapping of a constraint plane's normal, and maps that scale a material property.
// Plain C++ on the kernel's types; a lookup never allocates.
#pragma once

#include "Geometry/ClosestPoint.h"
#include "Geometry/TriangleMesh.h"
#include "Proxy/SurfaceMaterial.h"

namespace proxima
{

/// The texture coordinate at a contact: the triangle's corner coordinates interpolated with the
/// contact weights (paper eq. 1). The mesh must have texture coordinates.
TexCoord interpolateTexCoord(const TriangleMesh& mesh, std::uint32_t triangle,
                             const ClosestPointResult& contact);

/// Blinn's bump mapping: `base` (unit, into free space) tilted by the surface gradient of the
/// height field amplitude * image(u, v) over the triangle, n' = normalise(n - grad h). False when
/// the triangle's texture coordinates are degenerate or the tilt would turn the normal past the
/// plane (the base normal then stands).
bool bumpedNormal(const TriangleMesh& mesh, std::uint32_t triangle, const TexCoord& uv,
                  const Vec3& base, const TextureMap& map, Vec3& out);

/// The product of the values at `uv` of the material's maps with `role` (1 without any).
double textureScale(const SurfaceMaterial& material, TextureRole role, const TexCoord& uv);

} // namespace proxima
