// solveGoal (the paper's dual-space Gilbert solve, eqs. 8-19, with its exact enumeration
// fallback) against an independent oracle: CGAL's quadratic-program solver in exact arithmetic
// (Gmpzf) on the same double inputs, min |x - v| subject to n_i . x >= 0.
//
// Tolerances, all relative to |v| (the finger's distance, the problem's only length):
// - feasibility n_i . x >= -1e-12 |v|: the solver's own acceptance threshold
//   (kFeasibilityTolerance), far above the ~1e-16 rounding of the dual solve;
// - displacement |x - x*| <= 1e-12 |v| against the exact optimum x*. A point that violates the
//   cone by e lies within e / sin(beta) of it, beta the smallest opening of the cone at that
//   point; the cases here keep beta >= 30 degrees where they can, so an answer at the solver's
//   own acceptance threshold (1e-12) stays within about 2e-12, and the rounding of a correct dual
//   solve is far below that (the worst seen is printed);
// - forces: |(v - x) + sum mu_i n_i| <= 1e-12 k (|v| + sum mu_i), the rounding of the sum
//   amplified by the conditioning k of the active normals (1 / |det| for three, 1 / (1 - g^2) for
//   two): depths solved from nearly dependent normals carry rounding in proportion, and the
//   solver accepts triples down to |det| = 1e-7. The worst k (sum mu / |v|) seen is printed.
#include "Proxy/GoalSolver.h"

#include "ProxyOracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace proxima
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kRelative = 1e-12;

struct Worst
{
  double displacement = 0.0;
  double infeasibility = 0.0;
  double force = 0.0;
  double slack = 0.0;
  double depthRatio = 0.0;
  double conditioning = 1.0;
  int fallbacks = 0;
  int cases = 0;
  void print(const std::string& name) const
  {
    std::cout << "[goal] " << name << ": " << cases << " cases, worst |x - x*|/|v| " << displacement
              << ", worst infeasibility/|v| " << infeasibility << ", worst force residual " << force
              << ", worst active-plane slack/|v| " << slack << ", worst sum(mu)/|v| " << depthRatio
              << " (conditioning up to " << conditioning << "), exact fallbacks " << fallbacks
              << "\n";
    testing::Test::RecordProperty(name + "_worst_displacement", oracle::str(displacement));
  }
};

std::string describe(const Vec3& v, const std::vector<Vec3>& normals)
{
  std::string text = "v = " + oracle::str(v) + ", normals = {";
  for (const Vec3& n : normals)
  {
    text += oracle::str(n) + ", ";
  }
  return text + "}";
}

// Checks one problem against the exact oracle; returns false (with gtest failures) if wrong.
bool checkGoal(const Vec3& v, const std::vector<Vec3>& normals, Worst& worst,
               double displacementTolerance = kRelative)
{
  const int count = static_cast<int>(normals.size());
  const GoalSolution solution = solveGoal(v, normals.data(), count);
  const Vec3 exact = oracle::projectOntoCone(v, normals.data(), count);
  const double scale = norm(v);
  const Vec3& x = solution.displacement;
  ++worst.cases;
  worst.fallbacks += solution.usedExactFallback ? 1 : 0;
  bool ok = true;
  if (!isFinite(x))
  {
    ADD_FAILURE() << "non-finite displacement for " << describe(v, normals);
    return false;
  }
  // Feasibility.
  double infeasibility = 0.0;
  for (const Vec3& n : normals)
  {
    infeasibility = std::max(infeasibility, -dot(n, x));
  }
  worst.infeasibility = std::max(worst.infeasibility, infeasibility / scale);
  if (infeasibility > kRelative * scale)
  {
    ADD_FAILURE() << "infeasible by " << infeasibility << ": x = " << oracle::str(x) << " for "
                  << describe(v, normals);
    ok = false;
  }
  // Optimality against the exact answer.
  const double error = distance(x, exact);
  worst.displacement = std::max(worst.displacement, error / scale);
  if (error > displacementTolerance * scale)
  {
    ADD_FAILURE() << "x = " << oracle::str(x) << " but the exact optimum is " << oracle::str(exact)
                  << " (|x - x*| = " << error << ", fallback " << solution.usedExactFallback
                  << ") for " << describe(v, normals);
    ok = false;
  }
  // Forces: finger - goal = -sum mu_i n_i with mu_i >= 0 on at most three distinct planes.
  if (solution.numActive < 0 || solution.numActive > 3)
  {
    ADD_FAILURE() << "numActive = " << solution.numActive;
    return false;
  }
  Vec3 residual = v - x;
  double sumDepth = 0.0;
  for (int k = 0; k < solution.numActive; ++k)
  {
    const int i = solution.active[k];
    if (i < 0 || i >= count)
    {
      ADD_FAILURE() << "active plane index " << i << " out of range";
      return false;
    }
    for (int j = 0; j < k; ++j)
    {
      if (solution.active[j] == i)
      {
        ADD_FAILURE() << "plane " << i << " active twice for " << describe(v, normals);
        ok = false;
      }
    }
    const double mu = solution.depth[k];
    if (!(mu >= 0.0) || !std::isfinite(mu))
    {
      ADD_FAILURE() << "depth " << mu << " of plane " << i << " for " << describe(v, normals);
      ok = false;
    }
    residual += normals[i] * mu;
    sumDepth += std::fabs(mu);
    // An active plane holds the goal on it (complementary slackness).
    const double slack = std::fabs(dot(normals[i], x));
    worst.slack = std::max(worst.slack, slack / scale);
    if (slack > kRelative * scale)
    {
      ADD_FAILURE() << "active plane " << i << " is " << slack << " off the goal for "
                    << describe(v, normals);
      ok = false;
    }
  }
  double conditioning = 1.0;
  if (solution.numActive == 2)
  {
    const double g = dot(normals[solution.active[0]], normals[solution.active[1]]);
    conditioning = 1.0 / std::max(1.0 - g * g, 1e-300);
  }
  else if (solution.numActive == 3)
  {
    conditioning =
      1.0 /
      std::max(std::fabs(dot(normals[solution.active[0]],
                             cross(normals[solution.active[1]], normals[solution.active[2]]))),
               1e-300);
  }
  worst.conditioning = std::max(worst.conditioning, conditioning);
  worst.depthRatio = std::max(worst.depthRatio, sumDepth / scale);
  const double forceError = norm(residual) / (scale + sumDepth) / conditioning;
  worst.force = std::max(worst.force, forceError);
  if (forceError > kRelative)
  {
    ADD_FAILURE() << "forces do not reproduce finger - goal: |v - x + sum mu n| = "
                  << norm(residual) << " (numActive " << solution.numActive
                  << ", x = " << oracle::str(x) << ", x* = " << oracle::str(exact) << ") for "
                  << describe(v, normals);
    ok = false;
  }
  return ok;
}

Vec3 randomUnit(std::mt19937_64& engine)
{
  std::normal_distribution<double> gauss;
  for (;;)
  {
    const Vec3 g{gauss(engine), gauss(engine), gauss(engine)};
    if (norm(g) > 1e-3)
    {
      return normalizedOrZero(g);
    }
  }
}

// A unit vector at `angle` from unit `axis`, at azimuth `phi` about it.
Vec3 tilted(const Vec3& axis, double angle, double phi)
{
  const Vec3 helper = std::fabs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 e1 = normalizedOrZero(cross(axis, helper));
  const Vec3 e2 = cross(axis, e1);
  return normalizedOrZero(axis * std::cos(angle) +
                          (e1 * std::cos(phi) + e2 * std::sin(phi)) * std::sin(angle));
}

TEST(GoalSolver, FreeFingerIsReachedAndZeroStepIsZero)
{
  Worst worst;
  const std::vector<Vec3> up = {{0, 0, 1}};
  EXPECT_TRUE(checkGoal({0.3, -0.2, 0.5}, up, worst));
  const GoalSolution none = solveGoal({0, 0, 0}, up.data(), 1);
  EXPECT_EQ(none.displacement, Vec3{});
  EXPECT_EQ(none.numActive, 0);
  const GoalSolution noPlanes = solveGoal({1, 2, 3}, nullptr, 0);
  EXPECT_EQ(noPlanes.displacement, (Vec3{1, 2, 3}));
}

TEST(GoalSolver, RandomPlanesAgainstExactQuadraticProgram)
{
  // 12,000 problems on fixed seeds: 1-16 planes, normals spread over a cap of half-angle 20-180
  // degrees (narrow caps leave a wide free cone, the realistic case; wide ones often pin the
  // proxy), finger directions anywhere, lengths from 1 um to 1 m.
  std::mt19937_64 engine(20240611);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Worst worst;
  int failures = 0;
  for (int trial = 0; trial < 12000 && failures < 10; ++trial)
  {
    const int count = 1 + static_cast<int>(uniform(engine) * 16);
    const Vec3 axis = randomUnit(engine);
    const double cap = (20.0 + 160.0 * uniform(engine)) * kPi / 180.0;
    std::vector<Vec3> normals;
    for (int i = 0; i < count; ++i)
    {
      normals.push_back(tilted(axis, cap * std::sqrt(uniform(engine)), 2 * kPi * uniform(engine)));
    }
    const double length = std::pow(10.0, -6.0 + 6.0 * uniform(engine));
    const Vec3 v = randomUnit(engine) * length;
    if (!checkGoal(v, normals, worst))
    {
      ++failures;
      ADD_FAILURE() << "trial " << trial;
    }
  }
  worst.print("random");
}

TEST(GoalSolver, RedundantAndDuplicatedPlanes)
{
  std::mt19937_64 engine(99);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Worst worst;
  for (int trial = 0; trial < 2000; ++trial)
  {
    const Vec3 axis = randomUnit(engine);
    std::vector<Vec3> base;
    const int count = 1 + trial % 4;
    for (int i = 0; i < count; ++i)
    {
      base.push_back(tilted(axis, 1.2 * uniform(engine), 2 * kPi * uniform(engine)));
    }
    std::vector<Vec3> normals;
    for (const Vec3& n : base)
    {
      // Each plane two to four times (exact copies, as from triangles sharing a vertex).
      const int copies = 2 + trial % 3;
      for (int c = 0; c < copies; ++c)
      {
        normals.push_back(n);
      }
    }
    if (base.size() >= 2)
    {
      // A redundant plane: the normalised sum of two others (implied by them).
      normals.push_back(normalizedOrZero(base[0] + base[1]));
    }
    std::shuffle(normals.begin(), normals.end(), engine);
    const Vec3 v = randomUnit(engine) * (0.001 + uniform(engine));
    ASSERT_TRUE(checkGoal(v, normals, worst)) << "trial " << trial;
  }
  worst.print("duplicates");
}

TEST(GoalSolver, PyramidApexFourToSixteenPlanes)
{
  // The proxy in the bottom of a funnel of n faces: n planes through one point. Face normals lean
  // `slope` from vertical toward the axis.
  Worst worst;
  std::mt19937_64 engine(4);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int sides = 4; sides <= 16; ++sides)
  {
    for (double slopeDegrees : {20.0, 45.0, 60.0, 80.0})
    {
      const double slope = slopeDegrees * kPi / 180.0;
      std::vector<Vec3> normals;
      for (int i = 0; i < sides; ++i)
      {
        const double phi = 2 * kPi * i / sides;
        normals.push_back(
          {-std::sin(slope) * std::cos(phi), -std::sin(slope) * std::sin(phi), std::cos(slope)});
      }
      // Straight down: pinned (x = 0), the forces of at most three faces hold the finger.
      EXPECT_TRUE(checkGoal({0, 0, -0.01}, normals, worst)) << sides << " sides";
      const GoalSolution down = solveGoal({0, 0, -0.01}, normals.data(), sides);
      EXPECT_LT(norm(down.displacement), 1e-14) << sides << " sides, slope " << slopeDegrees;
      // Every other direction, including up the faces and along the edges between them.
      for (int trial = 0; trial < 60; ++trial)
      {
        const Vec3 v{uniform(engine), uniform(engine), uniform(engine)};
        EXPECT_TRUE(checkGoal(v * 0.01, normals, worst)) << sides << " sides, trial " << trial;
      }
      for (int i = 0; i < sides; ++i)
      {
        // Exactly along a face and exactly along an edge (between faces i and i+1).
        const Vec3 along = cross(normals[i], cross(Vec3{0, 0, 1}, normals[i]));
        EXPECT_TRUE(checkGoal(along * 0.01 + Vec3{0, 0, -0.001}, normals, worst));
        const Vec3 edge = normalizedOrZero(cross(normals[i], normals[(i + 1) % sides]));
        EXPECT_TRUE(checkGoal(edge * 0.01, normals, worst));
        EXPECT_TRUE(checkGoal(edge * -0.01, normals, worst));
      }
    }
  }
  worst.print("apex");
}

TEST(GoalSolver, NearParallelPlanes)
{
  // Two or three planes whose normals differ by 1e-16 to 1e-6 rad: a nearly flat dihedral. The
  // Gram matrix is singular to double precision below ~1e-8 rad; the answer must not be.
  Worst worst;
  std::mt19937_64 engine(12);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (double angle : {1e-6, 1e-8, 1e-10, 1e-12, 1e-14, 1e-16})
  {
    for (int trial = 0; trial < 300; ++trial)
    {
      const Vec3 n0 = randomUnit(engine);
      std::vector<Vec3> normals = {n0, tilted(n0, angle, 2 * kPi * (0.5 + 0.5 * uniform(engine)))};
      if (trial % 2 == 0)
      {
        normals.push_back(tilted(n0, angle, 2 * kPi * (0.5 + 0.5 * uniform(engine))));
      }
      if (trial % 3 == 0)
      {
        normals.push_back(tilted(n0, 0.7, 0.0)); // a third, well separated plane
      }
      // The finger below the planes, mostly, with a tangential part.
      const Vec3 v = n0 * (-0.5 - 0.5 * std::fabs(uniform(engine))) +
                     Vec3{uniform(engine), uniform(engine), uniform(engine)} * 0.5;
      EXPECT_TRUE(checkGoal(v * 0.01, normals, worst)) << "angle " << angle << " trial " << trial;
    }
  }
  worst.print("near-parallel");
}

TEST(GoalSolver, FingerAboveSomePlanes)
{
  // Planes the finger lies above stay out of the dual (u . n >= 0) but still bound the answer.
  Worst worst;
  std::mt19937_64 engine(31);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 3000; ++trial)
  {
    const Vec3 v = randomUnit(engine) * 0.01;
    const Vec3 u = normalizedOrZero(v);
    std::vector<Vec3> normals;
    const int below = 1 + trial % 3;
    const int above = 1 + (trial / 3) % 4;
    for (int i = 0; i < below; ++i)
    {
      // u . n < 0: between 95 and 175 degrees from the finger direction.
      normals.push_back(
        tilted(u, (95.0 + 80.0 * uniform(engine)) * kPi / 180.0, 2 * kPi * uniform(engine)));
    }
    for (int i = 0; i < above; ++i)
    {
      // u . n >= 0: between 10 and 90 degrees, the last exactly 90 (the finger in the plane).
      const double degrees =
        i + 1 == above && trial % 5 == 0 ? 90.0 : 10.0 + 80.0 * uniform(engine);
      normals.push_back(tilted(u, degrees * kPi / 180.0, 2 * kPi * uniform(engine)));
    }
    std::shuffle(normals.begin(), normals.end(), engine);
    ASSERT_TRUE(checkGoal(v, normals, worst)) << "trial " << trial;
  }
  worst.print("finger-above");
}

TEST(GoalSolver, NarrowGrooveFingerAboveOneFaceBelowTheOther)
{
  // A groove along x of opening 10-85 degrees: face normals lean toward each other. A finger
  // above face A (u . nA > 0) and below face B: projecting onto B alone crosses A, which the dual
  // (built from B only) cannot see; the answer is on the groove line or on B, never beyond A.
  Worst worst;
  int fallbacks = 0;
  for (double opening = 10.0; opening < 90.0; opening += 5.0)
  {
    const double half = 0.5 * opening * kPi / 180.0;
    // Inward normals of the faces: face A rises at +half from vertical toward +y.
    const Vec3 nA{0, -std::cos(half), std::sin(half)};
    const Vec3 nB{0, std::cos(half), std::sin(half)};
    const std::vector<Vec3> normals = {nA, nB};
    for (int i = 1; i < 40; ++i)
    {
      const double phi = 2 * kPi * i / 40;
      for (double alongX : {0.0, 0.004, -0.007})
      {
        const Vec3 v{alongX, 0.01 * std::cos(phi), 0.01 * std::sin(phi)};
        const bool mixed = (dot(v, nA) > 0) != (dot(v, nB) > 0);
        const GoalSolution s = solveGoal(v, normals.data(), 2);
        fallbacks += mixed && s.usedExactFallback ? 1 : 0;
        EXPECT_TRUE(checkGoal(v, normals, worst)) << "opening " << opening << " phi " << phi;
      }
    }
  }
  worst.print("narrow-groove");
  // The case exists: some mixed fingers needed the exact enumeration.
  EXPECT_GT(fallbacks, 0);
}

TEST(GoalSolver, FingerInTwoPlanesToRounding)
{
  // Found by FingerAboveSomePlanes and the apex edges: the finger lies in both planes to
  // rounding (u . n ~ -1e-17), the dual points c_i n_i are ~1e17 from the origin, and GJK's
  // answer was feasible but 9 cm from the optimum for a 3.6 cm finger distance (before the KKT
  // check in solveGoal sent such answers to the exact enumeration).
  Worst worst;
  const std::vector<Vec3> normals = {{0, 0, 1}, normalizedOrZero(Vec3{-3, -2, 1})};
  EXPECT_TRUE(checkGoal({-0.02, 0.03, -1e-17}, normals, worst));
  const std::vector<Vec3> recorded = {
    {0.69252836107023874, -0.023134662174973203, -0.72101959510086766},
    {-0.5324820452820973, -0.10064561049752213, 0.84043639410711823}};
  EXPECT_TRUE(checkGoal({-0.0065789433085324178, -0.00430276393161288, -0.0061809163958047369},
                        recorded, worst));
}

TEST(GoalSolver, EnumerationAloneAgreesWithOracle)
{
  // The fallback is also a public entry point: same checks on a few thousand random problems.
  std::mt19937_64 engine(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Worst worst;
  for (int trial = 0; trial < 2000; ++trial)
  {
    const int count = 1 + trial % 8;
    const Vec3 axis = randomUnit(engine);
    std::vector<Vec3> normals;
    for (int i = 0; i < count; ++i)
    {
      normals.push_back(tilted(axis, 1.4 * std::sqrt(uniform(engine)), 2 * kPi * uniform(engine)));
    }
    const Vec3 v = randomUnit(engine) * 0.01;
    const GoalSolution s = solveGoalByEnumeration(v, normals.data(), count);
    const Vec3 exact = oracle::projectOntoCone(v, normals.data(), count);
    ++worst.cases;
    worst.displacement = std::max(worst.displacement, distance(s.displacement, exact) / 0.01);
    ASSERT_LE(distance(s.displacement, exact), kRelative * 0.01)
      << "trial " << trial << ": " << describe(v, normals);
  }
  worst.print("enumeration");
}

TEST(GoalSolver, EnumerationAtThirtyTwoPlanesAgreesWithOracle)
{
  // The fallback's worst case by design: the most planes the solver holds, a funnel whose apex
  // pins the proxy, so that no single plane or pair answers and every single and pair is tried
  // before a triple gives the depths; and random directions around it. Checked against the exact
  // QP of the oracle, through the fallback alone and through solveGoal.
  constexpr int kPlanes = kMaxConstraintPlanes;
  std::mt19937_64 engine(32);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Worst worst;
  for (double slopeDegrees : {10.0, 45.0, 80.0})
  {
    const double slope = slopeDegrees * kPi / 180.0;
    // 31 faces and one more plane, steep and facing down, to fill the 32.
    std::vector<Vec3> normals;
    for (int i = 0; i < kPlanes - 1; ++i)
    {
      const double phi = 2 * kPi * i / (kPlanes - 1);
      normals.push_back(
        {-std::sin(slope) * std::cos(phi), -std::sin(slope) * std::sin(phi), std::cos(slope)});
    }
    normals.push_back(normalizedOrZero(Vec3{1.0, 0.0, -0.1}));
    const Vec3 down{0, 0, -0.01};
    const GoalSolution pinned = solveGoalByEnumeration(down, normals.data(), kPlanes);
    EXPECT_LT(norm(pinned.displacement), 1e-14) << "slope " << slopeDegrees;
    EXPECT_GE(pinned.numActive, 2) << "slope " << slopeDegrees; // a pair or a triple pins it
    // The depths hold the finger: finger - goal = -sum mu_i n_i with mu_i >= 0.
    Vec3 held = down;
    for (int k = 0; k < pinned.numActive; ++k)
    {
      EXPECT_GE(pinned.depth[k], 0.0);
      held += normals[pinned.active[k]] * pinned.depth[k];
    }
    EXPECT_LT(norm(held), 1e-12) << "slope " << slopeDegrees;
    for (int trial = 0; trial < 200; ++trial)
    {
      const Vec3 v = Vec3{uniform(engine), uniform(engine), uniform(engine)} * 0.01;
      const GoalSolution s = solveGoalByEnumeration(v, normals.data(), kPlanes);
      const Vec3 exact = oracle::projectOntoCone(v, normals.data(), kPlanes);
      ++worst.cases;
      worst.displacement = std::max(worst.displacement, distance(s.displacement, exact) / 0.01);
      ASSERT_LE(distance(s.displacement, exact), kRelative * 0.01)
        << "slope " << slopeDegrees << ", trial " << trial << ": " << describe(v, normals);
      EXPECT_TRUE(checkGoal(v, normals, worst));
    }
  }
  worst.print("enumeration at 32 planes");
}

} // namespace
} // namespace proxima
