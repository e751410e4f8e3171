// The Falcon driver through the real libusb (usbfs URBs on Linux), against the emulator behind a
// umockdev usbfs node: enumeration, the firmware upload, homing, encoder frames in and motor
// command frames out through bulk transfers with FTDI status bytes, an unplug mid-session, and a
// scripted path driving the solver with the forces arriving as the expected motor commands.
#include "Devices/DeviceRegistry.h"
#include "Devices/FalconDevice.h"
#include "Devices/LibusbTransport.h"

#include "DeviceTestScene.h"
#include "Runtime/SimulatedDevice.h"
#include "UmockdevDevices.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace proxima
{
namespace
{
using namespace proxima::testing;

std::vector<std::uint8_t> firmwareImage()
{
  std::vector<std::uint8_t> image(1000);
  for (std::size_t i = 0; i < image.size(); ++i)
  {
    image[i] = static_cast<std::uint8_t>((i * 131 + 7) & 0xff);
  }
  return image;
}

class LibusbUmockdev : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_TRUE(bed.active()) << "the umockdev preload library is not active in this process";
    bed.addFalcon(emulator);
    firmwarePath = (std::filesystem::temp_directory_path() /
                    ("proxima-falcon-" + std::to_string(::getpid()) + ".bin"))
                     .string();
    std::ofstream file(firmwarePath, std::ios::binary);
    const auto image = firmwareImage();
    file.write(reinterpret_cast<const char*>(image.data()),
               static_cast<std::streamsize>(image.size()));
  }
  void TearDown() override { std::remove(firmwarePath.c_str()); }

  std::unique_ptr<FalconDevice> openFalcon(const Vec3& worldOffset = {})
  {
    std::string error;
    auto transport = openFtdiTransport(0x0403, 0xcb48, error);
    EXPECT_TRUE(transport) << error;
    if (!transport)
    {
      return nullptr;
    }
    FalconSettings settings;
    settings.firmwarePath = firmwarePath;
    settings.worldOffset = worldOffset;
    auto device = std::make_unique<FalconDevice>(std::move(transport), settings);
    EXPECT_TRUE(device->open(error)) << error;
    return device;
  }

  UmockdevBed bed;
  FalconEmulator emulator{firmwareImage(), 2};
  std::string firmwarePath;
};

TEST_F(LibusbUmockdev, EnumeratesTheFalcon)
{
  const auto devices = enumerateUsbDevices(0x0403, 0xcb48);
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0].bus, 1);
  EXPECT_EQ(devices[0].address, 2);
  const auto connected = listConnectedDevices();
  ASSERT_EQ(connected.size(), 1u);
  EXPECT_EQ(connected[0].name, "falcon");
}

TEST_F(LibusbUmockdev, UploadsHomesAndReportsThePosition)
{
  auto device = openFalcon({0.0, 0.0, 0.0});
  ASSERT_TRUE(device);
  EXPECT_EQ(emulator.stage(), FalconEmulator::Stage::Running);
  EXPECT_TRUE(emulator.firmwareMatched());
  const Vec3 offset{0.004, -0.008, 0.012};
  emulator.setGripPosition(device->neutral() + offset);
  DeviceSample sample;
  for (int tick = 0; tick < 6; ++tick)
  {
    sample = device->read(tick * 0.001);
    device->writeForce({0.0, 0.0, 1.0}, tick * 0.001);
  }
  ASSERT_TRUE(device->homed());
  ASSERT_TRUE(sample.valid);
  EXPECT_LT(distance(sample.position, offset), 1e-4);
  const FalconFrame last = emulator.commandFrames().back();
  const auto expected = device->commandsFromTorques(
    DeltaKinematics().torques(device->anglesFromCounts(device->lastEncoders()), {0.0, 0.0, 1.0}));
  EXPECT_EQ(last.values, expected);
}

TEST_F(LibusbUmockdev, OpenedByNameWithAndWithoutFirmware)
{
  DeviceOptions options;
  options.path.append(0.0, {0.0, 0.0, 0.0});
  std::string error;
  EXPECT_FALSE(openDevice("falcon", options, error));
  EXPECT_NE(error.find("--falcon-firmware"), std::string::npos) << error;
  options.falconFirmware = firmwarePath;
  auto device = openDevice("falcon", options, error);
  ASSERT_TRUE(device) << error;
  EXPECT_STREQ(device->name(), "falcon");
  EXPECT_TRUE(emulator.firmwareMatched());
}

TEST_F(LibusbUmockdev, UnplugMidSessionGivesDisconnectedSamples)
{
  auto device = openFalcon();
  ASSERT_TRUE(device);
  emulator.setGripPosition(device->neutral());
  for (int tick = 0; tick < 4; ++tick)
  {
    device->read(tick * 0.001);
    device->writeForce({}, tick * 0.001);
  }
  ASSERT_TRUE(device->read(0.004).valid);
  bed.unplugFalcon();
  device->writeForce({1.0, 0.0, 0.0}, 0.004);
  for (int tick = 5; tick < 8; ++tick)
  {
    const DeviceSample sample = device->read(tick * 0.001);
    EXPECT_FALSE(sample.connected);
    EXPECT_FALSE(sample.valid);
    device->writeForce({1.0, 0.0, 0.0}, tick * 0.001);
  }
}

TEST_F(LibusbUmockdev, ScriptedPathDrivesTheSolverAndForcesReachTheMotors)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  auto falcon = openFalcon(path.positions.front());
  ASSERT_TRUE(falcon);
  const std::size_t framesBefore = emulator.commandFrames().size();
  std::size_t hint = 0;
  DrivenDevice device(*falcon, [&](double time) {
    emulator.setGripPosition(path.positionAt(time, hint) - path.positions.front() +
                             falcon->neutral());
  });
  const auto trace = scene.run(device, path);
  EXPECT_GT(contactTicks(trace), 100u);
  SimulatedDevice simulated(path);
  const auto reference = scene.run(simulated, path);
  ASSERT_EQ(trace.size(), reference.size());
  const auto frames = emulator.commandFrames();
  ASSERT_EQ(frames.size(), framesBefore + trace.size());
  const DeltaKinematics kinematics;
  std::size_t compared = 0;
  std::size_t nonZero = 0;
  for (std::size_t i = 0; i < trace.size(); ++i)
  {
    if (trace[i].conditions.has(TickCondition::fingerRefused))
    {
      continue; // homing
    }
    ++compared;
    // The device's frame answers the previous tick's command: its encoders are one tick old
    // (at tick 0, those of the path's start, where the grip rests before the run).
    EXPECT_LT(distance(trace[i].finger, reference[i == 0 ? 0 : i - 1].finger), 1e-4) << i;
    const auto counts = falcon->countsFromAngles(
      *kinematics.inverse(trace[i].finger - path.positions.front() + falcon->neutral()));
    const auto expected = falcon->commandsFromTorques(
      kinematics.torques(falcon->anglesFromCounts(counts), trace[i].force));
    for (std::size_t joint = 0; joint < 3; ++joint)
    {
      EXPECT_NEAR(frames[framesBefore + i].values[joint], expected[joint], 1.0) << "tick " << i;
      nonZero += frames[framesBefore + i].values[joint] != 0 ? 1 : 0;
    }
  }
  EXPECT_GT(compared, trace.size() - 5);
  EXPECT_GT(nonZero, 300u);
}

TEST_F(LibusbUmockdev, UnplugMidStrokeFadesTheForceAndReportsIt)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  auto falcon = openFalcon(path.positions.front());
  ASSERT_TRUE(falcon);
  std::size_t hint = 0;
  std::size_t tick = 0;
  DrivenDevice device(*falcon, [&](double time) {
    if (tick++ == kUnplugTick)
    {
      bed.unplugFalcon();
    }
    emulator.setGripPosition(path.positionAt(time, hint) - path.positions.front() +
                             falcon->neutral());
  });
  expectFadeOut(scene.run(device, path), kUnplugTick);
  EXPECT_FALSE(falcon->connected());
}

} // namespace
} // namespace proxima
