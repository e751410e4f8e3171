// The Falcon driver against its emulator through an in-memory transport: the firmware handshake
// and upload in libnifalcon's documented order, a clear error without a firmware file, homing,
// encoder counts to the grip position, forces to the motor commands J^T F (checked against a
// finite-difference Jacobian), short reads gathered, malformed frames refused, and an unplug.
#include "Devices/FalconDevice.h"

#include "Devices/FtdiRequests.h"
#include "FakeTransports.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace proxima
{
namespace
{
using testing::FakeBulkTransport;
using testing::FalconEmulator;

std::vector<std::uint8_t> firmwareImage()
{
  // 300 bytes: two full upload blocks of 128 and a short one.
  std::vector<std::uint8_t> image(300);
  for (std::size_t i = 0; i < image.size(); ++i)
  {
    image[i] = static_cast<std::uint8_t>((i * 37 + 11) & 0xff);
  }
  return image;
}

class FalconDeviceTest : public ::testing::Test
{
protected:
  FalconDeviceTest()
    : emulator(firmwareImage())
  {
    firmwarePath = (std::filesystem::temp_directory_path() /
                    ("proxima-falcon-firmware-" + std::to_string(::getpid()) + ".bin"))
                     .string();
    std::ofstream file(firmwarePath, std::ios::binary);
    const auto image = firmwareImage();
    file.write(reinterpret_cast<const char*>(image.data()),
               static_cast<std::streamsize>(image.size()));
  }
  ~FalconDeviceTest() override { std::remove(firmwarePath.c_str()); }

  std::unique_ptr<FalconDevice> makeDevice(std::size_t maxReadSize = 1024)
  {
    auto transport = std::make_unique<FakeBulkTransport>(emulator);
    transport->maxReadSize = maxReadSize;
    FalconSettings settings;
    settings.firmwarePath = firmwarePath;
    settings.worldOffset = {1.0, 2.0, 3.0};
    return std::make_unique<FalconDevice>(std::move(transport), settings);
  }

  /// Reads until homed (each read follows a frame the device answers).
  void home(FalconDevice& device)
  {
    for (int tick = 0; tick < 10 && !device.homed(); ++tick)
    {
      device.read(tick * 0.001);
      device.writeForce({}, tick * 0.001);
    }
    ASSERT_TRUE(device.homed());
  }

  FalconEmulator emulator;
  std::string firmwarePath;
};

TEST_F(FalconDeviceTest, UploadsTheFirmwareInTheDocumentedOrder)
{
  auto device = makeDevice();
  std::string error;
  ASSERT_TRUE(device->open(error)) << error;
  EXPECT_EQ(emulator.stage(), FalconEmulator::Stage::Running);
  EXPECT_TRUE(emulator.firmwareMatched());
  using namespace ftdi;
  // libnifalcon's FalconComm steps: purge, latency 16 ms, 8N1, 9600 baud, no flow control, RTS
  // low, DTR low, DTR high; then DTR low and the upload baud; then latency 1 ms, normal baud,
  // purge.
  const std::vector<std::pair<std::uint8_t, std::uint16_t>> expected{{kRequestReset, 1},
                                                                     {kRequestReset, 2},
                                                                     {kRequestLatencyTimer, 16},
                                                                     {kRequestLineProperties, 8},
                                                                     {kRequestBaudRate, 0x4138},
                                                                     {kRequestFlowControl, 0},
                                                                     {kRequestModemControl, 0x0200},
                                                                     {kRequestModemControl, 0x0100},
                                                                     {kRequestModemControl, 0x0101},
                                                                     {kRequestModemControl, 0x0100},
                                                                     {kRequestBaudRate, 0x15},
                                                                     {kRequestLatencyTimer, 1},
                                                                     {kRequestBaudRate, 0x02},
                                                                     {kRequestReset, 1},
                                                                     {kRequestReset, 2}};
  EXPECT_EQ(emulator.controlRequests(), expected);
}

TEST_F(FalconDeviceTest, MissingFirmwareIsAClearError)
{
  auto transport = std::make_unique<FakeBulkTransport>(emulator);
  FalconSettings settings;
  settings.firmwarePath = "/no/such/falcon-firmware.bin";
  FalconDevice device(std::move(transport), settings);
  std::string error;
  EXPECT_FALSE(device.open(error));
  EXPECT_NE(error.find("/no/such/falcon-firmware.bin: cannot open the Falcon firmware file"),
            std::string::npos)
    << error;
  EXPECT_NE(error.find("does not ship"), std::string::npos);
}

TEST_F(FalconDeviceTest, SilentBootloaderIsAClearError)
{
  // A device that never leaves the powered-on stage answers nothing.
  class Mute final : public BulkTransport
  {
  public:
    TransportResult control(std::uint8_t, std::uint16_t, std::uint16_t) override
    {
      return {TransportStatus::Ok, 0};
    }
    TransportResult write(std::span<const std::uint8_t> bytes) override
    {
      return {TransportStatus::Ok, bytes.size()};
    }
    TransportResult read(std::span<std::uint8_t>, int) override
    {
      return {TransportStatus::NoData, 0};
    }
  };
  FalconSettings settings;
  settings.firmwarePath = firmwarePath;
  FalconDevice device(std::make_unique<Mute>(), settings);
  std::string error;
  EXPECT_FALSE(device.open(error));
  EXPECT_NE(error.find("bootloader handshake"), std::string::npos) << error;
}

TEST_F(FalconDeviceTest, HomesThenReportsTheGripPosition)
{
  auto device = makeDevice();
  std::string error;
  ASSERT_TRUE(device->open(error)) << error;
  const Vec3 offset{0.01, -0.005, 0.02};
  emulator.setGripPosition(device->neutral() + offset);
  emulator.setButtons(0x5);
  // Before homing there is no position.
  EXPECT_FALSE(device->read(0.0).valid);
  device->writeForce({}, 0.0);
  home(*device);
  const DeviceSample sample = device->read(0.01);
  ASSERT_TRUE(sample.valid);
  EXPECT_EQ(sample.buttons, 0x5u);
  // Encoder quantization: about 0.4 mrad per count on 60 mm arms.
  EXPECT_LT(distance(sample.position, Vec3{1.0, 2.0, 3.0} + offset), 1e-4);
  // Frames sent before homing asked for it; the LED is red by default.
  const auto frames = emulator.commandFrames();
  ASSERT_FALSE(frames.empty());
  EXPECT_NE(frames.front().info & kFalconHomingMode, 0);
  EXPECT_NE(frames.front().info & kFalconLedRed, 0);
}

TEST_F(FalconDeviceTest, CountsTurnIntoArmAnglesThroughTheEncoderAndCapstan)
{
  // libnifalcon's encoder wheel has 320 slots, read in quadrature: 1280 counts per motor turn.
  // The 14.25 mm shaft drives the arm's 110 mm sector, so a motor turn turns the arm by
  // 360 degrees x 14.25 / 110; zero counts is 35 degrees.
  auto device = makeDevice();
  const double degree = std::numbers::pi / 180.0;
  const JointAngles zero = device->anglesFromCounts({0, 0, 0});
  const JointAngles turned = device->anglesFromCounts({1280, -1280, 2560});
  for (std::size_t i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(zero[i], 35.0 * degree, 1e-12);
  }
  const double perTurn = 360.0 * degree * 14.25 / 110.0;
  EXPECT_NEAR(turned[0] - zero[0], perTurn, 1e-12);
  EXPECT_NEAR(turned[1] - zero[1], -perTurn, 1e-12);
  EXPECT_NEAR(turned[2] - zero[2], 2.0 * perTurn, 1e-12);
  EXPECT_EQ(device->countsFromAngles(turned), (std::array<std::int16_t, 3>{1280, -1280, 2560}));
}

TEST_F(FalconDeviceTest, SaturatedCommandsKeepTheirRatios)
{
  // libnifalcon's sign and scale, -10000 commands per N m; past the limit all three shrink by
  // one factor, so the force on the grip keeps its direction.
  auto device = makeDevice();
  const auto small = device->commandsFromTorques({0.01, -0.02, 0.03});
  EXPECT_EQ(small, (std::array<std::int16_t, 3>{-100, 200, -300}));
  const auto large = device->commandsFromTorques({1.0, -0.5, 0.25});
  EXPECT_EQ(large, (std::array<std::int16_t, 3>{-4096, 2048, -1024}));
  const auto broken = device->commandsFromTorques({1.0, std::nan(""), 0.0});
  EXPECT_EQ(broken, (std::array<std::int16_t, 3>{0, 0, 0}));
}

TEST_F(FalconDeviceTest, ForceBecomesTheJacobianTransposeMotorCommands)
{
  auto device = makeDevice();
  std::string error;
  ASSERT_TRUE(device->open(error)) << error;
  emulator.setGripPosition(device->neutral() + Vec3{0.005, 0.01, -0.01});
  home(*device);
  device->read(0.02);
  const Vec3 force{1.5, -2.0, 3.0};
  device->writeForce(force, 0.02);
  const FalconFrame sent = emulator.commandFrames().back();

  // The oracle: J by central differences of the forward kinematics at the encoder angles.
  const DeltaKinematics kinematics;
  const JointAngles angles = device->anglesFromCounts(device->lastEncoders());
  JointAngles tau{};
  for (std::size_t joint = 0; joint < 3; ++joint)
  {
    JointAngles plus = angles;
    JointAngles minus = angles;
    plus[joint] += 1e-6;
    minus[joint] -= 1e-6;
    const Vec3 column = (*kinematics.forward(plus) - *kinematics.forward(minus)) / 2e-6;
    tau[joint] = dot(column, force);
  }
  // libnifalcon's scale and sign: -10000 commands per N m; this force needs no saturation.
  for (std::size_t joint = 0; joint < 3; ++joint)
  {
    const double expected = std::round(-10000.0 * tau[joint]);
    ASSERT_LT(std::abs(expected), 4096.0) << joint;
    EXPECT_NEAR(sent.values[joint], expected, 1.0) << joint;
    EXPECT_NE(sent.values[joint], 0);
  }
  EXPECT_EQ(sent.info & kFalconHomingMode, 0);
}

TEST_F(FalconDeviceTest, ShortReadsAreGatheredAndMalformedFramesRefused)
{
  auto device = makeDevice(20);
  std::string error;
  ASSERT_TRUE(device->open(error)) << error;
  const Vec3 offset{-0.01, 0.0, 0.01};
  emulator.setGripPosition(device->neutral() + offset);
  DeviceSample sample;
  for (int tick = 0; tick < 40; ++tick)
  {
    sample = device->read(tick * 0.001);
    device->writeForce({}, tick * 0.001);
  }
  ASSERT_TRUE(sample.valid);
  EXPECT_LT(distance(sample.position, Vec3{1.0, 2.0, 3.0} + offset), 1e-4);
  const std::uint64_t refusedBefore = device->frameReader().refusedFrames();
  emulator.queueRaw(
    {'<', 'A', 'A', 'Z', 'A', 'A', 'A', 'A', 'A', 'A', 'A', 'A', 'A', 'A', 'A', '>'});
  for (int tick = 40; tick < 80; ++tick)
  {
    sample = device->read(tick * 0.001);
    device->writeForce({}, tick * 0.001);
  }
  EXPECT_EQ(device->frameReader().refusedFrames(), refusedBefore + 1);
  EXPECT_LT(distance(sample.position, Vec3{1.0, 2.0, 3.0} + offset), 1e-4);
}

TEST_F(FalconDeviceTest, UnplugIsADisconnectedSampleNotACrash)
{
  auto device = makeDevice();
  std::string error;
  ASSERT_TRUE(device->open(error)) << error;
  emulator.setGripPosition(device->neutral());
  home(*device);
  emulator.unplug();
  for (int tick = 0; tick < 3; ++tick)
  {
    const DeviceSample sample = device->read(1.0 + tick * 0.001);
    EXPECT_FALSE(sample.connected);
    EXPECT_FALSE(sample.valid);
    device->writeForce({1, 1, 1}, 1.0 + tick * 0.001);
  }
  EXPECT_FALSE(device->connected());
}

} // namespace
} // namespace proxima
