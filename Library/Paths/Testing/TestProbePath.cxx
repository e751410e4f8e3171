// The probe path of PathGenerators.h against an independent oracle: on a faceted sphere the
// depth of a row is measured from the analytic sphere, not from the mesh the generator used.
#include "Geometry/ProceduralMeshes.h"
#include "Paths/PathGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace proxima
{
namespace
{
constexpr double kSphereRadius = 0.05;
const Vec3 kSphereCenter{0.12, -0.3, 0.07};

// Rodrigues' rotation, so that the icosphere's own axes (its poles on z) are not the world's.
Vec3 rotate(const Vec3& v, const Vec3& unitAxis, double angle)
{
  return v * std::cos(angle) + cross(unitAxis, v) * std::sin(angle) +
         unitAxis * (dot(unitAxis, v) * (1.0 - std::cos(angle)));
}

TriangleMesh tiltedSphere()
{
  TriangleSoup soup = makeIcosphere(5, kSphereRadius);
  const Vec3 axis = normalizedOrZero(Vec3{1, 2, 3});
  for (Vec3& p : soup.points)
  {
    p = kSphereCenter + rotate(p, axis, 0.7);
  }
  soup.pointNormals.clear();
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(std::move(soup), error)) << error.message;
  return mesh;
}

// How far a point is inside the analytic sphere (negative outside).
double depthInSphere(const Vec3& p)
{
  return kSphereRadius - distance(p, kSphereCenter);
}

// The facets lie inside the round sphere by up to about edge^2 / (6 R): 9 um for 20,480 facets
// of a 5 cm sphere; the oracle allows a little over twice that.
constexpr double kFacetTolerance = 25e-6;

struct Probe
{
  FingerPath path;
  std::vector<ProbePhase> phases;
};

Probe probe(const TriangleMesh& mesh, std::uint64_t seed)
{
  ProbeOptions options;
  options.seed = seed;
  Probe result;
  result.path = makeProbePath(mesh, options, &result.phases);
  return result;
}

TEST(ProbePath, SameSeedGivesTheSamePath)
{
  const TriangleMesh mesh = tiltedSphere();
  const Probe a = probe(mesh, 42);
  const Probe b = probe(mesh, 42);
  ASSERT_EQ(a.path.size(), b.path.size());
  EXPECT_EQ(a.path.times, b.path.times);
  for (std::size_t i = 0; i < a.path.size(); ++i)
  {
    ASSERT_EQ(a.path.positions[i], b.path.positions[i]) << i;
  }
  EXPECT_EQ(a.phases, b.phases);
}

TEST(ProbePath, DifferentSeedsGiveDifferentPaths)
{
  const TriangleMesh mesh = tiltedSphere();
  const Probe a = probe(mesh, 1);
  const Probe b = probe(mesh, 2);
  EXPECT_NE(a.path.positions.front(), b.path.positions.front());
  const std::size_t n = std::min(a.path.size(), b.path.size());
  std::size_t same = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    same += a.path.positions[i] == b.path.positions[i] ? 1 : 0;
  }
  EXPECT_LT(same, n / 100);
}

TEST(ProbePath, RowsAreAtTheRate)
{
  const TriangleMesh mesh = tiltedSphere();
  const Probe p = probe(mesh, 7);
  ASSERT_EQ(p.phases.size(), p.path.size());
  EXPECT_GE(p.path.endTime(), ProbeOptions{}.duration);
  EXPECT_EQ(p.path.times.front(), 0.0);
  for (std::size_t i = 1; i < p.path.size(); ++i)
  {
    ASSERT_GT(p.path.times[i], p.path.times[i - 1]) << i;
    ASSERT_NEAR(p.path.times[i] - p.path.times[i - 1], 1e-3, 1e-12) << i;
  }
}

// Every documented range, on several seeds, on a sphere whose "up" is not z.
TEST(ProbePath, OnATiltedSphereEveryPhaseKeepsItsRanges)
{
  const TriangleMesh mesh = tiltedSphere();
  const ProbeOptions defaults;
  std::size_t strokes = 0;
  std::size_t jabs = 0;
  std::size_t wanders = 0;
  std::size_t pressedRows = 0;
  Vec3 pressSideSum;
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
  {
    const Probe p = probe(mesh, seed);
    const FingerPath& path = p.path;
    ASSERT_EQ(p.phases.size(), path.size());
    double strokeLength = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
      const ProbePhase phase = p.phases[i];
      const ProbePhase previous = i > 0 ? p.phases[i - 1] : ProbePhase::Transit;
      const double depth = depthInSphere(path.positions[i]);
      if (phase == ProbePhase::Stroke || phase == ProbePhase::Dwell)
      {
        ++pressedRows;
        pressSideSum += path.positions[i] - kSphereCenter;
        ASSERT_GE(depth, defaults.pressDepthMin - kFacetTolerance)
          << "seed " << seed << " row " << i;
        ASSERT_LE(depth, defaults.pressDepthMax + kFacetTolerance)
          << "seed " << seed << " row " << i;
      }
      if (phase == ProbePhase::Approach && previous != ProbePhase::Approach)
      {
        // The row before an approach is where it starts: outside by the approach distance.
        ASSERT_GT(i, 0u);
        const double outside = -depthInSphere(path.positions[i - 1]);
        EXPECT_GE(outside, defaults.approachDistanceMin - kFacetTolerance) << seed << " " << i;
        EXPECT_LE(outside, defaults.approachDistanceMax + kFacetTolerance) << seed << " " << i;
      }
      if (phase == ProbePhase::Stroke && previous == ProbePhase::Stroke)
      {
        const double speed =
          distance(path.positions[i], path.positions[i - 1]) / (path.times[i] - path.times[i - 1]);
        ASSERT_GE(speed, defaults.strokeSpeedMin * (1 - 2e-3)) << seed << " " << i;
        ASSERT_LE(speed, defaults.strokeSpeedMax * (1 + 2e-3)) << seed << " " << i;
        strokeLength += distance(path.positions[i], path.positions[i - 1]);
      }
      if (phase == ProbePhase::Stroke &&
          (i + 1 == path.size() || p.phases[i + 1] != ProbePhase::Stroke))
      {
        // On a smooth sphere no stroke is cut short (by more than one step of 0.5 mm at most).
        ++strokes;
        EXPECT_GE(strokeLength, defaults.strokeLengthMin - 0.5e-3) << seed << " " << i;
        EXPECT_LE(strokeLength, defaults.strokeLengthMax) << seed << " " << i;
        strokeLength = 0.0;
      }
      if (phase == ProbePhase::Jab && previous != ProbePhase::Jab)
      {
        ++jabs;
      }
      if (phase == ProbePhase::Wander)
      {
        wanders += previous != ProbePhase::Wander ? 1 : 0;
      }
      if (i > 0 && phase == ProbePhase::Jab)
      {
        const double speed = distance(path.positions[i], path.positions[i - 1]) * 1e3;
        EXPECT_LE(speed, defaults.jabSpeedMax * (1 + 1e-9));
      }
      if (phase == ProbePhase::Transit)
      {
        // Between episodes the finger stays off the sphere (a straight move is taken only when
        // it crosses no facet; else it goes round).
        EXPECT_LT(depth, kFacetTolerance) << seed << " " << i;
      }
    }
  }
  EXPECT_GT(strokes, 20u);
  EXPECT_GT(jabs, 0u);
  EXPECT_GT(wanders, 0u);
  // Presses all round the sphere, not on one side: their mean offset is small against R.
  EXPECT_LT(norm(pressSideSum / static_cast<double>(pressedRows)), 0.5 * kSphereRadius);
}

TEST(ProbePath, WanderGoesThroughTheObject)
{
  const TriangleMesh mesh = tiltedSphere();
  ProbeOptions options;
  options.jabFraction = 0.0;
  options.wanderFraction = 1.0;
  options.duration = 1.0;
  std::vector<ProbePhase> phases;
  const FingerPath path = makeProbePath(mesh, options, &phases);
  double deepest = 0.0;
  for (std::size_t i = 0; i < path.size(); ++i)
  {
    if (phases[i] == ProbePhase::Wander)
    {
      deepest = std::max(deepest, depthInSphere(path.positions[i]));
    }
  }
  EXPECT_GT(deepest, 0.9 * kSphereRadius);
}

TEST(ProbePath, RefusesOptionsOutOfOrder)
{
  const TriangleMesh mesh = tiltedSphere();
  ProbeOptions options;
  options.pressDepthMin = 0.006;
  EXPECT_THROW(makeProbePath(mesh, options), std::invalid_argument);
  options = ProbeOptions{};
  options.rate = 0.0;
  EXPECT_THROW(makeProbePath(mesh, options), std::invalid_argument);
  options = ProbeOptions{};
  options.jabFraction = 0.7;
  options.wanderFraction = 0.5;
  EXPECT_THROW(makeProbePath(mesh, options), std::invalid_argument);
  EXPECT_THROW(makeProbePath(std::vector<ProbeSurface>{}, ProbeOptions{}), std::invalid_argument);
}
} // namespace
} // namespace proxima
