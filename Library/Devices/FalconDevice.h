// The Novint Falcon (USB 0403:cb48, an FTDI serial bridge) as a haptic device: uploads the
// firmware the user supplies (never shipped), homes, turns encoder counts into the grip position
// through the delta kinematics, and a force on the finger into motor commands through J^T. One
// frame goes out per writeForce and one comes back per read, so a lockstep run against the
// emulator is deterministic. All I/O goes through a BulkTransport (LibusbTransport for a real
// device); a vanished device becomes disconnected samples, never an exception.
#pragma once

#include "Devices/DeviceTransport.h"
#include "Devices/FalconFrame.h"
#include "Devices/FalconKinematics.h"
#include "Devices/FalconSpecification.h"
#include "Runtime/HapticDevice.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace proxima
{

/// How a FalconDevice opens, converts and limits: the firmware, the linkage, the encoder and
/// motor units, the force limit and where the grip sits in the world.
struct FalconSettings
{
  /// The firmware image to upload (the user's own copy; Documentation/Devices.md). Empty: the
  /// device already runs firmware (re-opened without a power cycle) and the upload is skipped.
  std::string firmwarePath;
  /// The linkage dimensions for the kinematics (libnifalcon's measurements by default).
  DeltaGeometry geometry;
  /// Encoder counts to arm angle: theta = thetaAtZeroCounts + counts / countsPerRadian
  /// (FalconSpecification.h: 35 degrees at zero counts, 1572.6 counts per radian, from
  /// libnifalcon's encoder wheel and capstan measurements).
  double thetaAtZeroCounts = falcon::kThetaAtZeroCounts;
  /// Encoder counts per radian of arm angle (see thetaAtZeroCounts).
  double countsPerRadian = falcon::kCountsPerArmRadian;
  /// Motor command units per N m of joint torque toward a larger angle (libnifalcon's -10000;
  /// negative: a positive command turns the arm toward fewer counts).
  double commandsPerNewtonMetre = falcon::kCommandsPerNewtonMetre;
  /// The largest command magnitude sent; larger commands are scaled down together, which keeps
  /// the force's direction. Not from a public source (the frame carries 16 bits; libnifalcon
  /// sets no limit): calibrate on a device (Documentation/Devices.md).
  int maxCommand = 4096;
  /// Largest force the servo may ask for, in newtons. Not from a public source.
  double maxForce = 8.0;
  /// World position = grip position (device frame: libnifalcon's, z along the delta axis
  /// toward the user) - neutral + worldOffset, where neutral is the grip with all arms at
  /// thetaAtZeroCounts (on the axis, 134.6 mm out from the base centre).
  Vec3 worldOffset;
  /// How long read() waits for the device's frame. Until every axis reports homed, samples are
  /// invalid (no position is trusted before homing).
  int readTimeoutMilliseconds = 2;
};

/// A Novint Falcon as a HapticDevice: open() uploads the firmware and starts frame I/O; read()
/// gives the grip's world position (m) once every axis is homed, and writeForce() turns a force
/// (N) into motor commands through J^T, within maxForce and maxCommand.
class FalconDevice final : public HapticDevice
{
public:
  /// Takes ownership of `transport` and does no I/O yet: call open() before the first read().
  FalconDevice(std::unique_ptr<BulkTransport> transport, const FalconSettings& settings);

  /// Uploads the firmware (when a path is set) and switches to normal I/O. False with `error`
  /// naming the problem: a missing firmware file, a device that does not answer the bootloader
  /// handshake, an upload whose echo differs.
  bool open(std::string& error);

  DeviceSample read(double time) override;
  void writeForce(const Vec3& force, double time) override;
  DeviceLimits limits() const override;
  const char* name() const override { return "falcon"; }

  /// LED bits (kFalconLedGreen, Blue, Red) sent with every frame from now on.
  void setLeds(std::uint8_t leds)
  {
    m_leds = leds & (kFalconLedGreen | kFalconLedBlue | kFalconLedRed);
  }

  /// True if the latest frame from the device reports all three axes homed.
  bool homed() const { return m_homed; }
  /// False once the transport reported the device gone; every later read() is a lost sample.
  bool connected() const { return m_connected; }
  /// Encoder counts of the latest valid frame from the device (zeros before the first).
  const std::array<std::int16_t, 3>& lastEncoders() const { return m_encoders; }
  /// Motor commands sent with the latest frame; zeros until the device is homed.
  const std::array<std::int16_t, 3>& lastCommands() const { return m_commands; }
  /// The reader of the device's frames, for its counts of dropped bytes and refused frames.
  const FalconFrameReader& frameReader() const { return m_reader; }
  /// The latest problem while running (device gone, encoders that describe no pose); empty if
  /// none. open() reports its own problems through its `error`.
  const std::string& lastError() const { return m_lastError; }

  /// Encoder counts to angles and back, and torques to commands: the unit conversions at the
  /// edge, public so that tests and the emulator use the very same numbers.
  JointAngles anglesFromCounts(const std::array<std::int16_t, 3>& counts) const;
  /// Encoder counts for arm angles (rad), rounded and clamped to the 16-bit range.
  std::array<std::int16_t, 3> countsFromAngles(const JointAngles& angles) const;
  /// Motor commands for joint torques (N m), all three scaled down together to at most
  /// maxCommand; all zero if any torque is not finite.
  std::array<std::int16_t, 3> commandsFromTorques(const JointAngles& torques) const;
  /// The device-frame grip position that maps to the world origin offset.
  const Vec3& neutral() const { return m_neutral; }

private:
  bool enterFirmwareMode(std::string& error);
  bool uploadFirmware(const std::vector<std::uint8_t>& image, std::string& error);
  bool enterNormalMode(std::string& error);
  bool expectBytes(const std::vector<std::uint8_t>& expected, const char* what, std::string& error);
  void sendFrame();
  DeviceSample lost();

  std::unique_ptr<BulkTransport> m_transport;
  FalconSettings m_settings;
  DeltaKinematics m_kinematics;
  Vec3 m_neutral;
  FalconFrameReader m_reader;
  std::array<std::int16_t, 3> m_encoders{0, 0, 0};
  std::array<std::int16_t, 3> m_commands{0, 0, 0};
  std::uint8_t m_buttons = 0;
  std::uint8_t m_leds = kFalconLedRed;
  bool m_homed = false;
  bool m_haveFrame = false;
  bool m_connected = true;
  std::string m_lastError;
};

} // namespace proxima
