#include "SpaceMouseEmulator.h"

#include <cmath>

namespace proxima::testing
{
namespace
{
void appendAxes(std::vector<std::uint8_t>& report, const std::array<int, 3>& axes)
{
  for (int value : axes)
  {
    const auto bits = static_cast<std::uint16_t>(static_cast<std::int16_t>(value));
    report.push_back(static_cast<std::uint8_t>(bits & 0xff));
    report.push_back(static_cast<std::uint8_t>(bits >> 8));
  }
}

void appendAxisReport(std::vector<std::uint8_t>& d, std::uint8_t id, std::uint8_t count)
{
  // Report ID, Logical min -350 / max 350, Report Size 16, Report Count `count`, Input (Data,
  // Variable, Absolute).
  const std::vector<std::uint8_t> items{0x85, id,   0x16, 0xa2, 0xfe,  0x26, 0x5e,
                                        0x01, 0x75, 0x10, 0x95, count, 0x81, 0x02};
  d.insert(d.end(), items.begin(), items.end());
}
} // namespace

std::vector<std::uint8_t> spaceMouseDescriptor(SpaceMouseLayout layout)
{
  // Usage Page (Generic Desktop), Usage (Multi-axis Controller), Collection (Application).
  std::vector<std::uint8_t> d{0x05, 0x01, 0x09, 0x08, 0xa1, 0x01};
  if (layout == SpaceMouseLayout::SixAxisReport)
  {
    appendAxisReport(d, 1, 6);
  }
  else
  {
    appendAxisReport(d, 1, 3);
    appendAxisReport(d, 2, 3);
  }
  // Report 3: 16 buttons of one bit (Report Size 1, Report Count 16, Input).
  const std::vector<std::uint8_t> buttons{0x85, 0x03, 0x75, 0x01, 0x95, 0x10, 0x81, 0x02};
  d.insert(d.end(), buttons.begin(), buttons.end());
  // Report 4 as output: the LED (Report Size 8, Count 1, Output).
  const std::vector<std::uint8_t> led{0x85, 0x04, 0x75, 0x08, 0x95, 0x01, 0x91, 0x02, 0xc0};
  d.insert(d.end(), led.begin(), led.end());
  return d;
}

SpaceMouseEmulator::SpaceMouseEmulator(SpaceMouseLayout layout)
  : m_layout(layout)
  , m_descriptor(spaceMouseDescriptor(layout))
{}

void SpaceMouseEmulator::setAxes(const std::array<int, 3>& translation,
                                 const std::array<int, 3>& rotation)
{
  std::lock_guard lock(m_mutex);
  std::vector<std::uint8_t> first{kSpaceMouseTranslationReport};
  appendAxes(first, translation);
  if (m_layout == SpaceMouseLayout::SixAxisReport)
  {
    appendAxes(first, rotation);
    m_pending.push_back(std::move(first));
    return;
  }
  m_pending.push_back(std::move(first));
  std::vector<std::uint8_t> second{kSpaceMouseRotationReport};
  appendAxes(second, rotation);
  m_pending.push_back(std::move(second));
}

void SpaceMouseEmulator::setButtons(std::uint32_t buttons)
{
  std::lock_guard lock(m_mutex);
  m_pending.push_back({kSpaceMouseButtonReport, static_cast<std::uint8_t>(buttons & 0xff),
                       static_cast<std::uint8_t>((buttons >> 8) & 0xff)});
}

void SpaceMouseEmulator::queueRaw(std::vector<std::uint8_t> report)
{
  std::lock_guard lock(m_mutex);
  m_pending.push_back(std::move(report));
}

std::vector<std::uint8_t> SpaceMouseEmulator::nextInputReport()
{
  std::lock_guard lock(m_mutex);
  if (m_pending.empty())
  {
    return {};
  }
  std::vector<std::uint8_t> report = std::move(m_pending.front());
  m_pending.pop_front();
  return report;
}

void SpaceMouseEmulator::onOutputReport(const std::vector<std::uint8_t>& report)
{
  std::lock_guard lock(m_mutex);
  m_outputReports.push_back(report);
  if (report.size() >= 2 && report[0] == kSpaceMouseLedReport)
  {
    m_led = report[1] != 0;
  }
}

bool SpaceMouseEmulator::ledOn() const
{
  std::lock_guard lock(m_mutex);
  return m_led;
}

std::size_t SpaceMouseEmulator::numOutputReports() const
{
  std::lock_guard lock(m_mutex);
  return m_outputReports.size();
}

void SpaceMouseEmulator::unplug()
{
  std::lock_guard lock(m_mutex);
  m_unplugged = true;
}

bool SpaceMouseEmulator::unplugged() const
{
  std::lock_guard lock(m_mutex);
  return m_unplugged;
}

void SpaceMouseEmulator::holdCapAt(const Vec3& offset, double metresPerCount)
{
  const Vec3 counts = offset / metresPerCount;
  setAxes({static_cast<int>(std::lround(counts.x)), static_cast<int>(std::lround(counts.y)),
           static_cast<int>(std::lround(-counts.z))},
          {0, 0, 0});
}

} // namespace proxima::testing
