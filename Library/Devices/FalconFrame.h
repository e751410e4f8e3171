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

constexpr std::size_t kFalconFrameSize = 16;
using FalconFrameBytes = std::array<std::uint8_t, kFalconFrameSize>;

/// Info bits of a frame to the device.
constexpr std::uint8_t kFalconHomingMode = 0x01;
constexpr std::uint8_t kFalconLedGreen = 0x02;
constexpr std::uint8_t kFalconLedBlue = 0x04;
constexpr std::uint8_t kFalconLedRed = 0x08;
/// Info bits of a frame from the device: the four buttons of the grip, and each axis homed.
constexpr std::uint8_t kFalconButtonMask = 0x0f;
constexpr std::uint8_t kFalconHomedAxis1 = 0x10;
constexpr std::uint8_t kFalconHomedAxis2 = 0x20;
constexpr std::uint8_t kFalconHomedAxis3 = 0x40;
constexpr std::uint8_t kFalconHomedAll = kFalconHomedAxis1 | kFalconHomedAxis2 | kFalconHomedAxis3;

struct FalconFrame
{
  /// Motor commands (to the device) or encoder counts (from it), axis 1 to 3.
  std::array<std::int16_t, 3> values{0, 0, 0};
  /// Sent as 'A' + value, so at most 0xbe.
  std::uint8_t info = 0;
  std::uint8_t reserved = 0;
};

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
  std::uint64_t droppedBytes() const { return m_droppedBytes; }
  std::uint64_t refusedFrames() const { return m_refusedFrames; }
  const std::string& lastError() const { return m_lastError; }

private:
  std::array<std::uint8_t, kFalconFrameSize> m_pending{};
  std::size_t m_numPending = 0;
  std::uint64_t m_droppedBytes = 0;
  std::uint64_t m_refusedFrames = 0;
  std::string m_lastError;
};

} // namespace proxima
