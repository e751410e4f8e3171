#include "Geometry/SimplexClosestPoint.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/Gjk.h"

namespace proxima
{
namespace
{
// Keeps the vertices whose weight is positive, in order, and their weights.
void compact(GjkVertex* vertices, double* weights, int& size)
{
  int kept = 0;
  for (int i = 0; i < size; ++i)
  {
    if (weights[i] > 0.0)
    {
      vertices[kept] = vertices[i];
      weights[kept] = weights[i];
      ++kept;
    }
  }
  if (kept == 0)
  {
    // All weights underflowed: keep the first vertex, which is a valid (if coarse) answer.
    weights[0] = 1.0;
    kept = 1;
  }
  size = kept;
}

Vec3 closestOnTriangle(GjkVertex* vertices, double* weights, int& size)
{
  const ClosestPointResult r =
    closestPointOnTriangle(Vec3{}, vertices[0].w, vertices[1].w, vertices[2].w);
  weights[0] = r.weights[0];
  weights[1] = r.weights[1];
  weights[2] = r.weights[2];
  size = 3;
  compact(vertices, weights, size);
  return r.point;
}

double signedVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return dot(b - a, cross(c - a, d - a));
}
} // namespace

Vec3 reduceSimplexToClosest(GjkVertex* vertices, double* weights, int& size)
{
  switch (size)
  {
    case 1: weights[0] = 1.0; return vertices[0].w;
    case 2:
    {
      const double s = closestParameterOnSegment(Vec3{}, vertices[0].w, vertices[1].w);
      weights[0] = 1.0 - s;
      weights[1] = s;
      const Vec3 p = vertices[0].w + (vertices[1].w - vertices[0].w) * s;
      compact(vertices, weights, size);
      return p;
    }
    case 3: return closestOnTriangle(vertices, weights, size);
    default: break;
  }

  // Tetrahedron: the origin is inside when the four sub-volumes with the origin replacing one
  // vertex all share the sign of the whole volume.
  const Vec3 o{};
  const Vec3& a = vertices[0].w;
  const Vec3& b = vertices[1].w;
  const Vec3& c = vertices[2].w;
  const Vec3& d = vertices[3].w;
  const double total = signedVolume(a, b, c, d);
  if (total != 0.0)
  {
    const double wa = signedVolume(o, b, c, d) / total;
    const double wb = signedVolume(a, o, c, d) / total;
    const double wc = signedVolume(a, b, o, d) / total;
    const double wd = signedVolume(a, b, c, o) / total;
    if (wa >= 0.0 && wb >= 0.0 && wc >= 0.0 && wd >= 0.0)
    {
      weights[0] = wa;
      weights[1] = wb;
      weights[2] = wc;
      weights[3] = wd;
      size = 4;
      return Vec3{};
    }
  }
  // Otherwise the nearest point lies on a face: take the best of the four.
  static constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  GjkVertex bestVertices[4];
  double bestWeights[4] = {1.0, 0.0, 0.0, 0.0};
  int bestSize = 0;
  Vec3 bestPoint{};
  double bestDistance = 0.0;
  for (const auto& face : kFaces)
  {
    GjkVertex faceVertices[4] = {vertices[face[0]], vertices[face[1]], vertices[face[2]], {}};
    double faceWeights[4] = {0.0, 0.0, 0.0, 0.0};
    int faceSize = 3;
    const Vec3 p = closestOnTriangle(faceVertices, faceWeights, faceSize);
    const double distanceSquared = dot(p, p);
    if (bestSize == 0 || distanceSquared < bestDistance)
    {
      bestDistance = distanceSquared;
      bestPoint = p;
      bestSize = faceSize;
      for (int i = 0; i < faceSize; ++i)
      {
        bestVertices[i] = faceVertices[i];
        bestWeights[i] = faceWeights[i];
      }
    }
  }
  for (int i = 0; i < bestSize; ++i)
  {
    vertices[i] = bestVertices[i];
    weights[i] = bestWeights[i];
  }
  size = bestSize;
  return bestPoint;
}

} // namespace proxima
