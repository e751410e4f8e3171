// In-memory transports over the emulators: the drivers' I/O with no kernel, hidapi or libusb in
// between. Short reads can be forced to show that the drivers gather or refuse them.
#pragma once

#include "Devices/DeviceTransport.h"
#include "FalconEmulator.h"
#include "SpaceMouseEmulator.h"

#include <algorithm>
#include <cstring>

namespace proxima::testing
{

class FakeReportTransport final : public ReportTransport
{
public:
  explicit FakeReportTransport(SpaceMouseEmulator& emulator)
    : m_emulator(emulator)
  {}

  TransportResult readReport(std::span<std::uint8_t> buffer, int /*timeout*/) override
  {
    if (m_emulator.unplugged())
    {
      return {TransportStatus::Disconnected, 0};
    }
    const std::vector<std::uint8_t> report = m_emulator.nextInputReport();
    if (report.empty())
    {
      return {TransportStatus::NoData, 0};
    }
    // Like hidraw: a report longer than the buffer is cut to it.
    const std::size_t size = std::min(report.size(), buffer.size());
    std::memcpy(buffer.data(), report.data(), size);
    return {TransportStatus::Ok, size};
  }
  TransportResult writeReport(std::span<const std::uint8_t> report) override
  {
    if (m_emulator.unplugged())
    {
      return {TransportStatus::Disconnected, 0};
    }
    m_emulator.onOutputReport({report.begin(), report.end()});
    return {TransportStatus::Ok, report.size()};
  }

private:
  SpaceMouseEmulator& m_emulator;
};

class FakeBulkTransport final : public BulkTransport
{
public:
  explicit FakeBulkTransport(FalconEmulator& emulator)
    : m_emulator(emulator)
  {}

  /// Each read returns at most this many bytes (a USB packet cut short, a slow bridge).
  std::size_t maxReadSize = 1024;

  TransportResult control(std::uint8_t request, std::uint16_t value, std::uint16_t index) override
  {
    if (m_emulator.unplugged())
    {
      return {TransportStatus::Disconnected, 0};
    }
    m_emulator.control(request, value, index);
    return {TransportStatus::Ok, 0};
  }
  TransportResult write(std::span<const std::uint8_t> bytes) override
  {
    if (m_emulator.unplugged())
    {
      return {TransportStatus::Disconnected, 0};
    }
    m_emulator.receive(bytes.data(), bytes.size());
    return {TransportStatus::Ok, bytes.size()};
  }
  TransportResult read(std::span<std::uint8_t> buffer, int /*timeout*/) override
  {
    if (m_emulator.unplugged())
    {
      return {TransportStatus::Disconnected, 0};
    }
    const std::vector<std::uint8_t> bytes =
      m_emulator.transmit(std::min(buffer.size(), maxReadSize));
    if (bytes.empty())
    {
      return {TransportStatus::NoData, 0};
    }
    std::memcpy(buffer.data(), bytes.data(), bytes.size());
    return {TransportStatus::Ok, bytes.size()};
  }

private:
  FalconEmulator& m_emulator;
};

} // namespace proxima::testing
