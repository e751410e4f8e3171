// gjkDistance over PointSetSupport against CGAL's Polytope_distance_d solved in exact arithmetic
// (Gmpzf: every double is exactly representable, so the oracle answers for exactly the inputs the
// kernel saw), and its sub-algorithm reduceSimplexToClosest against exact orientation tests and
// exact point-triangle distances. Polytope_distance_d costs about a millisecond per query, so
// the three GJK tests share 10,000 oracle calls between them.
//
// Tolerance. GJK stops when an iteration would shorten |v|^2 by less than 1e-14 of it, which
// bounds the distance error by 1e-14 relative, or when |v|^2 falls below 1e-26 of the largest
// |w|^2, i.e. |v| below 1e-13 of the size of the Minkowski difference. Each step also rounds in
// the sub-algorithm (a few epsilon of that size W = the longest |a_i - b_j|), and the points of
// the Minkowski difference are themselves differences of coordinates, rounded to epsilon times
// the largest coordinate M; so are the nearest points, which are sums in absolute coordinates.
// We allow
//   |d_gjk - d_exact| <= 1e-12 * W + 64 * epsilon * M,
// ten times the touching threshold; each test prints its worst error in units of
// epsilon * (W + M).
#include "Geometry/Gjk.h"
#include "Geometry/SimplexClosestPoint.h"

#include "ExactOracle.h"
#include "GeometryTestSupport.h"

#include <CGAL/Gmpzf.h>
#include <CGAL/Homogeneous.h>
#include <CGAL/Polytope_distance_d.h>
#include <CGAL/Polytope_distance_d_traits_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace proxima::test
{
namespace
{

using ExactHomogeneous = CGAL::Homogeneous<CGAL::Gmpzf>;
using PolytopeDistance =
  CGAL::Polytope_distance_d<CGAL::Polytope_distance_d_traits_3<ExactHomogeneous>>;

/// Exact distance between the convex hulls of two point sets, rounded to double at the end.
double exactHullDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  auto toPoints = [](const std::vector<Vec3>& set) {
    std::vector<ExactHomogeneous::Point_3> points;
    for (const Vec3& p : set)
    {
      points.emplace_back(CGAL::Gmpzf(p.x), CGAL::Gmpzf(p.y), CGAL::Gmpzf(p.z), CGAL::Gmpzf(1));
    }
    return points;
  };
  const auto pa = toPoints(a);
  const auto pb = toPoints(b);
  const PolytopeDistance solver(pa.begin(), pa.end(), pb.begin(), pb.end());
  const double numerator = CGAL::to_double(solver.squared_distance_numerator());
  const double denominator = CGAL::to_double(solver.squared_distance_denominator());
  return std::sqrt(numerator / denominator);
}

/// Exact distance from the origin to the hull of 1 to 4 points, the cheap way that a simplex
/// allows: zero when exact orientation tests put the origin inside the tetrahedron, else the
/// nearest of its faces (exact point-triangle distances; a face may be degenerate).
double exactSimplexDistance(const std::vector<Vec3>& w)
{
  const Vec3 o{};
  switch (w.size())
  {
    case 1: return norm(w[0]);
    case 2: return std::sqrt(exactSquaredDistance(o, w[0], w[1], w[1]));
    case 3: return std::sqrt(exactSquaredDistance(o, w[0], w[1], w[2]));
    default: break;
  }
  const auto e = [&](int i) { return toExact(w[i]); };
  const ExactKernel::Point_3 origin = toExact(o);
  const CGAL::Orientation whole = CGAL::orientation(e(0), e(1), e(2), e(3));
  if (whole != CGAL::COPLANAR)
  {
    const CGAL::Orientation parts[4] = {
      CGAL::orientation(origin, e(1), e(2), e(3)), CGAL::orientation(e(0), origin, e(2), e(3)),
      CGAL::orientation(e(0), e(1), origin, e(3)), CGAL::orientation(e(0), e(1), e(2), origin)};
    if (std::all_of(std::begin(parts), std::end(parts), [&](CGAL::Orientation part) {
          return part == whole || part == CGAL::COPLANAR;
        }))
    {
      return 0.0;
    }
  }
  return std::sqrt(std::min(
    {exactSquaredDistance(o, w[0], w[1], w[2]), exactSquaredDistance(o, w[0], w[1], w[3]),
     exactSquaredDistance(o, w[0], w[2], w[3]), exactSquaredDistance(o, w[1], w[2], w[3])}));
}

constexpr double kTolerance = 1e-12;

double minkowskiSize(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  double size = 0.0;
  for (const Vec3& p : a)
  {
    for (const Vec3& q : b)
    {
      size = std::fmax(size, norm(p - q));
    }
  }
  return size;
}

double largestCoordinate(const std::vector<Vec3>& set)
{
  double largest = 0.0;
  for (const Vec3& p : set)
  {
    largest = std::fmax(largest, maxAbsComponent(p));
  }
  return largest;
}

double tolerance(double minkowski, double largest)
{
  return kTolerance * minkowski + 64.0 * kEpsilon * largest;
}

std::string str(const std::vector<Vec3>& set)
{
  std::string out = "{";
  for (const Vec3& p : set)
  {
    out += test::str(p) + ", ";
  }
  return out + "}";
}

struct GjkCheck
{
  std::string failures;
  double errorInUlps = 0.0;
  int iterations = 0;
};

/// Runs GJK on (a, b) from `simplex` and checks the distance against the exact one, the nearest
/// points against each other, and the weights against the nearest points.
GjkCheck runAndCheck(const std::vector<Vec3>& a, const std::vector<Vec3>& b, GjkSimplex& simplex,
                     double exact)
{
  GjkCheck check;
  const PointSetSupport setA{a.data(), static_cast<int>(a.size())};
  const PointSetSupport setB{b.data(), static_cast<int>(b.size())};
  const GjkResult r = gjkDistance(setA, setB, simplex);
  check.iterations = r.iterations;
  const double W = std::fmax(minkowskiSize(a, b), std::numeric_limits<double>::min());
  const double M = std::fmax(largestCoordinate(a), largestCoordinate(b));
  const double tol = tolerance(W, M);
  const double error = std::fabs(r.distance - exact);
  check.errorInUlps = error / (kEpsilon * (W + M));
  if (!r.converged)
  {
    check.failures += " did not converge in " + std::to_string(r.iterations) + " iterations;";
  }
  if (!(error <= tol))
  {
    check.failures += " distance " + test::str(r.distance) + " but exact " + test::str(exact) +
                      " (tolerance " + test::str(tol) + ");";
  }
  if (!(std::fabs(distance(r.pointA, r.pointB) - r.distance) <= tol))
  {
    check.failures += " |pointA - pointB| = " + test::str(distance(r.pointA, r.pointB)) +
                      " but distance " + test::str(r.distance) + ";";
  }
  // The weights are a convex combination of each set's points that gives its nearest point.
  std::vector<double> weightsA(a.size(), 0.0);
  std::vector<double> weightsB(b.size(), 0.0);
  accumulateGjkWeights(simplex, weightsA.data(), weightsB.data());
  auto checkWeights = [&](const std::vector<Vec3>& set, const std::vector<double>& weights,
                          const Vec3& nearest, const char* which) {
    double sum = 0.0;
    Vec3 combination{};
    for (std::size_t i = 0; i < set.size(); ++i)
    {
      if (!(weights[i] >= 0.0))
      {
        check.failures += std::string(" negative weight on ") + which + ";";
      }
      sum += weights[i];
      combination += set[i] * weights[i];
    }
    // Inside a tetrahedron the weights are ratios of signed volumes, each rounded on its own:
    // their sum strays from 1 by the tetrahedron's conditioning (seen: 100 epsilon).
    if (!(std::fabs(sum - 1.0) <= 1e-12))
    {
      check.failures += std::string(" weights of ") + which + " sum to " + test::str(sum) + ";";
    }
    if (!(distance(combination, nearest) <= tol))
    {
      check.failures += std::string(" weights of ") + which + " give " + test::str(combination) +
                        " not " + test::str(nearest) + ";";
    }
  };
  checkWeights(a, weightsA, r.pointA, "A");
  checkWeights(b, weightsB, r.pointB, "B");
  return check;
}

enum class SetShape
{
  General,
  Coincident,
  Collinear,
  Coplanar
};

/// `count` points about `center`, `size` across, of the given shape. Degenerate shapes are built
/// on exactly representable offsets so they are degenerate in the kernel's arithmetic too.
std::vector<Vec3> makeSet(Random& random, int count, const Vec3& center, double size,
                          SetShape shape)
{
  std::vector<Vec3> set;
  for (int i = 0; i < count; ++i)
  {
    switch (shape)
    {
      case SetShape::General: set.push_back(center + random.inCube(size)); break;
      case SetShape::Coincident: set.push_back(center); break;
      case SetShape::Collinear:
        set.push_back(center + Vec3{1, 2, 3} * (size * 0.125 * random.integer(-8, 8)));
        break;
      case SetShape::Coplanar:
        // The plane z = center.z: coplanar exactly, whatever the rounding of the other axes.
        set.push_back(Vec3{center.x + random.uniform(-size, size),
                           center.y + random.uniform(-size, size), center.z});
        break;
    }
  }
  return set;
}

void runGjkTrials(const char* testName, std::uint64_t seed, int numTrials, bool degenerate)
{
  Random random(seed);
  FailureBudget budget;
  int numFailures = 0;
  double worstUlps = 0.0;
  int numOverlapping = 0;
  for (int trial = 0; trial < numTrials; ++trial)
  {
    const double size = random.logUniform(-6.0, 3.0);
    const Vec3 offset = random.chance(0.25) ? random.direction() * 1e4 : Vec3{};
    const SetShape shapeA =
      degenerate ? static_cast<SetShape>(random.integer(1, 3)) : SetShape::General;
    const SetShape shapeB =
      degenerate ? static_cast<SetShape>(random.integer(0, 3)) : SetShape::General;
    // Separations from deep overlap to far apart, in units of the sets' size.
    const Vec3 gap = random.direction() * (size * random.uniform(0.0, 4.0));
    const std::vector<Vec3> a = makeSet(random, random.integer(1, 8), offset, size, shapeA);
    const std::vector<Vec3> b = makeSet(random, random.integer(1, 8), offset + gap, size, shapeB);
    const double exact = exactHullDistance(a, b);
    numOverlapping += exact == 0.0 ? 1 : 0;
    GjkSimplex simplex;
    const GjkCheck check = runAndCheck(a, b, simplex, exact);
    worstUlps = std::fmax(worstUlps, check.errorInUlps);
    if (!check.failures.empty())
    {
      ++numFailures;
      if (budget.spend())
      {
        ADD_FAILURE() << "seed 0x" << std::hex << seed << std::dec << " trial " << trial
                      << "\n  A = " << str(a) << "\n  B = " << str(b) << "\n " << check.failures;
      }
    }
  }
  std::printf("[ %s ] %d trials, %d overlapping; worst distance error %.3g epsilon*(W+M)\n",
              testName, numTrials, numOverlapping, worstUlps);
  EXPECT_EQ(numFailures, 0) << "of " << numTrials << " trials";
  // The trials must cover both regimes, or the test says less than it claims.
  EXPECT_GT(numOverlapping, numTrials / 50);
  EXPECT_LT(numOverlapping, numTrials / 2);
}

TEST(Gjk, MatchesExactPolytopeDistanceOnRandomSets)
{
  runGjkTrials("general sets", 0x9e0001, 4000, false);
}

TEST(Gjk, MatchesExactPolytopeDistanceOnDegenerateSets)
{
  runGjkTrials("coincident, collinear, coplanar sets", 0x9e0002, 3000, true);
}

TEST(Gjk, WarmStartGivesTheSameAnswerInNoMoreIterations)
{
  Random random(0x9e0003);
  FailureBudget budget;
  int numFailures = 0;
  long coldIterations = 0;
  long warmIterations = 0;
  constexpr int kTrials = 3000;
  for (int trial = 0; trial < kTrials; ++trial)
  {
    const double size = random.logUniform(-3.0, 0.0);
    const Vec3 gap = random.direction() * (size * random.uniform(0.0, 4.0));
    const std::vector<Vec3> a =
      makeSet(random, random.integer(3, 8), Vec3{}, size, SetShape::General);
    std::vector<Vec3> b = makeSet(random, random.integer(3, 8), gap, size, SetShape::General);
    GjkSimplex carried;
    const PointSetSupport setA{a.data(), static_cast<int>(a.size())};
    gjkDistance(setA, PointSetSupport{b.data(), static_cast<int>(b.size())}, carried);
    // Move B a little, as a proxy moves between two ticks, and ask again from the old simplex.
    const Vec3 step = random.direction() * (size * 1e-3);
    for (Vec3& p : b)
    {
      p += step;
    }
    const double exact = exactHullDistance(a, b);
    GjkSimplex cold;
    const GjkCheck coldCheck = runAndCheck(a, b, cold, exact);
    const GjkCheck warmCheck = runAndCheck(a, b, carried, exact);
    coldIterations += coldCheck.iterations;
    warmIterations += warmCheck.iterations;
    if (!coldCheck.failures.empty() || !warmCheck.failures.empty())
    {
      ++numFailures;
      if (budget.spend())
      {
        ADD_FAILURE() << "seed 0x9e0003 trial " << trial << "\n  A = " << str(a)
                      << "\n  B (moved) = " << str(b) << "\n cold:" << coldCheck.failures
                      << "\n warm:" << warmCheck.failures;
      }
    }
  }
  std::printf("[ warm start ] mean iterations: cold %.3f, warm %.3f\n",
              double(coldIterations) / kTrials, double(warmIterations) / kTrials);
  EXPECT_EQ(numFailures, 0);
  EXPECT_LE(warmIterations, coldIterations);
}

TEST(Gjk, DegenerateAndNonFiniteInputsTerminate)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  GjkOptions options;
  const std::vector<std::vector<Vec3>> sets = {
    {{0, 0, 0}},
    {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
    {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}},
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}},
    {{1e-300, 0, 0}, {0, 1e-300, 0}},
  };
  for (const auto& a : sets)
  {
    for (const auto& b : sets)
    {
      GjkSimplex simplex;
      const GjkResult r = gjkDistance(PointSetSupport{a.data(), int(a.size())},
                                      PointSetSupport{b.data(), int(b.size())}, simplex, options);
      EXPECT_LE(r.iterations, options.maxIterations);
      EXPECT_TRUE(r.converged) << "A = " << str(a) << " B = " << str(b);
      EXPECT_TRUE(std::isfinite(r.distance)) << "A = " << str(a) << " B = " << str(b);
    }
  }
  // Non-finite points, and points whose squares overflow: the loop must end (converged false is
  // allowed) and never spin.
  const std::vector<std::vector<Vec3>> bad = {
    {{1e300, 0, 0}, {-1e300, 0, 0}},
    {{nan, 0, 0}},
    {{0, 0, 0}, {nan, nan, nan}, {1, 0, 0}},
    {{1, 0, 0}, {0, 1, 0}, {0, 0, nan}},
    {{inf, 0, 0}, {0, 0, 0}},
  };
  for (const auto& a : bad)
  {
    for (const auto& b : sets)
    {
      GjkSimplex simplex;
      const GjkResult r = gjkDistance(PointSetSupport{a.data(), int(a.size())},
                                      PointSetSupport{b.data(), int(b.size())}, simplex, options);
      EXPECT_LE(r.iterations, options.maxIterations) << "A = " << str(a);
      // A NaN answer must say so.
      if (!std::isfinite(r.distance))
      {
        EXPECT_FALSE(r.converged) << "A = " << str(a) << " B = " << str(b);
      }
    }
  }
}

TEST(ReduceSimplexToClosest, MatchesExactNearestPointOfTheSimplex)
{
  Random random(0x9e0004);
  FailureBudget budget;
  int numFailures = 0;
  const std::vector<Vec3> origin = {Vec3{}};
  for (int trial = 0; trial < 12000; ++trial)
  {
    const int size = 1 + trial % 4;
    GjkVertex vertices[4];
    std::vector<Vec3> points;
    const double scale = random.logUniform(-4.0, 2.0);
    const int degenerate = random.integer(0, 3); // 0: coincident pair, 1: flat, 2-3: general
    for (int i = 0; i < size; ++i)
    {
      Vec3 w = random.inCube(scale) + random.direction() * (scale * random.uniform(0.0, 1.5));
      if (degenerate == 0 && i == 1)
      {
        w = points[0];
      }
      if (degenerate == 1 && i == 3)
      {
        // In the plane of the first three (up to rounding).
        w = points[0] + (points[1] - points[0]) * 0.25 + (points[2] - points[0]) * 0.5;
      }
      points.push_back(w);
      vertices[i].w = w;
      vertices[i].indexA = i;
    }
    double weights[4] = {};
    int reducedSize = size;
    const Vec3 closest = reduceSimplexToClosest(vertices, weights, reducedSize);
    const double exact = exactSimplexDistance(points);
    const double W = std::fmax(minkowskiSize(points, origin), std::numeric_limits<double>::min());
    const double tol = tolerance(W, largestCoordinate(points));
    std::string failures;
    if (!(std::fabs(norm(closest) - exact) <= tol))
    {
      failures +=
        " |closest| = " + test::str(norm(closest)) + " but exact " + test::str(exact) + ";";
    }
    double sum = 0.0;
    Vec3 combination{};
    for (int i = 0; i < reducedSize; ++i)
    {
      failures += weights[i] >= 0.0 ? "" : " negative weight;";
      sum += weights[i];
      combination += points[vertices[i].indexA] * weights[i];
    }
    if (!(reducedSize >= 1 && reducedSize <= size && std::fabs(sum - 1.0) <= 1e-12 &&
          distance(combination, closest) <= tol))
    {
      failures += " kept " + std::to_string(reducedSize) + " vertices with weights summing to " +
                  test::str(sum) + " giving " + test::str(combination) + ";";
    }
    if (!failures.empty())
    {
      ++numFailures;
      if (budget.spend())
      {
        ADD_FAILURE() << "seed 0x9e0004 trial " << trial << " simplex " << str(points) << "\n "
                      << failures;
      }
    }
  }
  EXPECT_EQ(numFailures, 0);
}

} // namespace
} // namespace proxima::test
