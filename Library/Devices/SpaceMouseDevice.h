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

/// How a SpaceMouseDevice reads its reports and turns the cap's counts into the finger's
/// position (m) and orientation.
struct SpaceMouseSettings
{
  /// Which reports carry the rotation; openDevice() reads it from the report descriptor when it
  /// can, and else goes by the vendor ID.
  SpaceMouseLayout layout = SpaceMouseLayout::SplitReports;
  /// Position mode: finger = centre + counts x metresPerCount. Rate mode: finger velocity =
  /// counts x metresPerSecondPerCount, integrated on the runtime's clock.
  bool rateMode = false;
  /// Middle of the workspace in the world (m): the finger with the cap at rest in position
  /// mode, and where it starts in rate mode.
  Vec3 centre;
  /// Position mode: finger travel (m) per count of cap offset.
  double metresPerCount = 0.05 / 350.0;
  /// Rate mode: finger speed (m/s) per count of cap offset.
  double metresPerSecondPerCount = 0.1 / 350.0;
  /// Rotation: radians per count of the cap's twist (orientation of the sample).
  double radiansPerCount = 0.5 / 350.0;
  /// World axis i takes device axis axisMap[i] times axisSign[i]. The default puts the device's
  /// z (positive when the cap is pushed down) on world -z, so that pushing down moves the finger
  /// down in a z-up world.
  std::array<int, 3> axisMap{0, 1, 2};
  /// Factor (+1 or -1) by which world axis i takes its device axis (see axisMap).
  std::array<double, 3> axisSign{1.0, 1.0, -1.0};
  /// The finger stays within centre +- halfRange on each axis (rate mode integrates into it).
  double halfRange = 0.05;
  /// Input reports taken per tick at most (the device sends one per axis group and change).
  int maxReportsPerTick = 16;
};

/// A 3Dconnexion SpaceMouse as a HapticDevice: read() applies the reports that arrived since the
/// last tick and gives the finger within centre +- halfRange, with the cap's twist as its
/// orientation; writeForce() only keeps the force, since the device has no motors.
class SpaceMouseDevice final : public HapticDevice
{
public:
  /// Takes ownership of `transport`; does no I/O until the first read() or setLed().
  SpaceMouseDevice(std::unique_ptr<ReportTransport> transport, const SpaceMouseSettings& settings);

  DeviceSample read(double time) override;
  void writeForce(const Vec3& force, double time) override;
  DeviceLimits limits() const override;
  const char* name() const override { return "spacemouse"; }

  /// Switches the LED; false if the report could not be sent.
  bool setLed(bool on);

  /// The raw axis counts and buttons from the reports applied so far.
  const SpaceMouseState& state() const { return m_state; }
  /// Reports refused so far: unreadable or malformed.
  std::uint64_t refusedReports() const { return m_refusedReports; }
  /// Why the latest report was refused, or that the device is gone; empty if neither happened.
  const std::string& lastError() const { return m_lastError; }
  /// The force (N) of the latest writeForce(), kept for display only; zero before any.
  const Vec3& lastForce() const { return m_lastForce; }
  /// False once the transport reported the device gone; every later read() is a lost sample.
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
