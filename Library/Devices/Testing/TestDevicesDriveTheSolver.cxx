// A scripted finger path drives the solver through each device: the simulated device, the replay
// of its recording, the SpaceMouse driver on its emulator and the Falcon driver on its emulator
// (in-memory transports here; TestHidapiUmockdev and TestLibusbUmockdev do the same through the
// real hidapi and libusb). The drivers' traces follow the simulated one within the devices'
// quantization, and the forces reach the emulated Falcon as the motor commands J^T F.
#include "Devices/FalconDevice.h"
#include "Devices/FtdiRequests.h"
#include "Devices/ReplayDevice.h"
#include "Devices/SpaceMouseDevice.h"

#include "DeviceTestScene.h"
#include "FakeTransports.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace proxima
{
namespace
{
using namespace proxima::testing;

TEST(DevicesDriveTheSolver, SimulatedAndReplay)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  SimulatedDevice simulated(path);
  RecordingDevice recording(simulated, 400);
  const auto simulatedTrace = scene.run(recording, path);
  EXPECT_GT(contactTicks(simulatedTrace), 100u);
  ReplayDevice replay(recording.samples());
  const auto replayTrace = scene.run(replay, path);
  ASSERT_EQ(replayTrace.size(), simulatedTrace.size());
  for (std::size_t i = 0; i < replayTrace.size(); ++i)
  {
    EXPECT_EQ(replayTrace[i].force, simulatedTrace[i].force) << i;
  }
}

TEST(DevicesDriveTheSolver, SpaceMouseOnItsEmulator)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  SpaceMouseEmulator emulator(SpaceMouseLayout::SixAxisReport);
  SpaceMouseSettings settings;
  settings.layout = SpaceMouseLayout::SixAxisReport;
  settings.centre = path.positions.front();
  settings.metresPerCount = 1e-5;
  SpaceMouseDevice spaceMouse(std::make_unique<FakeReportTransport>(emulator), settings);
  std::size_t hint = 0;
  // The hand moves the cap so that the finger follows the path: counts = offset / scale, with
  // the z axis reversed.
  DrivenDevice device(spaceMouse, [&](double time) {
    emulator.holdCapAt(path.positionAt(time, hint) - settings.centre, settings.metresPerCount);
  });
  const auto trace = scene.run(device, path);
  SimulatedDevice simulated(path);
  const auto reference = scene.run(simulated, path);
  expectFollowsReference(trace, reference);
  EXPECT_EQ(spaceMouse.refusedReports(), 0u);
}

TEST(DevicesDriveTheSolver, FalconOnItsEmulatorAndItsMotorCommands)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  const std::vector<std::uint8_t> image(200, 0x5a);
  FalconEmulator emulator(image, 1);
  const std::string firmware = (std::filesystem::temp_directory_path() /
                                ("proxima-solver-falcon-" + std::to_string(::getpid()) + ".bin"))
                                 .string();
  {
    std::ofstream file(firmware, std::ios::binary);
    file.write(reinterpret_cast<const char*>(image.data()),
               static_cast<std::streamsize>(image.size()));
  }
  FalconSettings settings;
  settings.firmwarePath = firmware;
  settings.worldOffset = path.positions.front();
  FalconDevice falcon(std::make_unique<FakeBulkTransport>(emulator), settings);
  std::string error;
  ASSERT_TRUE(falcon.open(error)) << error;
  std::remove(firmware.c_str());
  ASSERT_EQ(emulator.stage(), FalconEmulator::Stage::Running);

  std::size_t hint = 0;
  DrivenDevice device(falcon, [&](double time) {
    emulator.setGripPosition(path.positionAt(time, hint) - settings.worldOffset + falcon.neutral());
  });
  // Homing takes the first tick, whose sample is refused.
  const auto trace = scene.run(device, path);
  EXPECT_GT(contactTicks(trace), 100u);
  SimulatedDevice simulated(path);
  const auto reference = scene.run(simulated, path);
  std::size_t compared = 0;
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
  }
  EXPECT_GT(compared, trace.size() - 5);

  // Every force of the trace reached the emulator as J^T F in motor commands: frame k + 1 carries
  // tick k's force (frame 0 is the one open() sends).
  const auto frames = emulator.commandFrames();
  ASSERT_EQ(frames.size(), trace.size() + 1);
  const DeltaKinematics kinematics;
  std::size_t nonZero = 0;
  for (std::size_t i = 0; i < trace.size(); ++i)
  {
    if (trace[i].conditions.has(TickCondition::fingerRefused))
    {
      continue;
    }
    const auto counts = falcon.countsFromAngles(
      *kinematics.inverse(trace[i].finger - settings.worldOffset + falcon.neutral()));
    const auto expected = falcon.commandsFromTorques(
      kinematics.torques(falcon.anglesFromCounts(counts), trace[i].force));
    for (std::size_t joint = 0; joint < 3; ++joint)
    {
      EXPECT_NEAR(frames[i + 1].values[joint], expected[joint], 1.0) << "tick " << i;
      nonZero += frames[i + 1].values[joint] != 0 ? 1 : 0;
    }
  }
  EXPECT_GT(nonZero, 300u);
}

// Unplugged mid-stroke, in contact: the driver turns the vanished device into disconnected
// samples and the servo fades the force out and reports the loss on every tick after.
TEST(DevicesDriveTheSolver, SpaceMouseUnpluggedMidSessionFadesTheForce)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  SpaceMouseEmulator emulator(SpaceMouseLayout::SplitReports);
  SpaceMouseSettings settings;
  settings.centre = path.positions.front();
  settings.metresPerCount = 1e-5;
  SpaceMouseDevice spaceMouse(std::make_unique<FakeReportTransport>(emulator), settings);
  std::size_t hint = 0;
  std::size_t tick = 0;
  DrivenDevice device(spaceMouse, [&](double time) {
    if (tick++ == kUnplugTick)
    {
      emulator.unplug();
    }
    emulator.holdCapAt(path.positionAt(time, hint) - settings.centre, settings.metresPerCount);
  });
  expectFadeOut(scene.run(device, path), kUnplugTick);
}

TEST(DevicesDriveTheSolver, FalconUnpluggedMidSessionFadesTheForce)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  FalconEmulator emulator({}, 1);
  FalconSettings settings;
  // No upload: an emulator whose firmware already runs (re-opened without a power cycle).
  emulator.control(ftdi::kRequestModemControl, ftdi::kDtrHigh, 0);
  emulator.control(ftdi::kRequestModemControl, ftdi::kDtrLow, 0);
  emulator.control(ftdi::kRequestBaudRate, ftdi::kBaudFirmwareUpload, 0);
  const std::uint8_t upload = 0x40;
  emulator.receive(&upload, 1);
  settings.worldOffset = path.positions.front();
  FalconDevice falcon(std::make_unique<FakeBulkTransport>(emulator), settings);
  std::string error;
  ASSERT_TRUE(falcon.open(error)) << error;
  ASSERT_EQ(emulator.stage(), FalconEmulator::Stage::Running);
  (void)emulator.transmit(1000); // the upload request's answer
  std::size_t hint = 0;
  std::size_t tick = 0;
  DrivenDevice device(falcon, [&](double time) {
    if (tick++ == kUnplugTick)
    {
      emulator.unplug();
    }
    emulator.setGripPosition(path.positionAt(time, hint) - settings.worldOffset + falcon.neutral());
  });
  expectFadeOut(scene.run(device, path), kUnplugTick);
  EXPECT_FALSE(falcon.connected());
}

} // namespace
} // namespace proxima
