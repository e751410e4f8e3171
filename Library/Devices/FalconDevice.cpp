#include "Devices/FalconDevice.h"

#include "Devices/FtdiRequests.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

namespace proxima
{
namespace
{
// The bootloader handshake and upload block size of libnifalcon's documentation (FalconComm).
const std::vector<std::uint8_t> kHandshakeRequest{0x0a, 0x43, 0x0d};
const std::vector<std::uint8_t> kHandshakeReply{0x00, 0x0a, 0x44, 0x2c, 0x0d};
constexpr std::uint8_t kUploadRequest = 0x40;
constexpr std::uint8_t kUploadReply = 0x41;
constexpr std::size_t kUploadBlock = 128;
// Reads during the handshake and upload wait this long in all before giving up.
constexpr int kHandshakeTimeoutMilliseconds = 1000;
} // namespace

FalconDevice::FalconDevice(std::unique_ptr<BulkTransport> transport, const FalconSettings& settings)
  : m_transport(std::move(transport))
  , m_settings(settings)
  , m_kinematics(settings.geometry)
{
  const double theta = settings.thetaAtZeroCounts;
  m_neutral = m_kinematics.forward({theta, theta, theta}).value_or(Vec3{});
}

JointAngles FalconDevice::anglesFromCounts(const std::array<std::int16_t, 3>& counts) const
{
  JointAngles angles{};
  for (std::size_t i = 0; i < 3; ++i)
  {
    angles[i] = m_settings.thetaAtZeroCounts + counts[i] / m_settings.countsPerRadian;
  }
  return angles;
}

std::array<std::int16_t, 3> FalconDevice::countsFromAngles(const JointAngles& angles) const
{
  std::array<std::int16_t, 3> counts{};
  for (std::size_t i = 0; i < 3; ++i)
  {
    const double value =
      std::round((angles[i] - m_settings.thetaAtZeroCounts) * m_settings.countsPerRadian);
    counts[i] = static_cast<std::int16_t>(std::clamp(value, -32768.0, 32767.0));
  }
  return counts;
}

std::array<std::int16_t, 3> FalconDevice::commandsFromTorques(const JointAngles& torques) const
{
  std::array<double, 3> values{};
  double largest = 0.0;
  std::array<std::int16_t, 3> commands{0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i)
  {
    values[i] = torques[i] * m_settings.commandsPerNewtonMetre;
    // One torque that is not a number makes the force unknown: send none.
    if (!std::isfinite(values[i]))
    {
      return commands;
    }
    largest = std::max(largest, std::abs(values[i]));
  }
  // Clamping one motor alone would turn the force on the grip; scaling all three keeps its
  // direction (libnifalcon scales its torques so, for the same reason).
  const double limit = m_settings.maxCommand;
  const double scale = largest > limit ? limit / largest : 1.0;
  for (std::size_t i = 0; i < 3; ++i)
  {
    commands[i] =
      static_cast<std::int16_t>(std::clamp(std::round(values[i] * scale), -limit, limit));
  }
  return commands;
}

bool FalconDevice::expectBytes(const std::vector<std::uint8_t>& expected, const char* what,
                               std::string& error)
{
  std::vector<std::uint8_t> received;
  std::array<std::uint8_t, 256> buffer{};
  // Short reads are normal on a serial bridge: gather until enough bytes came or time is up.
  for (int waited = 0; received.size() < expected.size() && waited < kHandshakeTimeoutMilliseconds;)
  {
    const std::size_t want = std::min(buffer.size(), expected.size() - received.size());
    const TransportResult result = m_transport->read(std::span(buffer.data(), want), 10);
    if (result.status == TransportStatus::Disconnected || result.status == TransportStatus::Failed)
    {
      error = std::string("the Falcon stopped answering during the ") + what;
      return false;
    }
    if (result.status == TransportStatus::NoData)
    {
      waited += 10;
      continue;
    }
    received.insert(received.end(), buffer.begin(),
                    buffer.begin() + static_cast<std::ptrdiff_t>(result.size));
  }
  if (received != expected)
  {
    error = std::string("the Falcon's answer to the ") + what +
            " is not what its bootloader sends (" + std::to_string(received.size()) + " of " +
            std::to_string(expected.size()) + " bytes, or different ones)";
    return false;
  }
  return true;
}

bool FalconDevice::enterFirmwareMode(std::string& error)
{
  using namespace ftdi;
  // The sequence of libnifalcon's documentation (FalconComm), step by step.
  const std::pair<std::uint8_t, std::uint16_t> setup[] = {
    {kRequestReset, kResetPurgeReceive}, {kRequestReset, kResetPurgeTransmit},
    {kRequestLatencyTimer, 16},          {kRequestLineProperties, kLine8N1},
    {kRequestBaudRate, kBaud9600},       {kRequestFlowControl, 0},
    {kRequestModemControl, kRtsLow},     {kRequestModemControl, kDtrLow},
    {kRequestModemControl, kDtrHigh}};
  for (const auto& [request, value] : setup)
  {
    if (!m_transport->control(request, value, 0).ok())
    {
      error = "the Falcon refused an FTDI setup request (" + std::to_string(request) + ")";
      return false;
    }
  }
  if (!m_transport->write(kHandshakeRequest).ok() ||
      !expectBytes(kHandshakeReply, "bootloader handshake", error))
  {
    if (error.empty())
    {
      error = "the Falcon could not be written to";
    }
    return false;
  }
  if (!m_transport->control(kRequestModemControl, kDtrLow, 0).ok() ||
      !m_transport->control(kRequestBaudRate, kBaudFirmwareUpload, 0).ok())
  {
    error = "the Falcon refused the upload baud rate";
    return false;
  }
  const std::uint8_t request = kUploadRequest;
  if (!m_transport->write(std::span(&request, 1)).ok() ||
      !expectBytes({kUploadReply}, "upload request", error))
  {
    if (error.empty())
    {
      error = "the Falcon could not be written to";
    }
    return false;
  }
  return true;
}

bool FalconDevice::uploadFirmware(const std::vector<std::uint8_t>& image, std::string& error)
{
  // Blocks of 128 bytes, each echoed back by the bootloader for checking.
  for (std::size_t at = 0; at < image.size(); at += kUploadBlock)
  {
    const std::size_t size = std::min(kUploadBlock, image.size() - at);
    const std::vector<std::uint8_t> block(image.begin() + static_cast<std::ptrdiff_t>(at),
                                          image.begin() + static_cast<std::ptrdiff_t>(at + size));
    if (!m_transport->write(block).ok())
    {
      error = "the Falcon stopped taking the firmware at byte " + std::to_string(at);
      return false;
    }
    if (!expectBytes(block, "firmware upload", error))
    {
      error += " at byte " + std::to_string(at);
      return false;
    }
  }
  return true;
}

bool FalconDevice::enterNormalMode(std::string& error)
{
  using namespace ftdi;
  if (!m_transport->control(kRequestLatencyTimer, 1, 0).ok() ||
      !m_transport->control(kRequestBaudRate, kBaudNormal, 0).ok() ||
      !m_transport->control(kRequestReset, kResetPurgeReceive, 0).ok() ||
      !m_transport->control(kRequestReset, kResetPurgeTransmit, 0).ok())
  {
    error = "the Falcon refused the switch to normal I/O";
    return false;
  }
  return true;
}

bool FalconDevice::open(std::string& error)
{
  if (!m_settings.firmwarePath.empty())
  {
    std::ifstream file(m_settings.firmwarePath, std::ios::binary);
    if (!file)
    {
      error = m_settings.firmwarePath +
              ": cannot open the Falcon firmware file; Proxima does not ship it: give your own "
              "copy with --falcon-firmware (Documentation/Devices.md)";
      return false;
    }
    const std::vector<std::uint8_t> image((std::istreambuf_iterator<char>(file)),
                                          std::istreambuf_iterator<char>());
    if (image.empty())
    {
      error = m_settings.firmwarePath + ": the Falcon firmware file is empty";
      return false;
    }
    if (!enterFirmwareMode(error) || !uploadFirmware(image, error))
    {
      return false;
    }
  }
  if (!enterNormalMode(error))
  {
    return false;
  }
  // The first frame asks for homing; the device answers every frame with one of its own.
  sendFrame();
  return m_connected;
}

void FalconDevice::sendFrame()
{
  FalconFrame frame;
  frame.values = m_commands;
  frame.info = static_cast<std::uint8_t>(m_leds | (m_homed ? 0 : kFalconHomingMode));
  const FalconFrameBytes bytes = encodeFalconFrame(frame);
  const TransportResult result = m_transport->write(bytes);
  if (result.status == TransportStatus::Disconnected)
  {
    m_connected = false;
    m_lastError = "the Falcon is gone";
  }
}

DeviceSample FalconDevice::lost()
{
  DeviceSample sample;
  sample.valid = false;
  sample.connected = false;
  return sample;
}

DeviceSample FalconDevice::read(double /*time*/)
{
  if (!m_connected)
  {
    return lost();
  }
  std::array<std::uint8_t, 64> buffer{};
  const TransportResult result = m_transport->read(buffer, m_settings.readTimeoutMilliseconds);
  if (result.status == TransportStatus::Disconnected)
  {
    m_connected = false;
    m_lastError = "the Falcon is gone";
    return lost();
  }
  DeviceSample sample;
  if (result.ok())
  {
    if (const auto frame = m_reader.push(
          std::span<const std::uint8_t>(buffer.data(), std::min(result.size, buffer.size()))))
    {
      m_encoders = frame->values;
      m_buttons = frame->info & kFalconButtonMask;
      m_homed = (frame->info & kFalconHomedAll) == kFalconHomedAll;
      m_haveFrame = true;
    }
  }
  sample.buttons = m_buttons;
  if (!m_haveFrame || !m_homed)
  {
    sample.valid = false;
    return sample;
  }
  const auto position = m_kinematics.forward(anglesFromCounts(m_encoders));
  if (!position)
  {
    // Encoders no pose explains: a corrupted frame that passed the codec. Refuse it.
    sample.valid = false;
    m_lastError = "the encoders describe no reachable pose";
    return sample;
  }
  sample.position = *position - m_neutral + m_settings.worldOffset;
  return sample;
}

void FalconDevice::writeForce(const Vec3& force, double /*time*/)
{
  if (!m_connected)
  {
    return;
  }
  Vec3 clamped = isFinite(force) ? force : Vec3{};
  const double magnitude = norm(clamped);
  if (magnitude > m_settings.maxForce)
  {
    clamped = clamped * (m_settings.maxForce / magnitude);
  }
  if (m_homed && m_haveFrame)
  {
    m_commands = commandsFromTorques(m_kinematics.torques(anglesFromCounts(m_encoders), clamped));
  }
  else
  {
    m_commands = {0, 0, 0};
  }
  sendFrame();
}

DeviceLimits FalconDevice::limits() const
{
  DeviceLimits limits;
  limits.maxForce = m_settings.maxForce;
  // A cube of 10 cm about the neutral pose: the Falcon's advertised reach.
  limits.workspace.lower = m_settings.worldOffset - Vec3{0.05, 0.05, 0.05};
  limits.workspace.upper = m_settings.worldOffset + Vec3{0.05, 0.05, 0.05};
  return limits;
}

} // namespace proxima
