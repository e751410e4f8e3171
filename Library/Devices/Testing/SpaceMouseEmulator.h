// An emulated SpaceMouse for tests: the cap's state is set by the test, and the emulator turns
// each change into the input reports a real device sends (split or six-axis layout), with the
// report descriptor that announces the layout. It records the output reports (LED) it gets.
#pragma once

#include "Core/Vec3.h"
#include "Devices/SpaceMouseReports.h"

#include <cstdint>
#include <deque>
#include <mutex>
#include <vector>

namespace proxima::testing
{

class SpaceMouseEmulator
{
public:
  explicit SpaceMouseEmulator(SpaceMouseLayout layout);

  /// Moves the cap: queues the reports a device sends for this change.
  void setAxes(const std::array<int, 3>& translation, const std::array<int, 3>& rotation);
  /// The hand holds the cap so that a position-mode driver with `metresPerCount` reads the finger
  /// `offset` metres from its centre: counts = offset / scale, rounded, with z reversed (the
  /// driver's default axis map); no rotation.
  void holdCapAt(const Vec3& offset, double metresPerCount);
  void setButtons(std::uint32_t buttons);
  /// Queues a report as is (malformed ones too).
  void queueRaw(std::vector<std::uint8_t> report);

  /// The next input report, or an empty vector when none is pending.
  std::vector<std::uint8_t> nextInputReport();
  void onOutputReport(const std::vector<std::uint8_t>& report);

  const std::vector<std::uint8_t>& reportDescriptor() const { return m_descriptor; }
  bool ledOn() const;
  std::size_t numOutputReports() const;

  /// Unplugged: the transports report a disconnect from now on.
  void unplug();
  bool unplugged() const;

private:
  mutable std::mutex m_mutex;
  SpaceMouseLayout m_layout;
  std::vector<std::uint8_t> m_descriptor;
  std::deque<std::vector<std::uint8_t>> m_pending;
  std::vector<std::vector<std::uint8_t>> m_outputReports;
  bool m_led = false;
  bool m_unplugged = false;
};

/// A report descriptor with input report 1 of 6 or 12 bytes (and 2 and 3 for the split layout),
/// written out byte by byte from the HID item encoding.
std::vector<std::uint8_t> spaceMouseDescriptor(SpaceMouseLayout layout);

} // namespace proxima::testing
