// sweepSphereTriangle and sweepSphereTriangleWithSkin against a brute-force oracle (SweepOracle.h):
// the first t at which the distance from start + t * motion to the triangle comes within the
// radius, found by golden-section search and bisection on the exact distance function evaluated in
// long double (Quad, 113-bit, for slivers, whose plane long double cannot resolve).
//
// What is checked, for a kernel answer t_k (d(t) is the oracle's distance along the path):
//   hit:     d(t_k) <= rho + tol (a real contact) and min over [0, t_k] of d >= rho - tol (nothing
//            was crossed before it), and where the path is not grazing, |t_k - t_oracle| <=
//            4 tol / |d'(t_oracle)|;
//   no hit:  min over [0, 1] of d >= rho - tol;
//   start already within the radius: hit at t = 0 exactly when the motion approaches the triangle
//            (cosine with the away direction below -tol / d(0)), no hit when it clearly leaves.
// rho is the radius, or for the skin variant the contact radius its documented rule picks from
// d(0). Answers within tol of a threshold may go either way: that is what "grazing" means.
//
// Tolerance. The kernel measures everything relative to a corner and the start: differences
// rounded to epsilon of the query's spread S (corners, start, end, radius), products a few
// epsilon of S^2, and positions rounded to epsilon of the largest coordinate M. Its corner and
// edge entries solve a t^2 + 2 b t + c = 0 with the discriminant formed as b^2 - a c, which
// cancels from |motion|^2 S^2 down to |motion|^2 rho^2: the entry point is then good to about
// epsilon S^2 / rho, not epsilon S (seen: 1.3e3 epsilon S for rho = S / 1000). We allow
//   tol = 64 epsilon (S + M) + 8 epsilon S^2 / rho
// on distances: 1.4e-14 relative when rho is comparable to S, as in the haptic loop (r = 1 mm,
// segments of a millimetre), and never more than 2e-12 relative for rho >= S / 1000, the
// smallest radius the random trials draw. A root t of d(t) = rho moves by
// tol / |d'(t)| when the distances move by tol, hence the t tolerance; for paths crossing the
// surface at more than 1/1000 of their length per unit t that is below 1e-9 * S / |motion|, the
// 1e-9 relative asked of t; the tests print the worst |t_k - t_oracle| they saw.
#include "Geometry/ClosestPoint.h"
#include "Geometry/SweptSphere.h"

#include "GeometryTestSupport.h"
#include "SweepOracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace proxima::test
{
namespace
{

constexpr double kSweepUlps = 64.0;

/// See the file comment: rounding of positions and of the quadratics' discriminants.
double sweepTolerance(double spreadLength, double largestCoordinate, double radius)
{
  return kSweepUlps * kEpsilon * (spreadLength + largestCoordinate) +
         8.0 * kEpsilon * spreadLength * spreadLength / radius;
}

struct SweepCase
{
  Vec3 start;
  Vec3 motion;
  double radius = 0.0;
  double skin = 0.0;
  TriangleCorners triangle;
};

std::string describe(const SweepCase& c)
{
  return "start " + test::str(c.start) + " motion " + test::str(c.motion) + " radius " +
         test::str(c.radius) + " skin " + test::str(c.skin) + " triangle " + test::str(c.triangle);
}

struct SweepStats
{
  int numTrials = 0;
  int numHits = 0;
  int numMisses = 0;
  int numStartsInContact = 0;
  int numWithinTolerance = 0; // answers the tolerance had to excuse
  double worstDeltaT = 0.0;   // over non-grazing hits
  void print(const char* name) const
  {
    std::printf("[ %s ] %d trials: %d hits, %d misses, %d start in contact, %d within tolerance "
                "of a threshold; worst |t - t_oracle| %.3g\n",
                name, numTrials, numHits, numMisses, numStartsInContact, numWithinTolerance,
                worstDeltaT);
  }
};

/// Checks a from-outside answer against the oracle for contact radius rho.
template <class T>
std::string checkFromOutside(const SweepResult& k, const SweepOracle<T>& oracle, long double rho,
                             double tol, SweepStats& stats)
{
  std::string f;
  if (k.hit)
  {
    const long double atHit = oracle.distanceAt(static_cast<T>(k.t));
    if (!(atHit <= rho + tol))
    {
      f += " stopped at t = " + test::str(k.t) + " where the distance is " +
           test::str(double(atHit)) + ", beyond the contact radius " + test::str(double(rho)) + ";";
    }
    const long double before = oracle.minDistanceUpTo(static_cast<T>(k.t));
    if (!(before >= rho - tol))
    {
      f += " passed within " + test::str(double(before)) + " before t = " + test::str(k.t) +
           " (contact radius " + test::str(double(rho)) + ");";
    }
    const auto entry = oracle.firstEntry(rho);
    if (entry.hit)
    {
      const long double slope = std::fabs(oracle.slopeAt(entry.t));
      const double deltaT = std::fabs(k.t - double(entry.t));
      if (slope > 0 && !(deltaT <= 4.0L * tol / slope + 1e-15L))
      {
        f += " t = " + test::str(k.t) + " but the oracle's is " + test::str(double(entry.t)) +
             " (slope " + test::str(double(slope)) + ");";
      }
      if (slope > 0 && 4.0L * tol / slope < 1e-9L)
      {
        stats.worstDeltaT = std::fmax(stats.worstDeltaT, deltaT);
      }
    }
    if (atHit > rho - tol && atHit < rho + tol && std::fabs(oracle.minDistance() - rho) <= tol)
    {
      ++stats.numWithinTolerance;
    }
  }
  else
  {
    const long double closest = oracle.minDistance();
    if (!(closest >= rho - tol))
    {
      f += " no hit, but the path comes within " + test::str(double(closest)) +
           " at t = " + test::str(double(oracle.argmin())) + " (contact radius " +
           test::str(double(rho)) + ");";
    }
    if (closest < rho + tol)
    {
      ++stats.numWithinTolerance;
    }
  }
  return f;
}

/// Checks an answer for a start already within the radius: hit at 0 iff approaching.
template <class T>
std::string checkTouching(const SweepResult& k, const SweepOracle<T>& oracle, double tol,
                          SweepStats& stats)
{
  std::string f;
  const long double d0 = oracle.distanceAt(T(0));
  if (k.hit && k.t != 0.0)
  {
    f += " started in contact but stopped at t = " + test::str(k.t) + " instead of 0;";
  }
  if (d0 <= tol)
  {
    ++stats.numWithinTolerance; // centre on the triangle: no away direction to judge by
    return f;
  }
  const long double cosine = oracle.startCosine();
  const long double cosineTolerance = tol / d0;
  if (cosine < -cosineTolerance && !k.hit)
  {
    f += " starts in contact and moves in (cosine " + test::str(double(cosine)) +
         ") but was not stopped;";
  }
  if (cosine > cosineTolerance && k.hit)
  {
    f += " starts in contact and moves away (cosine " + test::str(double(cosine)) +
         ") but was stopped;";
  }
  if (std::fabs(cosine) <= cosineTolerance)
  {
    ++stats.numWithinTolerance;
  }
  return f;
}

/// Runs the kernel on one case and checks it against the oracle in precision T, following the
/// documented rule of sweepSphereTriangleWithSkin (which with skin 0 is sweepSphereTriangle).
template <class T>
std::string checkSweep(const SweepCase& c, SweepStats& stats)
{
  const SweepResult k =
    c.skin > 0.0 ? sweepSphereTriangleWithSkin(c.start, c.motion, c.radius, c.skin, c.triangle)
                 : sweepSphereTriangle(c.start, c.motion, c.radius, c.triangle);
  const SweepOracle<T> oracle(c.start, c.motion, c.triangle);
  const Vec3 end = c.start + c.motion;
  const double S =
    std::fmax(spread({c.start, end, c.triangle.a, c.triangle.b, c.triangle.c}), c.radius + c.skin);
  const double M = magnitude({c.start, end, c.triangle.a, c.triangle.b, c.triangle.c});
  const double tol = sweepTolerance(S, M, c.radius);

  ++stats.numTrials;
  stats.numHits += k.hit ? 1 : 0;
  stats.numMisses += k.hit ? 0 : 1;
  std::string f;
  if (!(k.t >= 0.0 && k.t <= 1.0) || (!k.hit && k.t != 1.0))
  {
    f += " t = " + test::str(k.t) + " with hit = " + std::to_string(k.hit) + ";";
  }

  const long double d0 = oracle.distanceAt(T(0));
  const long double r = c.radius;
  const long double skin = c.skin;
  if (d0 < r - tol)
  {
    ++stats.numStartsInContact;
    return f + checkTouching(k, oracle, tol, stats);
  }
  // The contact radius of the documented rule: radius + skin for a fresh contact, else
  // max(radius, d0 - skin / 2); the rule is continuous at d0 = radius + 1.5 skin.
  const long double rho = d0 >= r + 1.5L * skin ? r + skin : std::fmax(r, d0 - 0.5L * skin);
  if (d0 <= r + tol)
  {
    // On the radius to within rounding: either the touching rule or the from-outside rule.
    ++stats.numStartsInContact;
    const std::string touching = checkTouching(k, oracle, tol, stats);
    const std::string outside = checkFromOutside(k, oracle, rho, tol, stats);
    return touching.empty() || outside.empty() ? f : f + touching + " /" + outside;
  }
  f += checkFromOutside(k, oracle, rho, tol, stats);
  // Documented for the skin rule: no stop is ever closer than the radius.
  if (k.hit && !(oracle.distanceAt(static_cast<T>(k.t)) >= r - tol))
  {
    f += " stopped closer than the radius;";
  }
  return f;
}

/// A point on a random feature of the triangle: a corner, an edge, or the face.
Vec3 pointOnFeature(Random& random, const TriangleCorners& t)
{
  const Vec3 corners[3] = {t.a, t.b, t.c};
  const int i = random.integer(0, 2);
  switch (random.integer(0, 2))
  {
    case 0: return corners[i];
    case 1: return corners[i] + (corners[(i + 1) % 3] - corners[i]) * random.uniform(0.0, 1.0);
    default: return pointOnTriangle(random, t);
  }
}

/// Random sweeps of four kinds (anywhere, aimed at a feature, grazing, starting in contact), about
/// `size` across, near `offset`, against a triangle of the given shape.
SweepCase makeSweepCase(Random& random, TriangleShape shape, double size, const Vec3& offset,
                        double aspect, int kind)
{
  SweepCase c;
  c.triangle = makeTriangle(random, shape, size, offset, aspect);
  c.radius = size * random.logUniform(-3.0, -0.3);
  const TriangleCorners& t = c.triangle;
  switch (kind)
  {
    case 0: // anywhere
    {
      c.start = (t.a + t.b + t.c) * (1.0 / 3.0) + random.inCube(2.0 * size);
      c.motion = random.direction() * (size * random.logUniform(-2.0, 0.7));
      break;
    }
    case 1: // aimed so that the path passes about one radius from a feature
    {
      const Vec3 target = pointOnFeature(random, t);
      const Vec3 direction = random.direction();
      const Vec3 aim =
        target + perpendicular(direction, random) * (c.radius * random.uniform(0.0, 1.2));
      const double length = size * random.logUniform(-2.0, 0.5);
      c.start = aim - direction * (length * random.uniform(0.05, 1.2));
      c.motion = direction * length;
      break;
    }
    case 2: // grazing: a line tangent to the sphere about a feature point, to within 1e-9
    {
      const Vec3 target = pointOnFeature(random, t);
      const Vec3 direction = random.direction();
      const double offBy = random.chance(0.5) ? 0.0 : random.uniform(-1e-9, 1e-9);
      const Vec3 aim = target + perpendicular(direction, random) * (c.radius * (1.0 + offBy));
      const double length = size * random.logUniform(-2.0, 0.5);
      c.start = aim - direction * (length * random.uniform(0.05, 1.2));
      c.motion = direction * length;
      break;
    }
    default: // starting within or on the radius, moving any way
    {
      const Vec3 target = pointOnFeature(random, t);
      const double depth = random.chance(0.3) ? 1.0 : random.uniform(0.0, 1.0);
      c.start = target + random.direction() * (c.radius * depth);
      c.motion = random.direction() * (size * random.logUniform(-2.0, 0.5));
      break;
    }
  }
  return c;
}

struct Scale
{
  double size;
  double offset;
};
constexpr Scale kScales[] = {{1.0, 0.0}, {1e-6, 0.0}, {1.0, 1e4}, {1e-3, 1e4}, {1e3, 0.0}};

template <class T>
void runSweepTrials(const char* name, std::uint64_t seed, int numTrials,
                    std::initializer_list<TriangleShape> shapes, double maxAspectExponent,
                    bool withSkin)
{
  Random random(seed);
  SweepStats stats;
  FailureBudget budget;
  int numFailures = 0;
  const std::vector<TriangleShape> shapeList(shapes);
  for (int trial = 0; trial < numTrials; ++trial)
  {
    const TriangleShape shape = shapeList[trial % shapeList.size()];
    const Scale scale = kScales[(trial / shapeList.size()) % std::size(kScales)];
    const Vec3 offset = random.direction() * scale.offset;
    SweepCase c = makeSweepCase(random, shape, scale.size, offset,
                                random.logUniform(0.0, maxAspectExponent), trial % 4);
    if (withSkin)
    {
      c.skin = c.radius * random.logUniform(-4.0, -0.5);
      if (trial % 4 == 3)
      {
        // Start around the stop distances of the rule: radius + 0.5, 1 and 1.5 skins.
        const Vec3 target = pointOnFeature(random, c.triangle);
        c.start = target + random.direction() * (c.radius + c.skin * random.uniform(0.0, 2.0));
      }
    }
    const std::string failures = checkSweep<T>(c, stats);
    if (!failures.empty())
    {
      ++numFailures;
      if (budget.spend())
      {
        ADD_FAILURE() << "seed 0x" << std::hex << seed << std::dec << " trial " << trial << " ("
                      << test::name(shape) << ")\n  " << describe(c) << "\n " << failures;
      }
    }
  }
  stats.print(name);
  EXPECT_EQ(numFailures, 0) << "of " << numTrials;
  // Coverage: the trials must exercise hits, misses and starts in contact, or they prove little.
  EXPECT_GT(stats.numHits, numTrials / 5);
  EXPECT_GT(stats.numMisses, numTrials / 10);
  EXPECT_GT(stats.numStartsInContact, numTrials / 20);
}

TEST(SweepSphereTriangle, MatchesBruteForceOnRandomSweeps)
{
  runSweepTrials<long double>("random sweeps", 0x5ee90001, 12000, {TriangleShape::Fat}, 0.0, false);
}

TEST(SweepSphereTriangle, MatchesBruteForceOnDegenerateTriangles)
{
  runSweepTrials<long double>(
    "zero-area triangles", 0x5ee90002, 6000,
    {TriangleShape::Collinear, TriangleShape::Coincident, TriangleShape::SinglePoint}, 0.0, false);
}

TEST(SweepSphereTriangle, MatchesBruteForceOnSlivers)
{
  // Quad precision: a cap of aspect 1e12 has a normal long double cannot resolve.
  runSweepTrials<Quad>("slivers to aspect 1e12", 0x5ee90003, 2000,
                       {TriangleShape::Needle, TriangleShape::Cap}, 12.0, false);
}

TEST(SweepSphereTriangleWithSkin, FollowsItsDocumentedRule)
{
  runSweepTrials<long double>("skin rule", 0x5ee90004, 12000, {TriangleShape::Fat}, 0.0, true);
}

TEST(SweepSphereTriangleWithSkin, FollowsItsDocumentedRuleOnDegenerateTriangles)
{
  runSweepTrials<Quad>("skin rule, slivers and zero area", 0x5ee90005, 2000,
                       {TriangleShape::Needle, TriangleShape::Cap, TriangleShape::Collinear,
                        TriangleShape::Coincident},
                       12.0, true);
}

// A caller that already has the triangle's closest point to the start (the candidate cache, from
// the gather at the same point) gets the same sweep, bit for bit, on every kind of triangle and
// start, in contact or not.
TEST(SweepSphereTriangleWithSkin, GivenTheClosestPointAnswersBitForBitAsWithout)
{
  Random random(0x5ee90006);
  const TriangleShape shapes[] = {TriangleShape::Fat, TriangleShape::Needle, TriangleShape::Cap,
                                  TriangleShape::Collinear, TriangleShape::Coincident};
  int hits = 0;
  for (int trial = 0; trial < 6000; ++trial)
  {
    const TriangleShape shape = shapes[trial % std::size(shapes)];
    const Scale scale = kScales[(trial / std::size(shapes)) % std::size(kScales)];
    SweepCase c = makeSweepCase(random, shape, scale.size, random.direction() * scale.offset,
                                random.logUniform(0.0, 12.0), trial % 4);
    c.skin = c.radius * random.logUniform(-4.0, -0.5);
    const TriangleCorners& t = c.triangle;
    const ClosestPointResult closest = closestPointOnTriangle(c.start, t.a, t.b, t.c);
    const SweepResult asked = sweepSphereTriangleWithSkin(c.start, c.motion, c.radius, c.skin, t);
    const SweepResult given =
      sweepSphereTriangleWithSkin(c.start, c.motion, c.radius, c.skin, t,
                                  KnownClosestPoint{closest.point, closest.squaredDistance});
    ASSERT_EQ(asked.hit, given.hit) << describe(c);
    ASSERT_EQ(std::memcmp(&asked.t, &given.t, sizeof asked.t), 0) << describe(c);
    hits += asked.hit ? 1 : 0;
  }
  EXPECT_GT(hits, 600); // the trials reach hits as well as misses
}

/// Axis-aligned setups whose answers are known in closed form and whose tangencies are exact in
/// double, so "tangent" means tangent and not "tangent to within rounding".
class AxisAlignedSweep : public ::testing::Test
{
protected:
  // The unit right triangle in the plane z = 0.
  const TriangleCorners m_triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const double m_radius = 0.25;
};

TEST_F(AxisAlignedSweep, FallingOntoTheFaceStopsOneRadiusAbove)
{
  const SweepResult r = sweepSphereTriangle({0.25, 0.25, 1.0}, {0, 0, -2.0}, m_radius, m_triangle);
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.t, 0.375); // (1 - 0.25) / 2, exact in binary
  const SweepResult below =
    sweepSphereTriangle({0.25, 0.25, -1.0}, {0, 0, 2.0}, m_radius, m_triangle);
  EXPECT_TRUE(below.hit);
  EXPECT_EQ(below.t, 0.375);
}

TEST_F(AxisAlignedSweep, ParallelToTheFaceAroundTheRadius)
{
  // Gliding in from x = -1 at height h over the face. The header's rule is "comes within radius":
  // at h = radius the sphere first touches edge CA (the y axis) at x = 0, t = 1/3, and that
  // touch counts; a hair higher nothing is touched; a hair lower the touch comes just before.
  const double above = 0.25 * (1.0 + 1e-9);
  EXPECT_FALSE(sweepSphereTriangle({-1.0, 0.25, above}, {3.0, 0, 0}, m_radius, m_triangle).hit);
  const SweepResult touching =
    sweepSphereTriangle({-1.0, 0.25, 0.25}, {3.0, 0, 0}, m_radius, m_triangle);
  EXPECT_TRUE(touching.hit);
  EXPECT_NEAR(touching.t, 1.0 / 3.0, 1e-15);
  const double below = 0.25 * (1.0 - 1e-9);
  const SweepResult grazing =
    sweepSphereTriangle({-1.0, 0.25, below}, {3.0, 0, 0}, m_radius, m_triangle);
  EXPECT_TRUE(grazing.hit);
  // Enters the cylinder about the y axis at x = -sqrt(0.25^2 - below^2) ~ -1.1e-5.
  const double entryX = -std::sqrt(0.0625 - below * below);
  EXPECT_NEAR(grazing.t, (1.0 + entryX) / 3.0, 1e-12);
  EXPECT_LT(grazing.t, 1.0 / 3.0);
}

TEST_F(AxisAlignedSweep, ParallelToAnEdgeAroundTheRadius)
{
  // Along edge AB (the x axis), beside it in -y. At distance exactly 0.25 the sphere touches
  // corner A at x = 0 (t = 1/3) and then slides tangent to the edge; a hair farther it misses.
  EXPECT_FALSE(
    sweepSphereTriangle({-1.0, -0.25 * (1.0 + 1e-9), 0.0}, {3.0, 0, 0}, m_radius, m_triangle).hit);
  const SweepResult tangent =
    sweepSphereTriangle({-1.0, -0.25, 0.0}, {3.0, 0, 0}, m_radius, m_triangle);
  EXPECT_TRUE(tangent.hit);
  EXPECT_NEAR(tangent.t, 1.0 / 3.0, 1e-15);
  // At distance 0.2 the sphere meets corner A's sphere: (x + 1)^2 + 0.2^2 = 0.25^2 first at
  // x = -0.15, i.e. t = 0.85 / 3.
  const SweepResult r = sweepSphereTriangle({-1.0, -0.2, 0.0}, {3.0, 0, 0}, m_radius, m_triangle);
  EXPECT_TRUE(r.hit);
  EXPECT_NEAR(r.t, 0.85 / 3.0, 1e-15);
  // Parallel to the edge and exactly over it, one radius above the face plane: touching all along
  // from x = 0; the first touch is corner A's sphere at x = 0.
  const SweepResult over =
    sweepSphereTriangle({-1.0, 0.0, 0.25}, {3.0, 0, 0}, m_radius, m_triangle);
  EXPECT_TRUE(over.hit);
  EXPECT_NEAR(over.t, 1.0 / 3.0, 1e-15);
}

TEST_F(AxisAlignedSweep, StartingInContact)
{
  const Vec3 start{0.25, 0.25, 0.1}; // 0.1 above the face, inside the radius
  EXPECT_FALSE(sweepSphereTriangle(start, {0, 0, 1}, m_radius, m_triangle).hit) << "moving away";
  EXPECT_FALSE(sweepSphereTriangle(start, {1, 0, 0}, m_radius, m_triangle).hit) << "tangent";
  const SweepResult in = sweepSphereTriangle(start, {0, 0, -1}, m_radius, m_triangle);
  EXPECT_TRUE(in.hit) << "moving in";
  EXPECT_EQ(in.t, 0.0);
  // Exactly at the radius: moving along or away is free, moving in is stopped at once.
  const Vec3 touching{0.25, 0.25, 0.25};
  EXPECT_FALSE(sweepSphereTriangle(touching, {1, 1, 0}, m_radius, m_triangle).hit);
  EXPECT_FALSE(sweepSphereTriangle(touching, {0, 0, 1}, m_radius, m_triangle).hit);
  const SweepResult pressing = sweepSphereTriangle(touching, {0, 0.5, -0.5}, m_radius, m_triangle);
  EXPECT_TRUE(pressing.hit);
  EXPECT_EQ(pressing.t, 0.0);
  // Centre exactly on the face: no away direction, so any motion is blocked.
  EXPECT_TRUE(sweepSphereTriangle({0.25, 0.25, 0}, {0, 0, 1}, m_radius, m_triangle).hit);
  // No motion at all is never a hit from outside.
  EXPECT_FALSE(sweepSphereTriangle({0.25, 0.25, 1.0}, {0, 0, 0}, m_radius, m_triangle).hit);
}

TEST_F(AxisAlignedSweep, SkinStopsFreshContactsEarlyAndNeverBlocksSliding)
{
  const double skin = 0.01;
  // Fresh contact from far above: stop at radius + skin.
  const SweepResult fresh =
    sweepSphereTriangleWithSkin({0.25, 0.25, 1.0}, {0, 0, -1.0}, m_radius, skin, m_triangle);
  EXPECT_TRUE(fresh.hit);
  EXPECT_NEAR(fresh.t, 1.0 - (m_radius + skin), 1e-15);
  // Resting where that stop left it and sliding along with a drift down of a quarter skin (as
  // rounding in the update stage would cause): not blocked.
  const Vec3 rest{0.25, 0.25, m_radius + skin};
  EXPECT_FALSE(
    sweepSphereTriangleWithSkin(rest, {0.3, 0.2, -0.25 * skin}, m_radius, skin, m_triangle).hit);
  // Pushing down from there is stopped at max(radius, d0 - skin / 2): half a skin lower.
  const SweepResult push =
    sweepSphereTriangleWithSkin(rest, {0, 0, -0.1}, m_radius, skin, m_triangle);
  EXPECT_TRUE(push.hit);
  EXPECT_NEAR(push.t, 0.5 * skin / 0.1, 1e-13);
  // Starting inside the skin but outside the radius: the stop is never closer than the radius.
  const Vec3 close{0.25, 0.25, m_radius + 0.2 * skin};
  const SweepResult deep =
    sweepSphereTriangleWithSkin(close, {0, 0, -0.1}, m_radius, skin, m_triangle);
  EXPECT_TRUE(deep.hit);
  EXPECT_NEAR(deep.t, 0.2 * skin / 0.1, 1e-13);
}

TEST(SweepSphereTriangle, RestartAfterAStopIsStillBlocked)
{
  // The move stage stops at a contact and starts the next sweep from there; rounding puts that
  // start a hair inside or outside the radius. Pushing on from it must be stopped at once, or
  // the proxy would tunnel through. Tilted triangles make the roundings disagree.
  Random random(0x5ee90006);
  FailureBudget budget;
  int numFailures = 0;
  int numChecked = 0;
  for (int trial = 0; trial < 10000; ++trial)
  {
    const double size = trial % 2 == 0 ? 1.0 : 1e-3;
    const Vec3 offset = trial % 3 == 0 ? random.direction() * 1e4 : Vec3{};
    const TriangleCorners t = makeTriangle(random, TriangleShape::Fat, size, offset, 1.0);
    const double radius = size * random.logUniform(-3.0, -0.5);
    const Vec3 target = pointOnFeature(random, t);
    const Vec3 direction = random.direction();
    const Vec3 start = target - direction * (size * 2.0);
    const Vec3 motion = direction * (size * 3.0);
    const SweepResult first = sweepSphereTriangle(start, motion, radius, t);
    if (!first.hit || first.t <= 0.0)
    {
      continue;
    }
    const Vec3 stop = start + motion * first.t;
    const Vec3 rest = start + motion; // the remaining motion, from the stop
    const SweepResult again = sweepSphereTriangle(stop, rest - stop, radius, t);
    ++numChecked;
    // The remainder goes straight on into the triangle, so it must stop (almost) at once.
    const SweepOracle<long double> oracle(stop, rest - stop, t);
    const double tol = sweepTolerance(3.0 * size, maxAbsComponent(stop), radius);
    const bool ok =
      again.hit && oracle.minDistanceUpTo(static_cast<long double>(again.t)) >= radius - tol;
    if (!ok)
    {
      ++numFailures;
      if (budget.spend())
      {
        ADD_FAILURE() << "seed 0x5ee90006 trial " << trial << ": stopped at " << str(stop) << " (t "
                      << first.t << "), restarting towards " << str(rest) << " gave hit "
                      << again.hit << " t " << again.t << "; triangle " << str(t) << " radius "
                      << str(radius);
      }
    }
  }
  EXPECT_EQ(numFailures, 0);
  EXPECT_GT(numChecked, 5000);
}

} // namespace
} // namespace proxima::test
