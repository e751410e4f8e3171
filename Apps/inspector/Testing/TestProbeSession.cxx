// Clearance by touch (ProbeMeter, ProbeSession) on two 10 mm blocks with a 2 mm slot between them
// (gap-blocks.obj: x from -11 to -1 mm and from 1 to 11 mm, z from 0 to 10 mm), where every
// figure is known in closed form: markers on the facing walls are the slot's width apart, the
// narrowest gap the probe passes through is the slot, a finger pushed into a wall leaves the
// proxy one radius off it, and a tool wider than the slot rests on its rims.
#include "Probing/ProbeMeter.h"
#include "Probing/ProbeSession.h"

#include "Geometry/ProceduralMeshes.h"
#include "IO/InputChecks/InputError.h"
#include "IO/PathAndTrace/FingerPathFile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace proxima::inspector
{
namespace
{
const std::string kTesting = PROXIMA_SOURCE_DIR "/Apps/inspector/Testing";
constexpr double kGap = 0.002;

ScriptedRunSettings slotSettings(double toolRadius)
{
  ScriptedRunSettings settings;
  settings.mesh = kTesting + "/gap-blocks.obj";
  settings.scale = 0.001;
  settings.radius = toolRadius;
  settings.stiffness = 1000.0;
  settings.path = "the test's path";
  return settings;
}

ProbeMeterSettings meterFor(double toolRadius)
{
  ProbeMeterSettings settings;
  settings.stopDepth = 0.5 * toolRadius;
  return settings;
}

TEST(ProbeSession, MarkersOnTheFacingWallsAreTheSlotApartAndTheGapIsTheSlot)
{
  // Down into the slot, pushed into the left wall (marked at 1.9 s), then the right one (2.9 s),
  // and out (gap-probe.csv, gap-marks.csv).
  const double radius = 0.0005;
  const FingerPath path = readFingerPathFile(kTesting + "/gap-probe.csv");
  const ProbeMeasurements m =
    playProbeSession(slotSettings(radius), path, {1.9, 2.9}, meterFor(radius));
  ASSERT_EQ(m.markers.size(), 2u);
  EXPECT_EQ(m.marksMissed, 0u);
  EXPECT_NEAR(m.markers[0].point.x, -kGap / 2, 1e-12);
  EXPECT_NEAR(m.markers[1].point.x, kGap / 2, 1e-12);
  EXPECT_NEAR(m.markers[0].normal.x, 1.0, 1e-12);
  EXPECT_NEAR(m.markers[1].normal.x, -1.0, 1e-12);
  ASSERT_EQ(m.distances.size(), 1u);
  EXPECT_NEAR(m.distances[0].distance, kGap, 1e-12);
  EXPECT_NEAR(m.distances[0].across, kGap, 1e-12);
  ASSERT_TRUE(m.narrowestGap.has_value());
  EXPECT_NEAR(m.narrowestGap->width, kGap, 1e-12);
  EXPECT_NEAR(m.narrowestGap->wall.x, -kGap / 2, 1e-12);
  EXPECT_NEAR(m.narrowestGap->across.x, kGap / 2, 1e-12);
  // Pushed 3 mm past the middle into each wall: the proxy one radius off it, the finger 2.5 mm
  // beyond the proxy.
  ASSERT_EQ(m.stopCount, 2u);
  ASSERT_EQ(m.stops.size(), 2u);
  EXPECT_NEAR(m.stops[0].proxy.x, -kGap / 2 + radius, 1e-9);
  EXPECT_NEAR(m.stops[1].proxy.x, kGap / 2 - radius, 1e-9);
  EXPECT_NEAR(m.stops[0].depth, 0.003 - (kGap / 2 - radius), 1e-9);
  EXPECT_LT(m.stops[0].endTime, m.stops[1].startTime);
  EXPECT_NEAR(m.deepestPress, 0.0025, 1e-9);
}

TEST(ProbeSession, AToolWiderThanTheSlotRestsOnItsRimsAndCannotReachItsFloor)
{
  // A 1.2 mm ball over a 2 mm slot: it touches both rims (x = -1 and 1 mm, z = 10 mm) with its
  // centre sqrt(R^2 - (gap/2)^2) above them, and the finger's 5 mm below is never reached.
  const double radius = 0.0012;
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.015});
  path.append(1.0, {0.0, 0.0, 0.005});
  path.append(1.5, {0.0, 0.0, 0.005});
  const ProbeMeasurements m = playProbeSession(slotSettings(radius), path, {1.4}, meterFor(radius));
  ASSERT_EQ(m.stopCount, 1u);
  const double rest = 0.010 + std::sqrt(radius * radius - kGap * kGap / 4);
  EXPECT_NEAR(m.stops[0].proxy.x, 0.0, 1e-9);
  EXPECT_NEAR(m.stops[0].proxy.z, rest, 1e-9);
  EXPECT_NEAR(m.stops[0].depth, rest - 0.005, 1e-9);
  // The marker is a rim, where the ball touches.
  ASSERT_EQ(m.markers.size(), 1u);
  EXPECT_NEAR(std::abs(m.markers[0].point.x), kGap / 2, 1e-9);
  EXPECT_NEAR(m.markers[0].point.z, 0.010, 1e-9);
}

TEST(ProbeMeter, AMarkInFreeSpaceIsMissedAndAPlateHasNoGap)
{
  CollisionScene scene;
  TriangleMesh plate;
  MeshError error;
  ASSERT_TRUE(plate.build(makeGrid(0.1, 4), error));
  scene.addObject(std::move(plate));
  ProbeMeter meter(scene, ProbeMeterSettings{});
  EXPECT_FALSE(meter.mark());
  HapticState free;
  free.time = 0.0;
  free.finger = free.proxy = {0.0, 0.0, 0.01};
  free.proxyRadius = 0.001;
  meter.addTick(free);
  EXPECT_FALSE(meter.mark());
  EXPECT_EQ(meter.measurements().marksMissed, 2u);
  // Resting on the plate: nothing across it, so no gap; pressed past the stop depth, one stop.
  HapticState resting = free;
  resting.time = 0.001;
  resting.proxy = {0.0, 0.0, 0.001};
  resting.finger = {0.0, 0.0, -0.002};
  resting.numContacts = 1;
  resting.contacts[0].point = {0.0, 0.0, 0.0};
  resting.contacts[0].normal = {0.0, 0.0, 1.0};
  meter.addTick(resting);
  EXPECT_TRUE(meter.mark());
  const ProbeMeasurements& m = meter.measurements();
  EXPECT_FALSE(m.narrowestGap.has_value());
  EXPECT_EQ(m.stopCount, 1u);
  EXPECT_NEAR(m.stops[0].depth, 0.003, 1e-15);
  ASSERT_EQ(m.markers.size(), 1u);
  EXPECT_TRUE(m.distances.empty());
}

TEST(ProbeSession, AMeshThatCannotBeReadIsNamed)
{
  ScriptedRunSettings settings = slotSettings(0.0005);
  settings.mesh = kTesting + "/no-such-part.stl";
  FingerPath path;
  path.append(0.0, {0.0, 0.0, 0.015});
  try
  {
    playProbeSession(settings, path, {}, ProbeMeterSettings{});
    FAIL() << "a missing part was played";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("no-such-part.stl"), std::string::npos)
      << error.what();
  }
}

} // namespace
} // namespace proxima::inspector
