// A 3Dconnexion SpaceMouse as the finger: the cap's translation moves the finger, as a position
// (the cap's offset scaled about a centre) or as a rate (the offset is a velocity). It has no
// motors: forces are kept for display only. The transport is hidapi's hidraw backend for a real
// device (HidapiTransport) or an emulator in tests; reports that are malformed are refused and
// counted, never trusted.
#pragma once

#include "Devices/DeviceTransport.h"
#include "Devices/SpaceMouseReports.h"
#include "Runtime/HapticDevice.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace proxima
{

struct SpaceMouseSettings
{
  SpaceMouseLayout layout = SpaceMouseLayout::SplitReports;
  /// Position mode: finger = centre + counts x metresPerCount. Rate mode: finger velocity =
  /// counts x metresPerSecondPerCount, integrated on the runtime's clock.
  bool rateMode = false;
  Vec3 centre;
  double metresPerCount = 0.05 / 350.0;
  double metresPerSecondPerCount = 0.1 / 350.0;
  /// Rotation: radians per count of the cap's twist (orientation of the sample).
  double radiansPerCount = 0.5 / 350.0;
  /// World axis i takes device axis axisMap[i] times axisSign[i]. The default puts the device's
  /// z (positive when the cap is pushed down) on world -z, so that pushing down moves the finger
  /// down in a z-up world.
  std::array<int, 3> axisMap{0, 1, 2};
  std::array<double, 3> axisSign{1.0, 1.0, -1.0};
  /// The finger stays within centre +- halfRange on each axis (rate mode integrates into it).
  double halfRange = 0.05;
  /// Input reports taken per tick at most (the device sends one per axis group and change).
  int maxReportsPerTick = 16;
};

class SpaceMouseDevice final : public HapticDevice
{
public:
  SpaceMouseDevice(std::unique_ptr<ReportTransport> transport, const SpaceMouseSettings& settings);

  DeviceSample read(double time) override;
  void writeForce(const Vec3& force, double time) override;
  DeviceLimits limits() const override;
  const char* name() const override { return "spacemouse"; }

  /// Switches the LED; false if the report could not be sent.
  bool setLed(bool on);

  const SpaceMouseState& state() const { return m_state; }
  std::uint64_t refusedReports() const { return m_refusedReports; }
  const std::string& lastError() const { return m_lastError; }
  const Vec3& lastForce() const { return m_lastForce; }
  bool connected() const { return m_connected; }

private:
  Vec3 mapped(const std::array<int, 3>& counts) const;

  std::unique_ptr<ReportTransport> m_transport;
  SpaceMouseSettings m_settings;
  SpaceMouseState m_state;
  Vec3 m_ratePosition;
  double m_lastTime = 0.0;
  bool m_started = false;
  bool m_connected = true;
  std::uint64_t m_refusedReports = 0;
  std::string m_lastError;
  Vec3 m_lastForce;
};

} // namespace proxima
