#include "Proxy/GoalSolver.h"

#include "Geometry/Gjk.h"

#include <cmath>

namespace proxima
{
namespace
{
// A step may cross a plane by this fraction of the finger distance before it counts as a
// violation: rounding in the dual solve is far below it, a real violation far above.
constexpr double kFeasibilityTolerance = 1e-12;

bool isFeasible(const Vec3& step, const Vec3* normals, int numPlanes, double scale)
{
  for (int i = 0; i < numPlanes; ++i)
  {
    if (dot(normals[i], step) < -kFeasibilityTolerance * scale)
    {
      return false;
    }
  }
  return true;
}

// The dual answer as a KKT point: each active plane holds the goal (n_i . x = 0) and the depths
// rebuild the spring, v - x = -sum mu_i n_i. Feasibility alone misses a dual solve that went
// wrong: a plane the finger lies in to rounding (u . n_i ~ -1e-17) puts c_i n_i ~1e17 from the
// origin, GJK's tolerances (relative to the largest |w|^2) then stop it at once, and its answer
// can be feasible yet far from the nearest point.
bool isKktPoint(const Vec3& toFinger, const Vec3* normals, const GoalSolution& s, double scale)
{
  Vec3 residual = toFinger - s.displacement;
  double depthSum = 0.0;
  for (int k = 0; k < s.numActive; ++k)
  {
    const Vec3& n = normals[s.active[k]];
    if (!(std::fabs(dot(n, s.displacement)) <= kFeasibilityTolerance * scale))
    {
      return false;
    }
    residual += n * s.depth[k];
    depthSum += s.depth[k];
  }
  return norm(residual) <= kFeasibilityTolerance * (scale + depthSum);
}

double determinant3(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return dot(a, cross(b, c));
}

// Solves G mu = rhs for the Gram matrix G of `count` normals by Cramer's rule; false if the
// normals are (nearly) dependent, in which case a smaller subset covers the same constraint.
bool solveGram(const Vec3* n, int count, const double* rhs, double* mu)
{
  if (count == 1)
  {
    mu[0] = rhs[0]; // unit normals: G = 1
    return true;
  }
  if (count == 2)
  {
    const double g01 = dot(n[0], n[1]);
    const double det = 1.0 - g01 * g01;
    if (!(det > 1e-14))
    {
      return false;
    }
    mu[0] = (rhs[0] - g01 * rhs[1]) / det;
    mu[1] = (rhs[1] - g01 * rhs[0]) / det;
    return true;
  }
  // Three planes meet in one line only if dependent; otherwise N^T x = 0 forces x = 0 and
  // finger = -N mu gives mu = -N^{-1} finger directly.
  const double det = determinant3(n[0], n[1], n[2]);
  if (!(std::fabs(det) > 1e-7))
  {
    return false;
  }
  // rhs here is N^T v; recover v's coordinates in the basis n0, n1, n2 via G mu = rhs.
  const double g01 = dot(n[0], n[1]);
  const double g02 = dot(n[0], n[2]);
  const double g12 = dot(n[1], n[2]);
  const Vec3 c0{1.0, g01, g02};
  const Vec3 c1{g01, 1.0, g12};
  const Vec3 c2{g02, g12, 1.0};
  const Vec3 r{rhs[0], rhs[1], rhs[2]};
  const double gramDet = determinant3(c0, c1, c2);
  mu[0] = determinant3(r, c1, c2) / gramDet;
  mu[1] = determinant3(c0, r, c2) / gramDet;
  mu[2] = determinant3(c0, c1, r) / gramDet;
  return true;
}
} // namespace

GoalSolution solveGoalByEnumeration(const Vec3& toFinger, const Vec3* normals, int numPlanes)
{
  GoalSolution best;
  best.usedExactFallback = true;
  const double scale = norm(toFinger);
  if (isFeasible(toFinger, normals, numPlanes, scale))
  {
    best.displacement = toFinger;
    return best;
  }
  // KKT: x = v + sum_{i in S} mu_i n_i with n_i . x = 0 on S, mu_i >= 0, and x feasible for all
  // planes. The problem is convex, so a feasible KKT point is the optimum: the enumeration goes
  // by the size of the active set and stops at the first size that has one (the nearest of that
  // size, against rounding). Three independent planes through the proxy pin it (x = 0), which is
  // feasible by itself, so triples need no feasibility check, only the signs of their depths.
  // The cost is bounded by design: at most m + m(m-1)/2 candidates checked against the m planes,
  // then at most m(m-1)(m-2)/6 3x3 solves; at m = kMaxConstraintPlanes = 32 about 21,000 dot
  // products. (Checking every triple against every plane, and keeping looking after the optimum
  // was found, made single iterations on CAD soups take about 2 ms.)
  double bestDistance = -1.0;
  int subset[3] = {0, 0, 0};
  auto tryCandidate = [&](int count) {
    Vec3 n[3];
    double rhs[3];
    for (int k = 0; k < count; ++k)
    {
      n[k] = normals[subset[k]];
      rhs[k] = -dot(n[k], toFinger);
    }
    double mu[3];
    if (!solveGram(n, count, rhs, mu))
    {
      return false;
    }
    Vec3 x = toFinger;
    for (int k = 0; k < count; ++k)
    {
      if (mu[k] < -kFeasibilityTolerance * scale)
      {
        return false;
      }
      x += n[k] * mu[k];
    }
    if (count == 3)
    {
      x = Vec3{}; // three independent planes through the proxy pin it
    }
    else if (!isFeasible(x, normals, numPlanes, scale))
    {
      return false;
    }
    const double d = squaredDistance(x, toFinger);
    if (bestDistance < 0.0 || d < bestDistance)
    {
      bestDistance = d;
      best.displacement = x;
      best.numActive = count;
      for (int k = 0; k < count; ++k)
      {
        best.active[k] = subset[k];
        best.depth[k] = std::fmax(mu[k], 0.0);
      }
    }
    return true;
  };
  for (int i = 0; i < numPlanes; ++i)
  {
    subset[0] = i;
    tryCandidate(1);
  }
  for (int i = 0; i < numPlanes && bestDistance < 0.0; ++i)
  {
    subset[0] = i;
    for (int j = i + 1; j < numPlanes; ++j)
    {
      subset[1] = j;
      tryCandidate(2);
    }
  }
  for (int i = 0; i < numPlanes && bestDistance < 0.0; ++i)
  {
    subset[0] = i;
    for (int j = i + 1; j < numPlanes && bestDistance < 0.0; ++j)
    {
      subset[1] = j;
      for (int k = j + 1; k < numPlanes; ++k)
      {
        subset[2] = k;
        if (tryCandidate(3))
        {
          break; // every valid triple pins the proxy at the same point
        }
      }
    }
  }
  if (bestDistance < 0.0)
  {
    // Only rounding can leave no candidate (all subsets marginally infeasible): stay put.
    best.displacement = Vec3{};
  }
  return best;
}

GoalSolution solveGoal(const Vec3& toFinger, const Vec3* normals, int numPlanes)
{
  GoalSolution solution;
  const double length = norm(toFinger);
  if (!(length > 0.0))
  {
    return solution;
  }
  const Vec3 u = toFinger / length;

  // Dual space, eq. 17: the origin and c_i n_i with c_i = 1 / (u . n_i), for the planes the
  // finger lies below (u . n_i < 0). Index 0 is the origin; plane of point k is planeOf[k].
  Vec3 dual[kMaxConstraintPlanes + 1];
  int planeOf[kMaxConstraintPlanes + 1];
  int numDual = 1;
  dual[0] = Vec3{};
  planeOf[0] = -1;
  for (int i = 0; i < numPlanes && i < kMaxConstraintPlanes; ++i)
  {
    const double un = dot(u, normals[i]);
    if (un < 0.0)
    {
      dual[numDual] = normals[i] / un;
      planeOf[numDual] = i;
      ++numDual;
    }
  }
  if (numDual == 1)
  {
    solution.displacement = toFinger;
  }
  else
  {
    const PointSetSupport hull{dual, numDual};
    const PointSetSupport finger{&u, 1};
    GjkSimplex simplex;
    const GjkResult nearest = gjkDistance(hull, finger, simplex);
    // Eq. 18: x = |u| (u_hat - S w).
    solution.displacement = (u - nearest.pointA) * length;
    for (int k = 0; k < simplex.size; ++k)
    {
      const int plane = planeOf[simplex.vertices[k].indexA];
      if (plane < 0 || !(simplex.weights[k] > 0.0) || solution.numActive == 3)
      {
        continue;
      }
      // Eq. 19 scaled: mu_i = |u| w_i / |u_hat . n_i|.
      solution.active[solution.numActive] = plane;
      solution.depth[solution.numActive] =
        length * simplex.weights[k] / std::fabs(dot(u, normals[plane]));
      ++solution.numActive;
    }
    if (!nearest.converged)
    {
      return solveGoalByEnumeration(toFinger, normals, numPlanes);
    }
  }
  if (!isFeasible(solution.displacement, normals, numPlanes, length) ||
      !isKktPoint(toFinger, normals, solution, length))
  {
    return solveGoalByEnumeration(toFinger, normals, numPlanes);
  }
  return solution;
}

} // namespace proxima
