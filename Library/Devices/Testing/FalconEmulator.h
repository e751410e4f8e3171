// An emulated Novint Falcon behind its FTDI bridge, for tests: the bootloader handshake and the
// echoed firmware upload of libnifalcon's documentation, then one encoder frame back for every
// command frame received. The grip's position is set by the test (through the inverse kinematics,
// an independent path from the driver's forward kinematics); the motor commands it receives are
// recorded, so a test can check the force that reached the motors.
#pragma once

#include "Devices/FalconFrame.h"
#include "Devices/FalconKinematics.h"

#include <cstdint>
#include <deque>
#include <mutex>
#include <vector>

namespace proxima::testing
{

class FalconEmulator
{
public:
  enum class Stage
  {
    PoweredOn,
    Bootloader,
    Uploading,
    Running
  };

  /// `firmware`: the image the emulated bootloader accepts (the upload must echo-match it).
  /// `homingFrames`: frames with the homing bit before the axes report homed (the user moving
  /// the grip through its home switches).
  FalconEmulator(std::vector<std::uint8_t> firmware, int homingFrames = 3,
                 const DeltaGeometry& geometry = DeltaGeometry{});

  /// Sets the grip's true position (device frame); encoder counts follow from it.
  void setGripPosition(const Vec3& position);
  void setEncoders(const std::array<std::int16_t, 3>& counts);
  void setButtons(std::uint8_t buttons);
  /// Bytes queued as is for the host to read (noise, malformed frames).
  void queueRaw(const std::vector<std::uint8_t>& bytes);

  // The FTDI side, as the transports see it.
  void control(std::uint8_t request, std::uint16_t value, std::uint16_t index);
  void receive(const std::uint8_t* bytes, std::size_t size);
  /// Takes up to `maxBytes` of what the device sends.
  std::vector<std::uint8_t> transmit(std::size_t maxBytes);

  void unplug();
  bool unplugged() const;

  Stage stage() const;
  bool firmwareMatched() const;
  /// Every command frame received while running, in order.
  std::vector<FalconFrame> commandFrames() const;
  std::vector<std::pair<std::uint8_t, std::uint16_t>> controlRequests() const;

  /// Counts per radian and angle at zero counts, as the driver's defaults.
  double countsPerRadian = 4000.0 / 1.5707963267948966;
  double thetaAtZeroCounts = 0.785398163397448;

private:
  void handleFrame(const FalconFrameBytes& bytes);

  mutable std::mutex m_mutex;
  std::vector<std::uint8_t> m_firmware;
  int m_homingFrames;
  DeltaKinematics m_kinematics;
  Stage m_stage = Stage::PoweredOn;
  bool m_dtrHigh = false;
  std::uint16_t m_baud = 0;
  std::vector<std::uint8_t> m_received;
  std::vector<std::uint8_t> m_uploaded;
  std::deque<std::uint8_t> m_outgoing;
  std::array<std::int16_t, 3> m_encoders{0, 0, 0};
  std::uint8_t m_buttons = 0;
  int m_framesWithHoming = 0;
  std::vector<FalconFrame> m_commands;
  std::vector<std::pair<std::uint8_t, std::uint16_t>> m_controls;
  bool m_unplugged = false;
};

} // namespace proxima::testing
