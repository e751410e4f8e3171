// The Novint Falcon's 16-byte frame, as libnifalcon's documentation describes it for the
// firmware it talks to: '<', three 16-bit values (motor commands to the device, encoder counts
// from it) as four nibbles each, low nibble first, every nibble sent as 'A' + nibble (0x41..0x50),
// an info byte (to the device: homing mode and LEDs; from it: buttons and homing status) and a
// reserved byte, both sent as 'A' + value, then '>'. An all-zero frame reads "<AAAAAAAAAAAAAA>".
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace proxima
{

/// Bytes in one frame, the '<' and '>' included.
constexpr std::size_t kFalconFrameSize = 16;
/// One frame as it travels over the wire.
using FalconFrameBytes = std::array<std::uint8_t, kFalconFrameSize>;

// Info bits of a frame to the device.
/// Homing mode: FalconDevice sets it in every frame until all three axes report homed.
constexpr std::uint8_t kFalconHomingMode = 0x01;
constexpr std::uint8_t kFalconLedGreen = 0x02; ///< Turns the green LED on.
constexpr std::uint8_t kFalconLedBlue = 0x04;  ///< Turns the blue LED on.
constexpr std::uint8_t kFalconLedRed = 0x08;   ///< Turns the red LED on.
// Info bits of a frame from the device: the four buttons of the grip, and each axis homed.
/// The four buttons of the grip, bit i for button i.
constexpr std::uint8_t kFalconButtonMask = 0x0f;
constexpr std::uint8_t kFalconHomedAxis1 = 0x10; ///< Axis 1 is homed.
constexpr std::uint8_t kFalconHomedAxis2 = 0x20; ///< Axis 2 is homed.
constexpr std::uint8_t kFalconHomedAxis3 = 0x40; ///< Axis 3 is homed.
/// All three axes homed: until then the encoder counts give no trusted position.
constexpr std::uint8_t kFalconHomedAll = kFalconHomedAxis1 | kFalconHomedAxis2 | kFalconHomedAxis3;

/// One frame to or from the Falcon, decoded.
struct FalconFrame
{
  /// Motor commands (to the device) or encoder counts (from it), axis 1 to 3.
  std::array<std::int16_t, 3> values{0, 0, 0};
  /// Sent as 'A' + value, so at most 0xbe.
  std::uint8_t info = 0;
  /// The frame's last data byte, unused by the driver: sent as 0 and kept as decoded. Sent as
  /// 'A' + value, so at most 0xbe.
  std::uint8_t reserved = 0;
};

/// Encodes a frame into its 16 bytes: '<', the nibbles of the three values, info, reserved, '>'.
FalconFrameBytes encodeFalconFrame(const FalconFrame& frame);

/// Decodes 16 bytes; refuses (nullopt, `error` set) a frame without its '<' and '>', with a
/// value nibble outside 'A'..'P' or an info or reserved byte below 'A'.
std::optional<FalconFrame> decodeFalconFrame(std::span<const std::uint8_t> bytes,
                                             std::string& error);

/// Finds frames in a byte stream: bytes arrive in arbitrary pieces over USB, and a frame may
/// straddle two reads. Bytes before a '<' are dropped (counted); a malformed frame is refused
/// (counted) and the search resumes after its '<'.
class FalconFrameReader
{
public:
  /// Adds bytes; returns the newest complete, valid frame among them (older ones are dropped:
  /// the servo wants the latest encoders).
  std::optional<FalconFrame> push(std::span<const std::uint8_t> bytes);
  /// Bytes dropped so far because they came outside a frame (before its '<').
  std::uint64_t droppedBytes() const { return m_droppedBytes; }
  /// Frames refused so far: cut short by the next '<', or malformed.
  std::uint64_t refusedFrames() const { return m_refusedFrames; }
  /// Why the latest frame was refused; empty if none was.
  const std::string& lastError() const { return m_lastError; }

private:
  std::array<std::uint8_t, kFalconFrameSize> m_pending{};
  std::size_t m_numPending = 0;
  std::uint64_t m_droppedBytes = 0;
  std::uint64_t m_refusedFrames = 0;
  std::string m_lastError;
};

} // namespace proxima
