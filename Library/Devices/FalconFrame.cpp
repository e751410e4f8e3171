#include "Devices/FalconFrame.h"

namespace proxima
{
namespace
{
constexpr std::uint8_t kNibbleBase = 0x41;

std::uint8_t nibbleByte(unsigned value)
{
  return static_cast<std::uint8_t>(kNibbleBase + (value & 0xfu));
}

bool nibbleOf(std::uint8_t byte, unsigned& value)
{
  if (byte < kNibbleBase || byte > kNibbleBase + 0xf)
  {
    return false;
  }
  value = static_cast<unsigned>(byte - kNibbleBase);
  return true;
}
} // namespace

FalconFrameBytes encodeFalconFrame(const FalconFrame& frame)
{
  FalconFrameBytes bytes{};
  bytes[0] = '<';
  for (std::size_t axis = 0; axis < 3; ++axis)
  {
    const auto value = static_cast<std::uint16_t>(frame.values[axis]);
    for (std::size_t nibble = 0; nibble < 4; ++nibble)
    {
      bytes[1 + 4 * axis + nibble] = nibbleByte(value >> (4 * nibble));
    }
  }
  bytes[13] = static_cast<std::uint8_t>(kNibbleBase + frame.info);
  bytes[14] = static_cast<std::uint8_t>(kNibbleBase + frame.reserved);
  bytes[15] = '>';
  return bytes;
}

std::optional<FalconFrame> decodeFalconFrame(std::span<const std::uint8_t> bytes,
                                             std::string& error)
{
  if (bytes.size() != kFalconFrameSize)
  {
    error = "a frame has 16 bytes, not " + std::to_string(bytes.size());
    return std::nullopt;
  }
  if (bytes[0] != '<' || bytes[15] != '>')
  {
    error = "a frame starts with '<' and ends with '>'";
    return std::nullopt;
  }
  FalconFrame frame;
  for (std::size_t i = 13; i < 15; ++i)
  {
    if (bytes[i] < kNibbleBase)
    {
      error =
        "byte " + std::to_string(i) + " of a frame is " + std::to_string(bytes[i]) + ", below 'A'";
      return std::nullopt;
    }
  }
  frame.info = static_cast<std::uint8_t>(bytes[13] - kNibbleBase);
  frame.reserved = static_cast<std::uint8_t>(bytes[14] - kNibbleBase);
  for (std::size_t i = 1; i < 13; ++i)
  {
    unsigned value = 0;
    if (!nibbleOf(bytes[i], value))
    {
      error = "byte " + std::to_string(i) + " of a frame is " + std::to_string(bytes[i]) +
              ", outside 'A'..'P'";
      return std::nullopt;
    }
    const std::size_t axis = (i - 1) / 4;
    const std::size_t nibble = (i - 1) % 4;
    const auto old = static_cast<std::uint16_t>(frame.values[axis]);
    frame.values[axis] = static_cast<std::int16_t>(old | (value << (4 * nibble)));
  }
  return frame;
}

std::optional<FalconFrame> FalconFrameReader::push(std::span<const std::uint8_t> bytes)
{
  std::optional<FalconFrame> newest;
  for (std::uint8_t byte : bytes)
  {
    if (m_numPending == 0 && byte != '<')
    {
      ++m_droppedBytes;
      continue;
    }
    if (m_numPending > 0 && byte == '<')
    {
      // A new frame begins before the last one ended: the partial one was short.
      ++m_refusedFrames;
      m_lastError = "a frame was cut short after " + std::to_string(m_numPending) + " bytes";
      m_numPending = 0;
    }
    m_pending[m_numPending++] = byte;
    if (m_numPending == kFalconFrameSize)
    {
      std::string error;
      if (auto frame = decodeFalconFrame(m_pending, error))
      {
        newest = frame;
      }
      else
      {
        ++m_refusedFrames;
        m_lastError = error;
      }
      m_numPending = 0;
    }
  }
  return newest;
}

} // namespace proxima
