#include "Devices/SpaceMouseDevice.h"

#include <algorithm>
#include <cmath>

namespace proxima
{

SpaceMouseDevice::SpaceMouseDevice(std::unique_ptr<ReportTransport> transport,
                                   const SpaceMouseSettings& settings)
  : m_transport(std::move(transport))
  , m_settings(settings)
  , m_ratePosition(settings.centre)
{}

Vec3 SpaceMouseDevice::mapped(const std::array<int, 3>& counts) const
{
  Vec3 result;
  for (int i = 0; i < 3; ++i)
  {
    const int source = std::clamp(m_settings.axisMap[static_cast<std::size_t>(i)], 0, 2);
    result[i] = m_settings.axisSign[static_cast<std::size_t>(i)] *
                static_cast<double>(counts[static_cast<std::size_t>(source)]);
  }
  return result;
}

DeviceSample SpaceMouseDevice::read(double time)
{
  DeviceSample sample;
  if (!m_connected)
  {
    sample.valid = false;
    sample.connected = false;
    return sample;
  }
  // Drain what the device sent since the last tick; the newest report of each kind wins.
  std::array<std::uint8_t, 64> buffer{};
  for (int i = 0; i < m_settings.maxReportsPerTick; ++i)
  {
    const TransportResult result = m_transport->readReport(buffer, 0);
    if (result.status == TransportStatus::NoData)
    {
      break;
    }
    if (result.status == TransportStatus::Disconnected)
    {
      m_connected = false;
      m_lastError = "the SpaceMouse is gone";
      sample.valid = false;
      sample.connected = false;
      return sample;
    }
    if (result.status == TransportStatus::Failed || result.size > buffer.size())
    {
      ++m_refusedReports;
      m_lastError = "a report could not be read";
      break;
    }
    const SpaceMouseReportResult applied = applySpaceMouseReport(
      std::span<const std::uint8_t>(buffer.data(), result.size), m_settings.layout, m_state);
    if (!applied.accepted)
    {
      ++m_refusedReports;
      m_lastError = applied.error;
    }
  }

  const Vec3 offset = mapped(m_state.translation);
  const Vec3 low = m_settings.centre - Vec3{1, 1, 1} * m_settings.halfRange;
  const Vec3 high = m_settings.centre + Vec3{1, 1, 1} * m_settings.halfRange;
  Vec3 position;
  if (m_settings.rateMode)
  {
    const double dt = m_started ? std::max(0.0, time - m_lastTime) : 0.0;
    m_ratePosition += offset * (m_settings.metresPerSecondPerCount * dt);
    m_ratePosition = componentMax(low, componentMin(high, m_ratePosition));
    position = m_ratePosition;
  }
  else
  {
    position =
      componentMax(low, componentMin(high, m_settings.centre + offset * m_settings.metresPerCount));
  }
  m_started = true;
  m_lastTime = time;

  sample.position = position;
  sample.buttons = m_state.buttons;
  // The cap's twist as a rotation vector, turned into a unit quaternion.
  const Vec3 rotation = mapped(m_state.rotation) * m_settings.radiansPerCount;
  const double angle = norm(rotation);
  sample.hasOrientation = true;
  if (angle > 0.0)
  {
    const Vec3 axis = rotation / angle;
    const double s = std::sin(0.5 * angle);
    sample.orientation = {std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s};
  }
  return sample;
}

void SpaceMouseDevice::writeForce(const Vec3& force, double /*time*/)
{
  m_lastForce = force;
}

DeviceLimits SpaceMouseDevice::limits() const
{
  DeviceLimits limits;
  limits.workspace.lower = m_settings.centre - Vec3{1, 1, 1} * m_settings.halfRange;
  limits.workspace.upper = m_settings.centre + Vec3{1, 1, 1} * m_settings.halfRange;
  return limits;
}

bool SpaceMouseDevice::setLed(bool on)
{
  if (!m_connected)
  {
    return false;
  }
  const auto report = spaceMouseLedReport(on);
  const TransportResult result = m_transport->writeReport(report);
  if (result.status == TransportStatus::Disconnected)
  {
    m_connected = false;
  }
  return result.ok();
}

} // namespace proxima
