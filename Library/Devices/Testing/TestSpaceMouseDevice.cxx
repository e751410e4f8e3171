// The SpaceMouse driver against its emulator through an in-memory transport: the cap's counts
// become the finger position (or velocity) by the documented scale and axis map, buttons and the
// LED pass, malformed reports are refused and counted, and an unplug is a disconnected sample.
#include "Devices/SpaceMouseDevice.h"

#include "FakeTransports.h"

#include <gtest/gtest.h>

namespace proxima
{
namespace
{
using testing::FakeReportTransport;
using testing::SpaceMouseEmulator;

SpaceMouseSettings settingsFor(SpaceMouseLayout layout)
{
  SpaceMouseSettings settings;
  settings.layout = layout;
  settings.centre = {0.1, 0.2, 0.3};
  settings.metresPerCount = 1e-4;
  return settings;
}

TEST(SpaceMouseDevice, PositionModeScalesAndMapsTheAxes)
{
  for (SpaceMouseLayout layout : {SpaceMouseLayout::SplitReports, SpaceMouseLayout::SixAxisReport})
  {
    SpaceMouseEmulator emulator(layout);
    SpaceMouseDevice device(std::make_unique<FakeReportTransport>(emulator), settingsFor(layout));
    DeviceSample sample = device.read(0.0);
    EXPECT_TRUE(sample.valid);
    EXPECT_EQ(sample.position, (Vec3{0.1, 0.2, 0.3}));
    emulator.setAxes({100, -50, 200}, {0, 0, 0});
    sample = device.read(0.001);
    // World z is the device's z reversed (pushing the cap down moves the finger down).
    EXPECT_NEAR(sample.position.x, 0.1 + 100e-4, 1e-15);
    EXPECT_NEAR(sample.position.y, 0.2 - 50e-4, 1e-15);
    EXPECT_NEAR(sample.position.z, 0.3 - 200e-4, 1e-15);
    EXPECT_EQ(device.refusedReports(), 0u);
  }
}

TEST(SpaceMouseDevice, RateModeIntegratesOnTheRuntimeClock)
{
  SpaceMouseEmulator emulator(SpaceMouseLayout::SplitReports);
  SpaceMouseSettings settings = settingsFor(SpaceMouseLayout::SplitReports);
  settings.rateMode = true;
  settings.metresPerSecondPerCount = 1e-3;
  SpaceMouseDevice device(std::make_unique<FakeReportTransport>(emulator), settings);
  device.read(0.0);
  emulator.setAxes({10, 0, 0}, {0, 0, 0});
  device.read(0.0);
  // 10 counts x 1e-3 m/s per count for 0.5 s = 5 mm.
  const DeviceSample sample = device.read(0.5);
  EXPECT_NEAR(sample.position.x, 0.1 + 0.005, 1e-15);
  // Clamped to the half range.
  EXPECT_NEAR(device.read(100.0).position.x, 0.1 + settings.halfRange, 1e-15);
}

TEST(SpaceMouseDevice, ButtonsRotationAndLed)
{
  SpaceMouseEmulator emulator(SpaceMouseLayout::SplitReports);
  SpaceMouseDevice device(std::make_unique<FakeReportTransport>(emulator),
                          settingsFor(SpaceMouseLayout::SplitReports));
  emulator.setButtons(0x3);
  emulator.setAxes({0, 0, 0}, {0, 0, 350});
  const DeviceSample sample = device.read(0.0);
  EXPECT_EQ(sample.buttons, 0x3u);
  ASSERT_TRUE(sample.hasOrientation);
  // 350 counts x 0.5/350 rad per count about world -z (the device's z reversed): 0.5 rad.
  EXPECT_NEAR(sample.orientation[0], std::cos(0.25), 1e-12);
  EXPECT_NEAR(sample.orientation[3], -std::sin(0.25), 1e-12);
  EXPECT_TRUE(device.setLed(true));
  EXPECT_TRUE(emulator.ledOn());
  EXPECT_TRUE(device.setLed(false));
  EXPECT_FALSE(emulator.ledOn());
}

TEST(SpaceMouseDevice, MalformedReportsAreRefusedNotTrusted)
{
  SpaceMouseEmulator emulator(SpaceMouseLayout::SixAxisReport);
  SpaceMouseDevice device(std::make_unique<FakeReportTransport>(emulator),
                          settingsFor(SpaceMouseLayout::SixAxisReport));
  emulator.setAxes({10, 20, 30}, {0, 0, 0});
  const Vec3 before = device.read(0.0).position;
  // A short report 1 (a split-layout report on a six-axis device) and an unknown ID.
  emulator.queueRaw({0x01, 0xff, 0x7f, 0xff, 0x7f, 0xff, 0x7f});
  emulator.queueRaw({0x09, 0x00});
  const DeviceSample after = device.read(0.001);
  EXPECT_TRUE(after.valid);
  EXPECT_EQ(after.position, before);
  EXPECT_EQ(device.refusedReports(), 2u);
  EXPECT_EQ(device.lastError(), "unknown report ID 9");
}

TEST(SpaceMouseDevice, UnplugIsADisconnectedSampleNotACrash)
{
  SpaceMouseEmulator emulator(SpaceMouseLayout::SplitReports);
  SpaceMouseDevice device(std::make_unique<FakeReportTransport>(emulator),
                          settingsFor(SpaceMouseLayout::SplitReports));
  EXPECT_TRUE(device.read(0.0).connected);
  emulator.unplug();
  for (int tick = 1; tick < 5; ++tick)
  {
    const DeviceSample sample = device.read(tick * 0.001);
    EXPECT_FALSE(sample.connected);
    EXPECT_FALSE(sample.valid);
  }
  device.writeForce({1, 2, 3}, 0.005);
  EXPECT_FALSE(device.setLed(true));
}

} // namespace
} // namespace proxima
