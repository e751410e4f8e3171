#include "FalconEmulator.h"

#include "Devices/FtdiRequests.h"

#include <algorithm>
#include <cmath>

namespace proxima::testing
{

FalconEmulator::FalconEmulator(std::vector<std::uint8_t> firmware, int homingFrames,
                               const DeltaGeometry& geometry)
  : m_firmware(std::move(firmware))
  , m_homingFrames(homingFrames)
  , m_kinematics(geometry)
{}

void FalconEmulator::setGripPosition(const Vec3& position)
{
  const auto angles = m_kinematics.inverse(position);
  if (!angles)
  {
    return;
  }
  std::array<std::int16_t, 3> counts{};
  for (std::size_t i = 0; i < 3; ++i)
  {
    counts[i] =
      static_cast<std::int16_t>(std::lround(((*angles)[i] - thetaAtZeroCounts) * countsPerRadian));
  }
  setEncoders(counts);
}

void FalconEmulator::setEncoders(const std::array<std::int16_t, 3>& counts)
{
  std::lock_guard lock(m_mutex);
  m_encoders = counts;
}

void FalconEmulator::setButtons(std::uint8_t buttons)
{
  std::lock_guard lock(m_mutex);
  m_buttons = buttons & kFalconButtonMask;
}

void FalconEmulator::queueRaw(const std::vector<std::uint8_t>& bytes)
{
  std::lock_guard lock(m_mutex);
  m_outgoing.insert(m_outgoing.end(), bytes.begin(), bytes.end());
}

void FalconEmulator::control(std::uint8_t request, std::uint16_t value, std::uint16_t /*index*/)
{
  std::lock_guard lock(m_mutex);
  m_controls.emplace_back(request, value);
  if (request == ftdi::kRequestModemControl && (value & 0x0100) != 0)
  {
    m_dtrHigh = (value & 1) != 0;
    // DTR high resets the microcontroller into its bootloader.
    if (m_dtrHigh)
    {
      m_stage = Stage::Bootloader;
      m_received.clear();
    }
  }
  else if (request == ftdi::kRequestBaudRate)
  {
    m_baud = value;
    if (m_stage == Stage::Uploading && value == ftdi::kBaudNormal)
    {
      // Normal I/O: the firmware runs if it is the one the bootloader knows.
      m_stage = m_uploaded == m_firmware ? Stage::Running : Stage::PoweredOn;
      m_received.clear();
    }
  }
  else if (request == ftdi::kRequestReset && value == ftdi::kResetPurgeReceive)
  {
    m_outgoing.clear();
  }
}

void FalconEmulator::receive(const std::uint8_t* bytes, std::size_t size)
{
  std::lock_guard lock(m_mutex);
  if (m_unplugged)
  {
    return;
  }
  for (std::size_t i = 0; i < size; ++i)
  {
    const std::uint8_t byte = bytes[i];
    switch (m_stage)
    {
      case Stage::PoweredOn: break;
      case Stage::Bootloader:
        m_received.push_back(byte);
        if (m_baud == ftdi::kBaud9600 && m_received == std::vector<std::uint8_t>{0x0a, 0x43, 0x0d})
        {
          for (int reply : {0x00, 0x0a, 0x44, 0x2c, 0x0d})
          {
            m_outgoing.push_back(static_cast<std::uint8_t>(reply));
          }
          m_received.clear();
        }
        else if (m_baud == ftdi::kBaudFirmwareUpload && !m_dtrHigh && byte == 0x40)
        {
          m_outgoing.push_back(0x41);
          m_stage = Stage::Uploading;
          m_uploaded.clear();
          m_received.clear();
        }
        break;
      case Stage::Uploading:
        // The bootloader echoes every byte it takes.
        m_uploaded.push_back(byte);
        m_outgoing.push_back(byte);
        break;
      case Stage::Running:
        m_received.push_back(byte);
        if (m_received.front() != '<')
        {
          m_received.clear();
        }
        else if (m_received.size() == kFalconFrameSize)
        {
          FalconFrameBytes frame{};
          std::copy(m_received.begin(), m_received.end(), frame.begin());
          m_received.clear();
          handleFrame(frame);
        }
        break;
    }
  }
}

void FalconEmulator::handleFrame(const FalconFrameBytes& bytes)
{
  std::string error;
  const auto frame = decodeFalconFrame(bytes, error);
  if (!frame)
  {
    return;
  }
  m_commands.push_back(*frame);
  if ((frame->info & kFalconHomingMode) != 0)
  {
    ++m_framesWithHoming;
  }
  FalconFrame reply;
  reply.values = m_encoders;
  reply.info = m_buttons;
  if (m_framesWithHoming >= m_homingFrames)
  {
    reply.info |= kFalconHomedAll;
  }
  const FalconFrameBytes out = encodeFalconFrame(reply);
  m_outgoing.insert(m_outgoing.end(), out.begin(), out.end());
}

std::vector<std::uint8_t> FalconEmulator::transmit(std::size_t maxBytes)
{
  std::lock_guard lock(m_mutex);
  const std::size_t count = std::min(maxBytes, m_outgoing.size());
  std::vector<std::uint8_t> bytes(m_outgoing.begin(),
                                  m_outgoing.begin() + static_cast<std::ptrdiff_t>(count));
  m_outgoing.erase(m_outgoing.begin(), m_outgoing.begin() + static_cast<std::ptrdiff_t>(count));
  return bytes;
}

void FalconEmulator::unplug()
{
  std::lock_guard lock(m_mutex);
  m_unplugged = true;
}

bool FalconEmulator::unplugged() const
{
  std::lock_guard lock(m_mutex);
  return m_unplugged;
}

FalconEmulator::Stage FalconEmulator::stage() const
{
  std::lock_guard lock(m_mutex);
  return m_stage;
}

bool FalconEmulator::firmwareMatched() const
{
  std::lock_guard lock(m_mutex);
  return m_uploaded == m_firmware;
}

std::vector<FalconFrame> FalconEmulator::commandFrames() const
{
  std::lock_guard lock(m_mutex);
  return m_commands;
}

std::vector<std::pair<std::uint8_t, std::uint16_t>> FalconEmulator::controlRequests() const
{
  std::lock_guard lock(m_mutex);
  return m_controls;
}

} // namespace proxima::testing
