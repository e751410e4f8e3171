// closestPointOnTriangle against CGAL's exact point-triangle distance, on fat triangles, slivers
// up to aspect ratio 1e12, zero-area triangles, and coordinates from 1e-6 to 1e4.
//
// Tolerances. The kernel forms differences of the inputs (each rounded once, relative to the
// query's spread S = the longest distance between p and the corners), a few dot and cross
// products of them, and writes the closest point in absolute coordinates (rounded to epsilon
// times the largest coordinate M). A backward-stable answer is therefore within a small multiple
// of epsilon * (S + M) of the exact distance whatever the triangle's shape: the distance to a set
// is 1-Lipschitz in the query point and in the corners, so slivers are not ill-conditioned for
// it. We allow 64 epsilon (S + M), about 1.4e-14 relative, for the distance and for the point
// lying on the triangle (the measured worst is about 2, printed by each test). Weights are
// barycentric coordinates, whose own conditioning degrades with the smallest angle: on the
// triangles the kernel treats as well-shaped (smallest altitude above 3% of the longest edge)
// they reproduce the point to about epsilon / 1e-3 = 1e3 epsilon of S, so that check allows
// 2048 epsilon (S + M), 4.5e-13 relative. Both sit below a 1e-12 relative bound and
// three orders of magnitude below DESIGN.md's 1e-9 m on decimetre scenes.
#include "Geometry/ClosestPoint.h"

#include "ExactOracle.h"
#include "GeometryTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

namespace proxima::test
{
namespace
{

constexpr double kDistanceUlps = 64.0;
constexpr double kWeightUlps = 2048.0;

double tolerance(double spreadLength, double largestCoordinate, double ulps = kDistanceUlps)
{
  return ulps * kEpsilon * (spreadLength + largestCoordinate);
}

/// The worst error seen, in units of epsilon * (S + M), so the margin to the tolerance shows.
struct WorstError
{
  double distanceUlps = 0.0;
  double weightUlps = 0.0;
  std::string where;
  void note(double distanceError, double weightError, double spreadLength, double largestCoordinate,
            const std::string& what)
  {
    const double scale = kEpsilon * (spreadLength + largestCoordinate);
    const double ulps = scale > 0.0 ? distanceError / scale : (distanceError > 0.0 ? 1e300 : 0.0);
    if (ulps > distanceUlps)
    {
      distanceUlps = ulps;
      where = what;
    }
    weightUlps = std::fmax(weightUlps, scale > 0.0 ? weightError / scale : 0.0);
  }
  void print(const char* test) const
  {
    std::printf("[ %s ] worst distance error %.3g, worst weight reproduction %.3g, in "
                "epsilon*(S+M) (distance at %s)\n",
                test, distanceUlps, weightUlps, where.c_str());
  }
};

/// Every property the kernel promises, checked against the exact oracle. Returns an empty string
/// when all hold, else what failed.
std::string checkClosestPoint(const Vec3& p, const TriangleCorners& t, WorstError& worst)
{
  const ClosestPointResult r = closestPointOnTriangle(p, t.a, t.b, t.c);
  const double S = spread({p, t.a, t.b, t.c});
  const double M = magnitude({p, t.a, t.b, t.c});
  const double tol = tolerance(S, M);
  std::string failures;

  const double exact = exactDistance(p, t);
  const double reported = std::sqrt(r.squaredDistance);
  const double error = std::fabs(reported - exact);
  const Vec3 reproduced = t.a * r.weights[0] + t.b * r.weights[1] + t.c * r.weights[2];
  worst.note(error, distance(reproduced, r.point), S, M, "p=" + str(p));
  if (!(error <= tol))
  {
    failures +=
      " distance " + str(reported) + " but exact " + str(exact) + " (tolerance " + str(tol) + ");";
  }
  // The reported squared distance is the distance to the reported point.
  if (!(std::fabs(distance(p, r.point) - reported) <= tol))
  {
    failures += " |p - point| = " + str(distance(p, r.point)) + " differs from the reported " +
                str(reported) + ";";
  }
  // The point lies on the triangle (exactly checked).
  const double offTriangle = exactDistance(r.point, t);
  if (!(offTriangle <= tol))
  {
    failures += " point " + str(r.point) + " is " + str(offTriangle) + " off the triangle;";
  }
  // Weights: non-negative, summing to one, reproducing the point.
  const double sum = r.weights[0] + r.weights[1] + r.weights[2];
  if (!(r.weights[0] >= 0.0 && r.weights[1] >= 0.0 && r.weights[2] >= 0.0))
  {
    failures += " negative weight {" + str(r.weights[0]) + ", " + str(r.weights[1]) + ", " +
                str(r.weights[2]) + "};";
  }
  if (!(std::fabs(sum - 1.0) <= 4.0 * kEpsilon))
  {
    failures += " weights sum to " + str(sum) + ";";
  }
  if (!(distance(reproduced, r.point) <= tolerance(S, M, kWeightUlps)))
  {
    failures += " weights give " + str(reproduced) + " not the point " + str(r.point) + ";";
  }
  // The feature names the corners that carry weight.
  const bool featureConsistent = [&] {
    switch (r.feature)
    {
      case TriangleFeature::VertexA:
        return r.weights[0] == 1.0 && r.weights[1] == 0.0 && r.weights[2] == 0.0;
      case TriangleFeature::VertexB:
        return r.weights[1] == 1.0 && r.weights[0] == 0.0 && r.weights[2] == 0.0;
      case TriangleFeature::VertexC:
        return r.weights[2] == 1.0 && r.weights[0] == 0.0 && r.weights[1] == 0.0;
      case TriangleFeature::EdgeAB: return r.weights[2] == 0.0;
      case TriangleFeature::EdgeBC: return r.weights[0] == 0.0;
      case TriangleFeature::EdgeCA: return r.weights[1] == 0.0;
      case TriangleFeature::Face: return true;
    }
    return false;
  }();
  if (!featureConsistent)
  {
    failures +=
      " feature " + std::to_string(static_cast<int>(r.feature)) + " disagrees with its weights;";
  }
  return failures;
}

/// A query point for triangle t: anywhere around it, on it, on an edge, on a corner, just off
/// its face, or far away.
Vec3 makeQueryPoint(Random& random, const TriangleCorners& t, double size)
{
  switch (random.integer(0, 6))
  {
    case 0: return pointOnTriangle(random, t);
    case 1:
    {
      const Vec3 corners[3] = {t.a, t.b, t.c};
      const int i = random.integer(0, 2);
      return corners[i] + (corners[(i + 1) % 3] - corners[i]) * random.uniform(0.0, 1.0);
    }
    case 2:
    {
      const Vec3 corners[3] = {t.a, t.b, t.c};
      return corners[random.integer(0, 2)];
    }
    case 3:
    {
      // Just off the face (or off whatever direction is handy when the triangle is flat).
      const Vec3 n = normalizedOrZero(cross(t.b - t.a, t.c - t.a));
      const Vec3 away = n == Vec3{} ? random.direction() : n;
      return pointOnTriangle(random, t) +
             away * (size * random.logUniform(-12.0, 0.0) * (random.chance(0.5) ? 1.0 : -1.0));
    }
    case 4: return (t.a + t.b + t.c) * (1.0 / 3.0) + random.direction() * (100.0 * size);
    default: return (t.a + t.b + t.c) * (1.0 / 3.0) + random.inCube(2.0 * size);
  }
}

struct Scale
{
  double size;
  double offset;
};

// Tiny triangles (1e-6) and large offsets (1e4) beside unit triangles: rounding at both ends.
constexpr Scale kScales[] = {{1.0, 0.0},  {1e-6, 0.0}, {1.0, 1e4},
                             {1e-3, 1e4}, {1e3, 0.0},  {1e-6, 1.0}};

void runTrials(const char* testName, std::uint64_t seed, int numTrials, const TriangleShape* shapes,
               int numShapes, double maxAspectExponent)
{
  Random random(seed);
  WorstError worst;
  FailureBudget budget;
  int numFailures = 0;
  for (int trial = 0; trial < numTrials; ++trial)
  {
    const TriangleShape shape = shapes[trial % numShapes];
    const Scale scale = kScales[(trial / numShapes) % std::size(kScales)];
    const Vec3 offset = random.direction() * scale.offset;
    const double aspect = random.logUniform(0.0, maxAspectExponent);
    const TriangleCorners t = makeTriangle(random, shape, scale.size, offset, aspect);
    const Vec3 p = makeQueryPoint(random, t, scale.size);
    const std::string failures = checkClosestPoint(p, t, worst);
    if (!failures.empty())
    {
      ++numFailures;
      if (budget.spend())
      {
        ADD_FAILURE() << "seed 0x" << std::hex << seed << std::dec << " trial " << trial
                      << " shape " << name(shape) << " aspect " << aspect << "\n  p = " << str(p)
                      << "\n  triangle = " << str(t) << "\n " << failures;
      }
    }
  }
  worst.print(testName);
  EXPECT_EQ(numFailures, 0) << "of " << numTrials << " trials (seed 0x" << std::hex << seed << ")";
}

TEST(ClosestPointOnTriangle, MatchesExactDistanceOnWellShapedTriangles)
{
  const TriangleShape shapes[] = {TriangleShape::Fat};
  runTrials("fat", 0x5eed0001, 12000, shapes, 1, 0.0);
}

TEST(ClosestPointOnTriangle, MatchesExactDistanceOnSliversToAspect1e12)
{
  const TriangleShape shapes[] = {TriangleShape::Needle, TriangleShape::Cap};
  runTrials("slivers", 0x5eed0002, 12000, shapes, 2, 12.0);
}

TEST(ClosestPointOnTriangle, MatchesExactDistanceOnZeroAreaTriangles)
{
  const TriangleShape shapes[] = {TriangleShape::Collinear, TriangleShape::Coincident,
                                  TriangleShape::SinglePoint};
  runTrials("zero area", 0x5eed0003, 12000, shapes, 3, 0.0);
}

TEST(ClosestPointOnTriangle, HandPickedFeaturesAreExact)
{
  // Right triangle in z = 0: answers known in closed form, independent of the kernel.
  const Vec3 a{0, 0, 0};
  const Vec3 b{4, 0, 0};
  const Vec3 c{0, 4, 0};
  struct Expect
  {
    Vec3 p;
    Vec3 point;
    TriangleFeature feature;
  };
  const Expect cases[] = {
    {{1, 1, 3}, {1, 1, 0}, TriangleFeature::Face},
    {{1, 1, -3}, {1, 1, 0}, TriangleFeature::Face},
    {{-1, -1, 0}, a, TriangleFeature::VertexA},
    {{6, -1, 2}, b, TriangleFeature::VertexB},
    {{-1, 7, 0}, c, TriangleFeature::VertexC},
    {{2, -5, 0}, {2, 0, 0}, TriangleFeature::EdgeAB},
    {{3, 3, 1}, {2, 2, 0}, TriangleFeature::EdgeBC},
    {{-2, 1, 0}, {0, 1, 0}, TriangleFeature::EdgeCA},
    {a, a, TriangleFeature::VertexA},
    {b, b, TriangleFeature::VertexB},
    {c, c, TriangleFeature::VertexC},
  };
  for (const Expect& e : cases)
  {
    const ClosestPointResult r = closestPointOnTriangle(e.p, a, b, c);
    EXPECT_EQ(r.point, e.point) << "p = " << str(e.p);
    EXPECT_EQ(r.feature, e.feature) << "p = " << str(e.p);
    EXPECT_EQ(r.squaredDistance, squaredDistance(e.p, e.point)) << "p = " << str(e.p);
  }
}

TEST(ClosestPointOnTriangle, ZeroAreaTrianglesAnswerWithTheirSegment)
{
  // Collinear with the middle corner first: the hull is the segment from b to c.
  const Vec3 a{0, 0, 0};
  const Vec3 b{1, 0, 0};
  const Vec3 c{-1, 0, 0};
  WorstError worst;
  for (const Vec3& p : {Vec3{0.5, 1, 0}, Vec3{-3, 0, 0}, Vec3{0, 0, 2}, Vec3{2, 2, 2}})
  {
    EXPECT_EQ(checkClosestPoint(p, {a, b, c}, worst), "") << "p = " << str(p);
    const ClosestPointResult r = closestPointOnTriangle(p, a, b, c);
    const double expected = squaredDistance(p, Vec3{std::clamp(p.x, -1.0, 1.0), 0, 0});
    EXPECT_EQ(r.squaredDistance, expected) << "p = " << str(p);
  }
  // All three corners coincide: the answer is that point with finite weights.
  const Vec3 q{2, -3, 5};
  const ClosestPointResult r = closestPointOnTriangle(Vec3{1, 1, 1}, q, q, q);
  EXPECT_EQ(r.point, q);
  EXPECT_EQ(r.squaredDistance, squaredDistance(Vec3{1, 1, 1}, q));
}

TEST(ClosestPointOnTriangle, RegressionCoincidentCornersKeepTheirThirdEdge)
{
  // With a == b, the region tests once took the zero-length edge AB for the answer and returned
  // corner a, 5 away from a point lying on the triangle (the segment a-c).
  const Vec3 a{0, 0, 0};
  const Vec3 c{10, 0, 0};
  for (const auto& [p, expected] : {std::pair{Vec3{5, 0, 0}, 0.0}, std::pair{Vec3{5, 2, 0}, 4.0},
                                    std::pair{Vec3{12, 0, 0}, 4.0}})
  {
    EXPECT_EQ(closestPointOnTriangle(p, a, a, c).squaredDistance, expected) << str(p);
    EXPECT_EQ(closestPointOnTriangle(p, c, a, a).squaredDistance, expected) << str(p);
    EXPECT_EQ(closestPointOnTriangle(p, a, c, a).squaredDistance, expected) << str(p);
  }
}

TEST(ClosestPointOnTriangle, RegressionCapSliverAnswersOnTheTriangle)
{
  // A cap of aspect 2e11 (seed 0x5eed0002): the face projection through a rounded normal once
  // landed 1.7e-7 off the triangle and reported 3.7e-8 for an exact distance of 1.3e-7.
  const Vec3 p{0.69843554952217102, 0.87579390815703462, 0.41953655466620732};
  const TriangleCorners t{{0.67823240765776993, 0.98668989608434066, 0.45957205287521008},
                          {0.97676344568484375, -0.65196799690576435, -0.13201514263756087},
                          {0.93382298330894242, -0.4162647747063874, -0.046921720269205713}};
  WorstError worst;
  EXPECT_EQ(checkClosestPoint(p, t, worst), "");
}

TEST(ClosestParameterOnSegment, MatchesProjectionAndClamps)
{
  Random random(0x5eed0004);
  FailureBudget budget;
  for (int trial = 0; trial < 10000; ++trial)
  {
    const Vec3 a = random.inCube(1.0);
    const Vec3 b = random.chance(0.05) ? a : random.inCube(1.0);
    const Vec3 p = random.inCube(2.0);
    const double s = closestParameterOnSegment(p, a, b);
    const TriangleCorners segment{a, b, b};
    const double exact = exactDistance(p, segment);
    const double achieved = distance(p, a + (b - a) * s);
    const double tol = tolerance(spread({p, a, b}), magnitude({p, a, b}));
    if (!(s >= 0.0 && s <= 1.0 && std::fabs(achieved - exact) <= tol) && budget.spend())
    {
      ADD_FAILURE() << "seed 0x5eed0004 trial " << trial << " p " << str(p) << " a " << str(a)
                    << " b " << str(b) << " s " << s << " distance " << achieved << " exact "
                    << exact;
    }
  }
}

} // namespace
} // namespace proxima::test
