// The SpaceMouse driver through the real hidapi hidraw backend, against the emulator behind a
// umockdev hidraw node: enumeration (udev and sysfs), the report descriptor from sysfs, reports
// in and the LED report out through read()/write() on the node, malformed reports refused, an
// unplug mid-session, and a scripted path driving the solver.
#include "Devices/DeviceRegistry.h"
#include "Devices/HidapiTransport.h"
#include "Devices/SpaceMouseDevice.h"

#include "DeviceTestScene.h"
#include "Runtime/SimulatedDevice.h"
#include "UmockdevDevices.h"

#include <gtest/gtest.h>

#include <cmath>

namespace proxima
{
namespace
{
using namespace proxima::testing;

class HidapiUmockdev : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_TRUE(bed.active()) << "the umockdev preload library is not active in this process";
    bed.addHidraw(emulator, 0x046d, 0xc626, "SpaceNavigator");
  }

  /// The SpaceMouse opened as the registry opens it, by name.
  std::unique_ptr<SpaceMouseDevice> openByHand(const SpaceMouseSettings& settings)
  {
    std::string error;
    auto transport = openHidapiTransport("/dev/hidraw0", error);
    EXPECT_TRUE(transport) << error;
    return std::make_unique<SpaceMouseDevice>(std::move(transport), settings);
  }

  UmockdevBed bed;
  SpaceMouseEmulator emulator{SpaceMouseLayout::SplitReports};
};

TEST_F(HidapiUmockdev, EnumeratesAndReadsTheDescriptorFromSysfs)
{
  const auto devices = enumerateHidDevices();
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0].path, "/dev/hidraw0");
  EXPECT_EQ(devices[0].vendorId, 0x046d);
  EXPECT_EQ(devices[0].productId, 0xc626);
  EXPECT_EQ(devices[0].product, "SpaceNavigator");
  std::string error;
  const auto descriptor = readHidReportDescriptor(devices[0].path, error);
  ASSERT_TRUE(descriptor) << error;
  EXPECT_EQ(*descriptor, emulator.reportDescriptor());
  EXPECT_EQ(spaceMouseLayoutFromDescriptor(*descriptor, error), SpaceMouseLayout::SplitReports);
  const auto connected = listConnectedDevices();
  ASSERT_EQ(connected.size(), 1u);
  EXPECT_EQ(connected[0].name, "spacemouse");
  EXPECT_NE(connected[0].description.find("046d:c626"), std::string::npos);
}

TEST_F(HidapiUmockdev, ReportsInLedOutMalformedRefused)
{
  SpaceMouseSettings settings;
  settings.metresPerCount = 1e-4;
  auto device = openByHand(settings);
  emulator.setAxes({100, 200, -300}, {0, 0, 0});
  emulator.setButtons(0x2);
  DeviceSample sample = device->read(0.0);
  ASSERT_TRUE(sample.valid);
  EXPECT_NEAR(sample.position.x, 0.01, 1e-15);
  EXPECT_NEAR(sample.position.y, 0.02, 1e-15);
  EXPECT_NEAR(sample.position.z, 0.03, 1e-15);
  EXPECT_EQ(sample.buttons, 0x2u);
  EXPECT_TRUE(device->setLed(true));
  EXPECT_TRUE(emulator.ledOn());
  // A report cut short and one of an unknown ID: refused, the position kept.
  emulator.queueRaw({0x01, 0x10});
  emulator.queueRaw({0x42, 0x00, 0x00});
  sample = device->read(0.001);
  EXPECT_EQ(device->refusedReports(), 2u);
  EXPECT_NEAR(sample.position.x, 0.01, 1e-15);
}

TEST_F(HidapiUmockdev, OpenedByNameThroughTheRegistry)
{
  DeviceOptions options;
  options.path.append(0.0, {0.5, 0.5, 0.5});
  std::string error;
  auto device = openDevice("spacemouse", options, error);
  ASSERT_TRUE(device) << error;
  EXPECT_STREQ(device->name(), "spacemouse");
  // The registry switches the LED on and centres the device on the path's start.
  EXPECT_TRUE(emulator.ledOn());
  EXPECT_EQ(device->read(0.0).position, (Vec3{0.5, 0.5, 0.5}));
}

TEST_F(HidapiUmockdev, UnplugMidSessionGivesDisconnectedSamples)
{
  auto device = openByHand(SpaceMouseSettings{});
  emulator.setAxes({10, 0, 0}, {0, 0, 0});
  EXPECT_TRUE(device->read(0.0).connected);
  bed.unplugHidraw();
  for (int tick = 1; tick < 4; ++tick)
  {
    const DeviceSample sample = device->read(tick * 0.001);
    EXPECT_FALSE(sample.connected);
    EXPECT_FALSE(sample.valid);
  }
  EXPECT_FALSE(device->setLed(false));
  EXPECT_TRUE(enumerateHidDevices().empty());
}

TEST_F(HidapiUmockdev, ScriptedPathDrivesTheSolver)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  SpaceMouseSettings settings;
  settings.centre = path.positions.front();
  settings.metresPerCount = 1e-5;
  auto spaceMouse = openByHand(settings);
  std::size_t hint = 0;
  DrivenDevice device(*spaceMouse, [&](double time) {
    emulator.holdCapAt(path.positionAt(time, hint) - settings.centre, settings.metresPerCount);
  });
  const auto trace = scene.run(device, path);
  SimulatedDevice simulated(path);
  const auto reference = scene.run(simulated, path);
  expectFollowsReference(trace, reference);
  EXPECT_EQ(spaceMouse->refusedReports(), 0u);
}

TEST_F(HidapiUmockdev, UnplugMidStrokeFadesTheForceAndReportsIt)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  SpaceMouseSettings settings;
  settings.centre = path.positions.front();
  settings.metresPerCount = 1e-5;
  auto spaceMouse = openByHand(settings);
  std::size_t hint = 0;
  std::size_t tick = 0;
  DrivenDevice device(*spaceMouse, [&](double time) {
    if (tick++ == kUnplugTick)
    {
      bed.unplugHidraw();
    }
    emulator.holdCapAt(path.positionAt(time, hint) - settings.centre, settings.metresPerCount);
  });
  expectFadeOut(scene.run(device, path), kUnplugTick);
}

// A newer device (vendor 256f) whose descriptor announces six axes in report 1: the registry
// reads the descriptor from sysfs and picks the layout from it.
TEST(HidapiUmockdevSixAxis, LayoutComesFromTheDescriptorInSysfs)
{
  UmockdevBed bed;
  ASSERT_TRUE(bed.active());
  SpaceMouseEmulator emulator(SpaceMouseLayout::SixAxisReport);
  bed.addHidraw(emulator, 0x256f, 0xc635, "SpaceMouse Compact");
  DeviceOptions options;
  options.path.append(0.0, {0.0, 0.0, 0.0});
  std::string error;
  auto device = openDevice("spacemouse", options, error);
  ASSERT_TRUE(device) << error;
  emulator.setAxes({350, 0, 0}, {0, 0, 0});
  const DeviceSample sample = device->read(0.0);
  ASSERT_TRUE(sample.valid);
  // 350 counts at the default 0.05 m per 350 counts; read with the split layout, this 13-byte
  // report would still give x, so check the rotation too.
  EXPECT_NEAR(sample.position.x, 0.05, 1e-15);
  emulator.setAxes({0, 0, 0}, {0, 0, 350});
  const DeviceSample turned = device->read(0.001);
  EXPECT_NEAR(turned.orientation[3], -std::sin(0.25), 1e-12);
  EXPECT_EQ(dynamic_cast<SpaceMouseDevice&>(*device).refusedReports(), 0u);
}

} // namespace
} // namespace proxima
