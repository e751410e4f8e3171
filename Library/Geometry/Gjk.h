// Gilbert-Johnson-Keerthi distance between two convex sets given by support mappings (paper
// eq. 1): the nearest points, their distance, and the weights of the nearest points over the
// sets' own points, which shading and texture interpolate with. The same routine solves the
// dual-space goal problem of section 2.2 (a point against the hull of {0, c_i n_i}).
//
// A support mapping is any type with `Vec3 support(const Vec3& direction, int& index) const`
// returning the point of the set farthest along `direction` and its index, and
// `Vec3 point(int index) const`. No virtual calls: GJK is a template over them.
#pragma once

#include "Core/Vec3.h"
#include "Geometry/SimplexClosestPoint.h"

#include <cmath>

namespace proxima
{

/// A convex hull of a few points held elsewhere (a triangle's corners, the dual-space columns).
struct PointSetSupport
{
  /// The points, not owned: they must outlive every query on this set.
  const Vec3* points = nullptr;
  /// How many points `points` holds; at least 1 for a query.
  int count = 0;

  /// The point farthest along `direction` (the first such point on a tie); `index` receives its
  /// index.
  Vec3 support(const Vec3& direction, int& index) const
  {
    index = 0;
    double best = dot(points[0], direction);
    for (int i = 1; i < count; ++i)
    {
      const double d = dot(points[i], direction);
      if (d > best)
      {
        best = d;
        index = i;
      }
    }
    return points[index];
  }
  /// The point with index `index`.
  Vec3 point(int index) const { return points[index]; }
};

/// One vertex of the GJK simplex in the Minkowski difference A - B, with its source indices.
struct GjkVertex
{
  /// The vertex: the point `indexA` of A minus the point `indexB` of B.
  Vec3 w;
  /// Index of the point of A, as the set's support mapping numbers it.
  int indexA = 0;
  /// Index of the point of B, as the set's support mapping numbers it.
  int indexB = 0;
};

/// The simplex carried from one query to the next: pass the same object again to warm-start a
/// query on sets that moved a little (the indices are kept, the points are re-read).
struct GjkSimplex
{
  /// The vertices; only the first `size` are in use.
  GjkVertex vertices[4];
  /// Barycentric weights of the point nearest the origin over the vertices in use (sum 1).
  double weights[4] = {1.0, 0.0, 0.0, 0.0};
  /// Number of vertices in use, 0 to 4; 0 asks for a cold start.
  int size = 0;
};

/// The stopping rules of gjkDistance().
struct GjkOptions
{
  /// Stop when an iteration would shorten |v|^2 by less than this fraction of it.
  double relativeTolerance = 1e-14;
  /// The sets touch when |v|^2 falls below this fraction of the largest |w|^2 seen.
  double touchTolerance = 1e-26;
  /// Most iterations a query may run; reaching the cap leaves GjkResult::converged false.
  int maxIterations = 64;
};

/// What gjkDistance() returns: the distance between the two sets and their nearest points.
struct GjkResult
{
  /// Distance between the hulls; close to 0 (within the touch tolerance) when they touch or
  /// overlap.
  double distance = 0.0;
  /// Nearest point of A (equal to pointB when the sets intersect).
  Vec3 pointA;
  /// Nearest point of B (equal to pointA when the sets intersect).
  Vec3 pointB;
  /// Number of iterations the query ran.
  int iterations = 0;
  /// False when the iteration cap was hit or a non-finite number stopped the loop.
  bool converged = false;
};

/// Distance between the convex hulls A and B. `simplex` is read as a warm start when its size is
/// non-zero and holds the final simplex on return.
template <class SetA, class SetB>
GjkResult gjkDistance(const SetA& a, const SetB& b, GjkSimplex& simplex,
                      const GjkOptions& options = GjkOptions{})
{
  GjkResult result;
  // Re-read warm-start vertices from their indices: the sets may have moved since.
  for (int i = 0; i < simplex.size; ++i)
  {
    GjkVertex& vertex = simplex.vertices[i];
    vertex.w = a.point(vertex.indexA) - b.point(vertex.indexB);
  }
  if (simplex.size == 0)
  {
    GjkVertex first;
    first.w =
      a.support(Vec3{1.0, 0.0, 0.0}, first.indexA) - b.support(Vec3{-1.0, 0.0, 0.0}, first.indexB);
    simplex.vertices[0] = first;
    simplex.size = 1;
  }
  Vec3 v = reduceSimplexToClosest(simplex.vertices, simplex.weights, simplex.size);
  double vv = dot(v, v);
  double maxWw = 0.0;
  for (int i = 0; i < simplex.size; ++i)
  {
    maxWw = std::fmax(maxWw, dot(simplex.vertices[i].w, simplex.vertices[i].w));
  }

  int iteration = 0;
  bool converged = false;
  while (iteration < options.maxIterations)
  {
    ++iteration;
    // Written so that a NaN anywhere fails the test and ends the loop instead of spinning.
    if (!(vv > options.touchTolerance * maxWw))
    {
      converged = std::isfinite(vv);
      break;
    }
    GjkVertex next;
    next.w = a.support(-v, next.indexA) - b.support(v, next.indexB);
    const double progress = vv - dot(v, next.w);
    if (!(progress > options.relativeTolerance * vv))
    {
      converged = std::isfinite(progress);
      break;
    }
    bool repeated = false;
    for (int i = 0; i < simplex.size; ++i)
    {
      repeated = repeated || (simplex.vertices[i].indexA == next.indexA &&
                              simplex.vertices[i].indexB == next.indexB);
    }
    if (repeated || simplex.size == 4)
    {
      converged = true;
      break;
    }
    GjkSimplex candidate = simplex;
    candidate.vertices[candidate.size++] = next;
    const Vec3 candidateV =
      reduceSimplexToClosest(candidate.vertices, candidate.weights, candidate.size);
    const double candidateVv = dot(candidateV, candidateV);
    // GJK must shorten v every step; if rounding says otherwise, the previous answer stands.
    if (!(candidateVv < vv))
    {
      converged = std::isfinite(candidateVv);
      break;
    }
    simplex = candidate;
    v = candidateV;
    vv = candidateVv;
    maxWw = std::fmax(maxWw, dot(next.w, next.w));
  }

  Vec3 pointA{};
  Vec3 pointB{};
  for (int i = 0; i < simplex.size; ++i)
  {
    pointA += a.point(simplex.vertices[i].indexA) * simplex.weights[i];
    pointB += b.point(simplex.vertices[i].indexB) * simplex.weights[i];
  }
  result.pointA = pointA;
  result.pointB = pointB;
  result.distance = std::sqrt(vv);
  result.iterations = iteration;
  result.converged = converged;
  return result;
}

/// Adds the simplex weights onto per-point weights of A and B (arrays of the sets' sizes, zeroed
/// by the caller): the contact weights of eq. 1.
inline void accumulateGjkWeights(const GjkSimplex& simplex, double* weightsA, double* weightsB)
{
  for (int i = 0; i < simplex.size; ++i)
  {
    if (weightsA != nullptr)
    {
      weightsA[simplex.vertices[i].indexA] += simplex.weights[i];
    }
    if (weightsB != nullptr)
    {
      weightsB[simplex.vertices[i].indexB] += simplex.weights[i];
    }
  }
}

} // namespace proxima
