// Stress: a long run without drift. The finger circles 2 mm deep under a faceted sphere with a
// period of exactly 1000 ticks, so every period repeats the same finger positions; the proxy at
// each period's start must come back to where it was in the second period (to 1e-9 m), and a
// sample of ticks is checked by the oracle (clearance, gap, local-minimum residual).
//
// PROXIMA_DRIFT_TICKS sets the length: 200,000 ticks in the stress label (a few seconds), ten
// million in the nightly run, `bash Tools/stress-drift.sh` (not part of CI: about a minute of the
// solver plus the sampled oracle checks).
#include "StressSupport.h"

#include "Geometry/ProceduralMeshes.h"
#include "ProxyOracle.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>

namespace proxima::stress
{
namespace
{
TEST(StressDrift, LongRunComesBackToTheSamePlaceEveryPeriod)
{
  const char* text = std::getenv("PROXIMA_DRIFT_TICKS");
  const char* scaleText = std::getenv("PROXIMA_STRESS_SCALE");
  const double scale = scaleText != nullptr ? std::atof(scaleText) : 1.0;
  const auto ticks = static_cast<std::uint64_t>(
    text != nullptr ? std::atof(text) : 200000.0 * (scale > 0.0 ? scale : 1.0));
  constexpr std::uint64_t kPeriod = 1000;
  const double sphere = 0.04;
  const double depth = 0.002;
  // Latitude 35 degrees: the circle crosses facet edges and corners of every kind.
  const double latitude = 35.0 * std::numbers::pi / 180.0;

  TriangleSoup soup = makeIcosphere(4, sphere);
  soup.pointNormals.clear();
  const std::unique_ptr<CollisionScene> scene = scenes::makeScene(std::move(soup));
  const oracle::MeshOracle oracle(*scene);
  ProxyParameters parameters;
  parameters.radius = 0.001;
  ProxySolver solver;
  solver.setScene(scene.get(), parameters);
  const oracle::OracleSettings settings =
    oracle::OracleSettings::forScene(scene->diagonal(), solver.skin());
  const oracle::TickChecker checker(oracle, *scene, parameters, settings);

  auto fingerAt = [&](std::uint64_t tick) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(tick % kPeriod) / kPeriod;
    const double r = sphere - depth;
    return Vec3{r * std::cos(latitude) * std::cos(angle), r * std::cos(latitude) * std::sin(angle),
                r * std::sin(latitude)};
  };
  solver.resetProxy(fingerAt(0) * ((sphere + 0.01) / (sphere - depth)));

  Vec3 reference;
  double drift = 0.0;
  double minClearance = 1e300;
  double maxGap = -1e300;
  double maxResidual = 0.0;
  std::uint64_t failures = 0;
  std::uint64_t capTicks = 0;
  for (std::uint64_t tick = 0; tick < ticks; ++tick)
  {
    const Vec3 finger = fingerAt(tick);
    const ProxyTickResult result = solver.update(finger);
    capTicks += result.conditions.has(TickCondition::hitIterationCap) ? 1 : 0;
    if (tick % kPeriod == 0 && tick >= 2 * kPeriod)
    {
      if (tick == 2 * kPeriod)
      {
        reference = result.proxy;
      }
      drift = std::max(drift, distance(result.proxy, reference));
    }
    // The oracle on a sample of ticks spread over every phase (1009 is prime to the period).
    if (tick % 1009 == 0)
    {
      const double clearance =
        oracle.distance(result.proxy, 2.0 * parameters.radius) - parameters.radius;
      minClearance = std::min(minClearance, clearance);
      if (result.numContacts > 0)
      {
        maxGap = std::max(maxGap, clearance);
      }
      const double residual = checker.residual(result.proxy, finger);
      maxResidual = std::max(maxResidual, residual);
      const bool bad = clearance < -settings.penetrationTolerance ||
                       (result.numContacts > 0 && clearance > settings.gapTolerance) ||
                       !(residual <= settings.residualTolerance);
      if (bad && failures++ < 5)
      {
        ADD_FAILURE() << "tick " << tick << ": clearance " << clearance << " m, residual "
                      << residual << " m (proxy " << oracle::str(result.proxy) << ", finger "
                      << oracle::str(finger) << ")";
      }
    }
  }
  std::cout << "[stress] drift: " << ticks << " ticks, proxy at each period's start within "
            << drift << " m of the second period's; sampled min clearance " << minClearance
            << " m, max gap " << maxGap << " m, max residual " << maxResidual << " m; " << capTicks
            << " ticks at the iteration cap\n";
  testing::Test::RecordProperty("drift_m", oracle::str(drift));
  EXPECT_LE(drift, 1e-9);
  EXPECT_EQ(failures, 0u);
  EXPECT_EQ(capTicks, 0u);
}

} // namespace
} // namespace proxima::stress
