#include "Proxy/SurfaceTexture.h"

#include <cmath>

namespace proxima
{

TexCoord interpolateTexCoord(const TriangleMesh& mesh, std::uint32_t triangle,
                             const ClosestPointResult& contact)
{
  const auto& index = mesh.indices(triangle);
  const std::vector<TexCoord>& coords = mesh.texCoords();
  TexCoord uv;
  for (int k = 0; k < 3; ++k)
  {
    uv.u += contact.weights[k] * coords[index[k]].u;
    uv.v += contact.weights[k] * coords[index[k]].v;
  }
  return uv;
}

bool bumpedNormal(const TriangleMesh& mesh, std::uint32_t triangle, const TexCoord& uv,
                  const Vec3& base, const TextureMap& map, Vec3& out)
{
  if (!map.image || map.image->empty())
  {
    return false;
  }
  // The surface gradients of u and v over the triangle: the vectors g in its plane with
  // g . e1 = du1 and g . e2 = du2 (likewise for v), from the 2x2 Gram system of its edges.
  const TriangleCorners& c = mesh.corners(triangle);
  const auto& index = mesh.indices(triangle);
  const std::vector<TexCoord>& coords = mesh.texCoords();
  const Vec3 e1 = c.b - c.a;
  const Vec3 e2 = c.c - c.a;
  const double g11 = dot(e1, e1);
  const double g12 = dot(e1, e2);
  const double g22 = dot(e2, e2);
  const double determinant = g11 * g22 - g12 * g12;
  if (!(determinant > 1e-24 * g11 * g22))
  {
    return false; // a sliver or zero-area triangle has no usable texture frame
  }
  auto gradientOf = [&](double d1, double d2) {
    const double a = (g22 * d1 - g12 * d2) / determinant;
    const double b = (g11 * d2 - g12 * d1) / determinant;
    return e1 * a + e2 * b;
  };
  const TexCoord& t0 = coords[index[0]];
  const TexCoord& t1 = coords[index[1]];
  const TexCoord& t2 = coords[index[2]];
  const Vec3 gradientU = gradientOf(t1.u - t0.u, t2.u - t0.u);
  const Vec3 gradientV = gradientOf(t1.v - t0.v, t2.v - t0.v);
  double dSampleDu = 0.0;
  double dSampleDv = 0.0;
  map.image->gradient(uv.u, uv.v, dSampleDu, dSampleDv);
  Vec3 heightGradient = (gradientU * dSampleDu + gradientV * dSampleDv) * map.amplitude;
  // Only the part along the surface tilts the normal (the triangle's plane and the base normal
  // differ where the base is shaded).
  heightGradient -= base * dot(heightGradient, base);
  const Vec3 tilted = base - heightGradient;
  const double length = norm(tilted);
  if (!(length > 0.0) || !(dot(tilted, base) > 0.0))
  {
    return false;
  }
  out = tilted / length;
  return true;
}

double textureScale(const SurfaceMaterial& material, TextureRole role, const TexCoord& uv)
{
  double scale = 1.0;
  for (const TextureMap& map : material.textures)
  {
    if (map.role == role && map.image && !map.image->empty())
    {
      scale *= map.image->sample(uv.u, uv.v);
    }
  }
  return scale;
}

} // namespace proxima
